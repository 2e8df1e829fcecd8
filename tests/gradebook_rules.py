"""What Canvas's and Moodle's gradebook imports do with a CSV file: ports of their code, for the tests.

Canvas: instructure/canvas-lms app/models/gradebook_importer.rb (GradebookImporter#parse!,
`update_column_count`, `process_student`, `process_submissions`, `no_score?`, `no_change_to_value?`;
read at the version the search index holds, id 398797707), then the upload posts each changed cell: a
blank over a score is `posted_grade: null`, a removal. A course student with no row is not in
`@students`, so none of their grades is touched.

Moodle: moodle/moodle grade/import/csv/classes/load_data.php (`prepare_import_grade_data`,
`map_user_data_with_value`, `check_user_exists`, `update_grade_item`) and grade/import/lib.php
(`grade_import_commit`: `update_final_grade(userid, finalgrade)`, where null clears the grade and only
false leaves it). Email and username match case-insensitively, an ID number exactly; a row whose user is
not found, or has no user value at all, aborts the whole import and nothing is written.
"""
from __future__ import annotations

import csv
import io
import re
from dataclasses import dataclass, field

_TITLE_AND_ID = re.compile(r"\A(.*)\s\((\d+)\)\Z")  # Assignment.title_and_id


@dataclass
class CanvasStudent:
    id: int
    name: str
    sis_user_id: str = ""
    login_id: str = ""


@dataclass
class CanvasCourse:
    students: list
    assignment_id: int
    assignment_title: str
    scores: dict = field(default_factory=dict)  # student id -> score as Canvas shows it ("" for none)


def canvas_import(text: str, course: CanvasCourse) -> dict[int, str]:
    """The course's scores in the assignment after importing `text` and saving every change the upload
    lists. A column of another title or id makes a new assignment: then no existing score changes."""
    rows = [r for r in csv.reader(io.StringIO(text)) if not re.fullmatch(r"[;, ]*", ",".join(r))]
    header = rows[0]
    assert len(header) > 3 and "Student" in header[0] and "ID" in header[1], "InvalidHeaderRow"
    columns = 3
    sis_user = sis_login = None
    if re.search(r"SIS\s+Login\s+ID", header[2]):
        sis_login, columns = 2, 4
    elif re.search(r"SIS\s+User\s+ID", header[2]) and re.search(r"SIS\s+Login\s+ID", header[3]):
        sis_user, sis_login, columns = 2, 3, 5
    assert "Section" in header[columns - 1], "InvalidHeaderRow: the last student column is not Section"
    index, existing = None, False
    for i, name in enumerate(header[columns:], start=columns):
        match = _TITLE_AND_ID.match(name)
        if match and int(match.group(2)) == course.assignment_id or name == course.assignment_title:
            index, existing = i, True
        elif index is None:
            index = i
    scores = dict(course.scores)
    if not existing:
        return scores  # a new assignment: the course's scores in this one are untouched
    for row in rows[1:]:
        if "Points Possible" in (row[0] or ""):
            continue
        student = _canvas_student(row, course, sis_user, sis_login)
        if student is None:
            continue  # a new User: shown apart, never given this assignment's existing score
        new, current = (row[index] or "").strip(), scores.get(student.id, "")
        if not _no_change(new, current):
            scores[student.id] = "" if _no_score(new) else new
    return scores


def _canvas_student(row, course, sis_user, sis_login):
    """process_student: Canvas ID, else SIS user ID, else SIS login ID, else the name."""
    by_id = {s.id: s for s in course.students}
    if row[1].strip().isdigit() and int(row[1]) in by_id:
        return by_id[int(row[1])]
    if sis_user is not None and row[sis_user]:
        found = next((s for s in course.students if s.sis_user_id == row[sis_user]), None)
        if found:
            return found
    if sis_login is not None and row[sis_login]:
        found = next((s for s in course.students if s.login_id == row[sis_login]), None)
        if found:
            return found
    return next((s for s in course.students if s.name == row[0]), None)


def _no_score(value: str) -> bool:
    return not value.strip() or value == "-"


def _no_change(new: str, current: str) -> bool:
    """no_change_to_value?: equal, or both without a score, or the same to two decimals."""
    if new == current or (_no_score(new) and _no_score(current)):
        return True
    if _no_score(new) or _no_score(current):
        return False
    if "EX" in (new.upper(), current.upper()):
        return False
    return f"{float(new):.2f}" == f"{float(current):.2f}"


@dataclass
class MoodleUser:
    id: int
    idnumber: str
    email: str
    username: str = ""


@dataclass
class MoodleImport:
    ok: bool
    grades: dict  # user id -> final grade (None: no grade)
    error: str = ""


_FIELDS = {"userid": "id", "useridnumber": "idnumber", "useremail": "email", "username": "username"}
_CASE_INSENSITIVE = ("email", "username")


def moodle_import(text: str, users: list, grades: dict, map_from: str, map_to: str, grade_column: str) -> MoodleImport:
    """Moodle's CSV grade import of `text`, the column `map_from` mapped to `map_to` (useridnumber,
    useremail...) and `grade_column` to the existing grade item holding `grades`."""
    rows = list(csv.reader(io.StringIO(text)))
    header = [h.strip() for h in rows[0]]
    user_key, grade_key = header.index(map_from), header.index(grade_column)
    buffered, student = [], None
    for line in rows[1:]:
        if len(line) <= 1:
            continue
        for key, value in enumerate(line):
            value = value.strip()
            if key == user_key and value:  # "Skip invalid row with blank user field."
                student = _moodle_user(users, _FIELDS[map_to], value)
                if student is None:
                    return MoodleImport(False, dict(grades), f"usermappingerror: {value}")
            elif key == grade_key:
                if value in ("", "-"):
                    final = None  # "No grade."
                else:
                    try:
                        final = float(value)
                    except ValueError:
                        return MoodleImport(False, dict(grades), f"badgrade: {value}")
        if student is None:
            return MoodleImport(False, dict(grades), "usermappingerrorusernotfound")
        buffered.append((student.id, final))
    out = dict(grades)
    for user_id, final in buffered:  # grade_import_commit: update_final_grade(userid, finalgrade)
        out[user_id] = final
    return MoodleImport(True, out)


def _moodle_user(users, field_name: str, value: str):
    """check_user_exists: email and username compared case-insensitively, other fields exactly; a
    value matching several users is an error too."""
    if field_name in _CASE_INSENSITIVE:
        found = [u for u in users if getattr(u, field_name).lower() == value.lower()]
    else:
        found = [u for u in users if str(getattr(u, field_name)) == value]
    return found[0] if len(found) == 1 else None
