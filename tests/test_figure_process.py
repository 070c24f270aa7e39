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


def _failing_at(failing: int, figure):
    """build_of for :func:`_specs`: figure ``failing`` raises, the others are ``figure(text)``."""
    def build_of(i):
        def build():
            if i == failing:
                raise RuntimeError(f"figure {i} cannot be drawn")
            return figure(f"figure {i}")
        return build
    return build_of


def test_a_failing_figure_raises_in_the_writing_process(two_processes, tmp_path):
    with pytest.raises(RuntimeError, match="figure 1 cannot be drawn"):
        draw_figures(_specs(_failing_at(1, _Figure)), tmp_path)


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


def _late(results):
    """``results`` as the grid-error estimate leaves them: the summary's late fields set
    (an estimate, one more warning), every other field the same object."""
    import dataclasses

    from conrod.results.grid_error import GridError, GridEstimate

    estimate = GridError(((72, 16), (52, 12), (36, 8)),
                         GridEstimate("h_min", 10.0, (3.0e-6, 2.9e-6, 2.8e-6), 2.0, 1e-7,
                                      (10.0, 10.0, 12.0)),
                         GridEstimate("p_max", 20.0, (9.0e7, 8.8e7, 8.5e7), 1.5, 2e6,
                                      (20.0, 20.0, 20.0)), "a note")
    summary = dataclasses.replace(results.summary, grid_error=estimate,
                                  warnings=(*results.summary.warnings, "a late warning"))
    if hasattr(results, "elastic"):
        return dataclasses.replace(results, elastic=dataclasses.replace(results.elastic,
                                                                        summary=summary))
    return dataclasses.replace(results, summary=summary)


def assert_drawn_ahead_as_written(results, tmp_path):
    """Every figure of ``results`` drawn ahead by a :class:`FigureDraft` is the file the
    writer draws for the results with their late fields set, byte for byte, and the writer
    takes it as drawn; a change elsewhere draws them again."""
    import dataclasses

    from conrod.output.registry import FigureDraft, figures, write_results

    draft = FigureDraft()
    draft.provisional(results)
    draft(lambda: True)  # nothing arrives: every figure drawn ahead
    final = _late(results)
    files = [spec.file for spec in figures(final)]
    assert sorted(draft.drawn_for(final)) == sorted(files) and files
    write_results(final, tmp_path / "fresh")  # drawn by the writer
    for name in files:
        assert draft.drawn[name] == (tmp_path / "fresh" / name).read_bytes(), name
    written = write_results(final, tmp_path / "ahead", draft=draft)
    assert {p.name for p in written} >= set(files)
    for name in files:
        assert (tmp_path / "ahead" / name).read_bytes() == draft.drawn[name]
    summary = getattr(results, "elastic", results).summary
    moved = dataclasses.replace(summary, p_max=summary.p_max * 1.01)  # a drawn field
    other = (dataclasses.replace(results, elastic=dataclasses.replace(results.elastic,
                                                                      summary=moved))
             if hasattr(results, "elastic") else dataclasses.replace(results, summary=moved))
    assert draft.drawn_for(other) == {}


def test_figures_drawn_ahead_are_those_the_writer_draws(tmp_path):
    """A run's figures drawn while it waits (``conrod run``: for its last coarse orbit)
    are the writer's own for the results the grid-error estimate leaves."""
    from conrod import Simulation
    from conrod.cases.case import Case

    case = Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm.toml")
    assert_drawn_ahead_as_written(Simulation(case).run(), tmp_path)


def test_a_draft_draws_only_while_the_run_waits_and_leaves_a_failing_figure_to_the_writer(
        tmp_path):
    from conrod.output.registry import FigureDraft

    class InMemory:
        """Saves its text (what ``savefig`` does with a figure) into a buffer."""

        def __init__(self, text: str):
            self.text = text

        def savefig(self, buffer, format, dpi, bbox_inches):  # noqa: A002 (matplotlib's)
            buffer.write(self.text.encode())

    draft = FigureDraft()
    draft(lambda: True)  # no results yet: nothing to draw
    assert draft.drawn == {}
    specs = _specs(lambda i: lambda: InMemory(f"figure {i}"))
    draft.results, draft._pending = object(), list(specs)
    answers = iter([True, True, False])
    draft(lambda: next(answers))  # two figures, then a result arrived
    assert draft.drawn == {"f0.png": b"figure 0", "f1.png": b"figure 1"}

    draft = FigureDraft()
    draft.results, draft._pending = object(), list(_specs(_failing_at(3, InMemory)))
    draft(lambda: True)
    assert sorted(draft.drawn) == ["f0.png", "f1.png", "f2.png"]  # the rest: the writer's
