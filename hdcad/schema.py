"""Typed input schemas (pydantic v2) with physical bounds, and hdcad-style error lines.

Every user file is validated here before it becomes one of hdcad's plain records: unknown
keys are refused, numbers must be real finite numbers (no strings, no booleans) within a
physical range, choices come from fixed lists. ``validated`` turns the first pydantic error
into one InputError naming the field (``cycle[0].torque_Nm``) and the allowed range; the
ranges are written once, in the ``Field`` descriptions below.

References
----------
Seed 000 p.014 (load-torque pattern), table 032-3 (load factor fw); seed 000 pp.016-019
(greases, lubricant temperature ranges).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, TypeVar

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from .errors import InputError

T = TypeVar("T", bound=BaseModel)


def _num(low: float, high: float, unit: str, *, strict_low: bool = False) -> Any:
    """A finite real number in [low, high] (or (low, high]); the bounds printed in errors."""
    bound = {"gt": low} if strict_low else {"ge": low}
    text = f"a number {'>' if strict_low else '>='} {low:g} and <= {high:g}" + \
        (f" {unit}" if unit else "")
    return Annotated[float, Field(le=high, allow_inf_nan=False, strict=True, description=text,
                                  **bound)]


Torque = _num(-1e7, 1e7, "N·m")
PositiveTime = _num(0.0, 1e9, "s", strict_low=True)
Speed = _num(0.0, 1e5, "r/min")
PositiveSpeed = _num(0.0, 1e5, "r/min", strict_low=True)
PositiveHours = _num(0.0, 1e9, "h", strict_low=True)
Force = _num(0.0, 1e9, "N")
Length = _num(0.0, 1e3, "m")
# the bounds of single fields, named so that annotations stay plain types
DriveDiameterRange = _num(2.0, 30.0, "mm")
DriveCircleRange = _num(5.0, 1000.0, "mm")
WaveGeneratorRpmRange = _num(-1e5, 1e5, "r/min")
RollerTorqueNmRange = _num(0.0, 1e7, "N·m")
RollerCircumferenceMmRange = _num(0.0, 1e5, "mm", strict_low=True)
MaxAdjustPerTurnDegRange = _num(0.0, 360.0, "deg", strict_low=True)
TotalPhaseDegRange = _num(0.0, 1e6, "deg", strict_low=True)
DriveTorqueNmRange = _num(0.0, 1e7, "N·m", strict_low=True)
FwRange = _num(1.0, 3.0, "")
AngleDegRange = _num(0.0, 360.0, "deg", strict_low=True)
CyclesPerMinRange = _num(0.0, 1e5, "cpm", strict_low=True)
AmbientCRange = _num(-60.0, 200.0, "°C")
LoadInertiaKgm2Range = _num(0.0, 1e6, "kg·m²", strict_low=True)
ResonanceBandRange = _num(0.01, 1.0, "")
StaticSafetyMinRange = _num(1.0, 10.0, "")
AdjustmentEfficiencyRange = _num(0.05, 1.0, "")
RotaryOringSpeedRange = _num(0.05, 2.0, "m/s")
MotorDiameterRange = _num(5.0, 500.0, "mm")
MotorLengthRange = _num(0.5, 300.0, "mm")
MotorShaftRange = _num(2.0, 100.0, "mm")
InputShaftMmRange = _num(1.0, 200.0, "mm")
WallMmRange = _num(2.0, 60.0, "mm")
FrictionCoefficientRange = _num(0.05, 0.5, "")
BoltSafetyFactorRange = _num(1.0, 5.0, "")
RunningGapMmRange = _num(0.2, 5.0, "mm")
InputThrustCapacityNRange = _num(0.0, 1e7, "N")


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class SegmentIn(_Strict):
    phase: Literal["start", "steady", "stop", "rest"]
    torque_Nm: Torque
    time_s: PositiveTime
    speed_rpm: Speed
    wave_generator_rpm: WaveGeneratorRpmRange = 0.0


class AdjustmentIn(_Strict):
    drive_speed_rpm: PositiveSpeed
    roller_speed_rpm: PositiveSpeed
    roller_torque_Nm: RollerTorqueNmRange | None = None
    roller_circumference_mm: RollerCircumferenceMmRange | None = None
    max_adjust_per_turn_deg: MaxAdjustPerTurnDegRange | None = None
    total_phase_deg: TotalPhaseDegRange | None = None
    drive_torque_Nm: DriveTorqueNmRange | None = None
    min_teeth: Annotated[int, Field(ge=8, le=400, strict=True,
                                    description="a whole number from 8 to 400")] = 16
    max_teeth: Annotated[int, Field(ge=8, le=400, strict=True,
                                    description="a whole number from 8 to 400")] = 120


class ShockIn(_Strict):
    torque_Nm: Torque
    time_s: PositiveTime
    speed_rpm: PositiveSpeed
    count: Annotated[int, Field(ge=0, le=10**12, strict=True,
                                description="a whole number >= 0 and <= 1e12")] | None = None


class ExternalLoadIn(_Strict):
    radial_N: Force
    axial_N: Force
    Lr_m: Length
    La_m: Length
    fw: FwRange = 1.5  # seed 000 table 032-3: smooth 1-1.2 … shocks 1.5-3


class OscillationIn(_Strict):
    angle_deg: AngleDegRange
    cycles_per_min: CyclesPerMinRange


class DutyIn(_Strict):
    cycle: Annotated[list[SegmentIn], Field(min_length=1, max_length=10_000,
                                            description="a list of 1 to 10000 segments")]
    max_output_speed_rpm: PositiveSpeed
    max_input_speed_rpm: PositiveSpeed
    required_life_h: PositiveHours
    shock: ShockIn | None = None
    lubrication: Literal["grease", "oil"] = "grease"
    grease: Literal["SK-1A", "SK-2", "4B No.2"] = "SK-1A"
    # the widest lubricant limit in tables 019-2/019-3 is -50…+160 °C
    ambient_C: AmbientCRange | None = None
    load_inertia_kgm2: LoadInertiaKgm2Range | None = None
    external_load: ExternalLoadIn | None = None
    oscillation: OscillationIn | None = None
    use: Literal["reducer", "differential"] = "reducer"
    adjustment: AdjustmentIn | None = None


class RulesIn(_Strict):
    resonance_band: ResonanceBandRange = 0.20
    static_safety_min: StaticSafetyMinRange | None = None
    adjustment_efficiency: AdjustmentEfficiencyRange = 0.6
    rotary_oring_speed_m_s: RotaryOringSpeedRange = 0.25


class DriveIn(_Strict):
    kind: Literal["none", "key", "bolts", "pins"] = "none"
    count: Annotated[int, Field(ge=1, le=36, strict=True,
                                description="a whole number from 1 to 36")] = 4
    thread: Literal["M3", "M4", "M5", "M6", "M8", "M10", "M12"] = "M6"
    diameter_mm: DriveDiameterRange = 6.0
    circle_mm: DriveCircleRange | None = None


class MotorIn(_Strict):
    """The user's motor: flange (pilot, bolt circle, holes) and shaft, in mm."""
    pilot_diameter_mm: MotorDiameterRange
    pilot_length_mm: MotorLengthRange
    bolt_circle_mm: MotorDiameterRange
    bolt_count: Annotated[int, Field(ge=2, le=12, strict=True,
                                     description="a whole number from 2 to 12")]
    bolt_thread: Literal["M3", "M4", "M5", "M6", "M8", "M10", "M12", "M16"]
    shaft_diameter_mm: MotorShaftRange
    shaft_length_mm: MotorLengthRange
    square_mm: MotorDiameterRange | None = None
    holes: Literal["clearance", "tapped"] = "clearance"


class DesignOptionsIn(_Strict):
    motor_flange: Annotated[str, Field(min_length=1, max_length=8, strict=True,
                                       description="a flange code such as KG")] | None = None
    input_shaft_mm: InputShaftMmRange | None = None
    material: Literal["steel", "aluminium", "cast_iron"] = "steel"
    wall_mm: WallMmRange = 8.0
    bolt_class: Literal["8.8", "10.9", "12.9"] = "12.9"
    axis: Literal["horizontal", "vertical"] = "horizontal"
    friction_coefficient: FrictionCoefficientRange = 0.15
    bolt_safety_factor: BoltSafetyFactorRange = 1.5
    running_gap_mm: RunningGapMmRange = 1.0
    input_thrust_capacity_N: InputThrustCapacityNRange | None = None
    rules: RulesIn | None = None
    drive: DriveIn | None = None
    motor: MotorIn | None = None


def validated(model: type[T], raw: Any, root: str = "") -> T:
    """``raw`` checked against ``model``; InputError on the first problem, one line."""
    if not isinstance(raw, dict):
        raise InputError(root or "file", "must be a mapping of key: value")
    try:
        return model.model_validate(raw)
    except ValidationError as exc:
        error = exc.errors(include_url=False)[0]
        raise InputError(_where(root, error["loc"]), _message(model, error)) from None


def _where(root: str, loc: tuple) -> str:
    text = root
    for part in loc:
        if isinstance(part, int):
            text += f"[{part}]"
        elif str(part) not in ("float", "int", "str", "none", "function-after"):
            text += f".{part}" if text else str(part)
    return text or "file"


def _message(model: type[BaseModel], error: dict) -> str:
    kind, given = error["type"], _short(error.get("input"))
    if kind == "extra_forbidden":
        return f"unknown key; allowed: {', '.join(_fields(model, error['loc'][:-1]))}"
    if kind == "missing":
        return "required"
    if kind == "literal_error":
        return f"must be one of {error['ctx']['expected'].replace(chr(39), '')} (got {given})"
    allowed = _description(model, error["loc"])
    return f"must be {allowed or error['msg'].lower()} (got {given})"


def _short(value: Any) -> str:
    text = repr(value) if isinstance(value, (str, int, float, bool, type(None))) \
        else f"a {type(value).__name__}"
    return text if len(text) <= 60 else text[:57] + "…"


def _field_info(model: type[BaseModel], loc: tuple):
    """The FieldInfo a location points at (through nested models and lists), or None."""
    current, info = model, None
    for part in loc:
        if isinstance(part, int) or current is None:
            continue
        info = current.model_fields.get(str(part))
        if info is None:
            return None
        current = _model_of(info.annotation)
    return info


def _model_of(annotation: Any) -> type[BaseModel] | None:
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()) or ():
        found = _model_of(arg)
        if found is not None:
            return found
    return None


def _description(model: type[BaseModel], loc: tuple) -> str:
    info = _field_info(model, loc)
    if info is None:
        return ""
    if info.description:
        return info.description
    for meta in info.metadata:
        if getattr(meta, "description", None):
            return meta.description
    for arg in getattr(info.annotation, "__args__", ()) or ():
        for meta in getattr(arg, "__metadata__", ()) or ():
            if getattr(meta, "description", None):
                return meta.description
    return ""


def _fields(model: type[BaseModel], loc: tuple) -> list[str]:
    current = model
    for part in loc:
        if isinstance(part, int):
            continue
        info = current.model_fields.get(str(part))
        current = _model_of(info.annotation) if info else None
        if current is None:
            return []
    return sorted(current.model_fields)
