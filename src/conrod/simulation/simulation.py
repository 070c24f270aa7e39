"""The orchestrator: ``Simulation(case).run() -> RunResults``.

.. code-block:: python

    from conrod import Case, Simulation
    results = Simulation(Case.from_toml("examples/passenger_car_diesel_2000rpm.toml")).run()
    results.summary.h_min          # [m]
    results.cycle.p_max            # [Pa] per output crank angle

Steps: loads (``[engine]`` via :mod:`conrod.loads.engine_loads` or ``[load]`` table) →
film model (``[solver] film``) → periodic orbit from the concentric start → heat balance
(viscosity from ``[lubricant]``, iterated when it depends on temperature) → characteristics
→ contact post-processing (:mod:`conrod.contact.analysis`)."""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from conrod.cases.case import Case
from conrod.contact.analysis import analyse_contact, asperity_friction_power
from conrod.contact.asperity import kernel_parameters
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmModel
from conrod.film.capabilities import HasEccentricityRange, SupportsDeformation
from conrod.film.factory import build_film_model
from conrod.io.cores import one_blas_thread
from conrod.loads.cycle import LoadCycle
from conrod.loads.forces import two_mass_split
from conrod.loads.oil_feed import feed_schedule, wear_diagram_angle
from conrod.loads.tilt import journal_tilt
from conrod.orbit.characteristics import cycle_characteristics, row_results
from conrod.orbit.heat_balance import relaxed_update
from conrod.orbit.integrators import Integrator
from conrod.orbit.periodic import PeriodicOrbit, periodic_orbit
from conrod.orbit.problem import OrbitProblem
from conrod.results.cycle_results import CycleResults, RunResults
from conrod.results.feed import starvation_warnings
from conrod.results.plausibility import check_run, table_range_warnings
from conrod.results.summary import contact_warnings, summarise
from conrod.simulation.as_built_run import as_built, warm_note
from conrod.simulation.feed_checks import check_journal_holes, check_oil_feed
from conrod.simulation.fields import signed_off, signoff_request
from conrod.simulation.orbit_outputs import (
    film_asperity_force,
    heat_balance_temperature,
    pressure_map,
    previous_cycle,
    rigid_film_thickness,
)
from conrod.simulation.thermal_maps import thermal_maps, thermal_orbit

DEFAULT_TABLE_LOAD_MASS = 1.0
"""Moving mass for table loads when ``[solver] mass_x/mass_y`` are not given [kg]."""

ProgressCallback = Callable[[str, int, float], None]
"""progress(stage, cycle, periodicity_error) — called after every integrated cycle."""


class Simulation:
    """Periodic journal-centre orbit and characteristics of one case.

    case : Case  Validated case (needs ``[bearing]`` with ``radial_clearance``,
        ``[lubricant]`` and ``[engine]`` or ``[load]``).
    film : FilmModel, film name or None  The film model object to use, or a registered
        name replacing ``[solver] film``; None: the case's.
    loads : LoadCycle or None  Load and surface speeds over the cycle; None: from the
        case's ``[engine]`` or ``[load]`` table.
    integrator : Integrator, integrator name or None  Orbit integrator object
        (:class:`~conrod.orbit.integrators.Integrator`) or a registered name replacing
        ``[solver] integrator``; None: the case's.
    housing : Housing, "rigid" or None  Elastic big-end housing
        (:class:`conrod.housing.housing.Housing`) whose bore deforms with the film
        (:class:`conrod.ehd.film.ElasticFilm`); "rigid": a rigid bore; None: the case's
        ``[housing]`` (rigid unless its model is builtin, mesh or compliance).
    rigid_companion : bool  With an elastic housing, also run the rigid bore and compare
        (:class:`conrod.results.ehd.ElasticRunResults`).
    signoff, fields : the sign-off's keywords (:func:`conrod.simulation.fields.signoff_request`).
    overrides : keyword arguments replacing other ``[solver]`` fields (e.g. ``max_cycles=2``,
        ``n_theta=72``); validated like the case file.
    """

    def __init__(self, case: Case, film: FilmModel | str | None = None,
                 loads: LoadCycle | None = None, integrator: Integrator | str | None = None,
                 housing: Any = None, rigid_companion: bool = True, **overrides: Any):
        if not isinstance(case, Case):  # the arguments, before anything is read from them
            shown = repr(case) if len(repr(case)) <= 60 else repr(case)[:57] + "..."
            raise CaseError(f"Simulation: case = {shown}: a conrod.Case is required "
                            "(Case.from_toml(path) or Case.from_dict(data))")
        for name, value in (("film", film), ("integrator", integrator)):
            if isinstance(value, bool | int | float | dict | list | tuple):
                raise CaseError(f"Simulation: {name} = {value!r}: a registered name or a "
                                f"{name} object is required (or None for the case's)")
        if not isinstance(rigid_companion, bool):
            raise CaseError(f"Simulation: rigid_companion = {rigid_companion!r}: True or False "
                            "is required")
        case.require("run", "bearing", "lubricant")
        if loads is None and case.engine is None and case.load is None:
            raise CaseError("run needs either [engine] or [load] (a load table) in the case file")
        bearing, lubricant = case.bearing, case.lubricant
        assert bearing is not None and lubricant is not None  # checked by require()
        if bearing.radial_clearance is None:
            raise CaseError("bearing.radial_clearance: required by 'run' [m]")
        if housing is not None and housing != "rigid" and not hasattr(
                housing, "corrected_compliance"):
            raise CaseError(f"housing = {type(housing).__name__}: not a housing (allowed: "
                            "None, 'rigid' or a conrod.housing.housing.Housing)")
        self._housing = housing
        self._rigid_companion = rigid_companion
        self.signoff, self._overrides = signoff_request(overrides)  # the sign-off's keywords
        names = {"film": film if isinstance(film, str) else None,
                 "integrator": integrator if isinstance(integrator, str) else None}
        self.case = case
        self._bearing, self._lubricant = bearing, lubricant
        self.solver = _solver_with(case, {**self._overrides, **names})
        self._film = None if film is None or isinstance(film, str) else film
        self._integrator = None if integrator is None or isinstance(integrator, str) else integrator
        self._names = names
        self._wear_angle = wear_diagram_angle(case)  # of a crank-pin hole at "wear_diagram"
        if self._film is None:
            check_oil_feed(bearing.geometry(self._wear_angle), self.solver.film)
        self._loads = loads if loads is not None else self._read_loads()  # bad tables fail here

    # -- components -------------------------------------------------------------------
    def geometry(self) -> BearingGeometry:
        """Bearing geometry with supply features from ``[bearing]``, as built and warm
        (:func:`conrod.simulation.as_built_run.as_built`)."""
        return as_built(self, self._bearing.geometry(self._wear_angle), self._film is None)

    def load_cycle(self) -> LoadCycle:
        """Load and surface speeds over the cycle (given, engine loads or the load table)."""
        return self._loads

    def _read_loads(self) -> LoadCycle:
        if self.case.load is not None:
            from conrod.loads.table_load import load_cycle_from_table

            return load_cycle_from_table(self.case.load, self.case.resolve(self.case.load.table))
        from conrod.loads.engine_loads import compute_engine_loads

        return compute_engine_loads(self.case).to_load_cycle()

    def masses(self) -> tuple[float, float]:
        """Moving masses along film x and y [kg] ([D0] §3.2).

        ``[solver] mass_x/mass_y`` when given. For engine loads (rod frame, x towards the
        small end): along the rod the piston plus the whole rod, across it the big-end share
        of the two-mass rod (:func:`conrod.loads.forces.two_mass_split`). For table loads
        :data:`DEFAULT_TABLE_LOAD_MASS`; a ``[load]`` table beside ``[engine]`` (which then
        gives the crank train) takes the engine's masses.
        """
        s, engine = self.solver, self.case.engine
        if engine is not None:
            along = engine.piston_mass + engine.rod_mass
            across = two_mass_split(engine.rod_mass, engine.rod_length,
                                    engine.rod_cg_from_big_end).big_end
        else:
            along = across = DEFAULT_TABLE_LOAD_MASS
        mass_x = s.mass_x if s.mass_x is not None else along
        mass_y = s.mass_y if s.mass_y is not None else (s.mass_x or across)
        return mass_x, mass_y

    def film_model(self) -> FilmModel:
        """The film model: the one given, else the one of ``[solver] film``; on the bore of
        the elastic housing when there is one and the film can take a deformation."""
        film = self._film if self._film is not None else self._named_film()
        housing = self.housing()
        if housing is None or not isinstance(film, SupportsDeformation):
            return film
        from conrod.ehd.mass_conserving_ehd import elastic_film

        loads = self.load_cycle()
        settings = dataclasses.replace(coupling_settings(self.case), cycle=loads.cycle)
        return elastic_film(film, housing, loads.crank_speed, settings,
                            _asperity_parameters(self.case))

    def _film_name(self) -> str:
        """Name of the film model: the given object's, else ``[solver] film``."""
        return self._film.name if self._film is not None else self.solver.film

    def _named_film(self) -> FilmModel:
        """The film of ``[solver] film`` with the case's pressure–viscosity law."""
        return build_film_model(self.solver, self.geometry(),
                                pressure_viscosity=self.case.lubricant.pressure_viscosity_law())

    def housing(self) -> Any:
        """The elastic housing (built once from ``[housing]``), or None for a rigid bore."""
        if self._housing is None:
            if self.case.housing.model == "rigid":
                self._housing = "rigid"
            else:
                from conrod.housing.housing import Housing

                self._housing = Housing.from_case(
                    self.case.model_copy(update={"solver": self.solver}))
        return None if self._housing == "rigid" else self._housing

    def elastic(self) -> bool:
        """True when the orbit runs on a deforming bore (a housing and a deformable film)."""
        film = self._film if self._film is not None else self._named_film()
        return self.housing() is not None and isinstance(film, SupportsDeformation)

    def case_record(self) -> Any:
        """What a result folder records of the case as run
        (:func:`conrod.simulation.recording.record_case`)."""
        from conrod.simulation.recording import record_case

        return record_case(self.case, self.solver)

    def integrator(self) -> Integrator | str:
        """The orbit integrator: the object given, else the name of ``[solver]``."""
        return self._integrator if self._integrator is not None else self.solver.integrator

    def problem(self, viscosity: float | None = None) -> OrbitProblem:
        """Orbit problem at ``viscosity`` [Pa s] (default: at the supply temperature)."""
        lubricant = self._lubricant
        mu = viscosity or lubricant.viscosity_at(lubricant.supply_temperature)
        mass_x, mass_y = self.masses()
        tilt = journal_tilt(self.case, self.load_cycle())
        check_journal_holes(self.geometry(), self._film_name(), tilt)
        film = self.film_model()
        return OrbitProblem(
            film, self.load_cycle(), mu, mass_x, mass_y,
            self.case.contact.dry_friction_coefficient, _contact_thickness(self.solver, film),
            _asperity_parameters(self.case), tilt,
            feed_schedule(self.case, self.load_cycle(),
                          lubricant.density_at(lubricant.supply_temperature), self._wear_angle))

    # -- run --------------------------------------------------------------------------
    def run(self, progress: ProgressCallback | None = None) -> RunResults | Any:
        """Periodic orbit, heat balance, characteristics and contact post-processing; with
        an elastic housing the elastic answer, its diagnostics and the rigid companion
        (:class:`conrod.results.ehd.ElasticRunResults`). BLAS on one thread meanwhile."""
        with one_blas_thread():  # also where NumPy was loaded first (conrod.io.cores)
            if not self.elastic():
                results = signed_off(*self.run_orbit(progress), self.case, self.signoff)
                if self.housing() is None:
                    return results
                note = (f"[housing] model = {self.case.housing.model!r} not coupled: film "
                        f"{results.summary.film_model!r} cannot take a bore deformation "
                        "(allowed: reynolds, mass_conserving); the bore is rigid")
                return dataclasses.replace(results, summary=dataclasses.replace(
                    results.summary, warnings=(*results.summary.warnings, note)))
            check_journal_holes(self.geometry(), self._film_name(), None, elastic=True)
            from conrod.simulation.ehd_run import elastic_run

            return elastic_run(self, progress)

    def rigid_companion(self, integrator: str | None = None,
                        **overrides: Any) -> Simulation | None:
        """The same simulation on a rigid bore (None when not asked for); ``integrator``:
        the one the elastic run used (so that ``auto`` cannot choose a journal with mass
        for the rigid run and a massless one for the elastic run); ``overrides``: other
        ``[solver]`` fields replaced (as in :class:`Simulation`)."""
        if not self._rigid_companion:
            return None
        film = self._film if self._film is not None else self._names["film"]
        if integrator is None:
            integrator = (self._integrator if self._integrator is not None
                          else self._names["integrator"])
        return Simulation(self.case, film=film, loads=self._loads, integrator=integrator,
                          housing="rigid", **{**self._overrides, **overrides})

    def run_orbit(self, progress: ProgressCallback | None = None
                  ) -> tuple[RunResults, ThermalOrbit]:
        """The orbit of this simulation's film as it is, without the elastic parts of
        :meth:`run`: the periodic orbit (heat balance included), its characteristics,
        contact and plausibility warnings, and the :class:`ThermalOrbit` it came from
        (:meth:`run`'s results for a rigid bore; :mod:`conrod.simulation.ehd_run` adds the
        bore's diagnostics); BLAS on one thread, as :meth:`run` (the grid error calls this)."""
        start = time.perf_counter()
        with one_blas_thread():
            thermal = thermal_orbit(self, self._thermal_orbit, progress)  # heat balance or film
        orbit, problem, cycle = thermal.orbit, thermal.problem, thermal.cycle
        summary = summarise(cycle, orbit, problem, self.solver, thermal.temperature,
                            thermal.cycles, thermal.iterations, _name(self.integrator(), problem))
        contact = analyse_contact(self.case, cycle, thermal.asperity_force)
        boundary = contact.boundary_friction_power
        summary = dataclasses.replace(
            summary, roughness=self.case.contact.roughness,
            mean_boundary_friction_power=0.0 if boundary is None else float(boundary.mean()))
        pressure, grid = pressure_map(problem, cycle, orbit.last.film_memory)
        angles, thickness = rigid_film_thickness(cycle, problem.clearance)
        results = RunResults(
            cycle=cycle, summary=summary, clearance=problem.clearance,
            pressure_at_p_max=pressure, pressure_grid=grid,
            previous_cycle_eccentricity=previous_cycle(orbit), contact=contact,
            film_thickness=thickness, film_angles=angles,
            contact_radius=problem.contact_radius, case_record=self.case_record(),
            thermal_film=getattr(thermal, "film", None), thermal_maps=thermal_maps(self, thermal),
        )
        warnings = (summary.warnings  # check_run: or ConvergenceError
                    + tuple(check_run(results, self.case, problem.contact_radius))
                    + tuple(contact_warnings(cycle))
                    + tuple(starvation_warnings(cycle.feed, cycle.crank_angle_deg)))
        if isinstance(problem.film, HasEccentricityRange):
            warnings += tuple(table_range_warnings(cycle, problem.film.eccentricity_max))
        wall_time = time.perf_counter() - start
        summary = dataclasses.replace(summary, warnings=warnings, wall_time=wall_time)
        resolved = self.case.model_copy(update={"solver": self.solver})  # with the overrides
        return dataclasses.replace(results, summary=summary, model=self._model_description(),
                                   case_hash=resolved.content_hash(),
                                   settings=self.solver.model_dump(mode="json")), thermal

    def _model_description(self) -> dict[str, str]:
        """What is computed, in words, for the headline."""
        law = self._lubricant.pressure_viscosity_law()
        model = {"housing": "elastic bore (EHD)" if self.elastic() else "rigid bore",
                 "viscosity": "isoviscous" if law is None else f"piezoviscous ({law.law})"}
        model["housing"] += warm_note(self)
        engine = self.case.engine
        if engine is not None and engine.pressure_model is not None and self.case.load is None:
            model["exhaust_opening_deg"] = "170"  # step of the [D3] gas-pressure model
        return model

    def _thermal_orbit(self, problem: OrbitProblem, progress: ProgressCallback | None
    ) -> ThermalOrbit:
        """Orbit, its characteristics and the effective temperature, iterated when μ
        depends on T (heat balance); the characteristics are solved once per orbit."""
        lubricant, s = self._lubricant, self.solver
        temperature = lubricant.supply_temperature
        viscosity, cycles, state = problem.viscosity, 0, None
        iterations = s.thermal_iterations if lubricant.temperature_dependent else 0
        for iteration in range(iterations + 1):
            stage = "orbit" if iteration == 0 else f"heat balance {iteration}"
            current = problem.with_viscosity(viscosity)
            orbit = self._orbit(current, state, stage, progress)
            cycles += orbit.cycles_run
            keep = self.signoff.wanted and not orbit.last.film_memory  # the sign-off reads
            rows = row_results(current, orbit.last, with_pressure=keep)  # them (cycle_fields)
            cycle = cycle_characteristics(current, orbit.last, rows)
            asperity = film_asperity_force(current, cycle, orbit.last.film_memory)
            boundary = asperity_friction_power(self.case, cycle, asperity)
            target = heat_balance_temperature(cycle, lubricant, float(boundary.mean()))
            if (target is None or iteration == iterations
                    or abs(target - temperature) <= s.thermal_tolerance):
                return ThermalOrbit(orbit, current, cycle, target, cycles, iteration, asperity,
                                    rows if keep else None)
            temperature, state = relaxed_update(temperature, target), orbit.last.end_state
            viscosity = lubricant.viscosity_at(temperature)
        raise AssertionError("unreachable")  # pragma: no cover

    def _orbit(self, problem, state, stage, progress) -> PeriodicOrbit:
        def on_cycle(cycle: int, error: float) -> None:
            if progress is not None:
                progress(stage, cycle, error)

        in_cycle = getattr(progress, "in_cycle", None)  # optional: crank angle in a cycle
        cycle_deg = math.degrees(problem.loads.cycle)

        def on_angle(cycle: int, phi: float) -> None:
            in_cycle(stage, cycle, math.degrees(phi), cycle_deg)

        return periodic_orbit(problem, self.solver, integrator=self.integrator(),
                              start=state, on_cycle=on_cycle,
                              on_angle=on_angle if in_cycle is not None else None)


@dataclasses.dataclass(frozen=True)
class ThermalOrbit:
    """The converged orbit of the heat balance and what was computed along with it: the
    periodic orbit, its problem (at the converged viscosity), the cycle characteristics,
    the effective temperature [°C] (None without a heat balance), the cycles integrated,
    the heat-balance iterations [-] and the asperity force of a film that carries it [N]."""

    orbit: PeriodicOrbit
    problem: OrbitProblem
    cycle: CycleResults
    temperature: float | None
    cycles: int
    iterations: int
    asperity_force: np.ndarray | None = None
    """Greenwood–Tripp asperity force at each output angle as the film computed it on its
    own (deformed) gap [N]; None when the film does not carry it (the contact analysis then
    takes it on the rigid shell)."""
    rows: list | None = None
    """The film results the characteristics came from, one per output angle, with their
    pressure fields, for the sign-off to read instead of solving the film there again
    (:func:`conrod.simulation.fields.cycle_fields`); None where no sign-off is asked for
    or the orbit carried a film memory (its rows are read from that memory)."""


def default_film(case: Case) -> FilmModel:
    """The film model of ``[solver] film`` for the case's bearing."""
    if case.bearing is None:
        raise CaseError("[bearing]: required for a film model")
    return build_film_model(case.solver, case.bearing.geometry())


def _contact_thickness(solver, film) -> float:
    """h_c of the rigid contact circle [m]; on a deforming bore the circle is widened by
    one clearance (the bore gives way under the film), so that the journal is stopped by
    the deformed film (h_min on the deformed bore) and not by the rigid circle."""
    if hasattr(film, "housing"):
        return solver.contact_film_thickness - film.geometry.radial_clearance
    return solver.contact_film_thickness


def coupling_settings(case: Case):
    """:class:`conrod.ehd.film.ElasticSettings` of ``[housing]``."""
    from conrod.ehd.film import ElasticSettings

    h = case.housing
    return ElasticSettings(tolerance=h.coupling_tolerance,
                           rigid_start=float(np.radians(h.rigid_start_deg)),
                           increment_share=h.increment_share, max_iterations=h.coupling_iterations)


def _name(choice: Integrator | str, problem: OrbitProblem | None = None) -> str:
    """Integrator name; an automatic choice names what it chose, e.g. 'auto (implicit)'."""
    if isinstance(choice, str):
        from conrod.registry import integrator

        choice = integrator(choice)
    choose = getattr(choice, "choose", None)
    if choose is not None and problem is not None:
        return f"{choice.name} ({choose(problem).name})"
    return choice.name


def _solver_with(case: Case, overrides: dict[str, Any]):
    clean = {k: v for k, v in overrides.items() if v is not None}
    if not clean:
        return case.solver
    from conrod.cases.base import validate_section
    from conrod.cases.solver import SolverSection

    return validate_section(SolverSection, {**case.solver.model_dump(), **clean}, "solver")


def _asperity_parameters(case: Case):
    """Greenwood–Tripp kernel parameters when ``[contact] model = "greenwood_tripp"``."""
    if case.contact.model != "greenwood_tripp":
        return None
    return kernel_parameters(case)


__all__ = ["Simulation", "default_film"]
