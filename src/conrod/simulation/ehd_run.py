"""The elastohydrodynamic run of :class:`conrod.simulation.simulation.Simulation`: the orbit on the
deforming bore, its per-angle coupling diagnostics and the rigid companion run."""

from __future__ import annotations

import dataclasses
import time

import numpy as np

from conrod import registry
from conrod.contact.analysis import analyse_contact
from conrod.ehd.cycle import displacement_split, elastic_cycle
from conrod.errors import CaseError
from conrod.film.capabilities import HasContentStep
from conrod.orbit.implicit_step import needs_journal_step
from conrod.orbit.integrators import declared, resolved
from conrod.results.ehd import ElasticRunResults
from conrod.results.summary import film_minimum
from conrod.simulation import side_runs
from conrod.simulation.fields import signed_off


def check_integrator(simulation) -> None:
    """CaseError naming the field, before anything runs, for an integrator that cannot
    run the elastic film, by what the integrator declares
    (:func:`conrod.orbit.integrators.declared`): one that does not solve the film's bore
    with the journal (``rk2``) for the isoviscous Reynolds film, whose bore is solved only
    with the journal's implicit step (rk2's explicit step of a few hundredths of a degree
    makes the bore rate in the squeeze term stiff; the implicit steps of
    :mod:`conrod.orbit.implicit_step` run it); one that does not advance a memory in
    lock-step with a fixed step (``implicit``, ``adaptive``) for a film without the exact
    response (mass-conserving, pressure-dependent viscosity)."""
    integrator = simulation.integrator()
    if isinstance(integrator, str):
        integrator = registry.integrator(integrator)
    name = integrator.name
    film = simulation.film_model()
    if needs_journal_step(film):
        if declared(integrator, "journal_step"):
            return
        raise CaseError(
            f"solver.integrator = {name!r} with an elastic [housing]: its explicit step of "
            "a few hundredths of a degree makes the bore rate in the squeeze term too stiff "
            "for the coupling (allowed: implicit, adaptive or auto for the journal with "
            "mass, quasi_static for the massless journal)")
    if declared(integrator, "fixed_step"):
        return
    raise CaseError(
        f"solver.integrator = {name!r} with an elastic [housing]: the "
        f"{film.base.name} film's memory advances in lock-step with a "
        "fixed step, which an error-controlled integrator cannot hold (allowed: "
        "quasi_static or auto for the massless journal, rk2 for the journal with mass)")


def elastic_run(simulation, progress=None) -> ElasticRunResults:
    """Elastic answer, diagnostics and (unless skipped) the rigid companion run (computed
    on a second core meanwhile where one is idle: :mod:`conrod.simulation.side_runs`)."""
    check_integrator(simulation)
    with side_runs.beside(simulation):
        return _elastic_run(simulation, progress)


def _elastic_run(simulation, progress) -> ElasticRunResults:
    start = time.perf_counter()
    results, thermal = simulation.run_orbit(progress)
    results = signed_off(results, thermal, simulation.case, simulation.signoff)
    problem, orbit = thermal.problem, thermal.orbit
    integrator = simulation.integrator()
    if isinstance(integrator, str):
        integrator = registry.integrator(integrator)
    integrator = resolved(integrator, problem)  # an automatic integrator: the one it chose
    name = integrator.name
    rows = stress_rows(results.cycle, simulation.case)
    assembly = problem.film.housing.assembly
    joint = assembly is not None and assembly.joint is not None  # pressures at every row
    diagnostics = elastic_cycle(problem, results.cycle, orbit.last.film_memory,
                                massless=not declared(integrator, "with_mass"),
                                pressure_rows=tuple(range(len(results.cycle.crank_angle)))
                                if joint else tuple(rows.values()))
    film = problem.film
    from conrod.housing.as_built import carried_bore_shape

    angles, thickness = diagnostics.film_thickness(
        results.cycle, problem.clearance,
        bore_shape=carried_bore_shape(film.base.geometry, film.housing))
    results = dataclasses.replace(results, film_thickness=thickness, film_angles=angles)
    if film.carries_asperity():  # contact columns from the asperity on the deformed film
        results = dataclasses.replace(results, contact=analyse_contact(
            simulation.case, results.cycle, diagnostics.columns.get(
                "asperity_force_N", np.zeros(len(results.cycle.crank_angle)))))
    thinnest = film_minimum(results.cycle)
    split = None if thinnest is None else displacement_split(
        film, results.cycle, diagnostics.deformation,
        int(np.argmin(np.abs(results.cycle.crank_angle - thinnest[1]))))
    fields = {angle: diagnostics.pressures[row] for angle, row in rows.items()}
    stresses = _peak_load_stresses(film.housing, results, diagnostics)
    elastic_seconds = time.perf_counter() - start
    companion = simulation.rigid_companion(integrator=name)  # same journal model as above
    rigid = None if companion is None else side_runs.take(side_runs.RIGID)
    if rigid is side_runs.MISSING:
        rigid = companion.run_orbit(_staged(progress, "rigid "))[0]
    info = {
        "housing_model": simulation.case.housing.model,
        "bore_nodes": int(len(film.housing.angles)),
        "coupling_tolerance_m": film.coupling.tolerance,
        "rigid_start_deg": float(np.degrees(film.settings.rigid_start)),
        "jacobian_builds": film.jacobian.builds + film.balance_jacobian.builds + sum(
            chord.builds for chord in film.chords.values()),
        "elastic_wall_time_s": elastic_seconds,
        "deformation_rate_in_squeeze_term": bool(
            isinstance(film, HasContentStep) or (film.settings.deformation_rate
                                              and film.base.name == "reynolds")),
    }
    from conrod.housing.as_built import as_built_summary

    info.update(as_built_summary(film.housing))
    if joint:
        from conrod.simulation.joint_run import joint_over_run

        info["joint_over_run"] = joint_over_run(film.housing, results, diagnostics.pressures)
    if not film.housing.uniform_in_z:  # a 3-D compliance: bore nodes over the width
        info["bore_nodes"] = film.housing.node_count
        info["bore_axial_nodes"] = len(film.housing.axial)
    summary = dataclasses.replace(results.summary, wall_time=time.perf_counter() - start)
    return ElasticRunResults(
        elastic=dataclasses.replace(results, summary=summary), columns=diagnostics.columns,
        deformation=diagnostics.deformation, bore_angles=diagnostics.angles,
        housing=film.housing, rigid=rigid, info=info,
        peak_load_index=diagnostics.peak_load_index,
        peak_load_pressure=diagnostics.peak_load_pressure, pressure_fields=fields,
        stresses=stresses, bore_displacement=split, deformation_field=diagnostics.field)


def stress_rows(cycle, case) -> dict[float, int]:
    """Crank angle [deg] → output row of the film pressure fields an elastic run keeps for
    the rod stresses: the largest load and ``[housing] stress_angles`` (default 360°, the
    gas-exchange TDC), each at the nearest output angle."""
    degrees = np.asarray(cycle.crank_angle_deg)
    peak = int(np.argmax(np.hypot(cycle.load_x, cycle.load_y)))
    rows = {float(degrees[peak]): peak}
    wanted = case.housing.stress_angles or [360.0]
    length = float(degrees[-1] - degrees[0] + np.median(np.diff(degrees)))
    for angle in wanted:
        row = int(np.argmin(np.abs((degrees - angle + 0.5 * length) % length - 0.5 * length)))
        rows.setdefault(float(degrees[row]), row)
    return rows


def _peak_load_stresses(housing, results, diagnostics) -> dict | None:
    """Rod stresses at the largest load under the elastic film pressure and a cosine load
    of the same resultant; None without a finite-element rod or a pressure field."""
    if diagnostics.peak_load_pressure is None or not housing.structure_factory:
        return None
    theta, z = results.pressure_grid
    angle = float(results.cycle.crank_angle[diagnostics.peak_load_index])
    return housing.stresses(diagnostics.peak_load_pressure, z, angle, theta)


def _staged(progress, prefix: str):
    if progress is None:
        return None

    def report(stage: str, cycle: int, error: float) -> None:
        progress(prefix + stage, cycle, error)

    return report
