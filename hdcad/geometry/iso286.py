"""ISO 286 limits of the fits the generated parts carry (holes H7, H8, M7; shafts g6, h7,
k5, h11, f7), from catalog tables ``iso286_h7_g6`` and ``iso286_grades_deviations``.

References
----------
ISO 286-1:2010 Table 1 (standard tolerance grades), ISO 286-2:2010 (fundamental deviations).
"""

from __future__ import annotations

from ..catalog import Catalog
from .part import Fit

CODES = ("H7", "H8", "M7", "g6", "h7", "k5", "h11", "f7")


def _row(catalog: Catalog, table: str, nominal_mm: float) -> dict:
    row = next((r for r in catalog.rows(table) if r["over_mm"] < nominal_mm <= r["upto_mm"]),
               None)
    if row is None:
        raise ValueError(f"Ø{nominal_mm:g} is outside the ISO 286 ranges of table {table}")
    return row


def deviations_um(catalog: Catalog, nominal_mm: float, code: str) -> tuple[float, float]:
    """(upper, lower) deviation [µm] of tolerance class ``code`` at ``nominal_mm``."""
    a = _row(catalog, "iso286_h7_g6", nominal_mm)
    b = _row(catalog, "iso286_grades_deviations", nominal_mm)
    table = {"H7": lambda: (a["IT7_um"], 0.0),
             "H8": lambda: (b["IT8_um"], 0.0),
             "M7": lambda: (0.0, -a["IT7_um"]),
             "g6": lambda: (-a["g_es_below_zero_um"], -a["g_es_below_zero_um"] - a["IT6_um"]),
             "k5": lambda: (b["k_ei_um"] + b["IT5_um"], b["k_ei_um"]),
             "h7": lambda: (0.0, -a["IT7_um"]),
             "h11": lambda: (0.0, -b["IT11_um"]),
             "f7": lambda: (-b["f_es_below_zero_um"], -b["f_es_below_zero_um"] - a["IT7_um"])}
    if code not in table:
        raise ValueError(f"fit {code!r} is not tabulated; known: {', '.join(CODES)}")
    return table[code]()


def iso286_fit(catalog: Catalog, feature: str, nominal_mm: float, code: str, mate: str,
               reason: str) -> Fit:
    """A Fit record with its ISO 286 deviations [µm]; capital codes are holes."""
    source = (catalog.table("iso286_h7_g6").source if code in ("H7", "g6") else
              "ISO 286-1:2010 Table 1 / ISO 286-2:2010 (iso286_grades_deviations)")
    return Fit(feature, nominal_mm, code, "hole" if code[0].isupper() else "shaft",
               deviations_um(catalog, nominal_mm, code), mate, reason, source)
