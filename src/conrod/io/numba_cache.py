"""numba's disk cache of conrod's compiled kernels: a cache file that cannot be read is a
cache miss.

numba keeps each compiled kernel in an index file (``.nbi``) and data files (``.nbc``), in
``__pycache__`` beside the module or below ``NUMBA_CACHE_DIR``. A file cut short (a full
disk, a killed process, an interrupted copy) or otherwise unreadable makes numba raise
(``UnpicklingError``) every time the kernel is first called, and it never compiles again.
Under :func:`tolerate_unreadable_cache` loading one of conrod's kernels from such a file
discards that kernel's cache files instead, warns once per process
(:class:`~conrod.errors.CacheWarning`, one line), and numba compiles the kernel and saves a
good cache; the results are the same as with a good cache. A cache that cannot be written
(a full disk) is one warning too: the kernel is simply not cached.

numba judges a cached kernel fresh by the size and modification time of its own source
file only; a kernel that calls a compiled function of another module keeps that function's
old code when only the other module changed (an edited checkout, a partial update), and
gives old answers without a word. conrod's kernels are therefore stamped with
:func:`package_stamp` instead (a digest of the content of every module of the package): any
change to conrod's sources compiles them all again, and a copy of the package with the same
sources but new modification times (a wheel installed by pip, which does not keep them)
loads the kernels compiled beside the sources it was copied from
(``docs/install.md``, kernels compiled at ``pip install .``).

.. code-block:: python

    tolerate_unreadable_cache()   # done by ``import conrod``; numba need not be loaded yet

Compile time: :func:`default_optimisation_level` (also done by ``import conrod``) compiles
conrod's kernels at LLVM level :data:`OPTIMISATION_LEVEL` unless ``NUMBA_OPT`` is set. Two
processes that miss the same kernel in the same cache folder (the test suite's workers, a run
and its second process, a sweep's workers on a cold cache) compile it once: the first takes
the kernel's lock (a byte of :data:`LOCK_FILE` in the cache folder, locked with ``fcntl``;
the system releases it when the process ends, a compile that raises at once) until it has
saved the kernel, and the others wait for it and load the saved kernel instead of compiling
it as well. A folder where the lock file cannot be written (or locked: some network file
systems), a wait longer than :data:`LOCK_PATIENCE`, or ``CONROD_COMPILE_LOCK=0`` compiles as
numba does.
"""

from __future__ import annotations

import contextlib
import errno
import functools
import hashlib
import importlib.machinery
import os
import sys
import time
import warnings
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING, Any, cast

from conrod.errors import CacheWarning

try:
    import fcntl
except ImportError:  # pragma: no cover - not on Windows: kernels compiled as numba does
    fcntl = None  # type: ignore[assignment]

if TYPE_CHECKING:  # pragma: no cover
    from importlib.abc import Loader

OPTIMISATION_LEVEL = "2"
"""LLVM optimisation level of conrod's kernels (``NUMBA_OPT``; numba's own default is 3):
measured on the Reynolds film and its compiled orbit (``benchmarks/compile_benchmarks.md``),
level 2 compiles in about 3/4 of level 3's time and the kernels run as fast, with
bit-identical results."""
CACHING_MODULE = "numba.core.caching"
"""The numba module whose ``Cache`` loads and saves compiled kernels."""
OWN_PREFIX = "conrod."
"""Kernels of modules below this prefix are guarded; numba's other users are left alone."""
LOCK_FILE = "conrod-compile.lock"
"""File in each cache folder whose bytes lock the kernels being compiled (one byte per
kernel, at an offset hashed from the name of its index file)."""
LOCK_SWITCH = "CONROD_COMPILE_LOCK"
"""Environment variable: ``0`` turns the compile lock off."""
LOCK_PATIENCE = 300.0
"""Longest wait for another process compiling the same kernel [s]; then it is compiled here
too (the tilted flight, the longest, compiles in 70-110 s on 2 cores)."""
LOCK_POLL = 0.02
"""Interval of the lock's tries while another process holds it [s]."""
_state = {"warned": False}
_locks: dict[str, Any] = {"files": {}, "held": set()}


def default_optimisation_level() -> None:
    """``NUMBA_OPT`` = :data:`OPTIMISATION_LEVEL` unless the environment sets it; only
    before numba is imported (numba reads it once), so a program that loaded numba first
    keeps numba's setting."""
    if "numba" not in sys.modules:
        os.environ.setdefault("NUMBA_OPT", OPTIMISATION_LEVEL)


def tolerate_unreadable_cache() -> None:
    """Guard the loading of conrod's compiled kernels (idempotent). numba is not imported:
    if it is not loaded yet, its cache module is guarded as soon as it is."""
    module = sys.modules.get(CACHING_MODULE)
    if module is not None:
        guard(module)
    elif not any(isinstance(finder, _GuardOnImport) for finder in sys.meta_path):
        sys.meta_path.insert(0, _GuardOnImport())


def guard(caching: ModuleType) -> None:
    """Wrap ``Cache.load_overload`` and ``Cache.save_overload`` of numba's ``caching``."""
    cache_class = caching.Cache
    if getattr(cache_class.load_overload, "conrod_guarded", False):
        return
    load, save, init = (cache_class.load_overload, cache_class.save_overload,
                        cache_class.__init__)

    def stamped_init(self: Any, *args: Any, **kwargs: Any) -> None:
        init(self, *args, **kwargs)
        if _own(self):
            cache_file = numba_attribute(self, "_cache_file")
            vars(cache_file)["_source_stamp"] = package_stamp()

    def load_or_discard(self: Any, sig: Any, target_context: Any) -> Any:
        try:
            return load(self, sig, target_context)
        except Exception as error:  # any unreadable entry: a cache miss
            discard(self, error)
            return None

    def load_overload(self: Any, sig: Any, target_context: Any) -> Any:
        if not _own(self):
            return load(self, sig, target_context)
        found = load_or_discard(self, sig, target_context)
        if found is None and lock_kernel(self):  # another process may have compiled it
            found = load_or_discard(self, sig, target_context)  # while this one waited
            if found is not None:
                unlock_kernel(self)
        return found  # None: compiled here, the lock held until it is saved

    def save_overload(self: Any, sig: Any, data: Any) -> None:
        if not _own(self):
            save(self, sig, data)
            return
        try:
            save(self, sig, data)
        except OSError as error:  # the folder takes no file (full, read-only): not cached
            name, folder, _ = _files(self)
            warn_once(f"compiled-kernel cache of {name!r} in {folder!r} could not be written "
                      f"({error.strerror or error}); going on without it")
        except Exception as error:  # its index could not be read (nor removed): not cached
            discard(self, error)
        finally:
            unlock_kernel(self)

    load_overload.conrod_guarded = True  # type: ignore[attr-defined]
    cache_class.__init__ = stamped_init
    cache_class.load_overload = load_overload
    cache_class.save_overload = save_overload
    with contextlib.suppress(Exception):  # numba's events: a lock of a failed compile
        from numba.core import event

        event.register("numba:compile", _failed_compile_listener(event.Listener)())


def _failed_compile_listener(base: type) -> type:
    """A numba event listener releasing the lock of a kernel whose compile raised (the
    signature did not become one of its dispatcher's overloads; numba then saves nothing):
    otherwise another process of a long-lived program (a sweep's worker) would wait
    :data:`LOCK_PATIENCE` for it."""

    class FailedCompile(base):  # type: ignore[misc, valid-type]
        def on_start(self, event: Any) -> None:
            pass

        def on_end(self, event: Any) -> None:
            release_if_failed(event.data)

    return FailedCompile


def release_if_failed(data: Any) -> None:
    """Release the kernel's lock if the compile of ``data`` (the ``numba:compile`` event's
    dispatcher and argument types) left no overload."""
    with contextlib.suppress(Exception):
        dispatcher = data["dispatcher"]
        cache = vars(dispatcher).get("_cache")
        if cache is not None and hasattr(cache, "_cache_file") and _own(cache) and (
                tuple(data["args"]) not in dispatcher.overloads):
            unlock_kernel(cache)


@functools.cache
def package_stamp(root: str | None = None) -> str:
    """A digest of the relative path and content of every ``.py`` file below ``root``
    (default: conrod's package folder), computed once per process (2 MB, 20 ms)."""
    folder = Path(root) if root is not None else Path(__file__).resolve().parents[1]
    digest = hashlib.sha256()
    for path in sorted(folder.rglob("*.py")):
        content = path.read_bytes()
        digest.update(f"{path.relative_to(folder).as_posix()}:{len(content)};".encode())
        digest.update(content)
    return digest.hexdigest()


def lock_kernel(cache: Any) -> bool:
    """Take the lock of ``cache``'s kernel, waiting while another process holds it (module
    docstring); True when this process holds it now (also when it held it already), False
    when it cannot be locked. A compile that raises releases it
    (:func:`release_if_failed`; numba then compiles again with literal arguments, or the
    error reaches the caller)."""
    key = _lock_key(cache)
    if key is None:
        return False
    if key in _locks["held"]:
        return True
    descriptor, offset = key
    deadline = time.monotonic() + LOCK_PATIENCE
    while True:
        try:
            fcntl.lockf(descriptor, fcntl.LOCK_EX | fcntl.LOCK_NB, 1, offset)
        except OSError as error:
            if error.errno not in (errno.EACCES, errno.EAGAIN) or time.monotonic() > deadline:
                return False
            time.sleep(LOCK_POLL)
            continue
        _locks["held"].add(key)
        return True


def unlock_kernel(cache: Any) -> None:
    """Release the lock of ``cache``'s kernel if this process holds it."""
    key = _lock_key(cache)
    if key is not None and key in _locks["held"]:
        _locks["held"].discard(key)
        with contextlib.suppress(OSError):
            fcntl.lockf(key[0], fcntl.LOCK_UN, 1, key[1])


def _lock_key(cache: Any) -> tuple[int, int] | None:
    """(descriptor of the cache folder's lock file, byte of the kernel), or None where the
    file cannot be opened for writing (kept open for the process's life: closing any
    descriptor of the file would release all its locks)."""
    if fcntl is None or os.environ.get(LOCK_SWITCH, "1") == "0":
        return None
    _, folder, index_name = _files(cache)
    files = _locks["files"]
    if folder not in files:
        try:
            files[folder] = os.open(os.path.join(folder, LOCK_FILE), os.O_RDWR | os.O_CREAT,
                                    0o666)
        except OSError:
            files[folder] = None
    if files[folder] is None:
        return None
    offset = int.from_bytes(hashlib.sha256(index_name.encode()).digest()[:5], "big")
    return files[folder], offset


def numba_attribute(instance: Any, name: str) -> Any:
    """An attribute numba sets on its cache objects (it offers no public accessor)."""
    return vars(instance)[name]


def _own(cache: Any) -> bool:
    function = numba_attribute(cache, "_py_func")
    return str(getattr(function, "__module__", "")).startswith(OWN_PREFIX)


def _files(cache: Any) -> tuple[str, str, str]:
    """(kernel name, cache folder, index file name) of a numba cache."""
    folder = str(numba_attribute(cache, "_cache_path"))
    index_name = str(numba_attribute(numba_attribute(cache, "_cache_file"), "_index_name"))
    return index_name.split("-")[0], folder, index_name


def discard(cache: Any, error: BaseException) -> None:
    """Remove the index and data files of ``cache``'s kernel; warn once per process."""
    name, folder, index_name = _files(cache)
    base = index_name.removesuffix(".nbi")
    with contextlib.suppress(OSError):
        for entry in os.scandir(folder):
            if entry.name == index_name or (entry.name.startswith(f"{base}.")
                                            and entry.name.endswith(".nbc")):
                with contextlib.suppress(OSError):
                    os.remove(entry.path)
    warn_once(f"compiled-kernel cache of {name!r} in {folder!r} could not be read "
              f"({str(error) or type(error).__name__}); discarded, compiling it again "
              "(slower this once)")


def warn_once(message: str) -> None:
    """One :class:`CacheWarning` per process (one bad file is enough to know)."""
    if not _state["warned"]:
        _state["warned"] = True
        warnings.warn(message, CacheWarning, stacklevel=3)


class _GuardOnImport:
    """A ``sys.meta_path`` finder: finds numba's caching module as the path finder does, and
    guards it once loaded."""

    def find_spec(self, fullname: str, path: Any, target: Any = None) -> Any:
        if fullname != CACHING_MODULE:
            return None
        with contextlib.suppress(ValueError):
            sys.meta_path.remove(self)
        spec = importlib.machinery.PathFinder.find_spec(fullname, path)
        if spec is not None and spec.loader is not None:
            spec.loader = cast("Loader", _GuardingLoader(spec.loader))
        return spec


class _GuardingLoader:
    """Delegates to numba's own loader, then guards the module it executed."""

    def __init__(self, loader: Any):
        self.loader = loader

    def create_module(self, spec: Any) -> Any:
        return self.loader.create_module(spec)

    def exec_module(self, module: ModuleType) -> None:
        self.loader.exec_module(module)
        guard(module)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.loader, name)
