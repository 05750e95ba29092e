"""The duty file: load-torque cycle on the output side, speeds, shock and required life.

The shape follows the catalog's load-torque pattern (seed 000 p.014, graph 014-1):
start / steady / stop / rest segments with torque Tn [N·m], time tn [s] and average output
speed nn [r/min], the maximum output and input speeds, one shock Ts, ts, ns and the required
life L10. Every bad value raises :class:`InputError` naming the field and the allowed range.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, asdict
from pathlib import Path
from typing import Any


from .errors import InputError

PHASES = ("start", "steady", "stop", "rest")
LUBRICATIONS = ("grease", "oil")
GREASES = ("SK-1A", "SK-2", "4B No.2")
TOP_KEYS = {"cycle", "max_output_speed_rpm", "max_input_speed_rpm", "shock", "required_life_h",
            "lubrication", "grease", "ambient_C", "load_inertia_kgm2", "external_load"}
SEGMENT_KEYS = ("phase", "torque_Nm", "time_s", "speed_rpm")
SHOCK_KEYS = {"torque_Nm", "time_s", "speed_rpm", "count"}
LOAD_KEYS = {"radial_N", "axial_N", "Lr_m", "La_m", "fw"}
FW_RANGE = (1.0, 3.0)  # seed 000 table 032-3: smooth 1-1.2 … shock/vibration 1.5-3
AMBIENT_RANGE_C = (-60.0, 200.0)  # widest lubricant limit in 019-2/019-3 is -50…+160 °C


@dataclass(frozen=True)
class Segment:
    phase: str
    torque_Nm: float
    time_s: float
    speed_rpm: float


@dataclass(frozen=True)
class Shock:
    torque_Nm: float
    time_s: float
    speed_rpm: float
    count: int | None = None


@dataclass(frozen=True)
class ExternalLoad:
    radial_N: float
    axial_N: float
    Lr_m: float
    La_m: float
    fw: float


@dataclass(frozen=True)
class Duty:
    cycle: tuple[Segment, ...]
    max_output_speed_rpm: float
    max_input_speed_rpm: float
    shock: Shock | None
    required_life_h: float
    lubrication: str = "grease"
    grease: str = "SK-1A"
    ambient_C: float | None = None
    load_inertia_kgm2: float | None = None
    external_load: ExternalLoad | None = None
    name: str = field(default="", compare=False)

    def as_dict(self) -> dict[str, Any]:
        out = asdict(self)
        out["cycle"] = [asdict(s) for s in self.cycle]
        return out


# sane magnitudes per unit: far beyond any strain wave gear, small enough that sums,
# powers and products of them stay finite (the load pattern raises torques to the 3rd power)
PHYSICAL_LIMITS = {"N·m": 1e7, "s": 1e9, "r/min": 1e5, "h": 1e9, "kg·m²": 1e6, "N": 1e9,
                   "m": 1e3}


def _number(value: Any, where: str, low: float | None = None, *, strict_low: bool = False,
            high: float | None = None, unit: str = "") -> float:
    limit = PHYSICAL_LIMITS.get(unit)
    if limit is not None:
        high = limit if high is None else high
        low = -limit if low is None else low
    allowed = _range_text(low, high, strict_low, unit)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise InputError(where, f"must be a number {allowed} (got {value!r})")
    number = float(value)
    if not math.isfinite(number):
        raise InputError(where, f"must be a finite number {allowed} (got {value!r})")
    too_low = low is not None and (number <= low if strict_low else number < low)
    if too_low or (high is not None and number > high):
        raise InputError(where, f"must be {allowed} (got {value!r})")
    return number


def _range_text(low, high, strict_low, unit) -> str:
    unit = f" {unit}" if unit else ""
    if low is not None and high is not None:
        return f"in [{low:g}, {high:g}]{unit}"
    if low is not None:
        return f"{'>' if strict_low else '>='} {low:g}{unit}"
    return f"<= {high:g}{unit}" if high is not None else "(any finite value)"


def _mapping(value: Any, where: str, keys: set[str], required: set[str]) -> dict:
    if not isinstance(value, dict):
        raise InputError(where, f"must be a mapping with keys {', '.join(sorted(keys))}")
    unknown = sorted(str(k) for k in value if k not in keys)
    if unknown:
        raise InputError(f"{where}.{unknown[0]}" if where else unknown[0],
                         f"unknown key; allowed: {', '.join(sorted(keys))}")
    missing = sorted(k for k in required if k not in value)
    if missing:
        raise InputError(f"{where}.{missing[0]}" if where else missing[0], "required")
    return value


def _segment(raw: Any, index: int) -> Segment:
    where = f"cycle[{index}]"
    raw = _mapping(raw, where, set(SEGMENT_KEYS), set(SEGMENT_KEYS))
    phase = raw["phase"]
    if phase not in PHASES:
        raise InputError(f"{where}.phase", f"must be one of {', '.join(PHASES)} (got {phase!r})")
    segment = Segment(
        phase=phase,
        torque_Nm=_number(raw["torque_Nm"], f"{where}.torque_Nm", unit="N·m"),
        time_s=_number(raw["time_s"], f"{where}.time_s", 0.0, strict_low=True, unit="s"),
        speed_rpm=_number(raw["speed_rpm"], f"{where}.speed_rpm", 0.0, unit="r/min"),
    )
    if phase == "rest" and segment.speed_rpm != 0:
        raise InputError(f"{where}.speed_rpm", f"must be 0 in a rest segment "
                                               f"(got {segment.speed_rpm:g})")
    return segment


def _shock(raw: Any, max_output: float) -> Shock:
    raw = _mapping(raw, "shock", SHOCK_KEYS, {"torque_Nm", "time_s", "speed_rpm"})
    count = raw.get("count")
    if count is not None and (isinstance(count, bool) or not isinstance(count, int)
                              or not 0 <= count <= 1e12):
        raise InputError("shock.count", f"must be a whole number in [0, 1e12] (got "
                                        f"{str(count)[:40]!r})")
    return Shock(
        torque_Nm=abs(_number(raw["torque_Nm"], "shock.torque_Nm", unit="N·m")),
        time_s=_number(raw["time_s"], "shock.time_s", 0.0, strict_low=True, unit="s"),
        speed_rpm=_number(raw["speed_rpm"], "shock.speed_rpm", 0.0, strict_low=True,
                          high=max_output, unit="r/min (up to max_output_speed_rpm)"),
        count=count,
    )


def _external_load(raw: Any) -> ExternalLoad:
    raw = _mapping(raw, "external_load", LOAD_KEYS, LOAD_KEYS - {"fw"})
    return ExternalLoad(
        radial_N=_number(raw["radial_N"], "external_load.radial_N", 0.0, unit="N"),
        axial_N=_number(raw["axial_N"], "external_load.axial_N", 0.0, unit="N"),
        Lr_m=_number(raw["Lr_m"], "external_load.Lr_m", 0.0, unit="m"),
        La_m=_number(raw["La_m"], "external_load.La_m", 0.0, unit="m"),
        fw=_number(raw.get("fw", 1.5), "external_load.fw", FW_RANGE[0], high=FW_RANGE[1]),
    )


def _choice(raw: dict, key: str, allowed: tuple[str, ...], default: str) -> str:
    value = raw.get(key, default)
    if value not in allowed:
        raise InputError(key, f"must be one of {', '.join(allowed)} (got {value!r})")
    return value


def parse_duty(raw: Any, name: str = "") -> Duty:
    """Validate a duty mapping (as loaded from YAML) and return a :class:`Duty`."""
    required = {"cycle", "max_output_speed_rpm", "max_input_speed_rpm", "required_life_h"}
    raw = _mapping(raw, "", TOP_KEYS, required)
    if not isinstance(raw["cycle"], list) or not raw["cycle"]:
        raise InputError("cycle", "must be a non-empty list of segments "
                                  "{phase, torque_Nm, time_s, speed_rpm}")
    cycle = tuple(_segment(seg, i) for i, seg in enumerate(raw["cycle"]))
    if not any(s.speed_rpm > 0 for s in cycle):
        raise InputError("cycle", "needs at least one moving segment (speed_rpm > 0)")
    max_out = _number(raw["max_output_speed_rpm"], "max_output_speed_rpm", 0.0,
                      strict_low=True, unit="r/min")
    for i, seg in enumerate(cycle):
        if seg.speed_rpm > max_out:
            raise InputError(f"cycle[{i}].speed_rpm",
                             f"must be <= max_output_speed_rpm {max_out:g} (got {seg.speed_rpm:g})")
    ambient = raw.get("ambient_C")
    inertia = raw.get("load_inertia_kgm2")
    return Duty(
        cycle=cycle,
        max_output_speed_rpm=max_out,
        max_input_speed_rpm=_number(raw["max_input_speed_rpm"], "max_input_speed_rpm", 0.0,
                                    strict_low=True, unit="r/min"),
        shock=_shock(raw["shock"], max_out) if raw.get("shock") is not None else None,
        required_life_h=_number(raw["required_life_h"], "required_life_h", 0.0,
                                strict_low=True, unit="h"),
        lubrication=_choice(raw, "lubrication", LUBRICATIONS, "grease"),
        grease=_choice(raw, "grease", GREASES, "SK-1A"),
        ambient_C=None if ambient is None else _number(
            ambient, "ambient_C", AMBIENT_RANGE_C[0], high=AMBIENT_RANGE_C[1], unit="°C"),
        load_inertia_kgm2=None if inertia is None else _number(
            inertia, "load_inertia_kgm2", 0.0, strict_low=True, unit="kg·m²"),
        external_load=(_external_load(raw["external_load"])
                       if raw.get("external_load") is not None else None),
        name=name,
    )


def load_duty(path: str | Path) -> Duty:
    """Read and validate a duty YAML file (regular file, ≤ 10 MB, UTF-8, safe YAML)."""
    from .safe_io import load_yaml
    path = Path(path)
    return parse_duty(load_yaml(path, "--duty"), name=path.name)
