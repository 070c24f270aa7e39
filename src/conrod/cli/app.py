"""The ``conrod`` command. Each sub-command lives in its own module and registers itself.

Exit codes: 0 success, 2 bad input (:class:`CaseError`), 3 solver did not converge
(:class:`ConvergenceError`). Errors print one message on stderr, never a traceback.
"""

from __future__ import annotations

import functools
import importlib
from collections.abc import Callable
from typing import Any, TypeVar

import typer

from conrod.errors import CaseError, ConvergenceError

app = typer.Typer(
    name="conrod",
    help="Connecting-rod bearing dynamics: loads, oil film, orbit, contact, wear, impacts.",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
)

COMMAND_MODULES = (
    "loads", "steady", "run", "mechanism", "housing", "stress", "sweep", "report", "plot_sweep",
)
"""Modules in :mod:`conrod.cli` that each define ``register(app)``."""

F = TypeVar("F", bound=Callable[..., Any])


@app.callback()
def _root() -> None:
    """Connecting-rod bearing dynamics (keeps sub-commands a group even if only one exists)."""


def exits_cleanly(command: F) -> F:
    """Decorator: turn conrod's own errors into one stderr line and an exit code."""

    @functools.wraps(command)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return command(*args, **kwargs)
        except CaseError as error:
            typer.echo(f"error: {error}", err=True)
            raise typer.Exit(code=2) from None
        except ConvergenceError as error:
            typer.echo(f"not converged: {error}", err=True)
            raise typer.Exit(code=3) from None

    return wrapper  # type: ignore[return-value]


def _register_commands() -> None:
    for name in COMMAND_MODULES:
        importlib.import_module(f"conrod.cli.{name}_command").register(app)


def main() -> None:
    """Entry point of the ``conrod`` console script."""
    _register_commands()
    app()
