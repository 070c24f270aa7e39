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
from conrod.simulation import side_runs

_register_commands()
EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture
def two_processes(monkeypatch):
    """An idle core: the figures are drawn in two processes."""
    monkeypatch.setenv(registry.FIGURE_SWITCH, "1")
    monkeypatch.setattr(registry, "spare_core", lambda: True)


class _Figure:
    """Its file is its text and the process that drew it."""

    def __init__(self, text: str):
        self.text = text

    def file(self) -> bytes:
        return f"{self.text} drawn by {os.getpid()}".encode()


@pytest.fixture(autouse=True)
def text_figures(monkeypatch):
    """The registry writes the file of a :class:`_Figure` (or :class:`_Either`) as it
    would write a matplotlib Figure's PNG; a real Figure is drawn as ever."""
    drawn = registry._figure_bytes

    def figure_bytes(figure, file_format):
        return figure.file() if hasattr(figure, "file") else drawn(figure, file_format)

    monkeypatch.setattr(registry, "_figure_bytes", figure_bytes)


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

    draft = FigureDraft(side_runs.fork)
    draft.provisional(results)
    _all_begun(draft)  # every figure drawn ahead, by the process
    final = _late(results)
    files = [spec.file for spec in figures(final)]
    assert sorted(draft.drawn_for(final)) == sorted(files) and files
    assert draft.drawer is None  # collected, the process ended
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


def _all_begun(draft, count=None):
    """Wait until the draft's process has begun every figure (the first ``count``)."""
    import time

    while side_runs.OPEN in draft.drawer.claims[:count]:
        time.sleep(0.01)


class _Either:
    """Its file is its text."""

    def __init__(self, text: str):
        self.text = text

    def file(self) -> bytes:
        return self.text.encode()


def test_a_draft_s_process_draws_and_leaves_what_it_does_not_deliver_to_the_writer(
        tmp_path, monkeypatch):
    """The process draws the figures in order, the run's process those it has not begun
    while it waits; one that fails there, or that it does not deliver within the patience,
    is drawn by the writer (none lost)."""
    from conrod.output.registry import FigureDraft

    parent = os.getpid()

    def build_of(i):
        def build():
            if os.getpid() != parent and i == 1:
                raise RuntimeError("figure 1 fails in the forked process only")
            if os.getpid() != parent and i == 3:
                import time

                time.sleep(60)  # stuck there
            return _Either(f"figure {i} drawn by {os.getpid()}")
        return build

    specs = _specs(build_of)
    monkeypatch.setattr(registry, "_figure_specs", lambda results: specs)
    monkeypatch.setattr(registry, "FIGURE_WAIT_MIN", 0.5)
    results = object()
    draft = FigureDraft(side_runs.fork)
    draft.provisional(results)
    _all_begun(draft, 4)  # f0–f3 begun there, where it sticks at f3
    drawn = draft.drawn_for(results)
    assert sorted(drawn) == ["f0.png", "f2.png", "f4.png"]  # f4 drawn here meanwhile
    assert [drawn[f"f{i}.png"].endswith(str(parent).encode()) for i in (0, 2, 4)] == [
        False, False, True]
    assert draft.drawn_for(object()) == {}  # other results: nothing drawn ahead for them
    paths = draw_figures(specs, tmp_path, drawn)
    texts = [p.read_text() for p in paths]
    assert all(text.startswith(f"figure {i} drawn by ") for i, text in enumerate(texts))
    assert [text.endswith(str(parent)) for text in texts] == [False, True, False, True, True]


def test_a_draft_for_new_results_drops_the_old_ones_and_ends_with_close(monkeypatch):
    from conrod.output.registry import FigureDraft

    specs = _specs(lambda i: lambda: _Either(f"figure {i}"))
    monkeypatch.setattr(registry, "_figure_specs", lambda results: specs)
    first, second = object(), object()
    draft = FigureDraft(side_runs.fork)
    draft.provisional(first)
    process = draft.drawer.process
    draft.provisional(second)  # the first process ended, a new one draws
    assert not process.is_alive() and draft.drawer.process is not process
    assert draft.drawn_for(first) == {}
    draft.close()
    assert draft.drawer is None and draft.drawn_for(second) == {}
