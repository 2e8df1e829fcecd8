"""The progress file: write-ahead log, one transaction per change, and a damaged, locked, foreign or newer
file reported in one line and left byte for byte as it was."""
import sqlite3

import pytest

from practice.store import SCHEMA_VERSION, ProgressError, Store, default_path


class FakeTemplate:
    id, digest, topic, chapter = "belts.demo", "abc", "belts", 1


def filled(path):
    store = Store(path)
    problem = store.add_problem(FakeTemplate, 2**64 + 5, "v1", "topic:belts")
    store.add_check(problem, "a", "12 kW", "correct", None, "correct")
    store.add_hint(problem, "b", 1)
    store.show_solution(problem)
    return store, problem


def test_a_new_file_is_made_in_write_ahead_mode_with_its_version(tmp_path):
    store, problem = filled(tmp_path / "deep" / "progress.sqlite3")
    db = sqlite3.connect(store.path)
    assert db.execute("PRAGMA journal_mode").fetchone()[0] == "wal"
    assert db.execute("PRAGMA user_version").fetchone()[0] == SCHEMA_VERSION
    assert store.problem(problem).seed == 2**64 + 5  # larger than SQLite's integers: kept exactly
    assert [c.answer for c in store.checks(problem)] == ["12 kW"] and store.solution_shown(problem)


def test_a_variant_is_recorded_once(tmp_path):
    store, _ = filled(tmp_path / "p.sqlite3")
    assert store.add_problem(FakeTemplate, 2**64 + 9, "v1", "all") is None
    assert store.variants_served("belts.demo") == {"v1"}


def test_readers_follow_the_file_by_the_ids_they_have_not_seen(tmp_path):
    store, problem = filled(tmp_path / "p.sqlite3")
    first = store.after({})
    assert [len(first[t]) for t in ("problems", "checks", "hints", "solutions")] == [1, 1, 1, 1]
    store.add_check(problem, "b", "3", "wrong", "ratio_inverted", "inverted")
    later = store.after({t: rows[-1][0] for t, rows in first.items()})
    assert [c.mistake for _, c in later["checks"]] == ["ratio_inverted"] and not later["problems"]


def test_a_change_that_fails_half_way_leaves_nothing(tmp_path):
    store, problem = filled(tmp_path / "p.sqlite3")
    with pytest.raises(RuntimeError):
        with store.transaction() as db:
            db.execute("INSERT INTO hints (problem, part, level, at) VALUES (?, 'a', 1, 0)", (problem,))
            raise RuntimeError("interrupted")
    assert [h.part for h in store.hints(problem)] == ["b"]


def test_a_file_that_is_not_a_database_is_reported_and_left_alone(tmp_path):
    path = tmp_path / "progress.sqlite3"
    path.write_bytes(b"my lab notes, not a database" * 100)
    before = path.read_bytes()
    with pytest.raises(ProgressError, match="is not a readable practice file .*left as it is"):
        Store(path)
    assert path.read_bytes() == before


def test_a_damaged_database_is_reported_and_left_alone(tmp_path):
    path = tmp_path / "progress.sqlite3"
    store, _ = filled(path)
    for i in range(200):
        store.add_check(1, "a", f"{i} kW", "wrong", None, "no")
    store.close()
    sqlite3.connect(path).execute("PRAGMA wal_checkpoint(TRUNCATE)").close()
    data = bytearray(path.read_bytes())
    data[4096:4 * 4096] = b"\x7f" * (3 * 4096)  # pages 2 to 4 overwritten
    path.write_bytes(bytes(data))
    with pytest.raises(ProgressError) as info:
        Store(path)
    assert "left as it is" in str(info.value) and str(path) in str(info.value)
    assert path.read_bytes() == bytes(data)


def test_a_locked_file_says_so_and_earlier_progress_survives(tmp_path):
    path = tmp_path / "p.sqlite3"
    store, problem = filled(path)
    store.busy_seconds = 0.2
    store.close()
    store = Store(path, busy_seconds=0.2)
    other = sqlite3.connect(path, isolation_level=None)
    other.execute("BEGIN EXCLUSIVE")
    with pytest.raises(ProgressError, match="busy: another exgen is writing to it. Nothing was lost"):
        store.add_check(problem, "b", "5 kW", "wrong", None, "no")
    other.execute("ROLLBACK")
    other.close()
    assert [c.answer for c in store.checks(problem)] == ["12 kW"]
    store.add_check(problem, "b", "5 kW", "wrong", None, "no")  # and it works again once released
    assert len(store.checks(problem)) == 2


def test_another_programs_database_is_not_written_to(tmp_path):
    path = tmp_path / "other.sqlite3"
    db = sqlite3.connect(path)
    db.execute("CREATE TABLE invoices (id INTEGER)")
    db.commit()
    db.close()
    before = path.read_bytes()
    with pytest.raises(ProgressError, match="an SQLite file of something else .*invoices"):
        Store(path)
    assert path.read_bytes() == before


def test_a_file_from_a_newer_exgen_is_left_alone(tmp_path):
    path = tmp_path / "p.sqlite3"
    filled(path)[0].close()
    db = sqlite3.connect(path)
    db.execute(f"PRAGMA user_version = {SCHEMA_VERSION + 1}")
    db.commit()
    db.close()
    with pytest.raises(ProgressError, match="newer exgen"):
        Store(path)


def test_a_folder_in_the_way_is_one_clear_error(tmp_path):
    (tmp_path / "p.sqlite3").mkdir()
    with pytest.raises(ProgressError, match="p.sqlite3"):
        Store(tmp_path / "p.sqlite3")


def test_the_default_file_follows_the_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("EXGEN_PRACTICE_DB", str(tmp_path / "x.sqlite3"))
    assert default_path() == tmp_path / "x.sqlite3"
    monkeypatch.delenv("EXGEN_PRACTICE_DB")
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    assert default_path() in (tmp_path / "exgen" / "practice.sqlite3",) or default_path().name == "practice.sqlite3"
