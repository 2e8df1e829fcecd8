"""What was issued: enough to rebuild and check every sheet later, never the secret or a seed.

Seeds are recorded by their derivation inputs only (a seed would let its holder rebuild the
key); the secret by a fingerprint, so grading with another secret is caught at once.
"""
from __future__ import annotations

import hashlib
import json
from pathlib import Path

from . import __version__
from .assignment import Assignment, Sheet
from .bank import Bank
from .seeds import fingerprint

SEED_DERIVATION = "HMAC-SHA256(course secret, '<assignment>/<student>/<slot>'), first 8 bytes, big-endian"


def bank_hash(bank: Bank) -> str:
    """One hash over every template's id and file content: changes when any template does."""
    digest = hashlib.sha256()
    for template_id in sorted(bank.templates):
        digest.update(f"{template_id}\0{bank.templates[template_id].version}\n".encode())
    return digest.hexdigest()


def build_manifest(assignment: Assignment, sheets: list[Sheet], bank: Bank, secret: bytes) -> dict:
    assignment_bytes = assignment.path.read_bytes() if assignment.path else b""
    used = sorted({q.variant.template.id for s in sheets for q in s.questions})
    return {
        "generator": {"name": "exgen", "version": __version__},
        "assignment": {
            "id": assignment.id, "title": assignment.title, "course": assignment.course, "due": assignment.due,
            "file": assignment.path.name if assignment.path else None,
            "file_sha256": hashlib.sha256(assignment_bytes).hexdigest(),
        },
        "bank_sha256": bank_hash(bank),
        "templates": {tid: bank.get(tid).version for tid in used},
        "secret_fingerprint": fingerprint(secret),
        "seed_derivation": SEED_DERIVATION,
        "students": [
            {
                "id": s.student.id, "name": s.student.name, "code": s.code, "points": s.points,
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


def read_manifest(path: Path) -> dict:
    return json.loads(path.read_text(encoding="utf-8"))
