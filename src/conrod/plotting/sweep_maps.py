"""Engine maps of a sweep over two axes (speed × load): contour maps of a characteristic
with its limit contour and the variants marked by status (:mod:`conrod.sweep.status`):

* ``ok``: a small filled dot;
* ``warning`` (a crossed limit, contact carrying the load, ...) or ``not_periodic``: a
  hollow circle (doubtful or over a limit: read its warnings);
* ``failed``: a cross; no value, the map has a hole there.

The contours are drawn through the variants that have a value (``ok`` and warned alike: a
warned point is a real result over a limit or doubtful, and the limit contour must pass
through it); nothing is computed here beyond the contour lines matplotlib draws.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from conrod.plotting.sweep_plots import column_label  # noqa: E402

SCALES = {"_m": (1e6, "µm"), "_Pa": (1e-6, "MPa"), "_m3_s": (6e4, "l/min"), "_W": (1.0, "W"),
          "_C": (1.0, "°C")}
"""Column suffix → (factor, engineering unit) of the map's colour scale."""


def engine_map_figure(frame, x: str, y: str, column: str, limit: float | None = None,
                      labels: dict[str, str] | None = None, title: str = "") -> Figure:
    """``column`` over the axes ``x`` and ``y`` as filled contours, the contour of
    ``limit`` (same unit as ``column``) dashed, the variants marked by status."""
    factor, unit = next(((f, u) for suffix, (f, u) in SCALES.items()
                         if column.endswith(suffix) and not column.endswith("_Pa_s")),
                        (1.0, ""))
    grid = frame.pivot_table(index=y, columns=x, values=column, aggfunc="first")
    (x_factor, x_label), (y_factor, y_label) = (_axis(x, labels), _axis(y, labels))
    xs = grid.columns.to_numpy(float) * x_factor
    ys = grid.index.to_numpy(float) * y_factor
    values = np.ma.masked_invalid(grid.to_numpy(float) * factor)
    fig = Figure(figsize=(6.4, 4.6))
    ax = fig.add_subplot()
    if values.count() >= 4 and len(xs) > 1 and len(ys) > 1:
        filled = ax.contourf(xs, ys, values, levels=12, cmap="viridis")
        fig.colorbar(filled, ax=ax, label=f"{title or column} [{unit}]")
        if limit is not None and values.min() < limit * factor < values.max():
            ax.contour(xs, ys, values, levels=[limit * factor], colors="C3",
                       linewidths=1.6, linestyles="--")
            ax.plot([], [], "--", color="C3", label=f"limit {limit * factor:.3g} {unit}")
    _mark_status(ax, frame, x, y, x_factor, y_factor)
    ax.set_xlabel(x_label)
    ax.set_ylabel(y_label)
    ax.legend(fontsize=7, loc="best", framealpha=0.8)
    ax.set_title(title or column, fontsize=10)
    fig.subplots_adjust(bottom=0.14)  # the axis label within the canvas
    return fig


def _axis(column: str, labels: dict[str, str] | None) -> tuple[float, str]:
    """(factor, label) of an axis: a pressure in MPa, other units as the column has them."""
    label = column_label(column, labels)
    if label.endswith("[Pa]"):
        return 1e-6, label[:-4] + "[MPa]"
    return 1.0, label


def _mark_status(ax, frame, x: str, y: str, x_factor: float, y_factor: float) -> None:
    status = frame.get("status")
    kinds = (("ok", dict(marker="o", ms=3, color="k", ls="none"), "ok"),
             ("warning", dict(marker="o", ms=8, mfc="none", color="C1", ls="none", mew=1.5),
              "warning (limit crossed or doubtful)"),
             ("not_periodic", dict(marker="s", ms=8, mfc="none", color="C1", ls="none"),
              "not periodic"),
             ("failed", dict(marker="x", ms=8, color="C3", ls="none", mew=2), "failed"))
    for name, style, label in kinds:
        chosen = frame if status is None and name == "ok" else (
            frame[status == name] if status is not None else frame.iloc[:0])
        if len(chosen):
            ax.plot(chosen[x] * x_factor, chosen[y] * y_factor,
                    label=f"{label} ({len(chosen)})", **style)
