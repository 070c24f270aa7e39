"""The report as PDF, printed by a headless Chromium (or Chrome) from the HTML file."""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from conrod.errors import CaseError
from conrod.io.atomic import atomic_path

BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable", "chrome")
"""Executables tried in this order (``CONROD_BROWSER`` overrides)."""

HEADLESS_FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                  "--no-first-run", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--no-pdf-header-footer")
PRINT_TIMEOUT_S = 120.0


def find_browser() -> str:
    """Path of a Chromium-family browser, or :class:`CaseError` saying how to get one."""
    override = os.environ.get("CONROD_BROWSER")
    for name in ((override,) if override else BROWSERS):
        found = shutil.which(name)
        if found:
            return found
    raise CaseError("--pdf needs a Chromium or Chrome browser, none found on PATH "
                    f"(tried {', '.join((override,) if override else BROWSERS)}); install one, "
                    "e.g. 'apt-get install chromium', or set CONROD_BROWSER")


def html_to_pdf(html_file: Path, pdf_file: Path) -> Path:
    """Print ``html_file`` to ``pdf_file`` (atomically) with the headless browser."""
    browser = find_browser()
    with tempfile.TemporaryDirectory(prefix="conrod-browser-") as profile, \
            atomic_path(pdf_file) as tmp:
        command = [browser, *HEADLESS_FLAGS, f"--user-data-dir={profile}",
                   f"--print-to-pdf={tmp}", Path(html_file).resolve().as_uri()]
        done = subprocess.run(command, capture_output=True, text=True, timeout=PRINT_TIMEOUT_S,
                              check=False)
        if done.returncode != 0 or tmp.stat().st_size == 0:
            last = (done.stderr.strip().splitlines() or ["no output"])[-1]
            raise CaseError(f"{browser} could not print {html_file} to PDF "
                            f"(exit {done.returncode}: {last})")
    return pdf_file
