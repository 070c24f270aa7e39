"""Nastran matrices: DMIG bulk data entries and OP4 (OUTPUT4) files, read and written
(docs/elastic.md; the common types in :mod:`conrod.housing.matrix_formats`).

* **DMIG** (bulk data, MSC Nastran Quick Reference Guide): the header entry
  ``DMIG, NAME, 0, IFO, TIN, TOUT, POLAR, , NCOL`` and column entries
  ``DMIG, NAME, GJ, CJ, , G1, C1, A1, B1`` continued by ``G, C, A, B`` quadruplets; small
  field (8 characters), large field (``DMIG*``, 16 characters) or free field (commas);
  reals with ``E``, ``D`` or the implicit exponent (``1.5-3``). IFO = 6 (symmetric) may give
  one triangle; real matrices only (TIN = 1 or 2).
* **OP4** (OUTPUT4): ASCII — a header ``NCOL NROW FORM TYPE NAME [format]``, then
  per column ``ICOL IROW NW`` and the values from row IROW on (dense), or ``ICOL 0 NW``
  followed by string headers (one integer IS = IROW + 65536 (L + 1); two integers
  ``L+1 IROW`` when NROW < 0, the BIGMAT form), or ``ICOL −IROW NW`` per string (NASTRAN-95
  sparse); the record ICOL = NCOL + 1 ends the matrix. Binary — Fortran unformatted
  sequential records with 4-byte length markers, either byte order: the header record
  (NCOL, NROW, FORM, TYPE, NAME) and per column (ICOL, IROW, NW, NW single-precision
  words of values, two per double). Real matrices only; a binary sparse (string) matrix
  is refused.
"""

from __future__ import annotations

import re
import struct
from pathlib import Path

import numpy as np

from conrod.housing.matrix_formats import (
    FormatError,
    LabelledMatrix,
    integer_field,
    nastran_real,
    symmetric_from_triangle,
)


# ----------------------------------------------------------------------- Nastran DMIG
def _card_fields(lines: list[str]) -> list[list[str]]:
    """Bulk-data entries as lists of data fields (the entry name first, continuation
    markers dropped), from small-field, large-field and free-field lines."""
    cards: list[list[str]] = []
    for raw in lines:
        line = raw.split("$", 1)[0].rstrip("\n\r")
        if not line.strip():
            continue
        head = line[:8]
        if "," in line:  # free field: name or continuation marker first
            fields = [field.strip() for field in line.split(",")]
            first, data = fields[0], fields[1:]
            if len(data) > 8:
                data = data[:8]  # a trailing continuation marker
        elif head.strip().endswith("*") or head.startswith("*"):  # large field
            first = head.strip()
            data = [line[8 + 16 * k:24 + 16 * k] for k in range(4)]
        else:  # small field
            first = head.strip()
            data = [line[8 + 8 * k:16 + 8 * k] for k in range(8)]
        continuation = first == "" or first.startswith(("+", "*"))
        if continuation and cards:
            cards[-1].extend(data)
        elif not continuation:
            cards.append([first.rstrip("*").upper(), *data])
    return cards


def read_dmig(path: Path, name: str | None = None) -> LabelledMatrix:
    """The real matrix ``name`` (the only one when None) of a Nastran DMIG file, its rows
    labelled (grid, component) in the order the file first names them."""
    try:
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError as error:
        raise FormatError(f"cannot be read ({error})") from None
    entries = [card for card in _card_fields(lines) if card[0] == "DMIG"]
    headers = {card[1].strip().upper(): card for card in entries if card[2].strip() == "0"}
    if not headers:
        raise FormatError("holds no DMIG header entry (DMIG, NAME, 0, IFO, TIN, ...)")
    if name is None and len(headers) > 1:
        raise FormatError(f"holds the DMIG matrices {', '.join(sorted(headers))} (set "
                          "housing.matrix_name to one of them)")
    key = (name or next(iter(headers))).upper()
    if key not in headers:
        raise FormatError(f"holds no DMIG matrix {key!r} (found: {', '.join(sorted(headers))})")
    header = headers[key]
    ifo, tin = integer_field(header[3], "IFO"), integer_field(header[4], "TIN")
    if tin not in (1, 2):
        raise FormatError(f"DMIG {key} has TIN = {tin}: a complex matrix (allowed: 1 or 2, "
                          "real)")
    triplets = []
    for card in entries:
        if card[1].strip().upper() != key or card[2].strip() == "0":
            continue
        column = (integer_field(card[2], "GJ"), integer_field(card[3], "CJ"))
        rest = card[5:]
        for k in range(0, len(rest) - 2, 4):
            if not rest[k].strip():
                continue
            row = (integer_field(rest[k], "G"), integer_field(rest[k + 1], "C"))
            triplets.append((row, column, nastran_real(rest[k + 2])))
    return _labelled(triplets, symmetric=ifo == 6)


def _labelled(triplets, symmetric: bool) -> LabelledMatrix:
    labels: list[tuple[int, int]] = []
    index: dict[tuple[int, int], int] = {}
    for row, column, _ in triplets:
        for label in (column, row):
            if label not in index:
                index[label] = len(labels)
                labels.append(label)
    size = len(labels)
    matrix, given = np.zeros((size, size)), np.zeros((size, size), dtype=bool)
    for row, column, value in triplets:
        matrix[index[row], index[column]] = value
        given[index[row], index[column]] = True
    if symmetric:
        matrix = symmetric_from_triangle(matrix, given)
    return LabelledMatrix(matrix, labels)


def nastran_field_real(value: float, width: int) -> str:
    """The most precise text of ``value`` that fits a field of ``width`` characters: fixed
    point, or the mantissa with the implicit exponent (``6.02364+0``) [-]."""
    candidates = []
    for digits in range(width, -1, -1):
        text = f"{value:.{digits}f}"
        if len(text) <= width and float(text) != 0.0 or value == 0.0:
            candidates.append(text if len(text) <= width else "0.")
            break
    for digits in range(width, -1, -1):
        mantissa, exponent = f"{value:.{digits}E}".split("E")
        text = f"{mantissa}{int(exponent):+d}"
        if len(text) <= width:
            candidates.append(text)
            break
    return min(candidates, key=lambda text: abs(nastran_real(text) - value))


def write_dmig(path: Path, name: str, matrix: np.ndarray, labels: list[tuple[int, int]],
               field: str = "large") -> Path:
    """Write the lower triangle of the symmetric ``matrix`` as DMIG ``name`` (IFO = 6,
    TIN = TOUT = 2) with rows labelled (grid, component), in ``field`` format: 'small',
    'large' or 'free'."""
    n = len(labels)
    header = ["DMIG", name, "0", "6", "2", "2", "", "", str(n)]
    cards = [header]
    for j in range(n):
        card = ["DMIG", name, str(labels[j][0]), str(labels[j][1]), ""]
        for i in range(j, n):
            if matrix[i, j] != 0.0 or i == j:
                card += [str(labels[i][0]), str(labels[i][1]), "", ""]
                card[-2] = repr(float(matrix[i, j]))
        cards.append(card)
    lines = ["$ DMIG written by conrod (bulk data entries, to include)"]
    for card in cards:
        lines += _format_card(card, field)
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _format_card(card: list[str], field: str) -> list[str]:
    name, data = card[0], card[1:]
    if field == "free":
        chunks = [data[k:k + 8] for k in range(0, len(data), 8)] or [[]]
        return [",".join([name if k == 0 else "+", *chunk]) for k, chunk in enumerate(chunks)]
    width, per_line = (8, 8) if field == "small" else (16, 4)
    out = []
    for k in range(0, max(len(data), 1), per_line):
        chunk = data[k:k + per_line]
        texts = [_fit(text, width) for text in chunk]
        first = (name + ("*" if width == 16 else "")) if k == 0 else ("*" if width == 16
                                                                       else "+")
        out.append(f"{first:<8}" + "".join(f"{text:>{width}}" for text in texts))
    return out


def _fit(text: str, width: int) -> str:
    if len(text) <= width:
        return text
    return nastran_field_real(float(text), width)


# ------------------------------------------------------------------------ Nastran OP4
_FORTRAN_REAL = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+)(?:[EeDd][-+]?\d+)?")


def _op4_values(line: str) -> list[float]:
    return [float(token.upper().replace("D", "E")) for token in _FORTRAN_REAL.findall(line)]


def read_op4(path: Path, name: str | None = None) -> LabelledMatrix:
    """The real matrix ``name`` (the first when None) of an ASCII or binary OP4 file."""
    try:
        data = path.read_bytes()
    except OSError as error:
        raise FormatError(f"cannot be read ({error})") from None
    binary = len(data) >= 4 and struct.unpack("<i", data[:4])[0] in (24, 28) or (
        len(data) >= 4 and struct.unpack(">i", data[:4])[0] in (24, 28))
    matrices = _op4_binary(data) if binary else _op4_ascii(data.decode("ascii", "replace"))
    if not matrices:
        raise FormatError("holds no OP4 matrix")
    if name is None:
        return LabelledMatrix(next(iter(matrices.values())))
    key = name.upper()
    if key not in matrices:
        raise FormatError(f"holds no OP4 matrix {key!r} (found: {', '.join(matrices)})")
    return LabelledMatrix(matrices[key])


def _op4_header(fields: tuple[int, ...]) -> tuple[int, int, bool]:
    ncol, nrow, _, kind = fields
    if abs(kind) not in (1, 2):
        raise FormatError(f"OP4 matrix of TYPE {kind}: complex (allowed: 1 or 2, real)")
    return ncol, abs(nrow), nrow < 0


_OP4_HEAD = re.compile(r"^\s*(-?\d+)\s+(-?\d+)\s+(-?\d+)\s+(-?\d+)\s*([A-Za-z]\S*)?")


def _op4_ascii(text: str) -> dict[str, np.ndarray]:
    lines = [line for line in text.splitlines() if line.strip()]
    matrices: dict[str, np.ndarray] = {}
    k = 0
    while k < len(lines):
        head = _OP4_HEAD.match(lines[k])
        if head is None:
            raise FormatError(f"line {k + 1} is not an OP4 header (NCOL NROW FORM TYPE NAME)")
        ncol, nrow, bigmat = _op4_header(tuple(int(head.group(i)) for i in range(1, 5)))
        name = (head.group(5) or f"MATRIX{len(matrices) + 1}").upper()
        matrix = np.zeros((nrow, ncol))
        k += 1
        column, row = 0, 0
        while k < len(lines):
            line = lines[k]
            if column > ncol and _OP4_HEAD.match(line):
                break  # the next matrix
            if "." in line:  # values
                values = _op4_values(line)
                if column > ncol:
                    k += 1
                    continue
                if row < 1 or row + len(values) - 1 > nrow:
                    raise FormatError(f"line {k + 1}: values beyond the {nrow} rows")
                matrix[row - 1:row - 1 + len(values), column - 1] = values
                row += len(values)
                k += 1
                continue
            numbers = [int(value) for value in line.split()]
            if len(numbers) == 3:
                if column > ncol:
                    break  # the next matrix
                column, row = numbers[0], numbers[1]
                row = -row if row < 0 else row
            elif len(numbers) == 1:
                row = numbers[0] % 65536
            elif len(numbers) == 2 and bigmat:
                row = numbers[1]
            else:
                raise FormatError(f"line {k + 1} is neither a column nor a string header")
            k += 1
        matrices[name] = matrix
    return matrices


def _op4_binary(data: bytes) -> dict[str, np.ndarray]:
    endian = "<" if struct.unpack("<i", data[:4])[0] in (24, 28) else ">"
    records, position = [], 0
    while position + 4 <= len(data):
        (length,) = struct.unpack(endian + "i", data[position:position + 4])
        end = position + 4 + length
        if length < 0 or end + 4 > len(data):
            raise FormatError(f"binary record at byte {position} runs past the end of the file")
        records.append(data[position + 4:end])
        position = end + 4
    matrices: dict[str, np.ndarray] = {}
    k = 0
    while k < len(records):
        head = records[k]
        ncol, nrow, bigmat = _op4_header(tuple(struct.unpack(endian + "4i", head[:16])))
        name = head[16:24].decode("ascii", "replace").strip().upper() or "MATRIX"
        kind = struct.unpack(endian + "4i", head[:16])[3]
        real = endian + ("d" if abs(kind) == 2 else "f")
        size = 8 if abs(kind) == 2 else 4
        matrix = np.zeros((nrow, ncol))
        k += 1
        while k < len(records):
            column, row, words = struct.unpack(endian + "3i", records[k][:12])
            k += 1
            if column > ncol:
                break
            if row == 0 or bigmat:
                raise FormatError("binary sparse OP4 (string) matrices are not read; write "
                                  "the matrix dense or as ASCII")
            count = words * 4 // size
            values = struct.unpack(f"{real[0]}{count}{real[1]}", records[k - 1][12:12 + count
                                                                                   * size])
            matrix[row - 1:row - 1 + count, column - 1] = values
        matrices[name] = matrix
    return matrices


def write_op4(path: Path, name: str, matrix: np.ndarray, binary: bool = False) -> Path:
    """Write ``matrix`` as a dense real double-precision OP4 (FORM 6 when symmetric, else
    2): ASCII in ``1P,3E23.16`` or binary (little-endian Fortran records)."""
    matrix = np.asarray(matrix, dtype=float)
    nrow, ncol = matrix.shape
    form = 6 if nrow == ncol and np.array_equal(matrix, matrix.T) else 2
    if binary:
        return _write_op4_binary(path, name, matrix, form)
    lines = [f"{ncol:8d}{nrow:8d}{form:8d}{2:8d}{name[:8]:<8}1P,3E23.16"]
    for column in range(ncol):
        nonzero = np.flatnonzero(matrix[:, column])
        if nonzero.size == 0:
            continue
        first, last = nonzero[0], nonzero[-1]
        values = matrix[first:last + 1, column]
        lines.append(f"{column + 1:8d}{first + 1:8d}{values.size:8d}")
        for k in range(0, values.size, 3):
            lines.append("".join(f"{value:23.16E}" for value in values[k:k + 3]))
    lines.append(f"{ncol + 1:8d}{1:8d}{1:8d}")
    lines.append(f"{1.0:23.16E}")
    path.write_text("\n".join(lines) + "\n", encoding="ascii")
    return path


def _write_op4_binary(path: Path, name: str, matrix: np.ndarray, form: int) -> Path:
    def record(payload: bytes) -> bytes:
        return struct.pack("<i", len(payload)) + payload + struct.pack("<i", len(payload))

    nrow, ncol = matrix.shape
    out = [record(struct.pack("<4i", ncol, nrow, form, 2) + f"{name[:8]:<8}".encode())]
    for column in range(ncol):
        nonzero = np.flatnonzero(matrix[:, column])
        if nonzero.size == 0:
            continue
        first, last = nonzero[0], nonzero[-1]
        values = matrix[first:last + 1, column]
        out.append(record(struct.pack("<3i", column + 1, first + 1, 2 * values.size)
                          + values.astype("<f8").tobytes()))
    out.append(record(struct.pack("<3i", ncol + 1, 1, 2) + struct.pack("<d", 0.0)))
    path.write_bytes(b"".join(out))
    return path


