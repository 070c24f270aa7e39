"""Result files of the contact analysis: wear tables and figures (atomic writes)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from conrod.io.atomic import write_csv


def write_wear_tables(contact, out_dir: Path) -> list[Path]:
    """``wear_journal.csv`` and ``wear_shell.csv`` with angle_deg, friction_work_J, wear_m."""
    wear = contact.wear
    angle = np.degrees(wear.element_angle)
    return [
        write_csv(out_dir / "wear_journal.csv", {
            "angle_deg": angle, "friction_work_J": wear.journal_work, "wear_m": wear.journal_wear,
        }),
        write_csv(out_dir / "wear_shell.csv", {
            "angle_deg": angle, "friction_work_J": wear.shell_work, "wear_m": wear.shell_wear,
        }),
    ]


def write_contact_figures(contact, out_dir: Path) -> list[Path]:
    """contact_cycle.png (seed Fig. 4.3.2), wear_unrolled.png and wear_polar.png (Fig. 4.5.1),
    contact_stress_surfaces.png (Fig. 4.4.1)."""
    from conrod.plotting.contact_plots import (
        plot_contact_cycle,
        plot_contact_stress_surfaces,
        plot_wear_polar,
        plot_wear_unrolled,
    )
    from conrod.plotting.save import save_figure

    return [
        save_figure(plot_contact_cycle(contact), out_dir / "contact_cycle.png"),
        save_figure(plot_wear_unrolled(contact), out_dir / "wear_unrolled.png"),
        save_figure(plot_wear_polar(contact), out_dir / "wear_polar.png"),
        save_figure(plot_contact_stress_surfaces(contact), out_dir / "contact_stress_surfaces.png"),
    ]


def write_contact_files(contact, out_dir: Path) -> list[Path]:
    """All contact result files in ``out_dir``; returns their paths."""
    out_dir.mkdir(parents=True, exist_ok=True)
    return write_wear_tables(contact, out_dir) + write_contact_figures(contact, out_dir)
