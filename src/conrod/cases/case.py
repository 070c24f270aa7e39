"""The case file: one TOML document, validated section by section.

.. code-block:: python

    case = Case.from_toml("examples/passenger_car_diesel_2000rpm.toml")
    case.engine.bore        # [m]

Relative file names inside the case (pressure traces, load tables) are resolved
against the folder of the case file (:meth:`Case.resolve`).
"""

from __future__ import annotations

import os
import tomllib
from pathlib import Path

from pydantic import Field, PrivateAttr, model_validator

from conrod.cases.base import Section, validate_section
from conrod.cases.bearing import BearingSection
from conrod.cases.contact import ContactSection
from conrod.cases.engine import EngineSection
from conrod.cases.housing import HousingSection
from conrod.cases.limits import LimitsSection
from conrod.cases.load import LoadTableSection
from conrod.cases.lubricant import LubricantSection
from conrod.cases.mechanism import ClearanceSection
from conrod.cases.misalignment import MisalignmentSection
from conrod.cases.rules import check_case
from conrod.cases.solver import SolverSection
from conrod.errors import CaseError
from conrod.io.text import read_utf8

ADDED_LATER = (("misalignment",), ("bearing", "profile"), ("bearing", "profile_file"),
               ("housing", "assembly"), ("housing", "thermal"), ("bearing", "journal_holes"),
               ("limits",))
"""Optional items added to the schema after cases were hashed: left out of
:meth:`Case.content_hash` while unset (None or an empty list), so an existing case keeps
its hash."""
ADDED_LATER_IN_ITEMS = (("bearing", "grooves", "fed_by_journal_holes", False),)
"""(section, list, key, default) of keys added later to the items of a list: left out of
the hash while at their default."""


class Case(Section):
    """A whole case file. Sections are optional here; each command says which it needs."""

    title: str | None = Field(default=None, min_length=1,
                              description="Free text shown on reports [-]")
    source: str | None = Field(default=None, min_length=1,
                               description="Citation of where the numbers come from [-]")
    engine: EngineSection | None = None
    bearing: BearingSection | None = None
    lubricant: LubricantSection | None = None
    load: LoadTableSection | None = None
    solver: SolverSection = SolverSection()
    contact: ContactSection = ContactSection()
    clearance: ClearanceSection | None = None
    housing: HousingSection = HousingSection()
    misalignment: MisalignmentSection | None = None
    limits: LimitsSection | None = None

    @model_validator(mode="after")
    def _check_housing_closes(self) -> Case:
        """The built-in rod must close (wall > 0, shank narrower than the head, ...)."""
        if self.housing.model == "builtin" and self.bearing is not None:
            rod_length = self.engine.rod_length if self.engine is not None else None
            self.housing.rod_outline(self.bearing.diameter, rod_length)
        return self

    @model_validator(mode="after")
    def _cross_section_rules(self) -> Case:
        check_case(self)
        return self

    _base_dir: Path = PrivateAttr(default_factory=Path.cwd)
    _path: Path | None = PrivateAttr(default=None)

    @classmethod
    def from_toml(cls, path: str | os.PathLike[str]) -> Case:
        """Read and validate a case file; raise :class:`CaseError` on any problem."""
        if not isinstance(path, str | os.PathLike):
            raise CaseError(f"Case.from_toml: path = {path!r}: a case-file path is required "
                            "(str or Path; Case.from_dict(data) for a dict)")
        path = Path(path)
        text = read_utf8(path, "case file")
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as error:
            raise CaseError(f"case file {str(path)!r}: not valid TOML ({error})") from None
        try:
            return cls.from_dict(data, base_dir=path.resolve().parent, path=path)
        except CaseError as error:
            lines = str(error).splitlines()
            raise CaseError("\n".join(f"case file {str(path)!r}: {line}" for line in lines)
                            ) from None

    @classmethod
    def from_dict(
        cls, data: dict, *, base_dir: str | os.PathLike[str] | None = None, path: Path | None = None
) -> Case:
        """Validate a case given as a dict (as parsed from TOML)."""
        case = validate_section(cls, data)
        case._base_dir = Path(base_dir) if base_dir is not None else Path.cwd()
        case._path = path
        if case.bearing is not None and case.bearing.profile_file is not None:
            case.bearing.read_profile_file(case.resolve(case.bearing.profile_file))
        return case

    def with_(self, **changes: object) -> Case:
        """A changed copy, validated like a case file. ``section__field=value`` sets one
        field (``case.with_(engine__speed=3000)``), ``field=value`` a top-level item; raise
        :class:`CaseError` naming the field when the copy is not a valid case."""
        data = self.model_dump(mode="python", exclude_unset=True)
        for key, value in changes.items():
            *sections, name = key.split("__")
            target = data
            for section in sections:
                if not isinstance(target.get(section, {}), dict):
                    raise CaseError(f"with_({key}=...): {section!r} is not a section")
                target = target.setdefault(section, {})
            target[name] = value
        return Case.from_dict(data, base_dir=self._base_dir, path=self._path)

    def content_hash(self) -> str:
        """SHA-256 (hex) of the validated case content, the same for equal cases (file
        names as written, not the files' content) [-]."""
        import hashlib
        import json

        data = self.model_dump(mode="json")
        for path in ADDED_LATER:  # unset, they hash as absent: a case keeps its hash
            owner = data
            for key in path[:-1]:
                owner = owner.get(key) or {}
            if path[-1] in owner and owner[path[-1]] in (None, []):
                del owner[path[-1]]
        for section, items, key, default in ADDED_LATER_IN_ITEMS:
            for item in (data.get(section) or {}).get(items) or ():
                if item.get(key, default) == default:
                    item.pop(key, None)
        text = json.dumps(data, sort_keys=True, default=str)
        return hashlib.sha256(text.encode("utf-8")).hexdigest()

    @property
    def path(self) -> Path | None:
        """The case file this case was read from, if any."""
        return self._path

    @property
    def base_dir(self) -> Path:
        """Folder against which relative file names in the case are resolved."""
        return self._base_dir

    def resolve(self, name: str | os.PathLike[str]) -> Path:
        """Absolute path of a file named in the case (relative to the case file's folder)."""
        candidate = Path(name)
        return candidate if candidate.is_absolute() else self._base_dir / candidate

    def require(self, command: str, *sections: str) -> None:
        """Raise :class:`CaseError` if a section needed by ``command`` is absent."""
        missing = [name for name in sections if getattr(self, name) is None]
        if missing:
            where = f" {str(self._path)!r}" if self._path else ""
            raise CaseError(
                f"case file{where} lacks the section(s) "
                + ", ".join(f"[{name}]" for name in missing)
                + f" needed by '{command}'"
)
