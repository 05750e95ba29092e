"""Channels in the wrong unit: found before any fit, corrected and reported as a rig finding.

A channel recorded in the wrong unit (degrees, arc-minutes or arc-seconds for radians, kN·m
or kgf·m for N·m, an input angle in revolutions or degrees, efficiency as a fraction or in
per mille) scales the data by 57.3, 3438, 206265, 1000, 9.81, 6.28, 1/57.3, 0.01 or 10
against the catalog: no
physical effect does that. The catalog's stiffness is an average (seed 000 p.020) and real
gears scatter by tens of percent, hysteresis and play add to the twist at small torque, so
only a factor beyond ``IMPLAUSIBLE`` (5) is taken as a unit error. When the factor is one of
the usual unit mistakes the channel is converted and the finding reported (``wrong_units``,
a measurement-chain effect); when it is not, reconcile stops with a bad-input message.

References
----------
Seed 000 p.020 (torsional stiffness, average values), p.021 (transmission error),
p.023 (efficiency in %, load torque up to rated).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .data import PER_MILLE, read_in_per_mille

IMPLAUSIBLE = 5.0  # data / catalog scale beyond which units, not the gear, are wrong
DEG_PER_RAD = 180.0 / math.pi
# A unit factor is accepted when the observed scale is within this factor of it: the
# catalog scatter and the effects move the scale by tens of percent, never by 2×.
MATCH = 2.0
# Efficiency tests run up to about rated torque (seed 000 p.023): a largest load below this
# share of the rated torque is a torque in kN·m.
TINY_LOAD = 0.01
# Two torsion unit readings whose shape misfits against the catalog curve are within this
# factor fit equally well (the test stayed on the curve's first segment)
SHAPE_TIE = 1.1


@dataclass(frozen=True)
class UnitFix:
    """A channel converted: ``data[column] *= factor``."""

    column: str
    factor: float
    reading: str
    observed_scale: float

    def as_dict(self) -> dict:
        return {"effect": "wrong_units", "column": self.column, "factor": self.factor,
                "reading": self.reading, "observed_scale": self.observed_scale}


# the catalog's own angle units: twist in arc-min (seed 000 p.020's worked example, seed 003's
# stiffness tables), transmission accuracy in arc-sec (seed 003 tables 051-1 and 059-1)
ANGLE_UNITS = (("degrees", DEG_PER_RAD), ("arc-minutes", 60.0 * DEG_PER_RAD),
               ("arc-seconds", 3600.0 * DEG_PER_RAD))


def _angle_fixes(column: str, what: str) -> tuple:
    return tuple((column, 1 / per_rad, f"{what} in {unit} instead of radians", per_rad)
                 for unit, per_rad in ANGLE_UNITS)


# (column, factor applied, reading, the scale it explains) per kind
# the catalog's other torque unit: kgf·m (seed 003's rating and stiffness tables print it
# beside N·m; 1 kgf·m = 9.80665 N·m, ISO 80000-4 standard gravity)
KGF_M = 9.80665
TORSION_FIXES = _angle_fixes("twist_rad", "twist") + (
    ("torque_Nm", 1000.0, "torque in kN·m instead of N·m", 1000.0),
    ("torque_Nm", KGF_M, "torque in kgf·m instead of N·m", KGF_M),
    ("twist_rad", 1e-3, "twist in mrad instead of rad", 1000.0))
TRANSMISSION_FIXES = _angle_fixes("output_angle_rad", "output angle") + (
    ("input_angle_rad", 2 * math.pi, "input angle in revolutions instead of radians",
     2 * math.pi),
    ("input_angle_rad", 1 / DEG_PER_RAD, "input angle in degrees instead of radians",
     1 / DEG_PER_RAD))


def _rms(values: np.ndarray) -> float:
    return float(np.sqrt(np.mean(np.square(values))))


def torsion_scale(data: dict, twist_of) -> float:
    """Measured twist / catalog twist at the recorded torques (RMS about the means)."""
    catalog = twist_of(data["torque_Nm"])
    measured = data["twist_rad"] - np.mean(data["twist_rad"])
    expected = _rms(catalog - np.mean(catalog))
    return _rms(measured) / expected if expected > 0 else 1.0


def shape_misfit(data: dict, twist_of) -> float:
    """RMS of the measured twist about the catalog curve scaled and offset to it (least
    squares), as a share of the twist's RMS about its mean [-]."""
    y = data["twist_rad"]
    X = np.column_stack([twist_of(data["torque_Nm"]), np.ones_like(y)])
    residual = y - X @ np.linalg.lstsq(X, y, rcond=None)[0]
    spread = _rms(y - np.mean(y))
    return _rms(residual) / spread if spread > 0 else 0.0


def torsion_fix(data: dict, fixes: list[UnitFix], twist_of) -> UnitFix:
    """The unit fix whose reading the catalog curve fits best. kN·m torque and a twist in
    mrad give the same scale against a linear curve, but the curve stiffens at T1 and T2:
    only the right torque unit puts those corners where the data bend. The shape decides
    (misfits within ``SHAPE_TIE`` of the best count as equal), then the scale nearest 1."""
    read = {fix: apply(data, [fix]) for fix in fixes}
    misfit = {fix: shape_misfit(read[fix], twist_of) for fix in fixes}
    best = min(misfit.values())
    tied = [fix for fix in fixes if misfit[fix] <= SHAPE_TIE * best]
    return min(tied, key=lambda f: abs(math.log(torsion_scale(read[f], twist_of))))


def find_fix(kind: str, data: dict, twist_of=None, ratio: float | None = None,
             rated_torque: float | None = None) -> list[UnitFix]:
    """Unit fixes the data need (possibly several candidates for torsion, best first is
    chosen by the caller); InputError when the data are implausibly scaled but no usual unit
    mistake explains it."""
    if kind == "torsion":
        scale = torsion_scale(data, twist_of)
        if 1 / IMPLAUSIBLE <= scale <= IMPLAUSIBLE:
            return []
        fixes = [UnitFix(c, f, r, scale) for c, f, r, s in TORSION_FIXES
                 if s / MATCH <= scale <= s * MATCH]
        if not fixes:
            raise InputError("twist_rad", f"the data are {scale:.3g} × the catalog twist at "
                                          "the recorded torques: probably wrong units")
        return fixes
    if kind == "transmission":
        x, y = data["input_angle_rad"], data["output_angle_rad"]
        if np.ptp(x) > 0:
            scale = abs(np.polyfit(x, y, 1)[0]) * ratio
            for column, factor, reading, explains in TRANSMISSION_FIXES:
                if explains / MATCH <= scale <= explains * MATCH:
                    return [UnitFix(column, factor, reading, scale)]
            if not 1 / IMPLAUSIBLE <= scale <= IMPLAUSIBLE:
                raise InputError("output_angle_rad", f"the output turns {scale:.3g} × input "
                                 "angle / ratio: probably wrong units or the wrong model")
        return []
    if kind == "efficiency":
        fixes = []
        if np.max(data["efficiency_pct"]) <= 1.0:
            fixes.append(UnitFix("efficiency_pct", 100.0, "efficiency as a fraction instead "
                                 "of percent", 0.01))
        if read_in_per_mille(data["efficiency_pct"]):
            fixes.append(UnitFix("efficiency_pct", 1.0 / PER_MILLE, "efficiency in per mille "
                                 "(‰, a logger's counts of 0.1 %) instead of percent",
                                 PER_MILLE))
        if rated_torque and np.max(np.abs(data["load_torque_Nm"])) < TINY_LOAD * rated_torque:
            fixes.append(UnitFix("load_torque_Nm", 1000.0, "load torque in kN·m instead of "
                                 "N·m", np.max(np.abs(data["load_torque_Nm"])) / rated_torque))
        return fixes
    return []


def apply(data: dict, fixes: list[UnitFix]) -> dict:
    out = dict(data)
    for fix in fixes:
        out[fix.column] = np.asarray(out[fix.column], dtype=float) * fix.factor
    return out
