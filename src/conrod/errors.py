"""Exception types of conrod.

Every error carries *what* failed, *where* and *by how much*, so that the CLI can
print one clear line and exit with code 2 (bad input) or 3 (no convergence).
"""

from __future__ import annotations


class ConrodError(Exception):
    """Base class of every error raised on purpose by conrod."""


class CaseError(ConrodError, ValueError):
    """Bad input: a case-file field, a data file or a command-line option.

    The message names the field, the offending value, the allowed range and the unit.
    """


class ConvergenceError(ConrodError, RuntimeError):
    """A solver did not converge.

    Parameters
    ----------
    message : str
        What did not converge.
    where : str
        Where it happened (e.g. ``"crank angle 372.0 deg"``).
    residual : float
        How far from convergence it stopped (in the solver's own measure).
    """

    def __init__(self, message: str, *, where: str = "", residual: float = float("nan")):
        self.where = where
        self.residual = residual
        detail = message
        if where:
            detail += f" at {where}"
        if residual == residual:  # not NaN
            detail += f" (residual {residual:.3g})"
        super().__init__(detail)


class FilmThicknessError(ConvergenceError):
    """The journal reached the shell: the film thickness is zero or negative somewhere.

    Inside an orbit this is a state the solver stepped into (a step too long for the
    contact model, or a film that cannot carry the load), not bad input: the CLI exits
    with code 3. Inputs that are themselves out of range (an eccentricity ratio ≥ 1 given
    to the steady calculator) are refused earlier as :class:`CaseError`.
    """


class NonFiniteResultError(ConvergenceError, ValueError):
    """A result holds NaN or infinity where only finite numbers may be written.

    A :class:`ConvergenceError` (the CLI exits with code 3) and a ``ValueError`` (what
    ``json.dumps(allow_nan=False)`` raises for the same fault).
    """


class CacheWarning(UserWarning):
    """An on-disk cache was corrupt (failed its checksum) and is being rebuilt."""
