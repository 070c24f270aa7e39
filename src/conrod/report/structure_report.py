"""Pages of result folders other than runs and sweeps: the housing study (``conrod
housing``), the rod-stress study (``conrod stress``), engine loads and mechanism runs. Each
shows what its command wrote: its summary in words and units, its figures with their
captions (from ``manifest.json``), the case it records and its files."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pandas as pd

from conrod.report.html import Image, Section, Table

TITLES = {"housing": "Elastic big end (housing study)", "stress": "Rod stresses",
          "loads": "Engine loads", "mechanism": "Slider-crank with clearances",
          "mechanism_sweep": "Operating-mode sweep of the mechanism"}
"""Manifest kind → page title."""


def other_sections(folder: Path, manifest: dict[str, Any]) -> tuple[str, list[Section]]:
    """(title, sections) of the page of a housing, stress, loads or mechanism folder."""
    kind = str(manifest.get("kind", ""))
    sections: list[Section] = []
    if kind == "stress":
        sections += _stress_sections(folder)
    sections += _summary_sections(folder, manifest)
    sections += _input_sections(folder, manifest)
    images = [Image(f.get("title", f["file"]), f.get("caption", ""),
                    (folder / f["file"]).read_bytes())
              for f in manifest.get("figures", []) if (folder / f["file"]).is_file()]
    if images:
        sections.append(Section("Figures", images))
    sections.append(Section("Result files", [Table(
        ["file", "title", "caption"],
        [[t["file"], t.get("title", ""), t.get("caption", "")]
         for t in manifest.get("tables", [])], "Tables written into the results folder.")]))
    return f"{TITLES.get(kind, 'conrod results')}: {folder.name}", sections


def _stress_sections(folder: Path) -> list[Section]:
    summary = _json(folder / "stress_summary.json")
    section = Section("Which pressure loads the rod", [
        f"Rod loaded by the {summary.get('pressure_source', 'film pressure of a run')}."])
    run = summary.get("pressure_run") or {}
    facts = [f"{key} = {_shown(value)}" for key, value in run.items() if value not in (None, [])]
    if facts:
        section.blocks.append("That run: " + "; ".join(facts) + ".")
    maxima = folder / "stress_maxima.csv"
    if maxima.is_file():
        frame = pd.read_csv(maxima)
        rows = [[f"{row.crank_angle_deg:g}", str(row.scheme),
                 f"{row.max_von_mises_Pa / 1e6:.1f}",
                 f"{row.big_end_max_von_mises_Pa / 1e6:.1f}",
                 f"{row.largest_displacement_m * 1e6:.1f}"] for row in frame.itertuples()]
        section.blocks.append(Table(
            ["crank angle [deg]", "load scheme", "max von Mises [MPa]",
             "big-end max [MPa]", "largest displacement [µm]"], rows,
            "Largest von Mises stress of the rod per crank angle under the film pressure "
            "and under a cosine load of the same resultant.",
            numeric=("max von Mises [MPa]", "big-end max [MPa]",
                     "largest displacement [µm]")))
    return [section]


def _summary_sections(folder: Path, manifest: dict[str, Any]) -> list[Section]:
    """Every JSON table of the folder as a table of its items (units in the key names)."""
    sections = []
    for table in manifest.get("tables", []):
        name = str(table.get("file", ""))
        if not name.endswith(".json") or not (folder / name).is_file():
            continue
        rows = [[key, _shown(value)] for key, value in _flat(_json(folder / name)).items()]
        if rows:
            sections.append(Section(table.get("title", name), [Table(
                ["item (unit in the name)", "value"], rows,
                f"{name}: {table.get('caption', '')}", numeric=("value",))]))
    return sections


def _input_sections(folder: Path, manifest: dict[str, Any]) -> list[Section]:
    from conrod.report.run_report import inputs_section

    recorded = manifest.get("case")
    if not isinstance(recorded, dict) or not (folder / str(recorded.get("file", ""))).is_file():
        return []
    return [inputs_section(folder / recorded["file"], None, (), recorded.get("set") or None,
                           recorded.get("source_name", ""))]


def _flat(data: Any, prefix: str = "") -> dict[str, Any]:
    if not isinstance(data, dict):
        return {prefix: data} if prefix else {}
    flat: dict[str, Any] = {}
    for key, value in data.items():
        name = f"{prefix}.{key}" if prefix else str(key)
        if isinstance(value, dict):
            flat.update(_flat(value, name))
        else:
            flat[name] = value
    return flat


def _json(path: Path) -> dict[str, Any]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def _shown(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, list):
        return ", ".join(_shown(item) for item in value) or "–"
    return "–" if value is None else str(value)
