"""Oil-supply features rasterised onto the film grid as Dirichlet regions.

Grooves and feed holes of :class:`~conrod.film.base.BearingGeometry` hold the supply
pressure; the bearing edges z = ±L/2 hold ambient (gauge 0) pressure. A feature
smaller than the grid spacing still marks its nearest node, so it is never lost.

Oil holes in the journal (:class:`~conrod.film.base.JournalHole`) turn with it: at each
instant :func:`instant_supply` adds their nodes, at the shell angle given by
``FilmState.journal_feed``, to the fixed shell features — a mask update, the film operator
is assembled as for a fixed hole. A groove ``fed_by_journal_holes`` takes the pressure of
a journal hole while one opens into it.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numba as nb
import numpy as np

from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FeedHole, Groove, JournalFeed
from conrod.film.characteristics import FilmGrid


def _angular_distance(theta: np.ndarray, angle: float) -> np.ndarray:
    """Shortest signed angle θ − angle wrapped into [−π, π) [rad]."""
    return (theta - angle + math.pi) % (2.0 * math.pi) - math.pi


def groove_mask(groove: Groove, grid: FilmGrid) -> np.ndarray:
    """Nodes covered by a full or partial circumferential groove, (n_θ, n_z + 1) bool."""
    theta, z = grid.theta, grid.z
    if groove.extent >= 2.0 * math.pi - 0.5 * grid.d_theta:
        in_arc = np.ones(grid.n_theta, dtype=bool)
    else:
        offset = (theta - groove.start_angle) % (2.0 * math.pi)
        in_arc = offset <= groove.extent + 1e-12
        if not in_arc.any():
            in_arc[int(np.argmin(np.abs(_angular_distance(theta, groove.start_angle))))] = True
    axial_gap = np.abs(z - groove.axial_position)
    in_band = axial_gap <= 0.5 * groove.width + 1e-12 * grid.width
    if not in_band.any():
        in_band[int(np.argmin(axial_gap))] = True
    return in_arc[:, None] & in_band[None, :]


def hole_mask(hole: FeedHole, grid: FilmGrid) -> np.ndarray:
    """Nodes inside a circular feed hole (distance on the unrolled shell), bool."""
    arc = grid.radius * _angular_distance(grid.theta, hole.angle)[:, None]
    axial = (grid.z - hole.axial_position)[None, :]
    distance = np.hypot(arc, axial)
    inside = distance <= 0.5 * hole.diameter
    if not inside.any():
        inside[np.unravel_index(int(np.argmin(distance)), distance.shape)] = True
    return inside


def supply_mask(geometry: BearingGeometry, grid: FilmGrid) -> np.ndarray:
    """Union of all groove and hole regions (edge rows excluded), bool (n_θ, n_z + 1)."""
    mask = np.zeros((grid.n_theta, grid.n_z + 1), dtype=bool)
    for groove in geometry.grooves:
        mask |= groove_mask(groove, grid)
    for hole in geometry.feed_holes:
        mask |= hole_mask(hole, grid)
    mask[:, [0, -1]] = False
    return mask


def edge_mask(grid: FilmGrid) -> np.ndarray:
    """The two bearing-edge rows z = ±L/2 (ambient pressure), bool (n_θ, n_z + 1)."""
    mask = np.zeros((grid.n_theta, grid.n_z + 1), dtype=bool)
    mask[:, [0, -1]] = True
    return mask


def nearest_theta_index(angle: float, grid: FilmGrid) -> int:
    """Index of the θ node closest to ``angle`` [rad]."""
    return int(round((angle % (2.0 * math.pi)) / grid.d_theta)) % grid.n_theta


def journal_hole_masks(geometry: BearingGeometry, grid: FilmGrid,
                       feed: JournalFeed) -> list[np.ndarray]:
    """Nodes of each journal hole at the shell angle θ = hole angle + journal angle (edge
    rows excluded), one bool (n_θ, n_z + 1) per hole."""
    masks = []
    theta, z = grid.theta, grid.z
    for hole in geometry.journal_holes:
        angle = hole.angle + feed.journal_angle
        mask = np.zeros((grid.n_theta, grid.n_z + 1), dtype=bool)
        if not _disc_nodes(theta, z, grid.radius, angle, 0.5 * hole.diameter,
                           hole.axial_position, mask):  # no node inside: the nearest
            mask = hole_mask(FeedHole(angle, hole.diameter, hole.axial_position), grid)
        mask[:, [0, -1]] = False
        if hole.axial_position == 0.0:  # mirror-symmetric to the last bit of z
            mask |= mask[:, ::-1]
        masks.append(mask)
    return masks


@nb.njit(cache=True)
def _disc_nodes(theta, z, radius, angle, half, axial, mask):  # pragma: no cover (compiled)
    """Mark in ``mask`` the nodes of :func:`hole_mask` (the same arithmetic, so the same
    nodes) of a hole at ``angle`` [rad], radius ``half`` [m], at ``axial`` [m]; True when
    any node lies inside."""
    found = False
    for i in range(theta.size):
        arc = radius * ((theta[i] - angle + math.pi) % (2.0 * math.pi) - math.pi)
        if abs(arc) > half:
            continue
        for j in range(z.size):
            if math.hypot(arc, z[j] - axial) <= half:
                mask[i, j] = True
                found = True
    return found


def checked_feed(geometry: BearingGeometry, feed: JournalFeed | None) -> JournalFeed:
    """``feed`` when it gives one pressure per journal hole; else CaseError."""
    holes = len(geometry.journal_holes)
    if feed is None:
        raise CaseError(f"FilmState journal_feed = None: the bearing has {holes} journal "
                        "hole(s), whose position and pressure change with the crank angle "
                        "(allowed: a JournalFeed; the orbit passes one at each instant)")
    if len(feed.pressures) != holes:
        raise CaseError(f"FilmState journal_feed pressures = {feed.pressures!r}: out of range "
                        f"(allowed: {holes} value(s) [Pa], one per journal hole)")
    return feed


def instant_supply(geometry: BearingGeometry, grid: FilmGrid, feed: JournalFeed | None,
                   fixed: np.ndarray, values: np.ndarray,
                   solved: Callable[[float], float] = float,
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """(Dirichlet mask, values, nodes fed by the journal holes) at one instant.

    ``fixed``, ``values``: the shell's fixed features and edges (not modified); the journal
    holes add their nodes at their pressure, ``solved(p)`` [Pa] the solved variable of a
    pressure (reduced pressure of a piezoviscous film); a groove ``fed_by_journal_holes``
    that a hole opens into takes the highest such hole pressure. Without journal holes the
    inputs themselves and None (today's problem, bit for bit).
    """
    if not geometry.journal_holes:
        return fixed, values, None
    feed = checked_feed(geometry, feed)
    fixed, values = fixed.copy(), values.copy()
    fed = np.zeros(fixed.shape, dtype=bool)
    holes = journal_hole_masks(geometry, grid, feed)
    order = np.argsort(feed.pressures)  # the highest pressure wins where holes overlap
    for k in order:
        mask, value = holes[k], solved(float(feed.pressures[k]))
        for groove in geometry.grooves:
            if groove.fed_by_journal_holes:
                region = groove_mask(groove, grid)
                region[:, [0, -1]] = False
                if (region & mask).any():
                    values[region] = value
                    fed |= region
        values[mask] = value
        fed |= mask
    fixed |= fed
    return fixed, values, fed


def journal_holes_symmetric(geometry: BearingGeometry) -> bool:
    """True when every journal hole's nodes are mirror images about the mid-plane at any
    angle (:func:`journal_hole_masks`): all holes centred at mid-width [-]."""
    return all(hole.axial_position == 0.0 for hole in geometry.journal_holes)
