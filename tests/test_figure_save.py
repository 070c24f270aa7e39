"""A figure's PNG drawn once (:func:`conrod.plotting.save.figure_bytes`): the single Agg
render cut to the padded tight box is ``savefig(bbox_inches="tight")`` 's image within a
fraction of a pixel, and pixel for pixel ``savefig`` 's image of the same box moved to whole
pixels; a figure that overhangs its canvas is drawn by ``savefig`` itself; every figure of
the README job fits its canvas.

The figures are those of the README job (KamAZ-740, elastic big end, Reynolds film),
coarsened as in ``tests/test_outputs_elastic.py`` (36 × 8 grid, massless orbit).
"""

from __future__ import annotations

import io

import matplotlib
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.transforms import Bbox
from PIL import Image

import conrod.output  # noqa: F401  (registers the tables and figures)
from conrod import Simulation
from conrod.output.registry import FIGURE_DPI, figures
from conrod.plotting.save import figure_bytes, png_drawn_once
from elastic_helpers import kamaz_case

pytestmark = pytest.mark.slow

README_JOB_FIGURES = (
    "orbit.png", "hmin_pmax.png", "friction_flow.png", "pressure_map.png",
    "film_thickness_map.png", "min_film_envelope.png", "indicator_maps_shell.png",
    "indicator_maps_journal.png", "erosion_map.png", "hmin_pmax_rigid_elastic.png",
    "deformed_bore.png", "deformed_film_maps.png", "von_mises_film_pressure.png",
    "von_mises_cosine_load.png")
"""The figures ``conrod run examples/kamaz_740_truck_diesel.toml --film reynolds`` writes."""
PIXELS_TIPPED = 1e-4
"""Share of the pixels that may differ between a figure drawn once and ``savefig`` 's image
of its box on whole pixels [-]: ``savefig`` shifts the figure by the box's corner in floating
point, k / dpi × dpi, which can tip a pixel on an edge (measured: none in 13 of the 14
figures, 2 of the orbit's 603 000); a cut one pixel off differs in thousands."""


def _savefig(figure: Figure, bbox_inches="tight") -> bytes:
    """``figure`` as ``savefig`` writes it (no "Software" entry) [PNG bytes]."""
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=FIGURE_DPI, bbox_inches=bbox_inches,
                   metadata={"Software": None})
    return buffer.getvalue()


def _rgb(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=float)


def _half_a_pixel(image: np.ndarray) -> float:
    """The mean absolute difference of the RGB values [0–255] of ``image`` and itself half a
    pixel across and half a pixel down, taken as half of that one pixel across plus half of
    that one pixel down."""
    across = np.abs(image[:, 1:] - image[:, :-1]).mean()
    down = np.abs(image[1:] - image[:-1]).mean()
    return 0.5 * (across + down)


def _box_on_whole_pixels(figure: Figure) -> Bbox:
    """The padded tight box [in] of ``figure`` drawn with its layout, its corner moved to
    the nearest pixel."""
    figure.set_dpi(FIGURE_DPI)
    canvas = FigureCanvasAgg(figure)
    canvas.draw()
    box = figure.get_tightbbox(canvas.get_renderer()).padded(
        matplotlib.rcParams["savefig.pad_inches"])
    x0, y0 = (round(corner * FIGURE_DPI) / FIGURE_DPI for corner in box.p0)
    return Bbox.from_bounds(x0, y0, box.width, box.height)


@pytest.fixture(scope="module")
def readme_job():
    case = kamaz_case(n_theta=36, n_z=8, film="reynolds", integrator="quasi_static",
                      quasi_static_step_deg=2.0, output_step_deg=4.0)
    return {spec.file: spec.build for spec in figures(Simulation(case).run())}


@pytest.fixture(scope="module")
def drawn(readme_job):
    """File → (``savefig(bbox_inches="tight")`` 's PNG, the PNG drawn once or None)."""
    return {file: (_savefig(build()), png_drawn_once(build(), FIGURE_DPI))
            for file, build in readme_job.items()}


def test_every_figure_of_the_readme_job_is_drawn_once(drawn):
    assert tuple(drawn) == README_JOB_FIGURES
    assert [file for file, (_, once) in drawn.items() if once is None] == []


def test_a_figure_drawn_once_is_savefig_s_image_within_a_fraction_of_a_pixel(drawn):
    """Same size within 2 px each way; the mean absolute difference of the RGB values no
    larger than ``savefig`` 's image moved by half a pixel each way: measured 0.21 (erosion
    map) to 0.70 (orbit) of that bound, 0.9 to 3.9 of 255."""
    for file, (tight, once) in drawn.items():
        today, fast = _rgb(tight), _rgb(once)
        assert np.all(np.abs(np.subtract(today.shape, fast.shape)) <= (2, 2, 0)), file
        rows, columns = min(today.shape[0], fast.shape[0]), min(today.shape[1], fast.shape[1])
        difference = np.abs(today[:rows, :columns] - fast[:rows, :columns]).mean()
        assert difference <= _half_a_pixel(today), (file, difference, _half_a_pixel(today))


def test_a_figure_drawn_once_is_savefig_s_image_of_its_box_on_whole_pixels(readme_job,
                                                                           drawn):
    """The only difference from ``savefig(bbox_inches="tight")``: where the box starts."""
    for file, build in readme_job.items():
        whole = _rgb(_savefig(build(), _box_on_whole_pixels(build())))
        once = _rgb(drawn[file][1])
        assert whole.shape == once.shape, file
        tipped = np.any(whole != once, axis=2).mean()
        assert tipped <= PIXELS_TIPPED, (file, tipped)


def test_the_written_file_is_the_figure_drawn_once_without_the_software_entry(readme_job,
                                                                             drawn):
    once = drawn["orbit.png"][1]
    assert figure_bytes(readme_job["orbit.png"](), "png", dpi=FIGURE_DPI) == once
    image = Image.open(io.BytesIO(once))
    assert "Software" not in image.info
    assert image.info["dpi"] == pytest.approx((FIGURE_DPI, FIGURE_DPI), abs=0.01)


def _overhanging() -> Figure:
    """A figure whose legend hangs out of the canvas to the right."""
    figure = Figure(figsize=(4.0, 3.0))
    axes = figure.subplots()
    axes.plot([0.0, 1.0], [0.0, 1.0], label="a line")
    axes.legend(loc="center left", bbox_to_anchor=(1.05, 0.5))
    return figure


def test_a_figure_overhanging_its_canvas_is_drawn_by_savefig():
    assert png_drawn_once(_overhanging(), FIGURE_DPI) is None
    written = figure_bytes(_overhanging(), "png", dpi=FIGURE_DPI)
    assert written == _savefig(_overhanging())
    assert Image.open(io.BytesIO(written)).width > 4.0 * FIGURE_DPI  # nothing cut


def test_other_formats_are_written_by_savefig_without_a_date():
    written = figure_bytes(_overhanging(), "pdf", dpi=FIGURE_DPI)
    buffer = io.BytesIO()
    _overhanging().savefig(buffer, format="pdf", dpi=FIGURE_DPI, bbox_inches="tight",
                           metadata={"CreationDate": None})
    assert written == buffer.getvalue() and b"/CreationDate" not in written
