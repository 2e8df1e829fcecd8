import pytest

from exgen.errors import SecretError
from exgen.seeds import derive_seed, fingerprint, load_secret, sheet_code

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
    code = sheet_code(SECRET, "tut1", "s001", ["v1"])
    assert len(code) == 9 and code[4] == "-"
    assert code != sheet_code(SECRET, "tut1", "s001", ["v2"])  # a changed template changes the code


def test_secret_from_environment_wins(monkeypatch, tmp_path):
    monkeypatch.setenv("EXGEN_SECRET", "x" * 20)
    assert load_secret(tmp_path / "none.secret") == (b"x" * 20, "$EXGEN_SECRET")


def test_secret_file_is_created_only_when_asked(monkeypatch, tmp_path):
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    path = tmp_path / "course.secret"
    with pytest.raises(SecretError, match="no course secret"):
        load_secret(path)
    secret, source = load_secret(path, create=True)
    assert source.endswith("(new)") and len(secret) == 64 and path.stat().st_mode & 0o077 == 0
    assert load_secret(path) == (secret, str(path))


def test_short_secret_is_refused(monkeypatch):
    monkeypatch.setenv("EXGEN_SECRET", "short")
    with pytest.raises(SecretError, match="shorter than 16 bytes"):
        load_secret(None)
