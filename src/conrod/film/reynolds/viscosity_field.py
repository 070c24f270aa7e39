"""A viscosity field μ(θ, z) [Pa s] in the Reynolds film (a thermal film).

With a viscosity varying over the film the Reynolds equation multiplied by 12 μ_r (μ_r the
state's scalar ``FilmState.viscosity``, the reference of the source terms) reads

.. math:: \\nabla\\cdot\\Big(h^3 \\frac{μ_r}{μ} \\nabla p\\Big) = 12 μ_r \\Big(\\frac U2
          \\partial_x h + \\partial_t h\\Big).

The field enters the flow conductances only, through the *conductance thickness*
h_μ = h (μ_r/μ)^{1/3}: every face conductance of :mod:`conrod.film.reynolds.kernel` and of
the multigrid (its coarse levels subsample h_μ like h) is the cube of the face average of
h_μ, h_μ,e³ = h_e³ μ_r/μ_e to second order in the grid spacing, while the source keeps the
film thickness h. A field equal to μ_r everywhere gives h_μ = h × 1.0 exactly: the scalar
answer bit for bit. The shear stress takes the local μ (:mod:`conrod.film.characteristics`).
"""

from __future__ import annotations

import numpy as np

from conrod.film.base import check_viscosity_field
from conrod.film.reynolds.kernel import mirror_equal
from conrod.film.reynolds.multigrid_operators import conductances


def state_field(state, carried: np.ndarray | None, shape: tuple[int, int]) -> np.ndarray | None:
    """The viscosity field of ``state`` [Pa s]: its own, else the film's ``carried`` one;
    :class:`~conrod.errors.CaseError` unless it has the grid's ``shape``; None: scalar."""
    field = state.viscosity_field if state.viscosity_field is not None else carried
    if field is not None and np.shape(field) != tuple(shape):
        check_viscosity_field(field, shape)
    return field


def conduction_thickness(h: np.ndarray, reference: float, field: np.ndarray) -> np.ndarray:
    """h_μ = h (μ_r/μ)^{1/3} [m] (module docstring), μ_r = ``reference`` [Pa s]."""
    return h * np.cbrt(reference / field)


def field_conductances(conduction: np.ndarray, grid) -> tuple[np.ndarray, np.ndarray]:
    """Face conductances a_E (n_θ, n_z + 1), a_N (n_θ, n_z) [m⁴] of the conductance
    thickness ``conduction`` [m] on ``grid`` (the shapes of
    :func:`conrod.film.reynolds.kernel.assemble_coefficients`)."""
    a_east, a_north = conductances(conduction, grid.radius, grid.d_theta, grid.d_z)
    return a_east, np.ascontiguousarray(a_north[:, :-1])


def mirror_symmetric(field: np.ndarray | None) -> bool:
    """True when ``field`` is None or equal to its mirror image about the mid-plane [-]
    (compiled: ~1 µs instead of numpy's ~6 µs for a comparison array and its ``all``, asked
    up to eight times per film solve and response of an elastic step)."""
    return field is None or mirror_equal(field)


def checked_field(field, shape: tuple[int, int]) -> np.ndarray | None:
    """``field`` [Pa s] as a read-only float array of ``shape``, checked
    (:func:`~conrod.film.base.check_viscosity_field`); None stays None."""
    if field is None:
        return None
    check_viscosity_field(field, shape)
    array = np.array(field, dtype=float)
    array.setflags(write=False)
    return array
