"""What was issued: enough to rebuild and check every sheet later, never the secret or a seed.

Seeds are recorded by their derivation inputs only (a seed would let its holder rebuild the key);
the secret by a fingerprint; each template by a version covering everything that can change a
number or a verdict (exgen.load.versions). Grading reads the roster, the questions and the sheet codes
from here, and `issue_mismatches` says what differs now, before any mark is given.
"""
from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, field
from pathlib import Path

from .. import __version__
from ..draw.seeds import fingerprint, legacy_fingerprint
from ..errors import ExgenError
from ..load.bank import Bank
from ..load.versions import LIBRARIES, current_hash, file_hashes, template_version
from ..runtime.outdir import recover
from .assignment import Assignment, QuestionSpec, Sheet, Student

FORMAT = 2
MANIFEST = "manifest.json"
SEED_DERIVATION = "HMAC-SHA256(course secret, '<assignment>/<student>/<slot>'), first 8 bytes, big-endian"


class ManifestError(ExgenError, ValueError):
    """A manifest that cannot be read, or grading conditions that differ from what it records."""

    def __init__(self, path, message: str):
        self.path = str(path)
        super().__init__(f"{self.path}: {message}")


@dataclass(frozen=True)
class Manifest:
    """A manifest read back: the assignment and roster as issued, each sheet's code, and the versions."""

    path: Path
    assignment: Assignment
    students: tuple[Student, ...]
    codes: dict[str, str]
    fingerprint: str
    secret_source: str = ""
    templates: dict[str, dict] = field(default_factory=dict)
    files: dict[str, str] = field(default_factory=dict)
    format: int = FORMAT


def build_manifest(assignment: Assignment, sheets: list[Sheet], bank: Bank, secret: bytes,
                   secret_source: str = "") -> dict:
    assignment_bytes = assignment.path.read_bytes() if assignment.path else b""
    used = sorted({q.variant.template.id for s in sheets for q in s.questions})
    versions = {tid: template_version(bank.get(tid)) for tid in used}
    files = {name: digest for v in versions.values() for name, digest in file_hashes(v).items()}
    points = {q.slot: q.points for q in sheets[0].questions} if sheets else {}
    return {
        "format": FORMAT,
        "generator": {"name": "exgen", "version": __version__},
        "assignment": {
            "id": assignment.id, "title": assignment.title, "course": assignment.course, "due": assignment.due,
            "file": assignment.path.name if assignment.path else None,
            "file_sha256": hashlib.sha256(assignment_bytes).hexdigest(),
            "questions": [{"slot": q.slot, "template": q.template, "points": points.get(q.slot, q.points)}
                          for q in assignment.questions],
        },
        "secret_fingerprint": fingerprint(secret),
        "secret_source": secret_source,
        "seed_derivation": SEED_DERIVATION,
        "templates": {tid: v.record() for tid, v in versions.items()},
        "files": dict(sorted(files.items())),
        "students": [
            {
                "id": s.student.id, "name": s.student.name, "email": s.student.email, "section": s.student.section,
                "code": s.code, "points": s.points,
                "questions": [
                    {"slot": q.slot, "template": q.variant.template.id, "points": q.points,
                     "seed_input": f"{assignment.id}/{s.student.id}/{q.slot}"}
                    for q in s.questions
                ],
            }
            for s in sheets
        ],
    }


def write_manifest(manifest: dict, path: Path) -> None:
    path.write_text(json.dumps(manifest, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")


def manifest_path(issued: Path) -> Path:
    """The manifest of an issued folder (the --out of `exgen generate`), or the file itself. A folder an
    interrupted rerun left aside is put back first (exgen.runtime.outdir.recover)."""
    issued = Path(issued)
    if not issued.exists():
        recover(issued.parent if issued.name == MANIFEST else issued)
    if issued.is_dir():
        return issued / MANIFEST
    if issued.suffix.lower() in (".yaml", ".yml"):
        raise ManifestError(issued, "grading now reads what was issued: give the folder `exgen generate` wrote "
                                    "(its --out, holding manifest.json), not the assignment file")
    return issued


def read_manifest(path: Path) -> Manifest:
    """Read a manifest back, checking its shape; ManifestError names the file and what is wrong."""
    path = manifest_path(path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise ManifestError(path, "no such file: give the folder `exgen generate` wrote, or its manifest.json") from None
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ManifestError(path, f"cannot read the manifest: {exc}") from None
    try:
        return _manifest(path, data)
    except (KeyError, TypeError, ValueError, AttributeError, IndexError) as exc:
        raise ManifestError(path, f"not a manifest written by exgen generate ({type(exc).__name__}: {exc})") from None


def _manifest(path: Path, data: dict) -> Manifest:
    form = int(data.get("format", 1))
    info = data["assignment"]
    students = data["students"]
    if form >= 2:
        questions = info["questions"]
    else:  # written before the questions were recorded on their own: the first sheet's
        questions = students[0]["questions"] if students else []
    specs = tuple(QuestionSpec(str(q["slot"]), str(q["template"]), float(q["points"]) if q.get("points") else None)
                  for q in questions)
    assignment = Assignment(id=str(info["id"]), title=str(info.get("title") or info["id"]), questions=specs,
                            course=str(info.get("course") or ""), due=str(info.get("due") or ""))
    roster = tuple(Student(str(s["id"]), str(s.get("name") or ""), str(s.get("email") or ""),
                           str(s.get("section") or "")) for s in students)
    codes = {str(s["id"]): str(s.get("code") or "") for s in students}
    templates = {str(k): (v if isinstance(v, dict) else {"file_sha256": str(v)}) for k, v in data["templates"].items()}
    return Manifest(path, assignment, roster, codes, str(data["secret_fingerprint"]),
                    str(data.get("secret_source") or ""), templates, dict(data.get("files") or {}), form)


# ---- what differs now -------------------------------------------------------------------------------

def secret_mismatch(manifest: Manifest, secret: bytes, source: str) -> str | None:
    """Why this secret is not the one the sheets were issued under, or None."""
    made = legacy_fingerprint(secret) if manifest.format < 2 else fingerprint(secret)
    if made == manifest.fingerprint:
        return None
    return (f"the course secret from {source} is not the one these sheets were issued under (its fingerprint is "
            f"{made}, the manifest's {manifest.fingerprint})")


def template_mismatches(manifest: Manifest, bank: Bank) -> list[str]:
    """One line per set of templates that would not give the issued numbers or verdicts now, naming what
    changed; templates with the same changes (every one a changed solver runs) share a line."""
    changes: dict[str, list[str]] = {}
    for template_id, recorded in manifest.templates.items():
        try:
            template = bank.get(template_id)
        except ExgenError:
            changes.setdefault("no longer in the template bank", []).append(template_id)
            continue
        if "file_sha256" in recorded:  # an older manifest: the template file's bytes, nothing else
            if template.path is None or hashlib.sha256(template.path.read_bytes()).hexdigest() != recorded["file_sha256"]:
                changes.setdefault(f"its template file {template.path} changed", []).append(template_id)
            continue
        current = template_version(template)
        if current.digest == recorded.get("version"):
            continue
        changes.setdefault("; ".join(_what_changed(manifest, template, recorded, current)), []).append(template_id)
    return [f"{_listed(ids)}: {what}" for what, ids in changes.items()]


def _listed(ids: list[str]) -> str:
    return ids[0] if len(ids) == 1 else ", ".join(ids[:-1]) + " and " + ids[-1]


def _what_changed(manifest: Manifest, template, recorded: dict, current) -> list[str]:
    changed = []
    if current.template != recorded.get("template"):
        changed.append(f"its template file {template.path} changed")
    names = sorted(set(recorded.get("code", [])) | set(recorded.get("data", [])))
    for name in names:
        now = current_hash(name, template)
        if now is None:
            changed.append(f"{name} is gone")
        elif now != manifest.files.get(name):
            changed.append(f"{name} changed")
    added = sorted(set(current.code) | set(current.data))
    changed += [f"it now also runs {name}" for name in added if name not in names]
    for library in LIBRARIES:
        was, now = recorded.get("libraries", {}).get(library), current.libraries.get(library)
        if was != now:
            changed.append(f"{library} was {was}, is {now}")
    return changed or ["its version differs"]


def issue_mismatches(manifest: Manifest, bank: Bank, secret: bytes, source: str) -> list[str]:
    """Everything that differs from what was issued: the secret, then each template."""
    problem = secret_mismatch(manifest, secret, source)
    return ([problem] if problem else []) + template_mismatches(manifest, bank)

