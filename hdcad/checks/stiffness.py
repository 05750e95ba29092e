"""Torsional stiffness, twist and torsional resonance.

References
----------
Seed 000 p.020: three-segment torque-twist curve K1 (0…T1), K2 (T1…T2), K3 (> T2); twist
example CSF-25-100: 2.9 N·m → 9.4×10⁻⁵ rad, 39 N·m → 9.4×10⁻⁴ rad.
Seed 000 p.021 (formulas 021-2, 021-3): f = (1/2π)·√(K/J); the transmission error has two
cycles per wave-generator revolution, so the resonant input speed is N = f/2·60
(15 Hz → 450 r/min).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

from ..duty import Segment
from .record import CheckResult, Quantity, compared, not_evaluated
from .rules import label

RESONANCE_BAND = 0.20
BAND_REASON = (
    "±20 % band on input speed: the catalog stiffness is an average value (tables 052-1/060-1) "
    "and f ∝ √(K/J), so ±20 % in speed covers K/J from −36 % to +44 %, i.e. stiffness scatter "
    "plus housing and shaft compliance not in the catalog value")


class MissingStiffness(ValueError):
    """The curve lacks a value needed at this torque."""


@dataclass(frozen=True)
class StiffnessCurve:
    """Three-segment torque-twist curve; T [N·m], K [N·m/rad], θ [rad]. None = missing."""

    K1: float | None
    T1: float | None = None
    K2: float | None = None
    T2: float | None = None
    K3: float | None = None
    theta1: float | None = None
    theta2: float | None = None

    @classmethod
    def linear(cls, k: float) -> "StiffnessCurve":
        """A single spring constant over the whole range (FD table 314-1)."""
        return cls(K1=k, T1=math.inf)

    def segment(self, torque_Nm: float) -> int:
        t = abs(torque_Nm)
        if self.T1 is not None and t <= self.T1:
            return 1
        if self.T1 is None:
            raise MissingStiffness("T1")
        if self.T2 is None:
            raise MissingStiffness("T2")
        return 2 if t <= self.T2 else 3

    def _theta1(self) -> float:
        return self.theta1 if self.theta1 is not None else self.T1 / self._need("K1")

    def _theta2(self) -> float:
        if self.theta2 is not None:
            return self.theta2
        return self._theta1() + (self.T2 - self.T1) / self._need("K2")

    def _need(self, name: str) -> float:
        value = getattr(self, name)
        if value is None:
            raise MissingStiffness(name)
        return value

    def twist(self, torque_Nm: float, segment: int | None = None) -> float:
        """Twist θ [rad] at torque T [N·m] (sign follows T).

        ``segment`` (1, 2, 3) may be given when the region is known but a boundary is not,
        as in the CSF-25-100 example: "39 N·m lies between T1 and T2" with T2 not printed.
        """
        t, sign = abs(torque_Nm), math.copysign(1.0, torque_Nm)
        seg = segment or self.segment(t)
        if seg == 1:
            return sign * t / self._need("K1")
        if seg == 2:
            return sign * (self._theta1() + (t - self.T1) / self._need("K2"))
        return sign * (self._theta2() + (t - self.T2) / self._need("K3"))

    def tangent(self, torque_Nm: float) -> float:
        """Spring constant [N·m/rad] of the segment that holds torque T [N·m]."""
        return self._need(f"K{self.segment(torque_Nm)}")


def natural_frequency(stiffness_Nm_per_rad: float, inertia_kgm2: float) -> float:
    """f = (1/2π)·√(K/J) [Hz]; K [N·m/rad], J [kg·m²]. Seed 000 formula 021-3."""
    return math.sqrt(stiffness_Nm_per_rad / inertia_kgm2) / (2.0 * math.pi)


def resonant_input_speed(frequency_Hz: float) -> float:
    """Input speed N [r/min] whose 2-per-revolution error excites f: N = f/2·60."""
    return frequency_Hz / 2.0 * 60.0


FORMULA = "f = (1/2π)·√(K/J);  N_res = f/2·60;  |ni − N_res|/N_res ≥ 20 % for steady segments"
TITLE = "Torsional resonance"


def torsional_resonance(cycle: Sequence[Segment], ratio: float, curve: StiffnessCurve | None,
                        inertia_kgm2: float | None, source: str,
                        band: float = RESONANCE_BAND) -> CheckResult:
    """Steady input speeds against the resonant input speed (separation ≥ ``band`` passes;
    the band is hdcad's own rule, see ``hdcad.checks.rules``)."""
    if inertia_kgm2 is None:
        return not_evaluated("torsional_resonance", TITLE, "stiffness", FORMULA,
                             "load_inertia_kgm2 (add it to the duty)")
    if curve is None:
        return not_evaluated("torsional_resonance", TITLE, "stiffness", FORMULA,
                             "torsional stiffness K1/K2/K3 missing from the catalog")
    steady = [s for s in cycle if s.phase == "steady" and s.speed_rpm > 0] or \
             [s for s in cycle if s.speed_rpm > 0]
    rows = []
    try:
        for seg in steady:
            k = curve.tangent(seg.torque_Nm)
            f = natural_frequency(k, inertia_kgm2)
            n_res = resonant_input_speed(f)
            n_in = seg.speed_rpm * ratio
            rows.append({"torque_Nm": seg.torque_Nm, "K_Nm_per_rad": k, "f_Hz": f,
                         "N_res_rpm": n_res, "ni_rpm": n_in,
                         "separation": abs(n_in - n_res) / n_res})
    except MissingStiffness as exc:
        return not_evaluated("torsional_resonance", TITLE, "stiffness", FORMULA,
                             f"stiffness value {exc} missing from the catalog")
    worst = min(rows, key=lambda r: r["separation"])
    inputs = {"J": Quantity(inertia_kgm2, "kg·m²"),
              "K (at operating torque)": Quantity(worst["K_Nm_per_rad"], "N·m/rad", source),
              "T (operating)": Quantity(worst["torque_Nm"], "N·m"),
              "ni (steady)": Quantity(worst["ni_rpm"], "r/min")}
    note = (f"f = {worst['f_Hz']:.1f} Hz, resonant input speed {worst['N_res_rpm']:.0f} r/min; "
            + (BAND_REASON if band == RESONANCE_BAND else f"±{band:.0%} band on input speed")
            + "; " + label("resonance_band", band))
    return compared("torsional_resonance", TITLE, "stiffness", FORMULA, inputs,
                    worst["separation"], band, "", ">=",
                    f"seed 000 p.021 (formulas 021-2, 021-3); stiffness {source}", note,
                    {"segments": rows})
