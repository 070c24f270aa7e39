"""The figures of a result set drawn in two processes (:func:`conrod.output.registry.
draw_figures`): the same files byte for byte as in one, every figure written when the
second process fails, a failure raised by the writing process."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app
from conrod.output import registry
from conrod.output.registry import FigureSpec, draw_figures

_register_commands()
EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture
def two_processes(monkeypatch):
    """An idle core: the figures are drawn in two processes."""
    monkeypatch.setenv(registry.FIGURE_SWITCH, "1")
    monkeypatch.setattr(registry, "spare_core", lambda: True)


class _Figure:
    """Writes its text as the file (what ``savefig`` does with a figure)."""

    def __init__(self, text: str):
        self.text = text

    def savefig(self, path, dpi, bbox_inches):
        Path(path).write_text(f"{self.text} drawn by {os.getpid()}")


def _specs(build_of):
    return tuple(FigureSpec(f"f{i}.png", f"figure {i}", "caption", build_of(i))
                 for i in range(5))


def test_loads_figures_in_two_processes_are_the_same_bytes(two_processes, tmp_path,
                                                           monkeypatch):
    outs = {}
    for mode in ("two", "one"):
        if mode == "one":
            monkeypatch.setenv(registry.FIGURE_SWITCH, "0")
        outs[mode] = tmp_path / mode
        result = CliRunner().invoke(app, ["loads", str(EXAMPLES / "passenger_car_diesel_"
                                                         "2000rpm.toml"),
                                          "--out", str(outs[mode])])
        assert result.exit_code == 0, result.output
    pngs = sorted(p.name for p in outs["one"].glob("*.png"))
    assert len(pngs) >= registry.TWO_PROCESSES_FROM
    for name in pngs:
        assert (outs["two"] / name).read_bytes() == (outs["one"] / name).read_bytes()


def test_every_second_figure_is_drawn_by_the_forked_process(two_processes, tmp_path):
    paths = draw_figures(_specs(lambda i: lambda: _Figure(f"figure {i}")), tmp_path)
    assert [p.name for p in paths] == [f"f{i}.png" for i in range(5)]
    drawers = [p.read_text().split(" drawn by ")[1] for p in paths]
    assert drawers[0::2] == [str(os.getpid())] * 3
    assert len(set(drawers[1::2])) == 1 and drawers[1] != str(os.getpid())


def test_what_the_process_fails_to_draw_is_drawn_here(two_processes, tmp_path):
    parent = os.getpid()

    def build_of(i):
        def build():
            if os.getpid() != parent and i == 3:
                raise RuntimeError("a figure failed in the forked process only")
            return _Figure(f"figure {i}")
        return build

    paths = draw_figures(_specs(build_of), tmp_path)
    assert all(p.read_text().startswith(f"figure {i} ") for i, p in enumerate(paths))
    assert paths[3].read_text().endswith(f"drawn by {parent}")


def test_a_failing_figure_raises_in_the_writing_process(two_processes, tmp_path):
    def build_of(i):
        def build():
            if i == 1:
                raise RuntimeError("figure 1 cannot be drawn")
            return _Figure(f"figure {i}")
        return build

    with pytest.raises(RuntimeError, match="figure 1 cannot be drawn"):
        draw_figures(_specs(build_of), tmp_path)


def test_a_stuck_process_is_ended_and_its_figures_drawn_here(two_processes, tmp_path,
                                                             monkeypatch):
    monkeypatch.setattr(registry, "FIGURE_WAIT_MIN", 0.5)
    parent = os.getpid()

    def build_of(i):
        def build():
            if os.getpid() != parent:
                import time

                time.sleep(60)  # stuck
            return _Figure(f"figure {i}")
        return build

    paths = draw_figures(_specs(build_of), tmp_path)
    assert all(p.read_text() == f"figure {i} drawn by {parent}" for i, p in enumerate(paths))
