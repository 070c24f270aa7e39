"""Sections of the report of one run folder (``conrod run`` output or a sweep variant).

Figures and tables are listed by the folder's ``manifest.json`` (title and caption of each
file) when it has one; otherwise the known file names of ``conrod run`` are captioned here
and the figures a folder lacks (sweep variants are written without figures) are drawn from
``cycle.csv`` and the wear tables.
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path
from typing import Any

import pandas as pd

from conrod.report.headline import comparison_section, headline_section, summary_section
from conrod.report.html import Image, Section, Table
from conrod.report.inputs import header_notes, input_rows

FILE_CAPTIONS = {
    "orbit.png": ("Journal-centre orbit", "Path of the journal centre relative to the shell "
                  "over the last (periodic) cycle, film frame, in µm, inside the clearance "
                  "circle; labels give the crank angle in degrees."),
    "hmin_pmax.png": ("Minimum film thickness and maximum film pressure", "h_min in µm (top) "
                      "and p_max in MPa (bottom) against crank angle in degrees over the last "
                      "cycle; shaded where the journal touches the shell."),
    "friction_flow.png": ("Friction power and oil flow", "Film friction power loss in W (top) "
                          "and side and supply flow in l/min (bottom) against crank angle in "
                          "degrees."),
    "pressure_map.png": ("Film pressure field at the largest p_max", "Gauge film pressure "
                         "p(θ, z) in MPa over the shell angle θ in degrees and the axial "
                         "position z in mm, at the crank angle of the largest p_max."),
    "contact_cycle.png": ("Contact over the cycle", "Contact stress in MPa with the "
                          "accumulated friction work in J (top), h_min in µm and p_max in MPa "
                          "against crank angle in degrees."),
    "wear_unrolled.png": ("Friction work and wear on journal and shell", "Friction work per "
                          "surface element in J and wear per cycle in nm against the surface "
                          "angle in degrees."),
    "wear_polar.png": ("Friction work around journal and shell", "Friction work per surface "
                       "element in J around the journal and the shell (polar, surface angle "
                       "in degrees)."),
    "contact_stress_surfaces.png": ("Largest contact stress on the surfaces", "Largest Hertz "
                                    "contact stress over the cycle in MPa against the surface "
                                    "angle in degrees on journal and shell."),
}
"""Figure files of ``conrod run`` → (title, caption), used when there is no manifest."""

SECTIONS = (
    ("Journal-centre orbit", ("orbit.png",), "orbit"),
    ("Minimum film thickness and maximum pressure", ("hmin_pmax.png", "pressure_map.png"),
     "hmin_pmax"),
    ("Friction and oil flow", ("friction_flow.png",), "friction_flow"),
    ("Contact and wear", ("contact_cycle.png", "wear_unrolled.png", "wear_polar.png",
                          "contact_stress_surfaces.png"), "contact"),
)
"""(section title, figure files, drawing used when none of the files exists)."""


def read_manifest(folder: Path) -> dict[str, Any] | None:
    """``manifest.json`` of a results folder, or None."""
    try:
        return json.loads((folder / "manifest.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def read_json(path: Path) -> dict[str, Any]:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}


def figure_catalogue(folder: Path, manifest: dict[str, Any] | None) -> dict[str, tuple]:
    """Figure file → (title, caption), in the manifest's order or by file name."""
    if manifest is not None:
        return {f["file"]: (f.get("title", f["file"]), f.get("caption", ""))
                for f in manifest.get("figures", []) if (folder / f["file"]).is_file()}
    return {p.name: FILE_CAPTIONS.get(p.name, (p.stem.replace("_", " "),
                                               f"Figure file {p.name} written by conrod."))
            for p in sorted(folder.glob("*.png"))}


def inputs_section(case_file: Path | None, case_data: dict | None,
                   swept: tuple[str, ...] = (), set_values: dict[str, Any] | None = None,
                   source_name: str = "") -> Section:
    """The case's inputs with units and the sources its comments cite; ``set_values``
    (dotted key → value) are the values the run set on top of the file; ``source_name``:
    the name of the file the result folder's copy ``case_file`` was taken from."""
    section = Section("Case inputs")
    if case_file is None and case_data is None:
        section.blocks.append("The case file is not known for this folder (a result folder "
                              "written by an older conrod); give it with --case to list the "
                              "inputs.")
        return section
    if case_file is not None:
        section.blocks.append(f"Case file: {source_name} (its copy in the result folder: "
                              f"{case_file.name})" if source_name else
                              f"Case file: {case_file.name}")
        notes = header_notes(case_file.read_text(encoding="utf-8")) if case_file.is_file() \
            else []
        if notes:
            section.blocks.append(" ".join(notes))
    if set_values:
        section.blocks.append("Set for this run on top of the case file (command-line "
                              "options): " + ", ".join(f"{k} = {_value(v)}"
                                                       for k, v in set_values.items()) + ".")
    rows = input_rows(case_file, case_data, swept, tuple(set_values or ()))
    section.blocks.append(Table(["key", "value", "unit", "source"],
                                [[r["key"], r["value"], r["unit"], r["source"]] for r in rows],
                                "Every key of the case; units from the case-file schema, "
                                "sources from the comments in the case file.",
                                numeric=("value",)))
    return section


def run_sections(folder: Path, case_file: Path | None = None) -> tuple[str, list[Section]]:
    """(title, sections) of the report of one run folder: headline with the warnings box,
    the rigid-vs-elastic comparison, the cycle summary, the inputs, then the figures."""
    from conrod.plotting import report_plots as plots

    manifest = read_manifest(folder)
    summary = read_json(folder / "summary.json")
    record = read_json(folder / "variant.json")
    case_data = record.get("case") or None
    if case_file is None and record.get("case_file"):
        case_file = Path(record["case_file"])
    recorded = (manifest or {}).get("case") if case_file is None and case_data is None \
        else None
    set_values = None
    if isinstance(recorded, dict) and (folder / str(recorded.get("file", ""))).is_file():
        case_file = folder / recorded["file"]
        set_values = recorded.get("set") or None
        case_data = _recorded_data(case_file, recorded)
    cycle = _csv(folder / "cycle.csv")
    sections = [headline_section(summary)] if summary else []
    if record.get("axes"):
        sections[0].blocks.insert(0, "Sweep variant: " + ", ".join(
            f"{k} = {v}" for k, v in record["axes"].items()))
    comparison = comparison_section(summary)
    if comparison is not None:
        sections.append(comparison)
    if summary:
        sections.append(summary_section(summary))
    sections.append(inputs_section(case_file, case_data, tuple(record.get("axes", {})),
                                   set_values, (recorded or {}).get("source_name", "")))
    engine_figures = engine_load_images(case_file, case_data)
    if engine_figures:
        sections.append(Section("Engine load diagrams", engine_figures))
    if cycle is not None:
        sections.append(Section("Load on the bearing", [Image(
            "Load diagram", "Load pressing the journal on the shell in the film frame, in kN: "
            "polar diagram (left, labels give the crank angle in degrees) and magnitude "
            "against crank angle in degrees (right).", plots.png_bytes(
                plots.load_diagram_figure(cycle)))]))
    sections += _figure_sections(folder, manifest, cycle)
    if manifest is not None and manifest.get("tables"):
        sections.append(Section("Result files", [Table(
            ["file", "title", "caption"],
            [[t["file"], t.get("title", ""), t.get("caption", "")] for t in manifest["tables"]],
            "Tables written into the results folder.")]))
    title = (case_data or {}).get("title") or f"conrod results: {folder.name}"
    return title, sections


def _figure_sections(folder: Path, manifest: dict | None, cycle) -> list[Section]:
    """The figure sections in their order, drawn from cycle.csv where the folder has none
    (a sweep variant written without figures); contact and wear only where the journal
    touched the shell."""
    catalogue = figure_catalogue(folder, manifest)
    sections = []
    for title, files, drawing in SECTIONS:
        images = [_file_image(folder, name, catalogue.pop(name)) for name in files
                  if name in catalogue]
        if not images and cycle is not None and (drawing != "contact" or _touches(cycle)):
            images = [_drawn(drawing, folder, cycle)]
        if images:
            sections.append(Section(title, images))
    if catalogue:
        sections.append(Section("Further figures", [_file_image(folder, name, entry)
                                                    for name, entry in catalogue.items()]))
    return sections


def _touches(cycle) -> bool:
    return "contact_force_N" in cycle and float(cycle["contact_force_N"].max()) > 0.0


def _recorded_data(case_file: Path, recorded: dict) -> dict | None:
    """The recorded case's values: the file with the values set on top (dotted keys)."""
    try:
        data = tomllib.loads(case_file.read_text(encoding="utf-8"))
    except (OSError, UnicodeError, tomllib.TOMLDecodeError):
        return None
    for key, value in (recorded.get("set") or {}).items():
        *sections, name = key.split(".")
        target = data
        for part in sections:
            target = target.setdefault(part, {})
        target[name] = value
    for key, name in (recorded.get("tables") or {}).items():
        section, field = key.split(".", 1)
        data.setdefault(section, {})[field] = name
    return data


def engine_load_images(case_file: Path | None, case_data: dict | None) -> list[Image]:
    """Polar load diagram, loads over the cycle and wear diagram of an ``[engine]`` case."""
    from conrod.cases.case import Case
    from conrod.errors import ConrodError
    from conrod.loads.engine_loads import compute_engine_loads
    from conrod.plotting import loads_plots
    from conrod.plotting.report_plots import png_bytes

    try:
        if case_data is not None:
            base = case_file.resolve().parent if case_file else None
            case = Case.from_dict(case_data, base_dir=base, path=case_file)
        elif case_file is not None:
            case = Case.from_toml(case_file)
        else:
            return []
        if case.engine is None or case.load is not None:  # table loads: no engine diagrams
            return []
        loads = compute_engine_loads(case)
    except ConrodError:
        return []
    return [
        Image("Polar load diagram of the crankpin", "Rod force on the crankpin in the crank "
              "frame in kN (tangential against radial), poles O and O' shifted by the "
              "rotating-mass force, labels give the crank angle in degrees; right: the low "
              "loads enlarged.", png_bytes(loads_plots.plot_polar_load_diagram(loads))),
        Image("Big-end load over the cycle", "Load magnitude with its mean (top) and gas, "
              "radial and tangential forces (bottom) in kN against crank angle in degrees "
              "from firing TDC.", png_bytes(loads_plots.plot_load_over_crank_angle(loads))),
        Image("Wear diagram of the crankpin", "Relative wear of the journal in the crank "
              "frame (strips proportional to the load, ±60° about each load direction; "
              "dimensionless, scaled to the largest) around the crankpin, angles in degrees "
              "from the outward crank radius; the arrow marks the oil-hole direction.",
              png_bytes(loads_plots.plot_wear_diagram(loads))),
    ]


def _file_image(folder: Path, name: str, entry: tuple) -> Image:
    return Image(entry[0], entry[1], (folder / name).read_bytes())


def _drawn(drawing: str, folder: Path, cycle: pd.DataFrame) -> Image:
    from conrod.plotting import report_plots as plots

    if drawing == "orbit":
        return Image("Journal-centre orbit", "Path of the journal centre relative to the shell "
                     "over the last cycle, film frame, in µm, inside the clearance circle.",
                     plots.png_bytes(plots.orbit_from_table(cycle)))
    if drawing == "hmin_pmax":
        return Image("Minimum film thickness and maximum film pressure", "h_min in µm (top) "
                     "and p_max in MPa (bottom) against crank angle in degrees.",
                     plots.png_bytes(plots.hmin_pmax_from_table(cycle)))
    if drawing == "friction_flow":
        return Image("Friction power and oil flow", "Film friction power loss in W (top) and "
                     "side and supply flow in l/min (bottom) against crank angle in degrees.",
                     plots.png_bytes(plots.friction_flow_from_table(cycle)))
    journal, shell = _csv(folder / "wear_journal.csv"), _csv(folder / "wear_shell.csv")
    return Image("Contact force and wear", "Hard-contact force in kN against crank angle in "
                 "degrees (top) and wear per cycle in nm on journal and shell against the "
                 "surface angle in degrees (bottom).",
                 plots.png_bytes(plots.contact_wear_from_tables(cycle, journal, shell)))


def _csv(path: Path) -> pd.DataFrame | None:
    return pd.read_csv(path) if path.is_file() else None


def _value(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    return "–" if value is None else str(value)
