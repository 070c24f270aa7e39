"""Caches on disk that cannot be used never fail a run: an unreadable compiled-kernel
(numba) cache file is discarded and compiled again; an unusable film-table cache folder is
skipped. Each says so in one warning line; the results are those of a good cache."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from hardening_helpers import cheap_table_run, mutated, write_case

SRC = Path(__file__).resolve().parents[1] / "src"


def _run(case: Path, out: Path, **env: str) -> subprocess.CompletedProcess:
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "run",
               str(case), "--out", str(out), "--no-figures"]
    return subprocess.run(command, capture_output=True, text=True, check=False, timeout=300,
                          env={**os.environ, "PYTHONPATH": str(SRC), **env})


def _warnings(stderr: str) -> list[str]:
    return [line for line in stderr.splitlines() if line.startswith("warning:")]


def test_a_truncated_numba_cache_file_is_discarded_and_compiled_again(tmp_path):
    case = write_case(tmp_path, mutated(cheap_table_run(), ("solver", "max_cycles"), 6))
    cache = tmp_path / "numba"
    first = _run(case, tmp_path / "first", NUMBA_CACHE_DIR=str(cache))
    assert first.returncode == 0, first.stderr
    assert _warnings(first.stderr) == []
    # two kernels the run calls itself (a callee linked into a cached caller is not read)
    data = sorted(cache.rglob("massless.*_contact_forces-*.nbc"))  # film/massless.py
    index = sorted(cache.rglob("velocity.short_bearing_cycle-*.nbi"))  # film/short/
    assert len(data) == 1 and len(index) == 1
    data[0].write_bytes(data[0].read_bytes()[:100])  # a data file cut short
    index[0].write_bytes(index[0].read_bytes()[:30])  # an index file cut short

    second = _run(case, tmp_path / "second", NUMBA_CACHE_DIR=str(cache))
    assert second.returncode == 0, second.stderr
    [warning] = _warnings(second.stderr)
    assert "could not be read (pickle data was truncated); discarded, compiling it again" \
        in warning
    assert "Traceback" not in second.stderr
    assert data[0].stat().st_size > 100 and index[0].stat().st_size > 30  # saved anew
    third = _run(case, tmp_path / "third", NUMBA_CACHE_DIR=str(cache))
    assert third.returncode == 0 and _warnings(third.stderr) == []
    for name in ("cycle.csv", "summary.json"):
        assert _strip_time(tmp_path / "first" / name) == _strip_time(tmp_path / "second" / name)
        assert _strip_time(tmp_path / "first" / name) == _strip_time(tmp_path / "third" / name)


def _strip_time(path: Path) -> list[str]:
    return [line for line in path.read_text(encoding="utf-8").splitlines()
            if "wall_time_s" not in line]


def _table(cache_dir):
    from conrod.film.base import BearingGeometry
    from conrod.film.short.film import ShortBearingFilm
    from conrod.film.table.film import TabulatedFilm

    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6)
    return TabulatedFilm(ShortBearingFilm(geometry), n_eps=5, n_direction=8,
                         cache_dir=cache_dir)


@pytest.mark.parametrize("place", ["a file", "below a file", "/proc"])
def test_an_unusable_table_cache_folder_is_skipped_with_one_warning(tmp_path, monkeypatch,
                                                                    place):
    from conrod.errors import CacheWarning
    from conrod.film.table import film as table

    monkeypatch.setattr(table, "UNUSABLE_FOLDERS", set())
    monkeypatch.setattr(table, "KEPT_IN_MEMORY", {})
    (tmp_path / "taken").write_text("not a folder")
    folder = {"a file": tmp_path / "taken", "below a file": tmp_path / "taken" / "tables",
              "/proc": Path("/proc/conrod-tables")}[place]
    reference = _table(tmp_path / "good")
    with pytest.warns(CacheWarning) as caught:
        film = _table(folder)
        again = _table(folder)  # the same process: kept in memory, no second warning
    assert [str(w.message) for w in caught] == [
        f"film table cache folder {str(folder)!r} cannot be used "
        f"({_reason(folder)}); going on without it (tables built in this process are kept "
        "in memory)"]
    assert not film.loaded_from_cache and again.tables is film.tables
    for name, values in reference.tables.items():
        np.testing.assert_array_equal(film.tables[name], values)


def _reason(folder: Path) -> str:
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        return error.strerror
    raise AssertionError(f"{folder} is usable")


def test_a_run_whose_table_cache_folder_is_a_file_exits_0_with_one_warning(tmp_path):
    home = tmp_path / "home"
    home.mkdir()
    (home / ".cache").write_text("a file where the cache folder would go")
    case = write_case(tmp_path, mutated(mutated(cheap_table_run(), ("solver", "film"), "table"),
                                        ("solver", "max_cycles"), 6))
    done = _run(case, tmp_path / "out", HOME=str(home))
    assert done.returncode == 0, done.stderr
    assert _warnings(done.stderr) == [
        f"warning: film table cache folder '{home}/.cache/conrod/tables' cannot be used (Not "
        "a directory); going on without it (tables built in this process are kept in memory)"]
    assert (tmp_path / "out" / "manifest.json").is_file()


class _CacheFile:
    def __init__(self):
        self._index_name = "short_bearing.kernel_force-30.py311.nbi"
        self._source_stamp = (1.0, 30)


class _Cache:
    """Stands for numba's per-function cache: loading finds a file cut short, saving a
    full disk."""

    def __init__(self, folder: Path, module: str):
        def kernel():
            return None

        kernel.__module__ = module
        self._py_func, self._cache_path, self._cache_file = kernel, folder, _CacheFile()

    def load_overload(self, sig, target_context):
        import pickle

        raise pickle.UnpicklingError("pickle data was truncated")

    def save_overload(self, sig, data):
        import errno

        raise OSError(errno.ENOSPC, "No space left on device")


def test_the_guard_turns_unreadable_and_unwritable_caches_into_one_warning_each(
        tmp_path, monkeypatch):
    import pickle
    import types

    from conrod.errors import CacheWarning
    from conrod.io import numba_cache

    (tmp_path / "short_bearing.kernel_force-30.py311.nbi").write_bytes(b"\x80")
    (tmp_path / "short_bearing.kernel_force-30.py311.1.nbc").write_bytes(b"\x80")
    (tmp_path / "other.kernel-9.py311.nbi").write_bytes(b"kept")
    caching = types.SimpleNamespace(Cache=type("Cache", (_Cache,), {}))
    numba_cache.guard(caching)
    for expected in ("could not be read (pickle data was truncated); discarded, compiling it "
                     "again", "could not be written (No space left on device); going on "
                     "without it"):
        monkeypatch.setattr(numba_cache, "_state", {"warned": False})
        cache = caching.Cache(tmp_path, "conrod.film.short.film")
        with pytest.warns(CacheWarning) as caught:
            if "read" in expected:
                assert cache.load_overload(None, None) is None
            else:
                cache.save_overload(None, None)
        [warning] = [str(w.message) for w in caught]
        assert warning.startswith(f"compiled-kernel cache of 'short_bearing.kernel_force' in "
                                  f"{str(tmp_path)!r} {expected}")
    assert sorted(p.name for p in tmp_path.iterdir()) == [  # the compile lock's file stays
        numba_cache.LOCK_FILE, "other.kernel-9.py311.nbi"]
    with pytest.raises(pickle.UnpicklingError):  # numba's other users: as numba does
        caching.Cache(tmp_path, "someone.else").load_overload(None, None)


def test_the_package_stamp_changes_with_the_content_of_any_module_not_its_time(tmp_path):
    import os

    from conrod.io.numba_cache import package_stamp

    (tmp_path / "sub").mkdir()
    for name in ("a.py", "sub/b.py"):
        (tmp_path / name).write_text("x = 1\n")
    before = package_stamp.__wrapped__(str(tmp_path))
    assert package_stamp.__wrapped__(str(tmp_path)) == before
    stat = (tmp_path / "sub" / "b.py").stat()
    os.utime(tmp_path / "sub" / "b.py", ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))
    assert package_stamp.__wrapped__(str(tmp_path)) == before  # a copy installed later
    (tmp_path / "sub" / "b.py").write_text("x = 2\n")  # same size, other code
    assert package_stamp.__wrapped__(str(tmp_path)) != before
    (tmp_path / "sub" / "b.py").write_text("x = 1\n")
    (tmp_path / "notes.txt").write_text("not a module")
    assert package_stamp.__wrapped__(str(tmp_path)) == before
    (tmp_path / "sub" / "b.py").rename(tmp_path / "b.py")  # the same code moved
    assert package_stamp.__wrapped__(str(tmp_path)) != before


def test_own_kernels_are_stamped_with_the_package_and_others_as_numba_does(tmp_path):
    import types

    from conrod.io import numba_cache

    caching = types.SimpleNamespace(Cache=type("Cache", (_Cache,), {}))
    numba_cache.guard(caching)
    own = numba_cache.numba_attribute(caching.Cache(tmp_path, "conrod.film.short.film"),
                                      "_cache_file")
    other = numba_cache.numba_attribute(caching.Cache(tmp_path, "someone.else"), "_cache_file")
    assert numba_cache.numba_attribute(own, "_source_stamp") == numba_cache.package_stamp()
    assert numba_cache.numba_attribute(other, "_source_stamp") == (1.0, 30)


def test_a_real_kernel_of_conrod_carries_the_package_stamp():
    from conrod.film.short import kernel
    from conrod.io.numba_cache import numba_attribute, package_stamp

    dispatcher = kernel.sommerfeld_angle
    cache_file = numba_attribute(numba_attribute(dispatcher, "_cache"), "_cache_file")
    assert numba_attribute(cache_file, "_source_stamp") == package_stamp()
