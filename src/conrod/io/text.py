"""Reading input text files: UTF-8 expected, anything else reported with its byte position.

.. code-block:: python

    text = read_utf8(Path("case.toml"), "case file")
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from conrod.errors import CaseError

MAX_INPUT_BYTES = 64 * 1024 * 1024
"""Largest input text file read (a case file or a table) [bytes]."""


def read_utf8(path: str | os.PathLike[str], what: str) -> str:
    """Text of ``path`` decoded as UTF-8 (a byte-order mark is skipped).

    ``what`` names the file in messages (e.g. ``"case file"``, ``"load.table"``). Raises
    :class:`CaseError` with one line when the file cannot be read, is too large or is not
    UTF-8 (then naming the offending byte, its position, line and column).
    """
    path = Path(path)
    try:
        if path.stat().st_size > MAX_INPUT_BYTES:
            raise CaseError(f"{what} {str(path)!r}: {path.stat().st_size} bytes is too large "
                            f"(allowed: <= {MAX_INPUT_BYTES} bytes)")
        data = path.read_bytes()
    except OSError as error:
        reason = error.strerror or type(error).__name__
        raise CaseError(f"{what} {str(path)!r}: cannot be read ({reason})") from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise CaseError(f"{what} {str(path)!r}: {_position(data, error.start)}") from None


def _position(data: bytes, start: int) -> str:
    line = data.count(b"\n", 0, start) + 1
    column = start - (data.rfind(b"\n", 0, start) + 1) + 1
    return (f"not UTF-8 text: byte 0x{data[start]:02x} at byte position {start} "
            f"(line {line}, column {column}); save the file as UTF-8")


_SPREADSHEET_ERROR = re.compile(r"^\s*#(N/A|VALUE!|REF!|DIV/0!|NUM!|NAME\?|NULL!|SPILL!|CALC!)",
                                re.IGNORECASE)
"""Spreadsheet error values (``#N/A`` ...): they start with '#' but are data, not comments."""


def csv_data_lines(text: str, path: str | os.PathLike[str], what: str) -> list[tuple[int, str]]:
    """Non-blank, non-comment lines of a CSV text as (line number from 1, line).

    A line whose first non-blank character is ``#`` is a comment, unless it starts with a
    spreadsheet error value such as ``#N/A`` or ``#DIV/0!`` — that is a broken data row and
    raises :class:`CaseError` naming the line. A file without any data line raises too.
    """
    lines = []
    for number, line in enumerate(text.splitlines(), start=1):
        if _SPREADSHEET_ERROR.match(line):
            cell = line.strip().split(",")[0]
            raise CaseError(f"{what} {str(path)!r}, line {number}: {cell!r} is a spreadsheet "
                            "error value, not a number (allowed: numbers; comments start "
                            "with '# ')")
        if line.strip() and not line.lstrip().startswith("#"):
            lines.append((number, line))
    if not lines:
        raise CaseError(f"{what} {str(path)!r}: no header and no data rows (the file holds "
                        "only comments or blank lines)")
    return lines
