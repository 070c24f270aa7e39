"""Oil holes in the crank pin: a supply region of the film that turns with the journal,
fed at the gallery pressure plus the centrifugal head of the drilling (Reynolds film)."""

from __future__ import annotations

import copy
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from conrod.cases.case import Case
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FeedHole, FilmState, Groove, JournalFeed, JournalHole
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.loads.cycle import LoadCycle
from conrod.loads.oil_feed import (
    FeedSchedule,
    HoleSupply,
    centrifugal_head,
    feed_schedule,
    journal_turn,
    mouth_radius,
)
from conrod.orbit import OrbitProblem, OrbitState, integrate_cycle
from orbit_helpers import solver

EXAMPLE = (Path(__file__).resolve().parents[1] / "examples"
           / "passenger_car_diesel_2000rpm_crank_fed.toml")
BASE = {"diameter": 0.05, "width": 0.02, "radial_clearance": 25e-6}
STATE = {"eccentricity_x": 15e-6, "eccentricity_y": 5e-6, "velocity_x": 1e-3,
         "journal_speed": 300.0, "viscosity": 0.01}


def _constant_feed(pressures, turned_per_cycle=0.0, cycle=2 * math.pi) -> FeedSchedule:
    """A feed with constant pressures whose journal turns ``turned_per_cycle`` [rad]
    uniformly over a cycle."""
    angles = np.linspace(0.0, cycle, 9)
    supplies = tuple(HoleSupply(None, np.array([p]), 0.0, 0.0, cycle) for p in pressures)
    return FeedSchedule(angles, angles * turned_per_cycle / cycle, cycle, supplies)


def _steady_loads(journal, shell, load=4000.0, n=72, cycle=2 * math.pi) -> LoadCycle:
    phi = np.linspace(0.0, cycle, n, endpoint=False)
    omega = 200.0
    return LoadCycle(phi, np.full(n, load), np.full(n, 0.3 * load), np.full(n, journal),
                     np.full(n, shell), omega, cycle)


def test_pin_hole_at_its_shell_angle_is_the_shell_hole_bit_for_bit():
    """A journal hole whose journal angle puts it at θ = 100° gives the film of a shell
    hole at 100° at the same pressure, to the last bit (force, flows, field)."""
    shell = ReynoldsFilm(BearingGeometry(**BASE, feed_holes=(FeedHole(math.radians(100.0),
                                                                       0.005),),
                                         supply_pressure=3e5), n_theta=72, n_z=16)
    pin = ReynoldsFilm(BearingGeometry(**BASE, journal_holes=(
        JournalHole(math.radians(100.0), 0.005),)), n_theta=72, n_z=16)
    a = shell.solve(FilmState(**STATE), with_pressure=True)
    b = pin.solve(FilmState(**STATE, journal_feed=JournalFeed(0.0, (3e5,))),
                  with_pressure=True)
    assert (a.force_x, a.force_y, a.supply_flow, a.side_flow) == (
        b.force_x, b.force_y, b.supply_flow, b.side_flow)
    assert np.array_equal(a.pressure, b.pressure)
    assert b.extra["journal_hole_flow_m3_per_s"] == b.supply_flow > 0.0


def test_pin_hole_at_zero_relative_speed_gives_the_fixed_hole_orbit():
    """Journal and shell turning together (ω_j = ω_b, the Couette term from their sum): the
    pin hole does not move on the shell, and the orbit is that of the same hole fixed in
    the shell, bit for bit."""
    loads = _steady_loads(150.0, 150.0)
    shell = ReynoldsFilm(BearingGeometry(**BASE, feed_holes=(FeedHole(2.0, 0.005),),
                                         supply_pressure=2e5), n_theta=36, n_z=8)
    pin = ReynoldsFilm(BearingGeometry(**BASE, journal_holes=(JournalHole(2.0, 0.005),)),
                       n_theta=36, n_z=8)
    feed = feed_schedule_of(loads, 2e5)
    assert feed.journal_angle(1.3) == 0.0 and feed.journal_angle(9.0) == 0.0
    runs = [integrate_cycle(OrbitProblem(film, loads, 0.01, 1.0, 1.0, feed=f),
                            OrbitState(5e-6, 0.0), solver(output_step_deg=10.0),
                            "quasi_static")
            for film, f in ((shell, None), (pin, feed))]
    assert np.array_equal(runs[0].x, runs[1].x) and np.array_equal(runs[0].y, runs[1].y)


def feed_schedule_of(loads: LoadCycle, pressure: float) -> FeedSchedule:
    """The feed of one hole at a constant ``pressure`` [Pa] on ``loads``' journal turn."""
    angles, turned = journal_turn(loads)
    return FeedSchedule(angles, turned, loads.cycle,
                        (HoleSupply(None, np.array([pressure]), 0.0, 0.0, loads.cycle),))


def _case(**hole) -> Case:
    data = tomllib.loads(EXAMPLE.read_text())
    data = copy.deepcopy(data)
    data["bearing"]["journal_holes"] = [{**data["bearing"]["journal_holes"][0], **hole}]
    return Case.from_dict(data, base_dir=EXAMPLE.parent)


def test_centrifugal_head_is_the_hand_formula():
    """p = (1 − k)(p_g + ρ ω² (r_out² − r_in²)/2) with r_out the hole's mouth on the pin:
    by hand for the shipped crank-fed case."""
    case = _case(angle=30.0, gallery_pressure=2.5e5, drilling_inner_radius=0.02,
                 loss_coefficient=0.1)
    rho, omega = 850.0, 2000.0 * math.pi / 30.0
    r, big_r = 0.5 * 0.0955, 0.5 * 0.0478
    r_out = math.sqrt((r + big_r * math.cos(math.radians(30.0))) ** 2
                      + (big_r * math.sin(math.radians(30.0))) ** 2)
    assert mouth_radius(r, big_r, math.radians(30.0)) == pytest.approx(r_out, rel=1e-15)
    head = 0.5 * rho * omega**2 * (r_out**2 - 0.02**2)
    assert centrifugal_head(rho, omega, 0.02, r_out) == pytest.approx(head, rel=1e-14)
    from conrod.loads.engine_loads import compute_engine_loads

    loads = compute_engine_loads(case).to_load_cycle()
    feed = feed_schedule(case, loads, rho, None)
    for phi in (0.0, 1.0, 7.0):
        assert feed.at(phi).pressures[0] == pytest.approx(0.9 * (2.5e5 + head), rel=1e-12)
    assert head == pytest.approx(0.825e5, rel=1e-3)  # 0.83 bar at 2000 rpm on this crank


def test_gallery_table_over_crank_angle_and_the_journal_turn():
    """A gallery table is interpolated periodically; ψ(φ) = φ + β(φ) for a crank pin."""
    case = _case(angle=0.0, gallery_pressure=[[0.0, 1e5], [360.0, 3e5]],
                 drilling_inner_radius=0.0)
    from conrod.loads.engine_loads import compute_engine_loads

    loads = compute_engine_loads(case).to_load_cycle()
    feed = feed_schedule(case, loads, 850.0, None)
    head = feed.supplies[0].head
    assert feed.at(math.pi).pressures[0] == pytest.approx(2e5 + head, rel=1e-12)
    assert feed.at(3 * math.pi).pressures[0] == pytest.approx(2e5 + head, rel=1e-12)
    lam = 0.5 * 0.0955 / 0.144
    for phi in (0.3, 2.0, 5.5, 11.0, 13.0):
        exact = phi + math.asin(lam * math.sin(phi))
        assert feed.journal_angle(phi) == pytest.approx(exact, abs=1e-5)


def test_no_gallery_pressure_and_no_speed_give_an_ambient_hole():
    """Gallery 0 Pa and crank speed 0: the hole's feed pressure is 0 (ambient) and the
    film holds gauge 0 on the hole's nodes (the same film as a shell hole at 0 Pa)."""
    supply = HoleSupply(None, np.array([0.0]), centrifugal_head(850.0, 0.0, 0.0, 0.07),
                        0.0, 4 * math.pi)
    assert supply.pressure(1.0) == 0.0
    pin = ReynoldsFilm(BearingGeometry(**BASE, journal_holes=(JournalHole(1.0, 0.006),)),
                       n_theta=72, n_z=16)
    shell = ReynoldsFilm(BearingGeometry(**BASE, feed_holes=(FeedHole(3.0, 0.006),)),
                         n_theta=72, n_z=16)
    b = pin.solve(FilmState(**STATE, journal_feed=JournalFeed(2.0, (0.0,))), with_pressure=True)
    a = shell.solve(FilmState(**STATE), with_pressure=True)
    assert np.array_equal(a.pressure, b.pressure)
    problem = pin.discrete_problem(FilmState(**STATE, journal_feed=JournalFeed(2.0, (0.0,))))
    assert problem.journal_holes.any() and np.all(b.pressure[problem.journal_holes] == 0.0)


def _ring_force(n_holes: int, film_kind=ReynoldsFilm, samples: int = 6) -> np.ndarray:
    """Mean film force over the journal angle of ``n_holes`` equal holes round the pin
    [N]."""
    holes = tuple(JournalHole(2 * math.pi * k / n_holes, 0.004) for k in range(n_holes))
    film = film_kind(BearingGeometry(**BASE, journal_holes=holes), n_theta=72, n_z=16)
    forces = [film.force(FilmState(**STATE, journal_feed=JournalFeed(
        2 * math.pi * s / (samples * n_holes), (2e5,) * n_holes))) for s in range(samples)]
    return np.mean(forces, axis=0)


def test_rotating_hole_force_is_periodic_and_its_mean_tends_to_the_groove():
    """At a fixed journal state the force of n holes round the pin repeats every 2π/n of
    journal turn (the relative rotation of one hole spacing), and its mean over a turn
    approaches the full circumferential groove of the holes' width as n grows."""
    holes = tuple(JournalHole(2 * math.pi * k / 4, 0.004) for k in range(4))
    film = ReynoldsFilm(BearingGeometry(**BASE, journal_holes=holes), n_theta=72, n_z=16)

    def force(angle):
        return np.array(film.force(FilmState(**STATE, journal_feed=JournalFeed(angle,
                                                                               (2e5,) * 4))))
    for angle in (0.1, 0.7):
        np.testing.assert_allclose(force(angle + 0.5 * math.pi), force(angle), rtol=1e-9)
    assert np.linalg.norm(force(0.1) - force(0.5)) > 1e-3 * np.linalg.norm(force(0.1))
    groove = ReynoldsFilm(BearingGeometry(**BASE, grooves=(Groove(width=0.004),),
                                          supply_pressure=2e5), n_theta=72, n_z=16)
    target = np.array(groove.force(FilmState(**STATE)))
    errors = [np.linalg.norm(_ring_force(n) - target) / np.linalg.norm(target)
              for n in (2, 8, 24, 72)]
    assert errors[0] > errors[1] > errors[2] > errors[3]
    # 72 holes of the groove's width, one per θ node: the ring closes into the groove
    assert errors[3] < 1e-12


def test_two_pin_holes_on_a_steady_load_give_an_orbit_periodic_at_their_spacing():
    """Steady load, journal turning at constant speed: two holes 180° apart make the
    massless orbit repeat every half turn (their passing frequency), not at the load."""
    loads = _steady_loads(200.0, 0.0)  # one relative turn per cycle of 2π
    film = ReynoldsFilm(BearingGeometry(**BASE, journal_holes=(
        JournalHole(0.0, 0.005), JournalHole(math.pi, 0.005))), n_theta=36, n_z=8)
    feed = _constant_feed((3e5, 3e5), turned_per_cycle=2 * math.pi)
    problem = OrbitProblem(film, loads, 0.01, 1.0, 1.0, feed=feed)
    state = OrbitState(10e-6, 5e-6)
    for _ in range(2):  # settle
        traj = integrate_cycle(problem, state, solver(output_step_deg=10.0), "quasi_static")
        state = traj.end_state
    half = traj.x.size // 2
    e = np.hypot(traj.x, traj.y)
    np.testing.assert_allclose(traj.x[half:], traj.x[:half], rtol=0, atol=2e-4 * 25e-6)
    assert np.ptp(e) > 1e-3 * 25e-6  # the holes do move the journal


@pytest.mark.parametrize(("hole", "field"), [
    ({"diameter": 0.021}, "bearing.journal_holes[0].diameter"),
    ({"axial_position": 0.009}, "bearing.journal_holes[0].axial_position"),
    ({"drilling_outer_radius": 0.09}, "bearing.journal_holes[0].drilling_outer_radius"),
    ({"gallery_pressure": -1.0e5}, "bearing.journal_holes.gallery_pressure"),
    ({"gallery_pressure": [[0.0, 1e5], [90.0, -2.0]]},
     "bearing.journal_holes.gallery_pressure[1]"),
])
def test_bad_pin_hole_gets_one_clear_line(hole, field):
    from conrod.simulation import Simulation

    with pytest.raises(CaseError) as error:
        Simulation(_case(**hole)).problem()
    message = str(error.value)
    assert field in message and "allowed" in message and "\n" not in message


def test_feed_without_crank_angle_is_refused_loudly():
    film = ReynoldsFilm(BearingGeometry(**BASE, journal_holes=(JournalHole(0.0, 0.005),)),
                        n_theta=36, n_z=8)
    with pytest.raises(CaseError, match="journal_feed"):
        film.force(FilmState(**STATE))
    with pytest.raises(CaseError, match="pressures"):
        film.force(FilmState(**STATE, journal_feed=JournalFeed(0.0, (1e5, 1e5))))
    with pytest.raises(CaseError, match="pressures"):
        JournalFeed(0.0, (-1.0,))


def _rotating_hole_cycle(grooves=()):
    """Periodic massless orbit of the mass-conserving film fed by one pin hole at 3 bar
    turning once per cycle under a rotating load (and its characteristics)."""
    from conrod.cases.solver import SolverSection
    from conrod.film.mass_conserving.film import MassConservingFilm
    from conrod.orbit.characteristics import cycle_characteristics
    from conrod.orbit.periodic import periodic_orbit
    from test_orbit_jfo import rotating_load

    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6,
                               grooves=grooves, journal_holes=(JournalHole(0.0, 0.005),))
    loads = rotating_load()
    problem = OrbitProblem(MassConservingFilm(geometry, n_theta=36, n_z=6), loads, 0.02,
                           1.0, 1.0, feed=feed_schedule_of(loads, 3e5))
    settings = SolverSection(integrator="quasi_static", quasi_static_step_deg=2.0,
                             output_step_deg=2.0, max_cycles=20, min_cycles=2,
                             periodicity_tolerance=1e-5)  # the balance holds on a periodic cycle
    result = periodic_orbit(problem, settings)
    return result, cycle_characteristics(problem, result.last)


def _defect(cycle) -> float:
    """|∮(supply − side flow) dt| / ∮ supply dt over the periodic cycle [-]."""
    return abs(float(np.mean(cycle.supply_flow - cycle.side_flow))) / float(
        np.mean(cycle.supply_flow))


@pytest.mark.slow
def test_mass_conserving_film_conserves_oil_through_a_turning_hole():
    """Over the periodic cycle the oil through the turning hole (its flux and the content
    it gives the nodes it comes over) leaves through the edges, to the film's own
    conservation tolerance (measured on 36 × 6: the same hole standing still 1.6e-3, turning
    9.6e-4; on 48 × 8 without the content the hole gives the nodes it comes over 13.7 %);
    the film starves at the loaded zone's inlet part of the
    cycle and the hole's flow is the whole supply."""
    result, cycle = _rotating_hole_cycle()
    assert result.periodic
    assert _defect(cycle) < 2e-3
    np.testing.assert_array_equal(cycle.feed["journal_hole_flow"], cycle.supply_flow)
    fraction = cycle.feed["inlet_film_fraction"]
    assert np.all((fraction >= 0.0) & (fraction <= 1.0)) and fraction.min() < 0.9


@pytest.mark.slow
def test_half_groove_fed_by_the_pin_hole_conserves_oil():
    """A half groove in the shell (0–180°) fed by the pin hole while it opens into it, at
    ambient otherwise: the groove takes the hole's pressure, and oil is conserved over
    the cycle with every held node's content change in the supply (measured 5.9e-3 on
    36 × 6, 3.1e-3 on 48 × 8; without the groove's content change in the supply 16 %)."""
    half = (Groove(0.0, math.pi, 0.003, 0.0, fed_by_journal_holes=True),)
    result, cycle = _rotating_hole_cycle(half)
    assert result.periodic
    assert _defect(cycle) < 1e-2
    # the hole feeds the groove: more oil than the hole alone gives
    assert np.mean(cycle.feed["journal_hole_flow"]) > 0.0


def test_inlet_film_fraction_reads_the_column_before_the_load_zone():
    """ϑ where the pressure, walking upstream from p_max, first falls to 10 % of it."""
    from conrod.film.mass_conserving.results import inlet_film_fraction

    n, m = 12, 5
    gauge = np.zeros((n, m))
    gauge[5:8, 1:-1] = [[1e5] * 3, [5e5] * 3, [2e5] * 3]  # load zone θ nodes 5–7
    fraction = np.ones((n, m))
    fraction[4, :] = 0.6  # just upstream of the zone for the positive transport
    fraction[8, :] = 0.3
    free = np.ones((n, m), dtype=bool)
    assert inlet_film_fraction(gauge, fraction, free, 100.0) == pytest.approx(0.6)
    assert inlet_film_fraction(gauge, fraction, free, -100.0) == pytest.approx(0.3)
    assert inlet_film_fraction(np.zeros((n, m)), fraction, free, 100.0) == 1.0


def test_starved_load_zone_warns_once():
    from conrod.results.feed import feed_headline, starvation_warnings

    angles = np.arange(4) * 90.0
    starved = {"journal_hole_flow": np.array([1e-7, 2e-7, -1e-8, 0.0]),
               "inlet_film_fraction": np.array([1.0, 0.5, 0.95, 1.0])}
    (warning,) = starvation_warnings(starved, angles)
    assert "0.50" in warning and "crank angle 90 deg" in warning and "25%" in warning
    full = dict(starved, inlet_film_fraction=np.ones(4))
    assert starvation_warnings(full, angles) == []
    assert "backflow over 25%" in feed_headline(starved)["crank-pin hole"]


@pytest.mark.slow
def test_shipped_crank_fed_example_writes_the_hole_columns(tmp_path):
    """``conrod run`` on the shipped example (coarse): the hole's columns in cycle.csv, its
    cycle figures in summary.json and the headline; the hole's shell angle is α + ψ with
    ψ the journal rotation of the same table, and the mean flow is the cycle's supply."""
    import json

    from typer.testing import CliRunner

    from conrod.cli.app import _register_commands, app
    from conrod.loads.oil_feed import wear_diagram_angle

    _register_commands()
    result = CliRunner().invoke(app, [
        "run", str(EXAMPLE), "--out", str(tmp_path), "--grid", "24x8", "--integrator",
        "quasi_static", "--max-cycles", "3", "--no-grid-error", "--no-figures"])
    assert result.exit_code in (0, 4), result.output
    assert "crank-pin hole" in result.output
    table = np.genfromtxt(tmp_path / "cycle.csv", delimiter=",", names=True)
    summary = json.loads((tmp_path / "summary.json").read_text())
    alpha = math.degrees(wear_diagram_angle(Case.from_toml(EXAMPLE)))
    expected = (alpha + table["journal_rotation_deg"]) % 360.0
    difference = (table["journal_hole_angle_shell_deg"] - expected + 180.0) % 360.0 - 180.0
    assert np.max(np.abs(difference)) < 1e-3
    assert summary["journal_hole_flow_mean_m3_s"] == pytest.approx(
        table["journal_hole_flow_m3_s"].mean(), rel=1e-12)
    np.testing.assert_array_equal(table["journal_hole_flow_m3_s"], table["supply_flow_m3_s"])
    assert np.all(table["journal_hole_pressure_Pa"] > 3.0e5)  # gallery plus the head


def test_no_journal_hole_leaves_the_film_problem_as_it_was():
    """Without journal holes the Dirichlet set and values are the film's own arrays (no
    copy, no new node): today's problem, bit for bit."""
    film = ReynoldsFilm(BearingGeometry(**BASE, feed_holes=(FeedHole(1.0, 0.005),),
                                        supply_pressure=1e5), n_theta=36, n_z=8)
    problem = film.discrete_problem(FilmState(**STATE))
    assert problem.journal_holes is None
    assert np.array_equal(problem.fixed, film.discrete_problem(FilmState(**STATE)).fixed)
    assert "journal_hole_flow_m3_per_s" not in film.solve(FilmState(**STATE)).extra


def test_journal_tilt_with_a_pin_hole_is_refused_before_the_run():
    from conrod.simulation import Simulation

    path = EXAMPLE.parent / "kamaz_740_truck_diesel_tilt.toml"
    data = tomllib.loads(path.read_text())
    data["bearing"]["journal_holes"] = [{"angle": 90.0, "diameter": 0.006,
                                         "gallery_pressure": 4e5}]
    case = Case.from_dict(data, base_dir=path.parent)
    with pytest.raises(CaseError, match="journal_holes with a journal tilt"):
        Simulation(case).problem()


@pytest.mark.parametrize("film", ["short", "mobility"])
def test_a_film_that_would_ignore_the_pin_hole_is_refused(film):
    from conrod.simulation import Simulation

    with pytest.raises(CaseError, match="the hole would be ignored"):
        Simulation(Case.from_toml(EXAMPLE), film=film).problem()


@pytest.mark.slow
@pytest.mark.parametrize(("integrator", "settings"), [("adaptive", {}),
                                                      ("rk2", {"step_deg": 0.05})])
def test_every_integrator_passes_the_crank_angle(integrator, settings):
    """adaptive and rk2 place the turning hole too (a film state without the feed would be
    refused): one cycle, finite, inside the clearance."""
    film = ReynoldsFilm(BearingGeometry(**BASE, journal_holes=(JournalHole(0.0, 0.005),)),
                        n_theta=24, n_z=4, tolerance=1e-10)
    problem = OrbitProblem(film, _steady_loads(200.0, 0.0), 0.01, 1.0, 1.0, 0.1, 2.5e-6,
                           feed=_constant_feed((3e5,), 2 * math.pi))
    traj = integrate_cycle(problem, OrbitState(10e-6, 5e-6),
                           solver(output_step_deg=10.0, **settings), integrator)
    ratio = np.hypot(traj.x, traj.y) / 25e-6
    assert np.all(np.isfinite(ratio)) and ratio.max() < 0.9 + 1e-9
