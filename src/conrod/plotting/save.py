"""Saving figures atomically with a headless backend."""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from matplotlib.figure import Figure  # noqa: E402

from conrod.io.atomic import atomic_path  # noqa: E402


def save_figure(figure: Figure, target: str | os.PathLike[str], *, dpi: int = 130) -> Path:
    """Write ``figure`` to ``target`` (format from the suffix) atomically, then close it."""
    import matplotlib.pyplot as plt

    with atomic_path(target) as tmp:
        figure.savefig(tmp, dpi=dpi, bbox_inches="tight")
    plt.close(figure)
    return Path(target)
