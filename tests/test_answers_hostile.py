"""Hostile answer files: each is refused with a clear SubmissionError (file and line), quickly, and
nothing in them is ever run or built."""
import os
import time

import pytest

from exgen.errors import SubmissionError
from graders.answers import read_submission
from graders.formats import MAX_FILE_BYTES

BILLION_LAUGHS = "\n".join(
    ["a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]"]
    + [f"a{i}: &a{i} [{', '.join(f'*a{i - 1}' for _ in range(9))}]" for i in range(1, 10)]
    + ["answers: {q1: {a: *a9}}"]
)


def hostile_files(tmp_path):
    marker = tmp_path / "pwned"
    return {
        "yaml bomb": ("bomb.yaml", BILLION_LAUGHS, "aliases", 2),
        "python object": ("obj.yaml", f"student: s001\nanswers: !!python/object/apply:os.system ['touch {marker}']\n",
                          "tag", 2),
        "python name": ("name.yaml", "answers:\n  q1:\n    a: !!python/name:os.system\n", "tag", 3),
        "binary tag": ("bin.yaml", "answers:\n  q1:\n    a: !!binary aGVsbG8=\n", "tag", 3),
        "local tag": ("tag.yaml", "answers:\n  q1: !mine {a: 1}\n", "tag", 2),
        "complex key": ("key.yaml", "answers:\n  ? [a, b]\n  : 1\n", "key", 2),
        "top-level list": ("list.yaml", "- 1\n- 2\n", "a list", 1),
        "top-level text": ("text.yaml", "just some text\n", "text", 1),
        "json list": ("list.json", "[1, 2, 3]", "a list", None),
        "answers a list": ("al.yaml", "student: s001\nanswers:\n  - 5 N\n", "`answers`", 2),
        "yaml syntax": ("syn.yaml", "answers:\n  q1:\n    a: \"5 N\n", "YAML", None),
        "json syntax": ("syn.json", '{"answers": {"q1": {"a": "5 N"}\n', "JSON", 2),
        "two documents": ("two.yaml", "a: 1\n---\nb: 2\n", "YAML", 2),
        "empty": ("empty.yaml", "", "empty", None),
        "deep yaml": ("deep.yaml", "[" * 100_000 + "]" * 100_000, "nested", 1),
        "deep yaml blocks": ("deepb.yaml", "".join(f"{' ' * i}k{i}:\n" for i in range(40)), "nested", None),
        "deep json": ("deep.json", "[" * 100_000 + "]" * 100_000, "nested", None),
        "control char": ("ctl.yaml", "answers:\n  q1:\n    a: 5\x07N\n", "YAML", 3),
        "huge csv field": ("huge.csv", "q1,a," + "9" * 200_000 + "\n", "CSV", 1),
    }, marker


@pytest.mark.parametrize("case", list(hostile_files(__import__("pathlib").Path("/x"))[0]))
def test_hostile_file_is_refused_with_its_reason(tmp_path, case):
    files, marker = hostile_files(tmp_path)
    name, text, reason, line = files[case]
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    start = time.perf_counter()
    with pytest.raises(SubmissionError) as caught:
        read_submission(path)
    assert time.perf_counter() - start < 5
    error = caught.value
    assert reason.lower() in error.detail.lower()
    assert str(path) in str(error)
    if line is not None:
        assert error.line == line
    assert not marker.exists()


@pytest.mark.parametrize("name, payload, reason, line", [
    ("latin1.yaml", "answers:\n  q1:\n    a: 5 \u00b0\n".encode("latin-1"), "UTF-8", 3),
    ("binary.yaml", bytes(range(256)) * 8, "binary", 1),
    ("nul.json", b'{"answers": {"q1": {"a": "5\x00N"}}}', "binary", 1),
    ("random.csv", os.urandom(4096).replace(b"\x00", b"") + b"\xff\xfe\xfd", "UTF-8", None),
])
def test_bytes_that_are_not_text(tmp_path, name, payload, reason, line):
    path = tmp_path / name
    path.write_bytes(payload)
    with pytest.raises(SubmissionError) as caught:
        read_submission(path)
    assert reason in caught.value.detail
    if line is not None:
        assert caught.value.line == line


@pytest.mark.parametrize("size", [MAX_FILE_BYTES + 1, 10 * 1024 * 1024])
def test_oversized_file_is_refused_before_it_is_read(tmp_path, size):
    path = tmp_path / "big.yaml"
    with path.open("wb") as handle:
        handle.write(b"answers:\n  q1:\n    a: \"")
        handle.truncate(size)
    start = time.perf_counter()
    with pytest.raises(SubmissionError, match="KiB"):
        read_submission(path)
    assert time.perf_counter() - start < 1


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="needs /dev/zero")
def test_endless_file_behind_a_link_is_bounded(tmp_path):
    path = tmp_path / "zero.yaml"
    path.symlink_to("/dev/zero")
    with pytest.raises(SubmissionError):
        read_submission(path)


def test_big_but_allowed_csv_field_is_an_unreadable_answer_not_a_crash(tmp_path):
    path = tmp_path / "s.csv"
    path.write_text("student,s001\nq1,a," + "9" * 100_000 + "\n", encoding="utf-8")
    assert len(read_submission(path).answers["q1"]["a"]) == 100_000
