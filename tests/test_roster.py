"""The class list as instructors and learning systems write it: every mistake one clear line with its line
and column, never a traceback; what spreadsheets and learning systems export is understood."""
import codecs
from pathlib import Path

import pytest

from exgen.errors import AssignmentError
from exgen.issue.roster import load_roster, read_roster


def roster(tmp_path: Path, content, name="roster.csv") -> Path:
    path = tmp_path / name
    path.write_bytes(content if isinstance(content, bytes) else content.encode("utf-8"))
    return path


def refusal(path: Path) -> str:
    with pytest.raises(AssignmentError) as caught:
        load_roster(path)
    message = str(caught.value)
    assert "\n" not in message and "Traceback" not in message
    return message


def test_a_row_with_an_extra_field_is_one_line_with_its_place(tmp_path):
    """`A1,Lim, Daniel,a@x,S1` under id,name,email,section was AttributeError: 'list' object has no
    attribute 'strip'."""
    path = roster(tmp_path, "id,name,email,section\nA0,Nur,n@x,S1\nA1,Lim, Daniel,a@x,S1\n")
    message = refusal(path)
    assert message.startswith(f"{path}:3:20: this row has 5 fields, but the header names 4")
    assert '"Lim, Daniel"' in message


def test_trailing_empty_fields_from_a_spreadsheet_are_no_extra_fields(tmp_path):
    path = roster(tmp_path, "id,name\nA1,One,,\nA2,Two,\n")
    assert [s.name for s in load_roster(path)] == ["One", "Two"]


def test_errors_count_lines_not_records(tmp_path):
    """A quoted name over two lines made every later error a line early."""
    path = roster(tmp_path, 'id,name\nA1,"Lim\nDaniel"\nA 2,Two\n')
    assert refusal(path).startswith(f"{path}:4:1: student id 'A 2' must be letters")


@pytest.mark.parametrize("delimiter", [";", "\t"])
def test_semicolon_and_tab_rosters_are_read(tmp_path, delimiter):
    """A semicolon roster was refused without naming the delimiter (answer CSVs accept semicolons)."""
    path = roster(tmp_path, delimiter.join(["id", "name", "email"]) + "\n" +
                  delimiter.join(["A1", "Lim, Daniel", "d@x"]) + "\n")
    assert [(s.id, s.name, s.email) for s in load_roster(path)] == [("A1", "Lim, Daniel", "d@x")]
    assert read_roster(path).delimiter == delimiter


@pytest.mark.parametrize("codec", ["utf-16", "utf-16-le", "utf-16-be", "utf-8-sig"])
def test_utf16_and_bom_rosters_are_read(tmp_path, codec):
    """UTF-16 rosters (Excel's "Unicode text") got the codec's message."""
    text = "id\tname\nA1\tZoë Lim\nA2\tŁukasz\n"
    bom = {"utf-16-le": codecs.BOM_UTF16_LE, "utf-16-be": codecs.BOM_UTF16_BE}.get(codec, b"")
    path = roster(tmp_path, bom + text.encode(codec))
    assert [s.name for s in load_roster(path)] == ["Zoë Lim", "Łukasz"]


def test_a_latin1_roster_is_refused_saying_what_it_would_read(tmp_path):
    path = roster(tmp_path, "id,name\nA1,Ann\nA2,Zo\xeb Lim\n".encode("latin-1"))
    message = refusal(path)
    assert message.startswith(f"{path}:3:6: not UTF-8 text (the byte 0xeb)")
    assert "'Zoë Lim'" in message and "save the roster as CSV UTF-8" in message


def test_utf16_without_its_byte_order_mark_is_refused_clearly(tmp_path):
    assert "UTF-16 text without its byte-order mark" in refusal(roster(tmp_path, "id\nA1\n".encode("utf-16-le")))


def test_ids_differing_only_in_capitals_are_one_student_twice(tmp_path):
    """A1 and a1 were two students: their folders collide on a case-insensitive file system."""
    path = roster(tmp_path, "id,name\nA1,One\nB1,Two\na1,Three\n")
    message = refusal(path)
    assert message.startswith(f"{path}:4:1: student id 'a1' is 'A1' of line 2 in other capitals")
    assert "Windows and macOS" in message
    assert refusal(roster(tmp_path, "id\nA1\nA1\n")).endswith("student id 'A1' appears twice (first on line 2)")


@pytest.mark.parametrize("header, row, expected", [
    ("ID Number,First name,Last name,Email address", "B1,Ann,Lee,ann@x", ("B1", "Ann Lee", "ann@x", "")),
    ("Student ID,Name,Group", "B1,Ann Lee,T2", ("B1", "Ann Lee", "", "T2")),
    ("Student,ID,SIS User ID,SIS Login ID,Section", "\"Lee, Ann\",4711,B1,ann@x,S1", ("B1", "Lee, Ann", "", "S1")),
    ("Username,Full name,E-mail", "b1,Ann Lee,ann@x", ("b1", "Ann Lee", "ann@x", "")),
    ("idnumber,firstname,lastname,email", "B1,Ann,Lee,ann@x", ("B1", "Ann Lee", "ann@x", "")),
])
def test_learning_system_exports_are_understood(tmp_path, header, row, expected):
    """A roster headed "ID Number" (the learning system's own name) was refused without a word on which
    header is wanted."""
    path = roster(tmp_path, f"{header}\n{row}\n")
    student = load_roster(path)[0]
    assert (student.id, student.name, student.email, student.section) == expected


def test_a_roster_without_any_id_column_says_which_header_is_wanted(tmp_path):
    path = roster(tmp_path, "Email address,First name\nann@x,Ann\n")
    message = refusal(path)
    assert message.startswith(f"{path}:1: no column of student ids: the roster needs one headed `id`")
    assert "ID number" in message and "found Email address, First name" in message


@pytest.mark.parametrize("content, expected", [
    ("", "the roster is empty"), ("id,name\n", "the roster lists no students"), ("id\n\n\n", "lists no students"),
    ("id,name\n,Nobody\n", ":2:1: no student id on this line"), (b"id\nA1\x00\n", "NUL bytes"),
])
def test_other_mistakes_are_one_line(tmp_path, content, expected):
    assert expected in refusal(roster(tmp_path, content))


def test_a_pipe_or_device_given_as_the_roster_is_refused_without_waiting(tmp_path):
    import os

    os.mkfifo(tmp_path / "roster.csv")
    assert "a named pipe, not a regular file" in refusal(tmp_path / "roster.csv")


def test_the_command_gives_a_roster_mistake_as_one_line(tmp_path, capsys):
    from exgen.cli import main

    path = roster(tmp_path, "id,name,email,section\nA1,Lim, Daniel,a@x,S1\n")
    examples = Path(__file__).parent.parent / "examples"
    assert main(["generate", str(examples / "tutorial1.yaml"), "--roster", str(path), "--out", str(tmp_path / "o"),
                 "--no-pdf", "--secret-file", str(roster(tmp_path, "a private course secret for tests", "s"))]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"exgen: {path}:2:20: this row has 5 fields")
