"""Hostile submissions folders, drawn from a seed: real answer files, each where a learning system or a
student might put it, among every shape of trouble a folder can hold (junk and photos, a named pipe, a
device node where one can be made, a folder a hundred levels deep, links and a link loop, a huge file, a
newer file holding only `student:`, hidden folders, exgen's own outputs, names with bidi characters, files
naming a student inside but placed nowhere).

`hostile_folder` writes one and returns what grading must make of it: which file is each real student's,
and every other entry, each of which grading must list by name (an entry inside a hidden folder or a
folder exgen wrote is listed through that folder).
"""
from __future__ import annotations

import json
import os
import random
from dataclasses import dataclass, field
from pathlib import Path

JUNK_SUFFIXES = (".jpg", ".png", ".pdf", ".docx", ".txt", "", ".yaml", ".json", ".csv", ".zip", ".heic")


@dataclass
class Expected:
    real: dict[str, Path] = field(default_factory=dict)    # student id -> the file that must be graded
    others: list[Path] = field(default_factory=list)        # every other entry: listed by name
    through: dict[Path, Path] = field(default_factory=dict)  # an entry listed through this folder
    specials: list[str] = field(default_factory=list)       # which special files could be made


def hostile_folder(root: Path, seed: int, forms: dict[str, dict], names: dict[str, str], junk: int = 300) -> Expected:
    """`forms`: each real student's answers (`student`, `code`, `answers`) by id, written as YAML or JSON;
    `names`: their full names."""
    rng = random.Random(seed)
    expected = Expected()
    root.mkdir(parents=True, exist_ok=True)
    ids = sorted(forms)
    for number, sid in enumerate(ids):
        place = _place(root, rng, sid, names[sid], number)
        place.parent.mkdir(parents=True, exist_ok=True)
        place.write_text(json.dumps(forms[sid]) if place.suffix == ".json" else _yaml(forms[sid]), encoding="utf-8")
        os.utime(place, (1_700_000_000, 1_700_000_000))
        expected.real[sid] = place
    _junk(root, rng, junk, expected)
    _troubles(root, rng, ids, expected)
    return expected


def _place(root: Path, rng: random.Random, sid: str, name: str, number: int) -> Path:
    places = [
        lambda: root / f"{sid}.yaml",
        lambda: root / sid / "answers.yaml",
        lambda: root / f"{name}_{4000 + number}_assignsubmission_file_" / "answers.yaml",
        lambda: root / f"tut1_{sid}_attempt_2.json",
        lambda: root / "by section" / "S1" / f"{sid}.yaml",
        lambda: root / sid / "/".join(f"level{i}" for i in range(100)) / "answers.yaml",
        lambda: root / "a" / "b" / "c" / "d" / "e" / "f" / f"{sid}.yaml",
    ]
    return places[rng.randrange(len(places))]()


def _junk(root: Path, rng: random.Random, count: int, expected: Expected) -> None:
    folders = [root, root / "scans", root / "misc" / "old", root / "AAA_junk"]
    for folder in folders:
        folder.mkdir(parents=True, exist_ok=True)
    for i in range(count):
        path = rng.choice(folders) / f"file{i:05d}{rng.choice(JUNK_SUFFIXES)}"
        path.write_bytes(bytes(rng.randrange(256) for _ in range(rng.randrange(1, 64))))
        expected.others.append(path)


def _troubles(root: Path, rng: random.Random, ids: list[str], expected: Expected) -> None:
    victim = rng.choice(ids)
    others = expected.others

    def made(path: Path) -> Path:
        others.append(path)
        return path

    os.mkfifo(made(root / "notes.yaml"))
    os.mkfifo(made(root / f"{victim}_late.yaml"))
    expected.specials.append("fifo")
    try:
        os.mknod(root / f"{victim}_device.yaml", 0o600 | 0o020000, os.makedev(1, 5))
        made(root / f"{victim}_device.yaml")
        expected.specials.append("device")
    except (PermissionError, OSError, AttributeError):
        pass
    deep = root / "deep" / "/".join(f"d{i}" for i in range(100))
    deep.mkdir(parents=True)
    (made(deep / "stray.yaml")).write_text("answers: {}\n")
    (made(deep / "photo.jpg")).write_bytes(b"\xff\xd8")
    made(root / "loop").symlink_to(".")
    (root / "up").mkdir()
    made(root / "up" / "down").symlink_to("..")
    made(root / f"{victim}_link.yaml").symlink_to(expected.real[victim])
    huge = made(root / f"{victim}_huge.yaml")
    with huge.open("wb") as handle:
        handle.write(b"answers:\n  q1:\n    a: \"")
        handle.truncate(20 * 1024 * 1024)
    empty = made(root / f"{victim}_resubmitted.yaml")
    empty.write_text(f"student: {victim}\n", encoding="utf-8")
    for hidden in (made(root / ".git"), made(root / "__MACOSX")):
        (hidden / "objects").mkdir(parents=True)
        for i in range(5):
            inner = hidden / "objects" / f"{victim}_{i:02x}.yaml"
            inner.write_text("answers: {}\n")
            expected.through[inner] = hidden
    (made(root / ".hidden.yaml")).write_text("{")
    output = made(root / "graded-last-week")
    output.mkdir()
    (output / ".exgen-output").write_text('{"kind": "grade"}')
    (output / "gradebook.csv").write_text("student,total\n")
    expected.through[output / "gradebook.csv"] = output
    (made(root / "gradebook.csv")).write_text("student,total\n")
    (made(root / f"s\u202egpj.{victim}.exe.yaml")).write_text("{")
    (made(root / "bomb.yaml")).write_text("a: &a [x, x]\nb: [*a, *a]\n")
    (made(root / "binary.json")).write_bytes(bytes(range(256)) * 8)
    (root / "nobody").mkdir()
    (made(root / "nobody" / "answers.yaml")).write_text(f"student: {rng.choice(ids)}\nanswers: {{}}\n")


def _yaml(data: dict) -> str:
    import yaml

    return yaml.safe_dump(data, allow_unicode=True, sort_keys=False)
