"""Geometric checks of a generated design: input bore and key, every bolt circle.

This module adapts the parts' records (bolt circles, dimensions) to the pure check
functions in :mod:`input_bore` and :mod:`bolts`; it imports no CAD code.
"""

from __future__ import annotations

from ..catalog import Catalog
from ..design_options import DesignOptions
from ..models import GearModel
from .bolts import bolt_pattern
from .fd import momentary_allowance
from .input_bore import KEY_LENGTH_FACTOR, KEY_SOURCE, key_stresses, select_key, input_bore
from .record import PASS, CheckResult, Quantity, compared, not_evaluated

FD_ADJUST_EFFICIENCY = 0.6  # seed 001 p.309: the FD example's efficiency for the WG torque


def momentary_torque_Nm(model: GearModel) -> float | None:
    """The gear's momentary maximum torque [N·m] (the joints must survive what it survives)."""
    datum = (momentary_allowance(model.fd_torque_by_speed) if model.is_fd
             else model.get("momentary_torque_Nm"))
    return None if datum is None else float(datum)


def input_torque_Nm(model: GearModel) -> float | None:
    """Torque at the wave generator for the output's momentary torque: T/(R·η) [N·m]."""
    out = momentary_torque_Nm(model)
    if out is None:
        return None
    efficiency = FD_ADJUST_EFFICIENCY if model.is_fd else 1.0
    return out / (model.ratio * efficiency)


def _fixed_bore(model: GearModel, catalog: Catalog, shaft: float | None, bore: float,
                source: str, torque: float | None) -> CheckResult:
    """Input shaft in a bore the catalog fixes (FD WG bore φN/φL H7), plus its key."""
    d = bore if shaft is None else shaft
    title, formula = "Input shaft bore and key", "d = d_bore (H7);  τ = 2T/(d·b·l), p = 2T/(d·(h−t1)·l)"
    inputs = {"d": Quantity(d, "mm"), "d_bore": Quantity(bore, "mm", source)}
    if torque is None:
        return not_evaluated("input_bore", title, "geometry", formula,
                             "momentary torque for the key load", inputs, d, "mm", source)
    key = select_key(d, catalog.rows("parallel_key_jisb1301"))
    details = {}
    if key:
        length = KEY_LENGTH_FACTOR * d
        tau, p = key_stresses(torque, d, key["b_mm"], key["h_mm"], key["t1_mm"], length)
        details = {"key_b_mm": key["b_mm"], "key_h_mm": key["h_mm"], "key_length_mm": length,
                   "tau_MPa": tau, "p_MPa": p, "T_Nm": torque}
    note = ("the catalog fixes this bore; other bores are not in the seeds"
            + (f"; key {key['b_mm']:g}×{key['h_mm']:g} ({KEY_SOURCE}): τ {details['tau_MPa']:.1f} MPa, "
               f"p {details['p_MPa']:.1f} MPa at T {torque:.2f} N·m" if key else ""))
    result = compared("input_bore", title, "geometry", formula, inputs, d, bore, "mm", "<=",
                      source, note, details)
    if abs(d - bore) > 1e-6:
        result.status = "fail"
    return result


def _bore_check(model, catalog, options) -> CheckResult:
    torque = input_torque_Nm(model)
    if model.is_fd:
        table = "fd0_dimensions" if model.family == "FD-0" else "fd2_dimensions"
        column = "N_H7_mm" if model.family == "FD-0" else "L_H7_mm"
        row = catalog.find(table, size=model.size)
        return _fixed_bore(model, catalog, options.input_shaft_mm, row[column],
                           catalog.table(table).source, torque)
    if model.family == "GH":
        if options.input_shaft_mm is None:
            return not_evaluated("input_bore", "Motor shaft in the input coupling", "geometry",
                                 "F_min ≤ d ≤ F_max", "input_shaft_mm (the motor shaft) in the "
                                 "design options")
        return _fixed_range(model, catalog, options)
    return _component_bore(model, catalog, options, torque)


def _component_bore(model, catalog, options, torque: float | None) -> CheckResult:
    """2A-GR: the requested input shaft (default: the standard hub bore of 027-1) against
    the hub and plug bores (027-1/027-2) and its JIS key; not evaluated without a torque."""
    hub = catalog.find("wg_hub_bore", size=model.size)
    shaft = options.input_shaft_mm
    if shaft is None and hub is not None:
        shaft = hub["standard_H7_mm"]
    result = input_bore(shaft or 0.0, model.size, torque or 0.0, hub,
                        catalog.find("wg_plug_bore", size=model.size))
    if options.input_shaft_mm is None:
        result.note = "input_shaft_mm not given: the standard hub bore is checked; " + result.note
    if torque is None and result.status == PASS:
        return not_evaluated(result.id, result.title, result.family, result.formula,
                             "momentary torque of the model (key load) missing from the "
                             "catalog", result.inputs, result.value, result.unit,
                             result.source, note=f"bore within the allowed range "
                                                 f"({result.note})", details=result.details)
    return result


def _torque_missing(record: CheckResult) -> CheckResult:
    """A bolt record whose geometry passes but whose load is unknown is not evaluated."""
    if record.status != PASS:
        return record
    return not_evaluated(record.id, record.title, record.family, record.formula,
                         "momentary torque of the model missing from the catalog (the torque "
                         "capacity has nothing to be compared with)", record.inputs,
                         record.value, record.unit, record.source,
                         note=f"geometry and thread criteria pass ({record.note})",
                         details=record.details)


def _fixed_range(model, catalog, options) -> CheckResult:
    code = options.motor_flange
    rows = catalog.rows("gh_motor_flange", series=model.series, size=model.size)
    row = next((r for r in rows if r["flange_code"] == code), None) or rows[0]
    d, low, high = options.input_shaft_mm, row["coupling_bore_min_mm"], row["coupling_bore_max_mm"]
    inputs = {"d": Quantity(d, "mm"), "F min": Quantity(low, "mm"), "F max": Quantity(high, "mm")}
    result = compared("input_bore", "Motor shaft in the input coupling", "geometry",
                      "F_min ≤ d ≤ F_max (coupling bore range of the flange table)", inputs, d,
                      high, "mm", "<=", catalog.table("gh_motor_flange").source,
                      f"flange {row['flange_code']}: coupling bores {low:g}…{high:g} mm")
    if d < low:
        result.status = "fail"
    return result


def geometric_checks(model: GearModel, parts: list, options: DesignOptions,
                     catalog: Catalog) -> list[CheckResult]:
    """input_bore and one bolt_pattern record per bolt circle of every part."""
    checks = [_bore_check(model, catalog, options)]
    if model.family == "GH" and not options.motor and not catalog.has("gh_input_interface"):
        checks.append(not_evaluated(
            "gh_interface", "Gear-head side of the motor flange", "geometry",
            "pilot, bolt circle and screws of the gear-head housing face",
            "the gear-head housing face (overlay table gh_input_interface: pilot Ø and kind, "
            "pilot depth, bolt circle, bolt count and thread, outline, O-ring); the seeds do "
            "not give it (lost figures 053-1 … 064-1), so the flange is NOT FOR MANUFACTURE",
            source="seed 003 tables 053-1 … 064-1 (motor side only)"))
    if model.family == "GH":
        from .motor import gh_mounting_plate
        plate = next((p for p in parts if p.name == "mounting_plate"), None)
        checks.append(gh_mounting_plate(catalog.has("gh_mounting_interface"),
                                        plate.dimensions if plate else None))
    known = momentary_torque_Nm(model)
    out_torque = known or 0.0
    for part in parts:
        # the motor flange carries the motor's reaction torque: output torque / R
        torque = (out_torque / model.ratio if part.name in ("motor_flange", "motor_adapter")
                  else out_torque)
        for circle in part.bolt_circles:
            record = bolt_pattern(
                f"{part.name}/{circle.name}", circle.diameter_mm, circle.count, circle.thread,
                circle.kind, circle.annulus_inner_mm, circle.annulus_outer_mm, circle.depth_mm,
                options.bolt_class, options.friction_coefficient, torque,
                options.bolt_safety_factor, catalog=catalog,
                outline_square_mm=getattr(circle, "outline_square_mm", None),
                start_angle_deg=circle.start_angle_deg,
                tapped_material="steel" if circle.kind == "clearance" else options.material)
            checks.append(record if known is not None else _torque_missing(record))
    return checks
