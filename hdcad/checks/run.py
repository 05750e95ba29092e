"""Run every selection check for one model and one duty.

This module only gathers the limits that belong to the model (catalog → check inputs) and
calls the pure check functions; it computes no physics of its own.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from ..catalog import Catalog, Datum
from ..duty import Duty
from ..models import GearModel
from . import fd as fd_rules
from .life import wg_life
from .load_pattern import average_output_speed, average_torque
from .lubrication import lubrication
from .main_bearing import main_bearing
from .record import CheckResult, FAIL, NOT_EVALUATED, WARN, not_evaluated
from .rules import Rules
from .differential import adjustment_checks, relative_speeds
from ..errors import InputError
from .speed import continuous_input_speed, avg_input_speed, max_input_speed, ratio_limit
from .stiffness import StiffnessCurve, torsional_resonance
from .strength import shock_count
from .thrust import thrust_angle, thrust_force
from .torque import avg_torque, momentary_torque, peak_torque


@dataclass
class Evaluation:
    """All check results for one model and duty, with the derived duty values."""

    model: GearModel
    duty: Duty
    derived: dict[str, float]
    checks: list[CheckResult]
    catalog_revision: str = ""
    assumptions: list[str] = field(default_factory=list)

    @property
    def failures(self) -> list[CheckResult]:
        return [c for c in self.checks if c.status == FAIL]

    @property
    def warnings(self) -> list[CheckResult]:
        return [c for c in self.checks if c.status == WARN]

    @property
    def not_evaluated(self) -> list[CheckResult]:
        return [c for c in self.checks if c.status == NOT_EVALUATED]

    @property
    def all_passed(self) -> bool:
        """True when no check fails (checks that could not be evaluated are listed apart)."""
        return not self.failures

    @property
    def verdict(self) -> str:
        if self.failures:
            return f"{len(self.failures)} check(s) fail"
        parts = ([f"{len(self.warnings)} to confirm with the maker"] if self.warnings else []) \
            + ([f"{len(self.not_evaluated)} not evaluated"] if self.not_evaluated else [])
        return "all evaluated checks pass; " + "; ".join(parts) if parts else "all checks pass"

    def check(self, check_id: str) -> CheckResult:
        return next(c for c in self.checks if c.id == check_id)

    def as_dict(self) -> dict:
        return {"model": self.model.code, "duty": self.duty.as_dict(), "derived": self.derived,
                "checks": [c.as_dict() for c in self.checks], "all_passed": self.all_passed,
                "verdict": self.verdict, "catalog_revision": self.catalog_revision,
                "assumptions": self.assumptions}


def derived_values(duty: Duty, ratio: float) -> dict[str, float]:
    """Tav, no_av, ni_av, ni_max and the largest torque of the duty.

    In differential use (FD) the "input" speeds are the wave generator's speed relative to
    the circular spline S, which the FD ratings are given against (seed 001 p.310)."""
    no_av = average_output_speed(duty.cycle)
    peak = max([abs(s.torque_Nm) for s in duty.cycle] +
               ([duty.shock.torque_Nm] if duty.shock else []))
    if duty.use == "differential":
        rel = relative_speeds(duty.cycle)
        ni_av, ni_max = rel["avg"], max(rel["max"], duty.max_output_speed_rpm)
    else:
        ni_av, ni_max = no_av * ratio, duty.max_output_speed_rpm * ratio
    return {"avg_torque_Nm": average_torque(duty.cycle), "avg_output_speed_rpm": no_av,
            "avg_input_speed_rpm": ni_av, "max_input_speed_rpm": ni_max,
            "max_output_speed_rpm": duty.max_output_speed_rpm, "max_torque_Nm": peak,
            "ratio": float(ratio)}


def stiffness_curve(model: GearModel) -> tuple[StiffnessCurve | None, str]:
    """The model's torque-twist curve and its source (None if the catalog has none)."""
    if model.is_fd:
        k = model.get("spring_constant_Nm_per_rad")
        return (StiffnessCurve.linear(float(k)), k.source) if k else (None, "")
    k1 = model.get("K1_Nm_per_rad")
    if k1 is None:
        return None, ""
    values = {name: (float(model.get(col)) if model.get(col) else None) for name, col in
              (("T1", "T1_Nm"), ("T2", "T2_Nm"), ("K2", "K2_Nm_per_rad"),
               ("K3", "K3_Nm_per_rad"), ("theta1", "theta1_rad"), ("theta2", "theta2_rad"))}
    return StiffnessCurve(K1=float(k1), **values), k1.source


def loaded_input_speed_rpm(duty: Duty, ratio: float) -> float:
    """Time-weighted input speed [r/min] of the moving segments only: the FD rating applies
    at the speed the gear turns under load, not at an average diluted by rest time."""
    if duty.use == "differential":
        return relative_speeds(duty.cycle)["loaded"]
    moving = [s for s in duty.cycle if s.speed_rpm > 0]
    return ratio * sum(s.speed_rpm * s.time_s for s in moving) / sum(s.time_s for s in moving)


def _fd_limits(model: GearModel, duty: Duty, derived: dict) -> dict:
    speed = loaded_input_speed_rpm(duty, model.ratio)
    avg_rating, avg_rule = fd_rules.rating_at_speed(model.fd_torque_by_speed, speed)
    avg_rule = (f"rated at {speed:.0f} r/min, the input speed of the moving segments "
                f"(rest time excluded); {avg_rule}")
    speed_key = f"max_input_speed_{duty.lubrication}_rpm"
    return {
        "avg_torque": (avg_rating, avg_rule),
        "peak_torque": (None, "start/stop peak torque: table 310-1 gives rated torque only"),
        "momentary": (fd_rules.momentary_allowance(model.fd_torque_by_speed),
                      "FD momentary allowance: 200 % of the 1450 r/min rating"),
        "avg_input_speed": (None, "the FD tables give no allowed average input speed "
                                  "(313-3/313-4 are maximum speeds)"),
        "max_input_speed": (model.get(speed_key),
                            f"{duty.lubrication} lubrication (table 313-3 oil / 313-4 grease)"),
    }


def _cup_limits(model: GearModel) -> dict:
    return {
        "avg_torque": (model.get("avg_torque_max_Nm"), ""),
        "peak_torque": (model.get("peak_torque_Nm"), ""),
        "momentary": (model.get("momentary_torque_Nm"), ""),
        "avg_input_speed": (model.get("avg_input_speed_max_rpm"), ""),
        "max_input_speed": (model.get("max_input_speed_rpm"), ""),
    }


def _thrust(model: GearModel, catalog: Catalog, torque: float,
            capacity_N: float | None) -> CheckResult:
    if model.is_fd:
        return thrust_force(torque, model.size, None,
                            applies="table 027-3 covers cup-type gears; the FD (pancake) type "
                                    "has no thrust formula in the seeds")
    beta = thrust_angle(model.ratio, catalog.rows("thrust_angle"))
    datum = None if beta is None else Datum(beta, "deg", catalog.table("thrust_angle").source)
    if model.family == "GH":
        return thrust_force(torque, model.size, datum, capacity_N=capacity_N,
                            missing_capacity="capacity of the gear head's own input bearings "
                                             "(not in the catalog); value reported for information")
    return thrust_force(torque, model.size, datum, capacity_N=capacity_N)


def _main_bearing_data(model: GearModel, catalog: Catalog) -> tuple[dict | None, str]:
    row = catalog.find("main_bearing", model=model.code)
    if row is not None:
        return row, ""
    if model.family in ("FD-2", "2A-GR"):
        return None, ("component set: the output bearing is the user's; supply its dp, R, C, "
                      "Co, Mc in an overlay table main_bearing")
    return None, (f"main-bearing data (dp, R, C, Co, Mc) for {model.code} missing from the "
                  "catalog; supply them in an overlay table main_bearing")


FD_DEFAULT_LUBRICATION = ("oil: the duty names no lubricant and FD units run in oil (seed 001 "
                          "p.315: grease only for ED ≤ 10 % and ≤ 10 min continuous running)")


def _line_driven() -> CheckResult:
    return not_evaluated("ratio_limit", "Ratio against motor speed", "speed",
                         "ni_max / no_max ≥ R", "nothing: in differential use the line shaft "
                         "drives the circular spline S, no motor drives the input through R")


def duty_for_model(model: GearModel, duty: Duty) -> Duty:
    """The duty as evaluated: an FD whose duty names no lubricant is oil-lubricated."""
    if model.is_fd and not duty.lubrication_given:
        return replace(duty, lubrication="oil", lubrication_given=True)
    return duty


def run_checks(model: GearModel, duty: Duty, catalog: Catalog,
               thrust_capacity_N: float | None = None, rules: Rules | None = None
               ) -> Evaluation:
    """Every selection check of the catalog for ``model`` under ``duty``; ``rules`` are
    hdcad's own choices where the catalog leaves one open (see ``hdcad.checks.rules``)."""
    rules = rules or Rules()
    defaulted = model.is_fd and not duty.lubrication_given
    duty = duty_for_model(model, duty)
    if duty.use == "differential" and not model.is_fd:
        raise InputError("use", f"differential applies to FD models only ({model.code} is "
                                f"{model.family})")
    differential = duty.use == "differential"
    derived = derived_values(duty, model.ratio)
    limits = _fd_limits(model, duty, derived) if model.is_fd else _cup_limits(model)
    curve, curve_source = stiffness_curve(model)
    bearing, bearing_missing = _main_bearing_data(model, catalog)
    oil_level = model.get("oil_level_A_mm")
    checks = [
        (_line_driven() if differential else
         ratio_limit(duty.max_input_speed_rpm, duty.max_output_speed_rpm, model.ratio)),
        avg_torque(derived["avg_torque_Nm"], *limits["avg_torque"]),
        avg_input_speed(derived["avg_input_speed_rpm"], *limits["avg_input_speed"]),
        max_input_speed(derived["max_input_speed_rpm"], *limits["max_input_speed"]),
        peak_torque(duty.cycle, *limits["peak_torque"]),
        momentary_torque(duty.shock, *limits["momentary"]),
        # differential: the shock's speed is the line shaft's, i.e. the relative WG speed
        shock_count(duty.shock, 1 if differential else model.ratio),
        wg_life(derived["avg_torque_Nm"], derived["avg_input_speed_rpm"], duty.required_life_h,
                model.get("rated_torque_Nm"), model.get("rated_input_speed_rpm"),
                model.get("L10_h"), model.get("L50_h")),
        _thrust(model, catalog, derived["max_torque_Nm"], thrust_capacity_N),
        torsional_resonance(duty.cycle, model.ratio, curve, duty.load_inertia_kgm2,
                            curve_source, rules.resonance_band),
        lubrication(model.family, model.size, model.ratio, duty,
                    catalog.rows("grease_suitability"), catalog.rows("lubricant_temperature"),
                    float(oil_level) if oil_level else None),
        main_bearing(duty.cycle, duty.external_load, bearing, duty.required_life_h,
                     bearing_missing, duty.oscillation, rules.static_safety_min),
    ]
    if model.family == "GH":
        checks.insert(4, continuous_input_speed(duty.cycle, model.ratio))
    checks += adjustment_checks(duty, model.ratio, rules.adjustment_efficiency)
    if defaulted:
        lub = next(c for c in checks if c.id == "lubrication")
        lub.note = f"{FD_DEFAULT_LUBRICATION}; {lub.note}"
    assumptions = [text for _, text in catalog.interpretations()]
    return Evaluation(model, duty, derived, checks, catalog.revision, assumptions)
