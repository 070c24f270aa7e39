"""The compiled bookkeeping of the elastic implicit step does what the NumPy it replaced
did, bit for bit: the mirror check, the largest magnitude, the row directions and row-load
response of the film's response, and a film state moved without a new check."""

import dataclasses

import numpy as np
import pytest
from scipy.sparse import coo_matrix

from conrod.film.base import FilmState
from conrod.film.rated_state import RatedFilmState, moved, rated
from conrod.film.reynolds.kernel import mirror_equal
from conrod.film.reynolds.response_kernel import row_directions, row_load_response
from conrod.numerics.newton import _largest


def test_mirror_check_is_numpys_comparison():
    rng = np.random.default_rng(1)
    for shape in ((1, 1), (4, 2), (7, 9), (36, 17), (12, 8)):
        field = rng.integers(0, 2, shape).astype(float)
        symmetric = 0.5 * (field + field[:, ::-1])
        for candidate in (field, symmetric, symmetric > 0.4):
            assert mirror_equal(candidate) == bool((candidate == candidate[:, ::-1]).all())
        assert mirror_equal(symmetric)
    with_nan = np.ones((3, 5))
    with_nan[1, 2] = np.nan  # on the mid-plane: NaN equals nothing, itself neither
    assert not mirror_equal(with_nan)


def test_largest_magnitude_is_numpys_including_nan():
    rng = np.random.default_rng(2)
    for size in (1, 2, 3, 74, 146):
        vector = rng.standard_normal(size) * 10.0 ** rng.uniform(-9, 3, size)
        assert _largest(vector) == np.abs(vector).max()
    assert _largest(np.array([-0.0, 0.0])) == 0.0
    assert np.isnan(_largest(np.array([1.0, np.nan, 5.0])))
    assert np.isnan(_largest(np.array([np.nan, 1.0])))


def _row_directions_before(rows, index):
    """The array formulation the compiled row directions replaced."""
    n_theta = rows.shape[0]
    right = np.zeros((n_theta, int(index.max()) + 1))
    bore = np.arange(n_theta)
    for shift in range(3):
        place = index[(bore - 1 + shift) % n_theta]
        keep = place >= 0
        right[np.broadcast_to(bore[:, None], place.shape)[keep], place[keep]] = \
            -rows[:, shift, :][keep]
    return right


@pytest.mark.parametrize("n_theta, n_nodes", [(3, 5), (24, 9), (72, 17)])
def test_row_directions_are_the_array_formulation(n_theta, n_nodes):
    rng = np.random.default_rng(n_theta)
    active = rng.random((n_theta, n_nodes)) < 0.6
    index = -np.ones((n_theta, n_nodes), dtype=np.int64)
    index[active] = np.arange(active.sum())
    rows = rng.standard_normal((n_theta, 3, n_nodes))
    assert np.array_equal(row_directions(rows, index), _row_directions_before(rows, index))


def _scipy_rows(solved, weights, node_rows, columns, n_rows):
    """SciPy's sparse rows times the directions, as the response computed them before."""
    matrix = coo_matrix((weights, (node_rows, columns)), shape=(n_rows, solved.shape[1]))
    return np.asarray(matrix.tocsr() @ solved.T)


@pytest.mark.parametrize("mirrored", [False, True])
def test_row_load_response_is_scipys_sparse_product(mirrored):
    rng = np.random.default_rng(5 + mirrored)
    checked = 0
    for _ in range(60):
        n_theta, n_nodes = int(rng.integers(3, 40)), int(rng.choice([5, 9, 17]))
        active = rng.random((n_theta, n_nodes)) < 0.7
        if mirrored:  # an active set alike in both halves, each node on its image's column
            active = active | active[:, ::-1]
        nodes = np.nonzero(active)
        if mirrored:
            keep = np.nonzero(nodes[1] <= (n_nodes - 1) // 2)[0]
            place = -np.ones(active.shape, dtype=np.int64)
            place[nodes[0][keep], nodes[1][keep]] = np.arange(keep.size)
            columns = place[nodes[0], np.minimum(nodes[1], n_nodes - 1 - nodes[1])]
            n_columns = keep.size
        else:
            columns, n_columns = np.arange(nodes[0].size), nodes[0].size
        weights = rng.standard_normal(nodes[0].size) * 10.0 ** rng.uniform(-6, -2)
        solved = rng.standard_normal((int(rng.integers(1, 80)), n_columns)) * 1e7
        assert np.array_equal(row_load_response(solved, weights, nodes[0], columns, n_theta),
                              _scipy_rows(solved, weights, nodes[0], columns, n_theta))
        checked += 1
    assert checked == 60


def test_moved_state_equals_a_new_state_and_refuses_checked_fields():
    state = FilmState(eccentricity_x=1e-5, eccentricity_y=-2e-5, velocity_x=0.1,
                      journal_speed=200.0, shell_speed=-20.0, viscosity=0.012)
    there = moved(state, eccentricity_x=3e-5, velocity_y=-0.2)
    assert there == dataclasses.replace(state, eccentricity_x=3e-5, velocity_y=-0.2)
    assert type(there) is FilmState and state.eccentricity_x == 1e-5  # a new state
    field, rate = np.ones((4, 3)), np.zeros((4, 3))
    both = rated(state, field, rate)
    assert type(both) is RatedFilmState and both.deformation is field
    assert both.deformation_rate is rate and both.viscosity == 0.012
    assert rated(state, field, None) == dataclasses.replace(state, deformation=field)
    with pytest.raises(ValueError, match="viscosity"):
        moved(state, viscosity=-1.0)  # a checked field: a new state must be made
    with pytest.raises(ValueError, match="deformation_rate"):
        moved(state, RatedFilmState, deformation=field)  # the rate missing


def test_length_of_two_components_is_numpys_hypot():
    from conrod.numerics.newton import length

    rng = np.random.default_rng(3)
    pairs = rng.standard_normal((20000, 2)) * 10.0 ** rng.uniform(-12, 6, (20000, 2))
    assert all(length(pair) == np.hypot(*pair) for pair in pairs)
    assert length(np.array([3.0, 4.0, 12.0])) == 13.0


def test_plane_housing_field_is_the_rows_repeated():
    from types import SimpleNamespace

    from conrod.housing.housing import Housing

    rows = np.random.default_rng(4).standard_normal(36)
    field = Housing.film_field(SimpleNamespace(axial=None), rows, 9)
    assert np.array_equal(field, np.repeat(rows[:, None], 9, axis=1))
    assert field.flags.c_contiguous and field.flags.writeable
