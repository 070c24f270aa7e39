"""Saving figures atomically with a headless backend."""

from __future__ import annotations

import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from matplotlib.figure import Figure  # noqa: E402

from conrod.io.atomic import atomic_path  # noqa: E402

_REPRODUCIBLE_METADATA = {".png": {"Software": None}, ".pdf": {"CreationDate": None},
                          ".svg": {"Date": None}}
"""Metadata entries removed per format so that reruns give byte-identical figures."""


def save_figure(figure: Figure, target: str | os.PathLike[str], *, dpi: int = 130) -> Path:
    """Write ``figure`` to ``target`` (format from the suffix) atomically, then close it."""
    import matplotlib.pyplot as plt

    with atomic_path(target) as tmp:
        # no "Software" (matplotlib version) or date in the file: same input, same bytes
        metadata = _REPRODUCIBLE_METADATA.get(Path(target).suffix.lower())
        figure.savefig(tmp, dpi=dpi, bbox_inches="tight", metadata=metadata)
    plt.close(figure)
    return Path(target)
