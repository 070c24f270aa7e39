"""Result folders written as a whole: the folder holds the complete old result or the
complete new one, never a mix, never a half-written or temporary file.

.. code-block:: python

    check_output_folder(out)              # before any computation: CaseError if unusable
    with staged_result_folder(out) as stage:
        write_csv(stage / "cycle.csv", ...)   # every file of the result goes into ``stage``

An output folder is either new, empty (hidden entries such as ``.gitkeep`` aside) or
owned by conrod: it holds the marker of the command's results (``manifest.json``; a
sweep folder: ``study.json``). Any other folder is refused before computing, naming what
is in it, so a rerun never mixes files of another origin into a result.

``stage`` is a hidden sibling folder of ``out`` (same file system). When the block ends
without an exception, a ``manifest.json`` (name, size and SHA-256 of every result file) is
added (unless the command writes a fixed set of files). The previous result of ``out``
(every file its manifest lists, and the report made from it) is dropped; hidden entries
and files added by hand to a conrod folder are carried over by hard link; then the stage
is swapped in: one atomic exchange of the two
folders (Linux ``renameat2(RENAME_EXCHANGE)``), or two renames elsewhere. On an exception
(or a kill) ``out`` is untouched; a stage left behind by a killed process is removed by the
next run that writes next to it.
"""

from __future__ import annotations

import contextlib
import ctypes
import hashlib
import json
import os
import shutil
import tempfile
from collections.abc import Iterator
from pathlib import Path

from conrod.errors import CaseError
from conrod.io.interrupts import raise_if_interrupted

MANIFEST = "manifest.json"
"""Name of the file listing the result files of a folder."""
STAGE_TAG = ".conrod-stage-"
"""Part of the name of a staging folder: ``.<out name>.conrod-stage-<pid>-<random>``."""
DERIVED_FILES = frozenset({"report.html", "report.pdf"})
"""Files made from a result folder's content (``conrod report``): stale after a rerun."""
SHOWN_ENTRIES = 4
"""How many entries of a refused folder the error names."""
RESERVED_PATH_BYTES = 200
"""Room kept in a path for what is written below ``--out``: staging names, result files,
a sweep's variant folders [bytes]."""
STAGE_NAME_BYTES = 100
"""A longer ``--out`` name is cut to this many bytes (and tagged with its hash) in the name
of the staging folder, so that the staging name fits in a file name [bytes]."""
_CHECKED: set[Path] = set()
"""Folders accepted by :func:`check_output_folder` in this process (with their inputs)."""
_RENAME_EXCHANGE = 2
_AT_FDCWD = -100


def check_output_folder(out: str | os.PathLike[str], option: str = "--out",
                        marker: str = MANIFEST,
                        inputs: tuple[str | os.PathLike[str], ...] = ()) -> Path:
    """Check that results can be written to ``out``; raise :class:`CaseError` if not.

    Done before any computation: ``out`` must not exist yet, or be an empty folder, or a
    folder of conrod's results (it holds ``marker``), or hold nothing but the command's
    own input files; no part of its path may be a file, it must not be (or contain) the
    current folder, and its parent must accept a new entry. Returns ``out`` as an
    absolute path; the result writers of this process then accept it.

    marker : str  File that marks a folder as conrod's (``manifest.json``; a sweep
        folder: ``study.json``).
    inputs : paths  The command's input files (case or study file), kept in place.
    """
    path = Path(out).absolute()
    shown = f"{option} {str(out)!r}"
    _check_lengths(path, shown)
    if path.exists() and not path.is_dir():
        raise CaseError(f"{shown}: is an existing file (allowed: a folder, new or existing)")
    _check_owned(path, shown, marker, {Path(p).absolute() for p in inputs})
    if Path.cwd() == path or path in Path.cwd().parents:
        raise CaseError(f"{shown}: is the current folder or contains it (allowed: a "
                        "results subfolder, e.g. results/run1)")
    existing = path.parent
    while not existing.exists():
        existing = existing.parent
    if not existing.is_dir():
        raise CaseError(f"{shown}: {str(existing)!r} is a file, not a folder")
    try:
        probe = tempfile.mkdtemp(prefix=".conrod-probe-", dir=existing)
    except OSError as error:
        raise CaseError(f"{shown}: cannot write in {str(existing)!r} "
                        f"({error.strerror or type(error).__name__})") from None
    os.rmdir(probe)
    _CHECKED.add(path)
    return path


def check_before_writing(out: str | os.PathLike[str], option: str) -> Path:
    """:func:`check_output_folder` for a writer called from Python (``option`` names its
    argument), unless a command of this process already checked ``out``."""
    if not isinstance(out, str | os.PathLike):
        raise CaseError(f"{option} = {out!r}: a folder path is required (str or Path)")
    path = Path(out).absolute()
    return path if path in _CHECKED else check_output_folder(out, option)


def _check_lengths(path: Path, shown: str) -> None:
    """Refuse names and paths the file system cannot hold (with room for the results)."""
    existing = next(folder for folder in path.parents if os.path.isdir(folder))
    name_max = _limit(existing, "PC_NAME_MAX", 255)
    path_max = _limit(existing, "PC_PATH_MAX", 4096)
    for part in path.parts[1:]:
        size = len(os.fsencode(part))
        if size > name_max:
            raise CaseError(f"{shown}: a folder name of {size} bytes is too long (allowed: "
                            f"<= {name_max} bytes per name)")
    size = len(os.fsencode(str(path)))
    if size > path_max - RESERVED_PATH_BYTES:
        raise CaseError(f"{shown}: a path of {size} bytes is too long (allowed: <= "
                        f"{path_max - RESERVED_PATH_BYTES} bytes, leaving room for the "
                        "result files)")


def _limit(folder: Path, name: str, default: int) -> int:
    """A file-system limit (``os.pathconf``) of ``folder``, ``default`` where unknown."""
    try:
        return int(os.pathconf(folder, name))
    except (OSError, ValueError):
        return default


def stage_prefix(target: Path) -> str:
    """Name prefix of the staging folders of ``target``: ``.<name>.conrod-stage-``, the
    name cut to :data:`STAGE_NAME_BYTES` and tagged with its hash when longer."""
    name = target.name
    if len(os.fsencode(name)) > STAGE_NAME_BYTES:
        digest = hashlib.sha256(os.fsencode(name)).hexdigest()[:12]
        while len(os.fsencode(name)) > STAGE_NAME_BYTES - len(digest) - 1:
            name = name[:-1]
        name = f"{name}~{digest}"
    return f".{name}{STAGE_TAG}"


def _check_owned(path: Path, shown: str, marker: str, inputs: set[Path] = frozenset()
                 ) -> None:
    """Refuse a non-empty folder that holds no conrod result (its files are not ours), saying
    why: a result folder is written and replaced as a whole, so conrod writes only into a
    new or empty folder or one of its own results. A folder that holds other result folders
    (``results`` after ``--out results/a``) is named as such, with the fix."""
    if not path.is_dir() or (path / marker).is_file():
        return
    entries = sorted(entry.name for entry in path.iterdir()
                     if not entry.name.startswith(".") and entry not in inputs)
    if not entries:
        return
    names = ", ".join(entries[:SHOWN_ENTRIES]) + (
        f", ... ({len(entries)} entries)" if len(entries) > SHOWN_ENTRIES else "")
    results = [name for name in entries if _holds_result(path / name)]
    if results:
        raise CaseError(
            f"{shown}: holds other result folders ({names}) and is not one itself (no "
            f"{marker}); a result is written into a folder of its own, replacing it as a "
            f"whole, so it cannot go here: give a folder of its own, e.g. a new subfolder "
            f"{(Path(path.name) / 'run2').as_posix()!r}")
    raise CaseError(f"{shown}: folder holds files conrod did not write ({names}) and no "
                    f"{marker}; a result folder is replaced as a whole, which would delete "
                    "them (allowed: a new or empty folder, one holding only the input file, "
                    "or a conrod results folder, whose previous results are replaced); "
                    "choose another folder or empty this one")


def _holds_result(entry: Path) -> bool:
    """True for a subfolder holding a conrod result (its manifest or a sweep's study)."""
    return entry.is_dir() and any((entry / name).is_file()
                                  for name in (MANIFEST, "study.json"))


@contextlib.contextmanager
def staged_result_folder(out: str | os.PathLike[str], *, manifest: bool = True
                         ) -> Iterator[Path]:
    """Yield an empty staging folder; swap it in as ``out`` when the block succeeds.

    manifest : bool  Add ``manifest.json`` (a command whose result is always the same
        fixed set of files may leave it out; the set is still swapped in as a whole).
    """
    target = Path(out).absolute()
    if target not in _CHECKED:  # writers called from Python: the same rule
        _check_owned(target, repr(str(out)), MANIFEST)
    target.parent.mkdir(parents=True, exist_ok=True)
    _remove_abandoned_stages(target)
    stage = Path(tempfile.mkdtemp(prefix=f"{stage_prefix(target)}{os.getpid()}-",
                                  dir=target.parent))
    try:
        yield stage
        if manifest:
            _write_manifest(stage)
        if target.is_dir():
            _carry_over_foreign_files(target, stage)
        _swap_in(stage, target)
    except BaseException:
        shutil.rmtree(stage, ignore_errors=True)
        raise


def result_files(folder: Path) -> dict[str, dict]:
    """Every regular file below ``folder`` (relative POSIX name → bytes and SHA-256)."""
    files = {}
    for path in sorted(p for p in folder.rglob("*") if p.is_file()):
        name = path.relative_to(folder).as_posix()
        if name != MANIFEST:
            digest = hashlib.sha256(path.read_bytes()).hexdigest()
            files[name] = {"bytes": path.stat().st_size, "sha256": digest}
    return files


def _write_manifest(stage: Path) -> None:
    """manifest.json listing the staged files (merged into one the writer made)."""
    manifest_path = stage / MANIFEST
    manifest: dict = {}
    if manifest_path.is_file():
        with contextlib.suppress(ValueError):
            loaded = json.loads(manifest_path.read_text(encoding="utf-8"))
            manifest = loaded if isinstance(loaded, dict) else {}
    manifest["files"] = result_files(stage)
    manifest_path.write_text(json.dumps(manifest, indent=2) + "\n", encoding="utf-8")


def _listed_files(folder: Path) -> set[str]:
    """Top-level names of the result files listed in ``folder``'s manifest."""
    try:
        files = json.loads((folder / MANIFEST).read_text(encoding="utf-8")).get("files", {})
    except (OSError, ValueError, AttributeError):
        return set()
    return {str(name).split("/")[0] for name in files} | {MANIFEST} | DERIVED_FILES


def _carry_over_foreign_files(target: Path, stage: Path) -> None:
    """Hard-link (or copy) into ``stage`` what ``target`` holds besides its last result
    (hidden entries, files added by hand to a conrod folder)."""
    listed = _listed_files(target)
    for entry in target.iterdir():
        if entry.name in listed or (stage / entry.name).exists():
            continue
        if entry.is_dir() and not entry.is_symlink():
            shutil.copytree(entry, stage / entry.name, symlinks=True, copy_function=_link)
        else:
            _link(entry, stage / entry.name)


def _link(source: os.PathLike[str] | str, target: os.PathLike[str] | str) -> None:
    try:
        os.link(source, target, follow_symlinks=False)
    except OSError:
        shutil.copy2(source, target, follow_symlinks=False)


def _swap_in(stage: Path, target: Path) -> None:
    """Make ``stage`` the folder ``target`` in one step; remove what was there."""
    raise_if_interrupted()  # Ctrl-C while writing: keep the old result
    os.chmod(stage, 0o755)  # mkdtemp makes it 0700
    if not target.exists():
        os.rename(stage, target)
        return
    if _exchange(stage, target):
        shutil.rmtree(stage, ignore_errors=True)  # now holds the previous result
        return
    old = Path(tempfile.mkdtemp(prefix=f"{stage_prefix(target)}{os.getpid()}-",
                                dir=target.parent))
    os.rmdir(old)
    os.rename(target, old)
    os.rename(stage, target)
    shutil.rmtree(old, ignore_errors=True)


def _exchange(first: Path, second: Path) -> bool:
    """Atomically exchange two paths (Linux renameat2); False where unsupported."""
    try:
        renameat2 = ctypes.CDLL(None, use_errno=True).renameat2
    except (AttributeError, OSError):
        return False
    result = renameat2(_AT_FDCWD, os.fsencode(first), _AT_FDCWD, os.fsencode(second),
                       _RENAME_EXCHANGE)
    return result == 0


def _remove_abandoned_stages(target: Path) -> None:
    """Remove stages next to ``target`` whose writing process no longer exists."""
    prefix = stage_prefix(target)
    for entry in target.parent.glob(f"{glob_escape(prefix)}*"):
        pid_text = entry.name[len(prefix):].split("-")[0]
        if pid_text.isdigit() and not _alive(int(pid_text)):
            shutil.rmtree(entry, ignore_errors=True)


def glob_escape(text: str) -> str:
    """``text`` with glob metacharacters escaped."""
    return "".join(f"[{c}]" if c in "*?[" else c for c in text)


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True
