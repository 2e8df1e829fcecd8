"""Reading answer files is bounded before anything is built: entries, nesting, notes and time per file."""
import json

import pytest
import yaml

from exgen.errors import SubmissionError
from graders import formats
from graders.answers import read_submission
from graders.echo import shown
from graders.formats import MAX_DEPTH, MAX_ENTRIES, MAX_FILE_BYTES, MAX_WARNINGS


def fill(text_of, size=MAX_FILE_BYTES - 64) -> str:
    """The longest text of repeated lines that still fits the size limit."""
    lines, total, i = [], 0, 0
    while total < size:
        line = text_of(i)
        lines.append(line)
        total += len(line.encode())
        i += 1
    return "".join(lines[:-1])


@pytest.mark.parametrize("name, text", [
    ("keys.yaml", "answers:\n  q1:\n" + fill(lambda i: f"    k{i}: \"1\"\n")),
    ("flow.yaml", "answers: [" + fill(lambda i: "1,") + "1]\n"),
    ("maps.yaml", "answers:\n" + fill(lambda i: f"  - {{a: {i}}}\n")),
    ("keys.json", "{" + fill(lambda i: f'"k{i}": "1",') + '"z": "1"}'),
    ("rows.csv", fill(lambda i: f"q{i},a,1\n")),
])
def test_a_file_at_the_size_limit_with_too_many_entries_is_refused(tmp_path, name, text):
    """A 256 KiB YAML file of many small entries took seconds in the pure-Python loader."""
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    assert path.stat().st_size <= MAX_FILE_BYTES
    with pytest.raises(SubmissionError, match=f"more than {MAX_ENTRIES}"):
        read_submission(path)


def test_yaml_events_come_from_libyaml_when_pyyaml_has_it():
    if yaml.__with_libyaml__:
        assert formats._EventLoader is yaml.CSafeLoader


@pytest.mark.parametrize("name, text", [
    ("a.yaml", "answers:\n  q1:\n    a: 5 N\n"),
    ("a.json", '{"answers": {"q1": {"a": "5 N"}}}'),
    ("a.csv", "q1,a,5 N\n" * 300),
])
def test_reading_stops_at_its_deadline(tmp_path, name, text):
    """The deadline starts before the file is opened, so it holds for every format (JSON's C scanner,
    which cannot be interrupted, reads at most the size limit)."""
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    assert read_submission(path).answers["q1"]["a"] == "5 N"
    with pytest.raises(SubmissionError, match="took too long to read"):
        read_submission(path, seconds=0)


def test_json_nesting_is_refused_with_its_line(tmp_path):
    path = tmp_path / "deep.json"
    path.write_text('{"answers":\n' + "[" * (MAX_DEPTH + 5) + "]" * (MAX_DEPTH + 5) + "}", encoding="utf-8")
    with pytest.raises(SubmissionError, match=f"nested more than {MAX_DEPTH} levels") as caught:
        read_submission(path)
    assert caught.value.line == 2


def test_brackets_inside_json_strings_are_not_nesting(tmp_path):
    path = tmp_path / "a.json"
    path.write_text(json.dumps({"answers": {"q1": {"a": "[" * 50 + " \\\" {{{{"}}}), encoding="utf-8")
    assert read_submission(path).answers["q1"]["a"].startswith("[[[")


def test_notes_about_one_file_are_capped(tmp_path):
    path = tmp_path / "s.csv"
    path.write_text("q1,a,1\n" * 500 + "junk\n" * 500, encoding="utf-8")
    warnings = read_submission(path).warnings
    assert len(warnings) == MAX_WARNINGS + 1 and warnings[-1].startswith("... and ")


def test_a_long_duplicate_key_is_not_echoed_whole(tmp_path):
    key = "k" * 100_000
    path = tmp_path / "s.json"
    path.write_text(f'{{"answers": {{"{key}": "1", "{key}": "2"}}}}', encoding="utf-8")
    warnings = read_submission(path).warnings
    assert warnings and max(len(w) for w in warnings) < 120


def test_an_editors_extra_txt_suffix_is_looked_through(tmp_path):
    path = tmp_path / "answers.yaml.txt"
    path.write_text("student: s001\nanswers:\n  q1:\n    a: 5 N\n", encoding="utf-8")
    assert read_submission(path).answers == {"q1": {"a": "5 N"}}


def test_a_second_yaml_document_is_refused_with_its_line(tmp_path):
    path = tmp_path / "two.yaml"
    path.write_text("answers: {}\n---\nanswers: {q1: {a: 1}}\n", encoding="utf-8")
    with pytest.raises(SubmissionError, match="second document") as caught:
        read_submission(path)
    assert caught.value.line == 2


@pytest.mark.parametrize("text, expected", [
    ("5\u202e N", "5 N"), ("\u2066abc\u2069", "abc"), ("a\u200bb", "a b"), ("a\x1b[31mb", "a [31mb"),
    ("line\nbreak\u2028here", "line break here"), ("\ufeff5", "5"), ("x" * 200, "x" * 79 + "\u2026"),
    ("\U0001f4a5 ok", "\U0001f4a5 ok"), ("caf\u00e9", "caf\u00e9"),
])
def test_echoed_text_is_one_short_line_without_hidden_characters(text, expected):
    assert shown(text, 80) == expected


def test_echoing_a_megabyte_costs_what_a_line_does():
    assert len(shown("\u202e" * 1_000_000 + "x" * 1_000_000, 60)) <= 60


def test_printable_text_holds_nothing_that_echoing_would_change():
    """`shown` returns printable text that is already one clean line as it is: it may, because no
    printable character is one it drops or a blank other than the space (the whole of Unicode checked)."""
    import unicodedata

    from exgen.echo import _DROPPED

    changed = [hex(c) for c in range(0x110000) if chr(c).isprintable() and chr(c) != " "
               and (chr(c).isspace() or unicodedata.category(chr(c)) in _DROPPED)]
    assert changed == []


@pytest.mark.parametrize("text, word, expected", [
    ("θ = 168.7°", None, "θ = 168.7°"),
    ("not within 1 % of the expected value, whatever its size", 48, "not within 1 % of the expected value, whatever its size"),
    ("cannot read '" + "9" * 60 + "' as a number", 48, "cannot read '" + "9" * 47 + "\u2026 as a number"),
    ("ω  = 3\u202e1", None, "ω = 3 1"),
])
def test_a_long_message_is_kept_whole_unless_one_word_is_too_long(text, word, expected):
    assert shown(text, 400, word=word) == expected
