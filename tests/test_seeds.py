import hashlib
import hmac
import os
from pathlib import Path

import pytest

from exgen.errors import SecretError
from exgen.seeds import derive_seed, fingerprint, legacy_fingerprint, load_secret, sheet_code

SECRET = b"course secret for tests only 0123456789"


def test_seed_is_a_pure_function_of_its_inputs():
    # A fixed value: the same in any process, on any machine, any day (no Python hash()).
    assert derive_seed(SECRET, "tut1", "s001", "q1") == derive_seed(SECRET, "tut1", "s001", "q1")
    # the value `openssl dgst -sha256 -hmac` gives for "tut1/s001/q1", first 8 bytes
    assert derive_seed(SECRET, "tut1", "s001", "q1") == 10592889222934143736


@pytest.mark.parametrize("other", [
    (SECRET, "tut1", "s002", "q1"), (SECRET, "tut2", "s001", "q1"), (SECRET, "tut1", "s001", "q2"),
    (b"another secret entirely, 16+ bytes", "tut1", "s001", "q1"),
])
def test_any_input_changes_the_seed(other):
    assert derive_seed(*other) != derive_seed(SECRET, "tut1", "s001", "q1")


def test_fingerprint_and_code_do_not_contain_the_secret():
    assert SECRET.hex()[:16] not in fingerprint(SECRET)
    code = sheet_code(SECRET, "tut1", "s001", ["q1=belts.a"])
    assert len(code) == 9 and code[4] == "-"
    assert code != sheet_code(SECRET, "tut1", "s001", ["q1=belts.b"])  # another question, another code
    assert code != sheet_code(SECRET, "tut1", "s002", ["q1=belts.a"])


def test_the_sheet_code_is_not_keyed_by_the_seed_key():
    """A code computed straight from the secret let a student test guesses of it at HMAC speed."""
    direct = hmac.new(SECRET, b"tut1/s001/q1=belts.a", hashlib.sha256).hexdigest()[:8].upper()
    assert sheet_code(SECRET, "tut1", "s001", ["q1=belts.a"]).replace("-", "") != direct
    assert fingerprint(SECRET) != legacy_fingerprint(SECRET)


def test_an_explicit_secret_file_beats_the_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("EXGEN_SECRET", "x" * 4 + "3f9a1c7e52b8d04e6a1f9c3b7d2e8a45")
    path = tmp_path / "course.secret"
    path.write_text(SECRET.decode() + "\n")
    assert load_secret(path) == (b"xxxx3f9a1c7e52b8d04e6a1f9c3b7d2e8a45", "$EXGEN_SECRET")  # a default file
    assert load_secret(path, explicit=True) == (SECRET, str(path))                            # --secret-file


def test_secret_file_is_created_only_when_asked(monkeypatch, tmp_path):
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    path = tmp_path / "course.secret"
    with pytest.raises(SecretError, match="no course secret"):
        load_secret(path)
    secret, source = load_secret(path, create=True)
    assert source.endswith("(new)") and len(secret) == 64 and path.stat().st_mode & 0o777 == 0o600
    assert load_secret(path) == (secret, str(path))


def test_secret_file_is_private_from_the_moment_it_exists(monkeypatch, tmp_path):
    """Made with O_CREAT|O_EXCL and mode 0600 in one call, never world-readable and chmod'ed later."""
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    calls = []
    real_open = os.open

    def recording_open(path, flags, mode=0o777, *args, **kwargs):
        calls.append((Path(path).name, flags, mode))
        return real_open(path, flags, mode, *args, **kwargs)

    monkeypatch.setattr(os, "open", recording_open)
    old_umask = os.umask(0)
    try:
        load_secret(tmp_path / "course.secret", create=True)
    finally:
        os.umask(old_umask)
    made = [c for c in calls if c[0] == "course.secret"]
    assert made and made[0][1] & os.O_CREAT and made[0][1] & os.O_EXCL and made[0][2] == 0o600
    assert (tmp_path / "course.secret").stat().st_mode & 0o777 == 0o600


def test_an_existing_secret_file_is_never_overwritten(monkeypatch, tmp_path):
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    path = tmp_path / "course.secret"
    path.write_text(SECRET.decode())
    assert load_secret(path, create=True) == (SECRET, str(path))


def test_short_secret_is_refused(monkeypatch):
    monkeypatch.setenv("EXGEN_SECRET", "short")
    with pytest.raises(SecretError, match="shorter than 16 bytes"):
        load_secret(None)


@pytest.mark.parametrize("weak", ["aaaaaaaaaaaaaaaa", "abcdefghijklmnopqrstuvwxyz", "abcabcabcabcabcabcabcabc",
                                  "password12345678", "0000000000000000000000000000000000000000",
                                  "1234567890123456789012345678901234567890"])
def test_a_secret_easy_to_guess_is_refused(monkeypatch, weak):
    monkeypatch.setenv("EXGEN_SECRET", weak)
    with pytest.raises(SecretError, match="too easy to guess") as caught:
        load_secret(None)
    assert "secrets.token_hex" in str(caught.value)


@pytest.mark.parametrize("strong", [  # secrets.token_hex(32), token_hex(16), token_urlsafe(16), a phrase
    "f8828de61ffe35429bff9c530b4658b114b03f370daceeaa5fb68b6f538c2ca6", "367e28d15f510420bc5d9000b60579d4", "-YPWNvvH8FsGU4kEm23aZA",
    "course secret for tests only 0123456789"])
def test_random_secrets_are_accepted(monkeypatch, strong):
    monkeypatch.setenv("EXGEN_SECRET", strong)
    assert load_secret(None)[0] == strong.encode()


def test_a_folder_given_as_the_secret_file_is_a_clear_error(monkeypatch, tmp_path):
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    with pytest.raises(SecretError, match="is a folder, not a secret file"):
        load_secret(tmp_path, explicit=True, create=True)
