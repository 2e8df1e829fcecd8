"""Seeds a student cannot derive: HMAC-SHA256 of the course secret over assignment/student/slot.

The secret stays with the instructor (a file or the EXGEN_SECRET variable) and is never
written on a sheet or into the manifest. What is written is checked with a second key,
stretched from the secret with scrypt: the sheet code printed on every sheet and the
fingerprint in the manifest. A student who tries guesses of the secret against their sheet
code pays a deliberately slow derivation per guess, and a secret too easy to guess is refused
when it is loaded, so the code is no usable oracle.
"""
from __future__ import annotations

import hashlib
import hmac
import math
import os
import secrets
from collections import Counter
from functools import lru_cache
from pathlib import Path

from ..errors import SecretError
from ..runtime.safefile import UnsafeFile, read_bytes

ENV_VAR = "EXGEN_SECRET"
MIN_SECRET_BYTES = 16
#: A rough count of a secret's guessing entropy below which it is refused.
MIN_SECRET_BITS = 80
#: scrypt cost of the check key (~32 MiB, ~0.1 s): what each offline guess of the secret costs.
_SCRYPT = {"n": 2**15, "r": 8, "p": 1, "maxmem": 64 * 2**20, "dklen": 32}
_CHECK_SALT = b"exgen: sheet codes and secret fingerprints"
MAKE_ONE = "python3 -c 'import secrets; print(secrets.token_hex(32))'"
#: A secret file holds one line; exgen writes 65 bytes.
MAX_SECRET_FILE = 1024
_NOT_A_SECRET = ("{path} does not look like a course secret ({why}): a course secret file holds one line, as the "
                 "file exgen creates does; give that file, or make one with: {make} > FILE")


#: Seeds of sheets are HMAC outputs below 2^64 (`derive_seed`); practice draws its seeds from the next
#: 2^64 numbers, so a practice problem is never an issued one, whatever the secret (which practice never has).
PRACTICE_SEEDS = range(2**64, 2**65)


def practice_seed() -> int:
    """A fresh seed from the practice range, disjoint from every seed a sheet can have."""
    return PRACTICE_SEEDS.start + secrets.randbits(64)


def derive_seed(secret: bytes, assignment: str, student: str, slot: str) -> int:
    """A 64-bit seed for one problem slot of one student's sheet."""
    message = f"{assignment}/{student}/{slot}".encode("utf-8")
    digest = hmac.new(secret, message, hashlib.sha256).digest()
    return int.from_bytes(digest[:8], "big")


#: The student part of a pool variant's seed input: '#' is never in a student id, so a pool variant
#: can never be some student's sheet.
POOL = "#pool"


def pool_seed(secret: bytes, scope: str, slot: str, index: int) -> int:
    """The seed of the index-th variant of a question pool exported to a learning system: keyed by the
    secret like a sheet's, so a student cannot rebuild the pool's answers either."""
    return derive_seed(secret, scope, POOL, f"{slot}/{index}")


@lru_cache(maxsize=4)
def _check_key(secret: bytes) -> bytes:
    """The key of everything written from the secret (codes, fingerprint): never the seed key itself."""
    return hashlib.scrypt(secret, salt=_CHECK_SALT, **_SCRYPT)


def fingerprint(secret: bytes) -> str:
    """A short public check value for a secret: grading under another secret is caught by it."""
    return hmac.new(_check_key(secret), b"fingerprint", hashlib.sha256).hexdigest()[:16]


def legacy_fingerprint(secret: bytes) -> str:
    """The fingerprint manifests written before the check key recorded (read, never written)."""
    return hmac.new(secret, b"exgen secret fingerprint", hashlib.sha256).hexdigest()[:16]


def sheet_code(secret: bytes, assignment: str, student: str, questions: list[str]) -> str:
    """A code printed on a sheet and its answer file, naming it: assignment, student and its questions
    ("slot=template"). A file carrying another sheet's code is caught at grading."""
    message = "/".join([assignment, student, *questions]).encode("utf-8")
    digest = hmac.new(_check_key(secret), message, hashlib.sha256).hexdigest()[:8].upper()
    return f"{digest[:4]}-{digest[4:]}"


def estimated_bits(secret: bytes) -> float:
    """A rough, deliberately pessimistic count of guessing entropy: symbol entropy (of the bytes, or of
    their steps if lower: 'abcdef...') times the length of the shortest repeating unit."""
    n = len(secret)
    if n < 2:
        return 0.0
    period = next((p for p in range(1, n) if secret[p:] == secret[:-p]), n)
    steps = bytes((b - a) % 256 for a, b in zip(secret, secret[1:]))
    per_symbol = min(_entropy(secret), _entropy(steps))
    return per_symbol * period


def _entropy(data: bytes) -> float:
    counts, n = Counter(data), len(data)
    return -sum(c / n * math.log2(c / n) for c in counts.values())


def check_strength(secret: bytes, source: str) -> None:
    """Refuse a secret a student could guess (too short, repetitive, a run of letters)."""
    if len(secret) < MIN_SECRET_BYTES:
        raise SecretError(f"the course secret from {source} is shorter than {MIN_SECRET_BYTES} bytes; "
                          f"make a random one with: {MAKE_ONE}")
    bits = estimated_bits(secret)
    if bits < MIN_SECRET_BITS:
        raise SecretError(f"the course secret from {source} is too easy to guess (about {bits:.0f} bits, at "
                          f"least {MIN_SECRET_BITS} needed); make a random one with: {MAKE_ONE}")


def load_secret(path: Path | None, *, create: bool = False, explicit: bool = False) -> tuple[bytes, str]:
    """The course secret and where it came from. An `explicit` file (given on the command line) wins;
    else EXGEN_SECRET; else the file, created (0600, atomically) if asked."""
    env = os.environ.get(ENV_VAR)
    if env and not explicit:
        secret, source = env.encode("utf-8"), f"${ENV_VAR}"
    elif path is not None and (path.exists() or not create):
        secret, source = _read(path), str(path)
    elif path is not None:
        secret, source = _create(path), f"{path} (new)"
    else:
        raise SecretError(f"no course secret: set {ENV_VAR} or give a secret file. "
                          "Grading needs the same secret that generated the sheets.")
    check_strength(secret, source)
    return secret, source


def _read(path: Path) -> bytes:
    """A secret file's secret: one line of text, as exgen writes it; anything else is refused, since a file
    given by mistake (/etc/passwd, a key, a spreadsheet) would silently seed every sheet."""
    if path.is_dir():
        raise SecretError(f"{path} is a folder, not a secret file")
    try:
        raw = read_bytes(path, MAX_SECRET_FILE)
    except FileNotFoundError:
        raise SecretError(f"no course secret: {path} does not exist (and {ENV_VAR} is not set). "
                          "Grading needs the same secret that generated the sheets.") from None
    except UnsafeFile as exc:
        raise SecretError(_NOT_A_SECRET.format(path=path, why=exc.reason, make=MAKE_ONE)) from None
    except OSError as exc:
        raise SecretError(f"cannot read the secret file {path}: {exc.strerror or exc}") from None
    secret = raw.strip()
    why = _not_a_secret(secret)
    if why:
        raise SecretError(_NOT_A_SECRET.format(path=path, why=why, make=MAKE_ONE))
    return secret


def _not_a_secret(secret: bytes) -> str:
    """Why the bytes of a secret file cannot be a course secret (one line of text), or ""."""
    if b"\x00" in secret:
        return "it holds NUL bytes, so it is no text"
    try:
        text = secret.decode("utf-8")
    except UnicodeDecodeError:
        return "it is not text"
    lines = text.splitlines()
    if len(lines) > 1:
        return f"it has {len(lines)} lines"
    if not text.isprintable():
        return "it holds control characters"
    return ""


def exposure(path: Path) -> str:
    """A warning if the secret file can be read (or changed) by other users of this computer, else ""."""
    if os.name != "posix":
        return ""
    try:
        mode = path.stat().st_mode
    except OSError:
        return ""
    if not mode & 0o077:
        return ""
    who = "other users of this computer" if mode & 0o007 else "the other members of its group"
    return (f"the secret file {path} can be read by {who} (mode {mode & 0o777:04o}): whoever reads it can rebuild "
            f"every student's answers; make it private with: chmod 600 {path}")


def _create(path: Path) -> bytes:
    """A new random secret in a file that is private (0600) from the moment it exists."""
    path.parent.mkdir(parents=True, exist_ok=True)
    secret = secrets.token_hex(32).encode("ascii")
    try:
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    except FileExistsError:  # made by another run meanwhile: use that one
        return _read(path)
    with os.fdopen(fd, "wb") as handle:
        handle.write(secret + b"\n")
        handle.flush()
        os.fsync(handle.fileno())
    return secret
