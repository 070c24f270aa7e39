"""Disk cache of condensed housings, as for the film tables: ``<sha256>.npz`` keyed by a hash
of the housing inputs and the film grid, written atomically (default folder
``~/.cache/conrod/housing``)."""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from conrod.io.atomic import atomic_path

CACHE_FORMAT = 1
"""Bumped whenever the stored content changes meaning (part of the key) [-]."""
DEFAULT_CACHE_DIR = Path.home() / ".cache" / "conrod" / "housing"


def cache_key(payload: dict[str, Any]) -> str:
    """SHA-256 of the JSON of ``payload`` (sorted keys) and the cache format."""
    text = json.dumps({"format": CACHE_FORMAT, **payload}, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def load_or_build(key: str, build: Callable[[], dict[str, np.ndarray]],
                  cache_dir: str | Path | None = None,
                  use_cache: bool = True) -> tuple[dict[str, np.ndarray], bool]:
    """Arrays stored under ``key``, or ``build()`` them and store them; (arrays, from_cache)."""
    folder = Path(cache_dir) if cache_dir is not None else DEFAULT_CACHE_DIR
    path = folder.expanduser() / f"{key}.npz"
    if use_cache and path.exists():
        with np.load(path, allow_pickle=False) as stored:
            return {name: stored[name].copy() for name in stored.files}, True
    arrays = build()
    if use_cache:
        save: Any = np.savez
        with atomic_path(path) as tmp:
            save(tmp, **arrays)
    return arrays, False
