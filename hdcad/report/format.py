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


def check_label(check_id: str, details: dict) -> str:
    """Check id, with the bolt circle's name where one id has several records."""
    name = details.get("name")
    return f"{check_id}[{name}]" if name else check_id


def margin_text(margin: float | None) -> str:
    return "—" if margin is None else f"{margin:+.0%}"


def status_text(status: str) -> str:
    return status.upper().replace("_", " ")


SENSE_SYMBOLS = {"<=": "≤", ">=": "≥"}


def sense_text(sense: str) -> str:
    return SENSE_SYMBOLS.get(sense, sense)


# unit spellings of catalog column names (``speed_rpm`` → rpm) as printed: one spelling each
UNIT_TEXT = {"rpm": "r/min", "Nm": "N·m", "Nm_per_rad": "N·m/rad", "kgfm": "kgf·m",
             "kgfm_per_arcmin": "kgf·m/arcmin", "cNm": "cN·m", "kgfcm": "kgf·cm",
             "kgm2": "kg·m²", "pct": "%", "C": "°C", "deg": "°"}


def unit_text(unit: str | None) -> str:
    """A unit as the sheet prints it (r/min, N·m, kg·m²), whatever spelling the data uses."""
    return UNIT_TEXT.get(unit or "", unit or "")
