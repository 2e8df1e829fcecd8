"""`exgen grade` over 60 real answer files among hostile company: 10,000 junk files, a named pipe, a device
node (where one can be made: as root), a folder 100 levels deep, a symbolic-link loop; each alone, then all
together. Prints, per folder, the wall and CPU time of the command (as a user runs it, a new process) and
whether its outcome is honest: exit 0, all 60 graded, every other entry counted as not graded.

    .venv/bin/python benchmarks/hostile_folder.py [--junk yaml|mixed] [--jobs N]

--junk yaml makes every junk file a tiny YAML file (each is read, to say whose it claims to be); mixed (the
default) makes a third of them YAML, a third photos, a third text.
"""
import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).parent.parent
STUDENTS = 60


def issue(work: Path, env: dict) -> Path:
    roster = work / "roster.csv"
    roster.write_text("id,name\n" + "".join(f"B{23000 + i},Student {i}\n" for i in range(STUDENTS)), encoding="utf-8")
    issued = work / "issued"
    subprocess.run([sys.executable, "-m", "exgen.cli", "generate", str(ROOT / "examples" / "tutorial1.yaml"),
                    "--roster", str(roster), "--out", str(issued), "--no-pdf"], check=True, env=env,
                   stdout=subprocess.DEVNULL)
    return issued


def real_files(issued: Path, folder: Path, secret: bytes) -> None:
    """Every student's form, answered right (the key's answers), as a learning system names the files."""
    from exgen.issue.assignment import load_assignment, build_sheet
    from exgen.issue.manifest import read_manifest
    from exgen.load.bank import load_bank

    bank = load_bank()
    manifest = read_manifest(issued)
    assignment = load_assignment(ROOT / "examples" / "tutorial1.yaml", bank)
    for student in manifest.students:
        sheet = build_sheet(assignment, student, bank, secret)
        data = {"student": student.id, "code": manifest.codes[student.id],
                "answers": {q.slot: {p: a.text for p, a in q.variant.answers.items()} for q in sheet.questions}}
        (folder / f"{student.id}.yaml").write_text(yaml.safe_dump(data, allow_unicode=True), encoding="utf-8")


def junk(folder: Path, kind: str) -> int:
    where = folder / "AAA_junk"
    where.mkdir()
    for i in range(10_000):
        suffix = ".yaml" if kind == "yaml" else (".yaml", ".jpg", ".txt")[i % 3]
        (where / f"junk{i:05d}{suffix}").write_bytes(b"x: 1\n" if suffix != ".jpg" else b"\xff\xd8\xff")
    return 10_000


def fifo(folder: Path) -> int:
    os.mkfifo(folder / "notes.yaml")
    os.mkfifo(folder / f"B{23000}_late.yaml")
    return 2


def device(folder: Path) -> int:
    try:
        os.mknod(folder / "B23001_device.yaml", 0o600 | 0o020000, os.makedev(1, 5))
    except (PermissionError, OSError, AttributeError):
        return -1
    return 1


def deep(folder: Path) -> int:
    bottom = folder / "deep" / "/".join(f"level{i}" for i in range(100))
    bottom.mkdir(parents=True)
    (bottom / "stray.yaml").write_text("answers: {}\n")
    return 1


def loop(folder: Path) -> int:
    (folder / "loop").symlink_to(".")
    (folder / "sub").mkdir()
    (folder / "sub" / "back").symlink_to("..")
    return 2


SHAPES = {"10,000 junk files": junk, "a named pipe": fifo, "a device node": device, "a folder 100 deep": deep,
          "a symbolic-link loop": loop}


def run(issued: Path, folder: Path, out: Path, env: dict, jobs: int | None) -> tuple[float, float, int, str]:
    shutil.rmtree(out, ignore_errors=True)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "exgen.cli", "grade", str(issued), str(folder), "--out", str(out),
                           *(["--jobs", str(jobs)] if jobs else [])], capture_output=True, text=True, env=env,
                          timeout=600)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, done.returncode, (done.stdout.splitlines() or [done.stderr.strip()])[0]


def main() -> None:
    options = argparse.ArgumentParser()
    options.add_argument("--junk", choices=("mixed", "yaml"), default="mixed")
    options.add_argument("--jobs", type=int)
    args = options.parse_args()
    secret = b"benchmark secret: 5b0e9c3d7a21f468e0c4"
    env = {**os.environ, "EXGEN_SECRET": secret.decode()}
    work = Path(tempfile.mkdtemp(prefix="exgen-hostile-folder-"))
    try:
        issued = issue(work, env)
        print(f"load average before: {' '.join(f'{x:.2f}' for x in os.getloadavg())}; {os.cpu_count()} cores; "
              f"junk: {args.junk}")
        cases = [("60 real files alone", [])] + [(f"60 real + {name}", [name]) for name in SHAPES] + [
            ("60 real + all of them", list(SHAPES))]
        for title, shapes in cases:
            folder = work / "handed"
            shutil.rmtree(folder, ignore_errors=True)
            folder.mkdir()
            real_files(issued, folder, secret)
            others = 0
            for name in shapes:
                made = SHAPES[name](folder, args.junk) if name == "10,000 junk files" else SHAPES[name](folder)
                if made < 0:
                    print(f"  ({name}: cannot be made here, not root)")
                    continue
                others += made
            wall, cpu, status, line = run(issued, folder, work / "graded", env, args.jobs)
            honest = status == 0 and line.startswith(f"{STUDENTS} student(s): {STUDENTS} graded") and (
                (others == 0 and "not graded" not in line) or f"; {others} file(s) not graded" in line)
            print(f"{title:34} {wall:6.2f} s wall, {cpu:6.2f} s CPU, exit {status}, "
                  f"{'honest' if honest else 'NOT HONEST'}: {line}")
        print(f"load average after: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
