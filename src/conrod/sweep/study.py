"""The study file: a base case, axes of values, and how they combine.

.. code-block:: toml

    base = "../passenger_car_diesel_2000rpm.toml"   # relative to the study file
    mode = "product"                                 # or "zip"

    [override.solver]                                # applied to every variant
    integrator = "quasi_static"

    [[axis]]
    key = "bearing.radial_clearance"                 # any dotted case key [unit of the key]
    values = [20e-6, 25e-6, 30e-6]

    [[axis]]
    key = "engine.speed"
    start = 1000
    stop = 3000
    num = 3

    [[axis]]
    key = "case"                                     # whole case files as an axis
    files = ["a.toml", "b.toml"]

``command = "mechanism"`` makes every variant a ``conrod mechanism`` run (clearance joints,
impacts) instead of the orbit of ``conrod run``.

Every variant is resolved and validated (:meth:`Study.variants`) before anything runs;
a bad key or value raises :class:`CaseError` naming the axis, the key and the value.
"""

from __future__ import annotations

import itertools
import os
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import Field, model_validator

from conrod.cases.base import Section, validate_section
from conrod.errors import CaseError
from conrod.io.interrupts import raise_if_interrupted
from conrod.sweep.variant import CASE_AXIS, Variant, resolve_variant


class AxisSection(Section):
    """One ``[[axis]]``: a dotted case key and its values (a list, or start/stop/num)."""

    key: str = Field(min_length=1, description="Dotted case key, e.g. bearing.radial_clearance [-]")
    values: list[Any] | None = Field(default=None, description="Values, in the key's unit")
    start: float | None = Field(default=None, description="First value, in the key's unit")
    stop: float | None = Field(default=None, description="Last value, in the key's unit")
    num: int | None = Field(default=None, ge=1, le=100000, description="Number of values [-]")
    files: list[str] | None = Field(
        default=None, description="Case files (key = \"case\"), relative to the study file [-]"
    )

    @model_validator(mode="after")
    def _one_form(self) -> AxisSection:
        forms = [self.values is not None, self.start is not None or self.stop is not None
                 or self.num is not None, self.files is not None]
        if sum(forms) != 1:
            raise ValueError(f"axis {self.key!r}: give exactly one of values = [...], "
                             "start/stop/num, or files = [...] (key = \"case\")")
        if (self.files is not None) != (self.key == CASE_AXIS):
            raise ValueError(f"axis {self.key!r}: files = [...] goes with key = \"case\" only")
        if forms[1] and None in (self.start, self.stop, self.num):
            raise ValueError(f"axis {self.key!r}: start, stop and num are all needed")
        return self

    def axis_values(self) -> list[Any]:
        """The values of this axis in study order."""
        if self.files is not None:
            return list(self.files)
        if self.values is not None:
            return list(self.values)
        return [float(v) for v in np.linspace(self.start, self.stop, self.num)]


class StudySection(Section):
    """A whole study file."""

    base: str | None = Field(default=None, description="Base case file, relative to the study [-]")
    mode: Literal["product", "zip"] = Field(default="product", description="How axes combine [-]")
    command: Literal["run", "mechanism"] = Field(
        default="run", description="What a variant computes: the orbit of 'conrod run' or the "
        "clearance-joint mechanism of 'conrod mechanism' [-]")
    title: str = Field(default="", description="Free text shown on reports [-]")
    override: dict[str, Any] = Field(
        default_factory=dict, description="Case keys set in every variant (nested tables) [-]"
    )
    axis: list[AxisSection] = Field(min_length=1, description="The axes of the study [-]")

    @model_validator(mode="after")
    def _consistent(self) -> StudySection:
        keys = [a.key for a in self.axis]
        repeated = sorted({k for k in keys if keys.count(k) > 1})
        if repeated:
            raise ValueError(f"axis key {repeated[0]!r} appears more than once")
        if self.base is None and CASE_AXIS not in keys:
            raise ValueError("study needs base = \"CASE.toml\" or an axis with key = \"case\"")
        if self.mode == "zip":
            lengths = {a.key: len(a.axis_values()) for a in self.axis}
            if len(set(lengths.values())) > 1:
                raise ValueError(f"mode = \"zip\" needs axes of equal length, got {lengths}")
        return self


@dataclass
class Study:
    """A validated study: its file, its axes and every resolved variant."""

    spec: StudySection
    folder: Path
    path: Path | None = None

    @classmethod
    def from_toml(cls, path: str | os.PathLike[str]) -> Study:
        """Read and validate a study file (not yet its variants: see :meth:`variants`)."""
        if not isinstance(path, str | os.PathLike) or not str(path):
            raise CaseError(f"study file = {path!r}: not a file path (allowed: the path of a "
                            "study file, e.g. 'examples/studies/passenger_car_3x3.toml')")
        path = Path(path)
        try:
            data = tomllib.loads(path.read_text(encoding="utf-8"))
        except OSError as error:
            raise CaseError(
                f"study file {str(path)!r}: cannot be read ({error.strerror})") from None
        except tomllib.TOMLDecodeError as error:
            raise CaseError(f"study file {str(path)!r}: not valid TOML ({error})") from None
        return cls.from_dict(data, folder=path.resolve().parent, path=path)

    @classmethod
    def from_dict(cls, data: dict, *, folder: str | os.PathLike[str] | None = None,
                  path: Path | None = None) -> Study:
        """Validate a study given as a dict; relative files resolve against ``folder``."""
        prefix = f"study {str(path)!r}" if path else "study"
        if not isinstance(data, dict):
            raise CaseError(f"{prefix} = {type(data).__name__}: not a table (allowed: a dict "
                            "of the study file's keys)")
        if folder is not None and not isinstance(folder, str | os.PathLike):
            raise CaseError(f"folder = {folder!r}: not a folder path (allowed: None or a "
                            "path)")
        try:
            spec = validate_section(StudySection, data)
        except CaseError as error:
            raise CaseError(f"{prefix}: {error}") from None
        return cls(spec, Path(folder) if folder is not None else Path.cwd(), path)

    @property
    def axis_keys(self) -> list[str]:
        """Dotted keys of the axes, in study order."""
        return [a.key for a in self.spec.axis]

    def points(self) -> list[dict[str, Any]]:
        """Axis values of every variant (product: last axis varies fastest)."""
        columns = [a.axis_values() for a in self.spec.axis]
        combos = zip(*columns, strict=True) if self.spec.mode == "zip" else itertools.product(
            *columns)
        return [dict(zip(self.axis_keys, combo, strict=True)) for combo in combos]

    def base_file(self, point: dict[str, Any]) -> Path:
        """The case file a variant starts from (the case axis, else ``base``)."""
        name = point.get(CASE_AXIS, self.spec.base)
        candidate = Path(str(name))
        return candidate if candidate.is_absolute() else self.folder / candidate

    def variants(self) -> list[Variant]:
        """Every variant resolved and validated; the first bad one raises :class:`CaseError`.
        Under the CLI's Ctrl-C handling, Ctrl-C stops it between two variants."""
        variants = []
        for index, point in enumerate(self.points()):
            raise_if_interrupted()
            variants.append(resolve_variant(self.base_file(point), point, self.spec.override,
                                            index, self.spec.command))
        return variants
