import hashlib
import hmac
import os
from pathlib import Path

import pytest

from exgen.draw.seeds import derive_seed, fingerprint, legacy_fingerprint, load_secret, sheet_code
from exgen.errors import SecretError

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


@pytest.mark.parametrize("content, why", [
    (b"root:x:0:0:root:/root:/bin/bash\ndaemon:x:1:1:daemon:/usr/sbin:/usr/sbin/nologin\n", "it has 2 lines"),
    (b"-----BEGIN OPENSSH PRIVATE KEY-----\nb3BlbnNzaC1rZXktdjEAAAAABG5vbmU\n-----END OPENSSH PRIVATE KEY-----\n",
     "it has 3 lines"),
    (bytes(range(256)), "NUL bytes"), (b"\xff\xfe\xfd" * 20, "it is not text"),
    (b"x" * 5000, "more than the 1 KiB allowed"), (b"a long secret\x07with a bell in it", "control characters"),
])
def test_a_file_that_is_no_course_secret_is_refused_in_one_line(monkeypatch, tmp_path, content, why):
    """`secret_file: /etc/passwd` was accepted: long and varied enough to pass as a strong secret."""
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    path = tmp_path / "course.secret"
    path.write_bytes(content)
    with pytest.raises(SecretError) as caught:
        load_secret(path, explicit=True)
    message = str(caught.value)
    assert message.startswith(f"{path} does not look like a course secret (") and why in message and "\n" not in message
    assert "token_hex" in message


@pytest.mark.skipif(not Path("/etc/passwd").is_file(), reason="needs /etc/passwd")
def test_etc_passwd_is_no_secret(monkeypatch):
    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    with pytest.raises(SecretError, match="does not look like a course secret"):
        load_secret(Path("/etc/passwd"), explicit=True)


def test_a_pipe_or_device_given_as_the_secret_file_is_refused_without_waiting(monkeypatch, tmp_path):
    """An ordinary open of a pipe waits for a writer for ever; /dev/zero never ends."""
    import threading

    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    os.mkfifo(tmp_path / "pipe")
    for path in (tmp_path / "pipe", Path("/dev/zero")):
        if not path.exists():
            continue
        outcome = []

        def load(path=path):
            try:
                load_secret(path, explicit=True)
            except SecretError as exc:
                outcome.append(str(exc))

        reader = threading.Thread(target=load, daemon=True)
        reader.start()
        reader.join(120)  # a hang guard only
        assert not reader.is_alive(), f"reading {path} as the secret hung"
        assert outcome and "not a regular file" in outcome[0]


@pytest.mark.parametrize("mode, warned", [(0o600, ""), (0o400, ""), (0o640, "the other members of its group"),
                                          (0o644, "other users of this computer"), (0o606, "other users")])
def test_a_secret_file_others_can_read_is_used_with_a_warning(monkeypatch, tmp_path, capsys, mode, warned):
    """A secret file readable by group or others was used without a word."""
    from exgen.cli import main

    monkeypatch.delenv("EXGEN_SECRET", raising=False)
    path = tmp_path / "course.secret"
    path.write_text(SECRET.decode() + "\n")
    path.chmod(mode)
    examples = Path(__file__).parent.parent / "examples"
    assert main(["generate", str(examples / "tutorial1.yaml"), "--out", str(tmp_path / "out"), "--no-pdf",
                 "--secret-file", str(path)]) == 0
    err = capsys.readouterr().err
    if warned:
        assert (f"warning: the secret file {path} can be read by {warned}" in err and f"chmod 600 {path}" in err
                and f"(mode {mode:04o})" in err)
    else:
        assert "warning" not in err
