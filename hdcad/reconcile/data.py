"""Measured data for ``hdcad reconcile``: CSV reading and validation.

Every kind has fixed column names (SI units in the name); extra columns are ignored.
Bad files raise :class:`hdcad.errors.InputError` naming the column and the row, so the command
line prints one line and exits 2.
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np

from ..errors import InputError

KINDS = ("torsion", "transmission", "efficiency", "vibration")
COLUMNS = {"torsion": ("torque_Nm", "twist_rad"),
           "transmission": ("input_angle_rad", "output_angle_rad"),
           "efficiency": ("input_speed_rpm", "load_torque_Nm", "temperature_C",
                          "efficiency_pct"),
           "vibration": ("time_s", "input_speed_rpm", "output_vibration_rad")}
# Columns a kind uses when the file has them: a torsion test's logger time (a loop that
# follows the loading rate is fitted in seconds instead of rows, reconcile.creep).
OPTIONAL = {"torsion": ("time_s",)}
# Fewest rows per kind. Design choice: the workflow cross-validates on 5 folds of contiguous
# chunks and fits up to ~8 parameters per model, so every fold must keep several times more
# rows than parameters (efficiency: 30 rows leave 24 to fit on, 3× the largest model, and
# take a 3 temperatures × 3 speeds × 4 loads grid of 36); a loop (torsion) or a run-up
# (vibration) needs enough samples to be resolved at all.
MIN_ROWS = {"torsion": 100, "transmission": 100, "efficiency": 30, "vibration": 200}
# Transmission: the 1× and 2× harmonics are separated from each other and from the offset only
# over whole WG revolutions; one revolution is the least that can name te_1x (seed 000 p.021).
MIN_WG_REVOLUTIONS = 1.0
# An efficiency measured as output over input power reads a little below 0 or above 100 %
# where its torques' errors are large against the power (light load, a glitch), and a drifting
# torque reading carries it above 100 %; such rows are kept (a gross one is set aside as an
# outlier, a drift is the rig's). Beyond this band a row is no efficiency.
EFFICIENCY_READING_PCT = (-100.0, 200.0)
PER_MILLE = 10.0  # an efficiency read in ‰ is 10× its value in %


def read_in_per_mille(efficiency: np.ndarray) -> bool:
    """Whether an efficiency column reads in per mille (a logger's counts of 0.1 %): a median
    above 100 % is no efficiency in percent."""
    return bool(np.median(efficiency) > 100.0)


def check_kind(kind: str) -> str:
    if kind not in KINDS:
        raise InputError("kind", f"{kind!r} is not a reconcile kind; allowed: {', '.join(KINDS)}")
    return kind


def read_data(kind: str, path) -> dict[str, np.ndarray]:
    """The kind's columns of a CSV file with a header row, as float arrays.

    Raises InputError for a missing file or column, a non-numeric or non-finite cell (naming
    its column and line), too few rows, or values the kind cannot use.
    """
    from ..safe_io import read_text
    check_kind(kind)
    path = Path(path)
    # 200 MB: ten million rows of a few columns; a regular UTF-8 file only
    text = read_text(path, "DATA.csv", max_bytes=200 * 1024 * 1024)
    try:
        reader = csv.reader(io.StringIO(text, newline=""))
        header = [h.strip() for h in next(reader, [])]
        columns = _column_indices(kind, header, path.name)
        rows = [row for row in reader if "".join(row).strip()]
    except csv.Error as exc:
        raise InputError("DATA.csv", f"{path.name} is not a CSV text file ({exc})") from None
    return validate_data(kind, _parse(rows, columns, path.name))


def _column_indices(kind: str, header: list[str], name: str) -> dict[str, int]:
    if not header:
        raise InputError("DATA.csv", f"{name} is empty; expected a header row with "
                                     f"{', '.join(COLUMNS[kind])}")
    missing = [c for c in COLUMNS[kind] if c not in header]
    if missing:
        raise InputError(missing[0], f"column missing from {name}; {kind} needs "
                                     f"{', '.join(COLUMNS[kind])}")
    return {c: header.index(c) for c in COLUMNS[kind] + OPTIONAL.get(kind, ())
            if c in header}


def _parse(rows: list[list[str]], columns: dict[str, int], name: str) -> dict[str, np.ndarray]:
    try:  # numpy reads the cells as float() does; a bad cell is found row by row below
        return {c: np.array([row[i] for row in rows], dtype=float) for c, i in columns.items()}
    except (ValueError, IndexError):
        pass
    out = {c: np.empty(len(rows)) for c in columns}
    for line, row in enumerate(rows, start=2):  # line 1 is the header
        for column, index in columns.items():
            text = row[index].strip() if index < len(row) else ""
            try:
                out[column][line - 2] = float(text)
            except ValueError:
                raise InputError(column, f"{name} line {line}: {text!r} is not a number") from None
    return out


def validate_data(kind: str, data: dict) -> dict[str, np.ndarray]:
    """The same checks as :func:`read_data` for in-memory columns; returns float arrays."""
    check_kind(kind)
    missing = [c for c in COLUMNS[kind] if c not in data]
    if missing:
        raise InputError(missing[0], f"column missing; {kind} needs {', '.join(COLUMNS[kind])}")
    names = COLUMNS[kind] + tuple(c for c in OPTIONAL.get(kind, ()) if c in data)
    try:
        out = {c: np.asarray(data[c], dtype=float).ravel() for c in names}
    except (TypeError, ValueError):
        raise InputError(kind, "columns must hold numbers") from None
    lengths = {len(v) for v in out.values()}
    if len(lengths) != 1:
        raise InputError(kind, "columns have different lengths")
    n = lengths.pop()
    for column, values in out.items():
        bad = np.flatnonzero(~np.isfinite(values))
        if bad.size:
            raise InputError(column, f"row {bad[0] + 1}: {values[bad[0]]} is not a finite "
                                     "number")
    if n < MIN_ROWS[kind]:
        raise InputError(kind, f"{n} rows; {kind} needs at least {MIN_ROWS[kind]}")
    _KIND_CHECKS[kind](out)
    return out


def _check_torsion(d: dict[str, np.ndarray]) -> None:
    if np.ptp(d["torque_Nm"]) <= 0:
        raise InputError("torque_Nm", "torque is constant; torsion needs loading cycles")
    if "time_s" in d:
        back = np.flatnonzero(np.diff(d["time_s"]) < 0)
        if back.size:
            raise InputError("time_s", f"row {back[0] + 2}: time runs back (a repeated time "
                                       "is allowed; the column is optional: leave it out to "
                                       "take the rows as equally spaced)")
        if np.ptp(d["time_s"]) <= 0:
            raise InputError("time_s", "time does not advance (the column is optional: leave "
                                       "it out to take the rows as equally spaced)")


def _check_transmission(d: dict[str, np.ndarray]) -> None:
    """Nothing before the units are read: an input angle in revolutions spans 2π times
    fewer 'radians' (:func:`check_revolutions` once they are)."""


def check_revolutions(d: dict[str, np.ndarray]) -> None:
    """A transmission record with its units read spans ``MIN_WG_REVOLUTIONS`` at least."""
    turns = np.ptp(d["input_angle_rad"]) / (2 * math.pi)
    if turns < MIN_WG_REVOLUTIONS:
        raise InputError("input_angle_rad", f"spans {turns:.2f} WG revolutions; transmission "
                                            f"needs at least {MIN_WG_REVOLUTIONS:g}")


def _check_efficiency(d: dict[str, np.ndarray]) -> None:
    eta = d["efficiency_pct"]
    low, high = EFFICIENCY_READING_PCT
    # a reading in per mille is converted with the units (units.find_fix)
    per_mille = PER_MILLE if read_in_per_mille(eta) else 1.0
    if eta.min() < low * per_mille or eta.max() > high * per_mille:
        raise InputError("efficiency_pct", f"must lie in {low:g}…{high:g} % (an efficiency, "
                                           "0…100 %, with its reading's error; or "
                                           f"{low * PER_MILLE:g}…{high * PER_MILLE:g} ‰)")
    if np.median(eta) <= 0:
        raise InputError("efficiency_pct", "median must be > 0 % (most rows read no power "
                                           "out: no efficiency test)")
    if (d["load_torque_Nm"] <= 0).any():
        raise InputError("load_torque_Nm", "must be > 0 (efficiency under load)")


def _check_vibration(d: dict[str, np.ndarray]) -> None:
    dt = np.diff(d["time_s"])
    if (dt <= 0).any():
        row = int(np.flatnonzero(dt <= 0)[0]) + 2
        raise InputError("time_s", f"row {row}: time must increase strictly")
    if (d["input_speed_rpm"] < 0).any():
        raise InputError("input_speed_rpm", "must be ≥ 0 (a run-up)")


_KIND_CHECKS = {"torsion": _check_torsion, "transmission": _check_transmission,
                "efficiency": _check_efficiency, "vibration": _check_vibration}
