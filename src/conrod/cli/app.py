"""The ``conrod`` command. Each sub-command lives in its own module and registers itself.

Exit codes: 0 success, 2 bad input (:class:`CaseError`, including an unusable ``--out``),
3 solver did not converge or a result is not finite (:class:`ConvergenceError`), 4 the
results could not be written (disk full, I/O error), 130 interrupted (Ctrl-C). Errors print
one message on stderr, never a traceback; results are written as a whole or not at all
(:mod:`conrod.io.result_folder`).
"""

from __future__ import annotations

import functools
import importlib
import os
import sys
import warnings
from collections.abc import Callable
from typing import Any, TypeVar

import typer

from conrod.errors import CaseError, ConvergenceError
from conrod.io.interrupts import EXIT_INTERRUPTED, deferred_interrupts

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
            with deferred_interrupts():
                return command(*args, **kwargs)
        except CaseError as error:
            typer.echo(f"error: {error}", err=True)
            raise typer.Exit(code=2) from None
        except ConvergenceError as error:
            typer.echo(f"not converged: {error}", err=True)
            raise typer.Exit(code=3) from None
        except KeyboardInterrupt:
            typer.echo("interrupted (nothing written)", err=True)
            raise typer.Exit(code=EXIT_INTERRUPTED) from None
        except OSError as error:
            where = f": {error.filename}" if error.filename else ""
            reason = error.strerror or str(error) or type(error).__name__
            typer.echo(f"error: cannot write the results ({reason}{where}); the output "
                       "folder is unchanged", err=True)
            raise typer.Exit(code=4) from None
        except (typer.Exit, typer.Abort):
            raise
        except Exception as error:  # a bug: one line, the traceback only on request
            if os.environ.get("CONROD_TRACEBACK"):
                raise
            typer.echo(f"internal error: {type(error).__name__}: {error} (a defect in conrod; "
                       "set CONROD_TRACEBACK=1 to see where)", err=True)
            raise typer.Exit(code=1) from None

    return wrapper  # type: ignore[return-value]


def _register_commands() -> None:
    for name in COMMAND_MODULES:
        importlib.import_module(f"conrod.cli.{name}_command").register(app)


def encoding_safe_streams() -> None:
    """Let stdout/stderr print '→', 'µ', 'Δ' on any terminal: characters the terminal's
    encoding lacks are replaced instead of raising UnicodeEncodeError."""
    for stream in (sys.stdout, sys.stderr):
        reconfigure = getattr(stream, "reconfigure", None)
        if reconfigure is not None:
            reconfigure(errors="replace")


def _one_line_warning(message: Any, category: Any, *args: Any, **kwargs: Any) -> str:
    return f"warning: {message}\n"


def main() -> None:
    """Entry point of the ``conrod`` console script."""
    encoding_safe_streams()
    warnings.formatwarning = _one_line_warning
    _register_commands()
    app()
