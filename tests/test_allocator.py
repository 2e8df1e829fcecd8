"""PDF workers start with a faster allocator where the system has one, and only then."""
from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

from exgen.runtime import allocator, parallel
from exgen.runtime.allocator import PRELOAD, SETTING, faster_allocator, preloaded


@pytest.fixture(autouse=True)
def fresh_choice():
    faster_allocator.cache_clear()
    yield
    faster_allocator.cache_clear()


def test_the_setting_keeps_the_system_allocator(monkeypatch):
    monkeypatch.setenv(SETTING, "system")
    assert faster_allocator() is None


def test_a_library_that_cannot_be_preloaded_is_not_used(monkeypatch, tmp_path):
    monkeypatch.setenv(SETTING, str(tmp_path / "libnothing.so"))  # the loader warns and goes on: refused
    assert faster_allocator() is None
    broken = tmp_path / "libbroken.so"
    broken.write_bytes(b"not a shared object")
    monkeypatch.setenv(SETTING, str(broken))
    assert faster_allocator() is None


def test_none_found_means_none(monkeypatch):
    monkeypatch.delenv(SETTING, raising=False)
    monkeypatch.setattr("ctypes.util.find_library", lambda name: None)
    assert faster_allocator() is None


def test_preloading_touches_only_processes_started_inside(monkeypatch):
    monkeypatch.setenv(PRELOAD, "libalready.so")
    with preloaded("libfaster.so"):
        assert os.environ[PRELOAD] == "libfaster.so:libalready.so"
    assert os.environ[PRELOAD] == "libalready.so"
    monkeypatch.delenv(PRELOAD)
    with preloaded("libfaster.so"):
        assert os.environ[PRELOAD] == "libfaster.so"
    assert PRELOAD not in os.environ
    with preloaded(None):
        assert PRELOAD not in os.environ


def _mapped_libraries() -> str:
    return Path("/proc/self/maps").read_text()


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="LD_PRELOAD and /proc are Linux's")
def test_workers_run_with_the_allocator_found(monkeypatch):
    monkeypatch.delenv(SETTING, raising=False)
    library = faster_allocator()
    if library is None:
        pytest.skip("no jemalloc on this machine (Debian and Ubuntu: libjemalloc2)")
    with parallel.pool(1, preload=library) as workers:
        maps = workers.submit(_mapped_libraries).result()
    assert "jemalloc" in maps
    assert "jemalloc" not in _mapped_libraries()  # this process keeps its own
    assert allocator.PRELOAD not in os.environ or "jemalloc" not in os.environ[allocator.PRELOAD]
