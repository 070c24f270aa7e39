"""A command's long-lived objects (the imported modules, then its results) are left out of the
garbage collector's passes while it computes and writes, and are collected again when it
ends (conrod.io.cores.long_lived_objects_frozen): the README job's run process spent 0.45 s
of its 6 s in full passes over them."""

from __future__ import annotations

import gc

import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app
from conrod.io.cores import long_lived_objects_frozen
from conrod.sweep.pool import DONE, LocalPool

EXAMPLE = "examples/passenger_car_diesel_2000rpm.toml"


def _tracked(thing: object) -> bool:
    """True when the collector's passes visit ``thing`` (a frozen object is not listed)."""
    return any(other is thing for other in gc.get_objects())


@pytest.fixture
def unfrozen():
    """Nothing frozen during the test (the suite freezes its modules after collecting them:
    tests/conftest.py); as it was after it."""
    frozen = gc.get_freeze_count() > 0
    gc.unfreeze()
    yield
    if frozen:
        gc.freeze()


def test_the_objects_of_the_block_s_start_are_left_alone_and_collected_after_it(unfrozen):
    before = [[]]
    with long_lived_objects_frozen() as freeze_alive:
        assert not _tracked(before) and gc.get_freeze_count() > 0
        made = [[]]
        assert _tracked(made)  # objects made in the block are collected as usual
        with long_lived_objects_frozen():
            assert not _tracked(made)
        assert not _tracked(before) and not _tracked(made)  # the inner end keeps the outer's
        later = [[]]
        freeze_alive()
        assert not _tracked(later)
    assert _tracked(before) and _tracked(made) and _tracked(later)
    assert gc.get_freeze_count() == 0


def test_objects_frozen_before_the_block_stay_frozen_after_it(unfrozen):
    """The program around it froze objects of its own: the block does not unfreeze them (nor
    what it froze itself: :func:`gc.unfreeze` cannot tell them apart)."""
    theirs = [[]]
    gc.freeze()
    with long_lived_objects_frozen():
        ours = [[]]
        with long_lived_objects_frozen():
            pass
    assert not _tracked(theirs) and not _tracked(ours)


def test_conrod_run_writes_its_results_with_them_left_alone(tmp_path, monkeypatch, repo,
                                                           unfrozen):
    """The results written are frozen while they are written; nothing is frozen after the
    command (an in-process caller's objects are collected as before)."""
    import conrod.output.registry as registry

    seen = []
    write = registry.write_results

    def spy(results, *args, **kwargs):
        seen.append((gc.get_freeze_count() > 0, _tracked(results)))
        return write(results, *args, **kwargs)

    monkeypatch.setattr(registry, "write_results", spy)
    _register_commands()
    result = CliRunner().invoke(app, ["run", str(repo / EXAMPLE), "--out",
                                      str(tmp_path / "out"), "--no-figures"])
    assert result.exit_code == 0, result.output
    assert seen == [(True, False)]
    assert gc.get_freeze_count() == 0


def _frozen_here(_: int) -> bool:
    return gc.get_freeze_count() > 0


def test_a_sweep_worker_computes_its_variants_with_its_start_left_alone(unfrozen):
    with LocalPool(_frozen_here, 1) as pool:
        outcomes = [(kind, value) for _, kind, value in pool.imap([(i,) for i in range(2)])]
    assert outcomes == [(DONE, True), (DONE, True)]
    assert gc.get_freeze_count() == 0  # the sweep's own process as it was
