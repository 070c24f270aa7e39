"""The ``conrod`` command. Each sub-command lives in its own module and registers itself.

Exit codes (:data:`EXIT_CODES`; the same table is in ``conrod --help`` and
``docs/reliability.md``): 0 success; 1 a defect in conrod; 2 bad input (:class:`CaseError`,
including an unusable ``--out``; nothing written); 3 not converged (a solver failed or a
result is not physical: nothing written; or the orbit is not periodic: results written
for diagnosis, ``summary.json["converged"]`` false); 4 finished with warnings (results
written; ``--accept-warnings`` makes it 0); 5 the results could not be written (disk full,
I/O error); 130 interrupted (Ctrl-C). Errors print one message on stderr, never a
traceback; results are written as a whole or not at all (:mod:`conrod.io.result_folder`).
"""

from __future__ import annotations

import contextlib
import functools
import gc
import importlib
import inspect
import os
import sys
import warnings
from collections.abc import Callable, Iterator, Sequence
from typing import Annotated, Any, TypeVar

from conrod.cli.options import optional_fields_stride
from conrod.errors import CaseError, ConvergenceError
from conrod.io.interrupts import (
    EXIT_INTERRUPTED,
    INTERRUPTED_MESSAGE,
    deferred_interrupts,
    interrupts_stop_at_once,
)

with interrupts_stop_at_once():  # Ctrl-C while the command line loads: one line, exit 130
    import typer

EXIT_OK, EXIT_DEFECT, EXIT_BAD_INPUT, EXIT_NOT_CONVERGED = 0, 1, 2, 3
EXIT_WARNINGS, EXIT_WRITE_FAILED = 4, 5
EXIT_CODES = {
    EXIT_OK: "success",
    EXIT_DEFECT: "a defect in conrod (CONROD_TRACEBACK=1 shows where)",
    EXIT_BAD_INPUT: "bad input (case file, option, --out); nothing written",
    EXIT_NOT_CONVERGED: "not converged: a solver failed or a result is not physical "
                        "(nothing written), or the orbit is not periodic (results written, "
                        "marked); --accept-warnings turns a written 3 or 4 into 0",
    EXIT_WARNINGS: "finished with warnings (results written)",
    EXIT_WRITE_FAILED: "the results could not be written (disk full, I/O error)",
    EXIT_INTERRUPTED: "interrupted (Ctrl-C); nothing written",
}
"""Exit code → meaning, shown by ``conrod --help``."""

app = typer.Typer(
    name="conrod",
    help="Connecting-rod bearing dynamics: loads, oil film, orbit, contact, wear, impacts.",
    epilog="Exit codes: " + "; ".join(f"{code} {text}" for code, text in EXIT_CODES.items()),
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    # plain click help: units such as [rpm] stay as written, the text takes the terminal's
    # width (up to 100 columns), and no help page imports rich or markdown-it (timings:
    # benchmarks/startup_benchmarks.md)
    rich_markup_mode=None,
    context_settings={"max_content_width": 100},
)

COMMAND_MODULES = (
    "loads", "steady", "run", "mechanism", "housing", "stress", "sweep", "report", "plot_sweep",
)
"""Modules in :mod:`conrod.cli` that each define ``register(app)``."""

F = TypeVar("F", bound=Callable[..., Any])


def _print_version(value: bool) -> None:
    if value:
        from conrod._version import __version__

        typer.echo(f"conrod {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: Annotated[bool, typer.Option(
        "--version", callback=_print_version, is_eager=True,
        help="Print the conrod version and exit.")] = False,
) -> None:
    """Connecting-rod bearing dynamics (keeps sub-commands a group even if only one exists)."""


def finish(warnings: Sequence[str], accept_warnings: bool, converged: bool = True) -> None:
    """End a command whose results are written: print the warnings on stderr and exit
    :data:`EXIT_NOT_CONVERGED` when not converged (non-periodic orbit), :data:`EXIT_WARNINGS`
    when there are warnings, else return (exit 0); ``accept_warnings``: always return."""
    for warning in warnings:
        typer.echo(f"warning: {warning}", err=True)
    if accept_warnings:
        return
    if not converged:
        typer.echo("not converged: results written for diagnosis only (exit 3; "
                   "--accept-warnings to exit 0)", err=True)
        raise typer.Exit(code=EXIT_NOT_CONVERGED)
    if warnings:
        typer.echo(f"finished with {len(warnings)} warning(s) (exit 4; --accept-warnings "
                   "to exit 0)", err=True)
        raise typer.Exit(code=EXIT_WARNINGS)


@contextlib.contextmanager
def printing_after_results(out: str | os.PathLike[str]) -> Iterator[None]:
    """Print on stdout what a command says once its results are written to ``out``.

    A standard output that fails then (the reader of a pipe stopped reading, a full disk)
    is no failed result: the exit code stays that of the results. A closed pipe is
    ignored (its reader wanted no more); another failure is one warning line on stderr.
    """
    try:
        yield
        sys.stdout.flush()
    except OSError as error:
        discard_stdout()
        if not isinstance(error, BrokenPipeError):
            reason = error.strerror or str(error) or type(error).__name__
            typer.echo(f"warning: standard output could not be written ({reason}); the "
                       f"results are complete in {out}", err=True)


def discard_stdout() -> None:
    """Send what is left of stdout to the null device, so that no later flush (at the
    latest when the interpreter exits) fails again on a broken stdout."""
    with contextlib.suppress(OSError, ValueError):
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, sys.stdout.fileno())
        os.close(null)


ACCEPT_WARNINGS_HELP = ("Exit 0 although the written results carry warnings (default: exit 4) "
                        "or the orbit is not periodic (default: exit 3).")


def exits_cleanly(command: F) -> F:
    """Decorator: turn conrod's own errors into one stderr line and an exit code."""

    @functools.wraps(command)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            with deferred_interrupts():
                return command(*args, **kwargs)
        except CaseError as error:
            typer.echo(f"error: {error}", err=True)
            raise typer.Exit(code=EXIT_BAD_INPUT) from None
        except ConvergenceError as error:
            typer.echo(f"not converged: {error}", err=True)
            raise typer.Exit(code=EXIT_NOT_CONVERGED) from None
        except KeyboardInterrupt:
            typer.echo(INTERRUPTED_MESSAGE, err=True)
            raise typer.Exit(code=EXIT_INTERRUPTED) from None
        except OSError as error:
            where = f": {error.filename}" if error.filename else ""
            reason = error.strerror or str(error) or type(error).__name__
            typer.echo(f"error: cannot write the results ({reason}{where}); the output "
                       "folder is unchanged", err=True)
            raise typer.Exit(code=EXIT_WRITE_FAILED) from None
        except (typer.Exit, typer.Abort):
            raise
        except Exception as error:  # a bug: one line, the traceback only on request
            if os.environ.get("CONROD_TRACEBACK"):
                raise
            typer.echo(f"internal error: {type(error).__name__}: {error} (a defect in conrod; "
                       "set CONROD_TRACEBACK=1 to see where)", err=True)
            raise typer.Exit(code=EXIT_DEFECT) from None

    return wrapper  # type: ignore[return-value]


_registered: list[str] = []
"""The command modules already registered on :data:`app` (in order)."""


def _register_commands() -> None:
    """Register every command module's commands on :data:`app`, each module once: a second
    call adds nothing (typer keeps every registration and builds all of them each time the
    app runs: a test invoking the app 40 times, registering before each, built 7,380
    commands, 42 of its 98 s under the profiler)."""
    for name in COMMAND_MODULES:
        if name not in _registered:
            importlib.import_module(f"conrod.cli.{name}_command").register(app)
            _registered.append(name)
    for info in app.registered_commands:  # `conrod --help` lists each whole, wrapped
        if info.short_help is None:
            info.short_help = summary(info.help or inspect.getdoc(info.callback) or "")


def summary(text: str) -> str:
    """The first paragraph of a command's help on one line: what ``conrod --help`` lists
    for it (click would cut it at the terminal's width with "...")."""
    return " ".join(text.strip().split("\n\n")[0].split())


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
    with interrupts_stop_at_once():  # a command defers Ctrl-C once it computes
        encoding_safe_streams()
        warnings.formatwarning = _one_line_warning
        _register_commands()
        sys.argv[1:] = optional_fields_stride(sys.argv[1:])
        code = exit_code(app)
        gc.freeze()  # the process ends: its last collection need not walk what is alive
        sys.exit(code)


def exit_code(command: Callable[..., Any]) -> int:
    """Run the typer ``command`` on ``sys.argv`` and return its exit code; a mistake on the
    command line (an unknown option or command, a value of the wrong type or choice, a
    missing argument) is one line on stderr, ``error: <click's message> (conrod ... --help)``,
    exit 2, instead of click's usage, hint and message; a missing command still prints the
    help."""
    try:
        # the exit code, or a command's None; pages and messages say "conrod" also where
        # Python runs it as ``python -c``
        outcome = command(standalone_mode=False, prog_name=app.info.name)
    except CLICK_ERROR as error:
        if type(error).__name__ == "NoArgsIsHelpError":  # `conrod` alone: the help
            error.show()
        else:
            context = getattr(error, "ctx", None)
            where = context.command_path if context is not None else _command_path()
            typer.echo(f"error: {' '.join(error.format_message().split())} "
                       f"(see {where} --help)", err=True)
        return int(error.exit_code)
    except typer.Abort:
        typer.echo("Aborted!", err=True)
        return 1
    return outcome if isinstance(outcome, int) else 0


def _command_path() -> str:
    """``conrod`` and the command that the first word of ``sys.argv`` not an option names
    (``conrod`` alone where it names none), for a mistake click reports without its context
    (an option given without its value)."""
    name = next((arg for arg in sys.argv[1:] if not arg.startswith("-")), None)
    commands = {info.name for info in app.registered_commands}
    return f"{app.info.name} {name}" if name in commands else str(app.info.name)


CLICK_ERROR = next(kind for kind in typer.BadParameter.__mro__
                   if kind.__name__ == "ClickException")
"""click's base of the errors it reports to the user (typer's own copy of click, or click)."""
