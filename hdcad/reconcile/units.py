"""Plausibility of the measured data's units against the catalog model.

A channel recorded in the wrong unit (degrees for radians, kN·m for N·m, efficiency as a
fraction) scales the data by 57.3, 1000 or 0.01 against the catalog: no physical effect
does that, so reconcile stops with a bad-input message naming the probable unit instead of
fitting effects to it. The catalog's stiffness is an average (seed 000 p.020) and real gears
scatter by tens of percent, hysteresis and play add to the twist at small torque: a factor
beyond ``IMPLAUSIBLE`` (10) is taken as a unit error, never as a gear property.

References
----------
Seed 000 p.020 (torsional stiffness, average values), p.021 (transmission error),
p.023 (efficiency in %).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

IMPLAUSIBLE = 10.0  # data / catalog scale beyond which units, not the gear, are wrong
DEG_PER_RAD = 180.0 / math.pi
KNOWN = ((DEG_PER_RAD, "degrees instead of radians"), (1000.0, "the torque in kN·m instead "
         "of N·m (or the angle in mrad)"), (1.0 / DEG_PER_RAD, "radians where degrees were "
         "meant"))


def _scale_text(scale: float) -> str:
    for factor, reading in KNOWN:
        if factor / 2.5 <= scale <= factor * 2.5:
            return f"probably {reading}"
    return "probably wrong units"


def check_units(kind: str, base) -> None:
    """InputError when the data are implausibly scaled against the catalog baseline."""
    if kind == "torsion":
        measured = base.y - np.mean(base.y)
        catalog = base.fixed - np.mean(base.fixed)
        _compare("twist_rad", _rms(measured), _rms(catalog), "the catalog twist at the "
                                                             "recorded torques")
    elif kind == "transmission":
        x, y = base.inputs.get("wg_angle_rad"), base.y
        if x is not None and np.ptp(x) > 0:
            slope = np.polyfit(x, y, 1)[0]
            expected = np.polyfit(x, base.fixed, 1)[0]
            _compare("output_angle_rad", abs(slope), abs(expected), "input angle / ratio")
    elif kind == "efficiency" and np.max(base.y) <= 1.0:
        raise InputError("efficiency_pct", "every value is ≤ 1: probably a fraction; give "
                                           "the efficiency in percent")


def _compare(column: str, measured: float, catalog: float, what: str) -> None:
    if measured <= 0 or catalog <= 0:
        return
    scale = measured / catalog
    if scale > IMPLAUSIBLE or scale < 1.0 / IMPLAUSIBLE:
        raise InputError(column, f"the data are {scale:.3g} × {what}: {_scale_text(scale)}")


def _rms(values: np.ndarray) -> float:
    return float(np.sqrt(np.mean(np.square(values))))
