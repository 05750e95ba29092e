"""How numbers and labels are printed, the same on the console and in the calculation sheet."""

from __future__ import annotations


def fmt(value, digits: int = 4) -> str:
    """A number for a table: thousands separators above 1000, else 4 significant digits."""
    if value is None:
        return "—"
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        return "yes" if value else "no"
    if value != value or value in (float("inf"), float("-inf")):
        return str(value)
    if abs(value) >= 1000:
        return f"{value:,.0f}"
    return f"{value:.{digits}g}"


def check_label(check_id: str, details: dict, criterion: bool = True) -> str:
    """Check id, with the bolt circle's name where one id has several records, and (unless
    ``criterion`` is False) the governing criterion where a check has several: the one its
    row's numbers belong to."""
    name, governing = details.get("name"), details.get("governing")
    label = f"{check_id}[{name}]" if name else check_id
    return f"{label} {governing}" if governing and criterion else label


def margin_text(margin: float | None) -> str:
    return "—" if margin is None else f"{margin:+.0%}"


def status_text(status: str) -> str:
    return status.upper().replace("_", " ")


SENSE_SYMBOLS = {"<=": "≤", ">=": "≥"}


def sense_text(sense: str) -> str:
    return SENSE_SYMBOLS.get(sense, sense)


# the relation that holds between value and limit when the check's own sense does not
FAILED_SENSE = {"<=": ">", ">=": "<"}


def relation_text(sense: str | None, status: str) -> str:
    """Operator printed between value and limit, true for the printed numbers.

    A passing check prints its sense (``319.7 ≤ 620``); a failing one prints the relation
    that made it fail (``0.1888 < 0.2``), so ``value op limit`` never reads as a pass.
    """
    if not sense:
        return ""
    # a warning with numbers is a value beyond a guide: the printed relation is the broken one
    return FAILED_SENSE.get(sense, sense) if status in ("fail", "warn") else sense_text(sense)


# unit spellings of catalog column names (``speed_rpm`` → rpm) as printed: one spelling each
UNIT_TEXT = {"rpm": "r/min", "Nm": "N·m", "Nm_per_rad": "N·m/rad", "kgfm": "kgf·m",
             "kgfm_per_arcmin": "kgf·m/arcmin", "cNm": "cN·m", "kgfcm": "kgf·cm",
             "kgm2": "kg·m²", "pct": "%", "C": "°C", "deg": "°"}


def unit_text(unit: str | None) -> str:
    """A unit as the sheet prints it (r/min, N·m, kg·m²), whatever spelling the data uses."""
    return UNIT_TEXT.get(unit or "", unit or "")
