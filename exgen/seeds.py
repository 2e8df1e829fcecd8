"""Seeds a student cannot derive: HMAC-SHA256 of the course secret over assignment/student/slot.

The secret stays with the instructor (a file or the EXGEN_SECRET variable) and is never
written on a sheet or into the manifest; the manifest records only a fingerprint of it, so
grading with a different secret is caught before it marks a whole class wrong.
"""
from __future__ import annotations

import hashlib
import hmac
import os
import secrets
from pathlib import Path

from .errors import SecretError

ENV_VAR = "EXGEN_SECRET"
MIN_SECRET_BYTES = 16


def derive_seed(secret: bytes, assignment: str, student: str, slot: str) -> int:
    """A 64-bit seed for one problem slot of one student's sheet."""
    message = f"{assignment}/{student}/{slot}".encode("utf-8")
    digest = hmac.new(secret, message, hashlib.sha256).digest()
    return int.from_bytes(digest[:8], "big")


def fingerprint(secret: bytes) -> str:
    """A short public check value for a secret (reveals nothing usable about it)."""
    return hmac.new(secret, b"exgen secret fingerprint", hashlib.sha256).hexdigest()[:16]


def sheet_code(secret: bytes, assignment: str, student: str, versions: list[str]) -> str:
    """A code printed on a sheet and its answer file; it changes if the secret or a template does."""
    message = "/".join([assignment, student, *versions]).encode("utf-8")
    digest = hmac.new(secret, message, hashlib.sha256).hexdigest()[:8].upper()
    return f"{digest[:4]}-{digest[4:]}"


def load_secret(path: Path | None, *, create: bool = False) -> tuple[bytes, str]:
    """The course secret and where it came from: EXGEN_SECRET, else the file (made if asked)."""
    env = os.environ.get(ENV_VAR)
    if env:
        secret = env.encode("utf-8")
        source = f"${ENV_VAR}"
    elif path is not None and path.is_file():
        secret = path.read_bytes().strip()
        source = str(path)
    elif path is not None and create:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(secrets.token_hex(32) + "\n", encoding="ascii")
        path.chmod(0o600)
        secret = path.read_bytes().strip()
        source = f"{path} (new)"
    else:
        where = f" and {path} does not exist" if path is not None else ""
        raise SecretError(
            f"no course secret: set {ENV_VAR} or give a secret file{where}. "
            "Grading needs the same secret that generated the sheets."
        )
    if len(secret) < MIN_SECRET_BYTES:
        raise SecretError(f"the course secret from {source} is shorter than {MIN_SECRET_BYTES} bytes")
    return secret, source
