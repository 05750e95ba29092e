"""The duty file: load-torque cycle on the output side, speeds, shock and required life.

The shape follows the catalog's load-torque pattern (seed 000 p.014, graph 014-1):
start / steady / stop / rest segments with torque Tn [N·m], time tn [s] and average output
speed nn [r/min], the maximum output and input speeds, one shock Ts, ts, ns and the required
life L10. Every bad value raises :class:`InputError` naming the field and the allowed range.
"""

from __future__ import annotations

from dataclasses import dataclass, field, asdict
from pathlib import Path
from typing import Any


from .errors import InputError

PHASES = ("start", "steady", "stop", "rest")
LUBRICATIONS = ("grease", "oil")
GREASES = ("SK-1A", "SK-2", "4B No.2")


@dataclass(frozen=True)
class Segment:
    phase: str
    torque_Nm: float
    time_s: float
    speed_rpm: float
    wave_generator_rpm: float = 0.0  # differential use: the adjusting input (0 = held)


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
class Oscillation:
    """An output that swings back and forth (seed 000 p.033, figure 033-1)."""
    angle_deg: float       # full oscillating angle (θ in 033-1 is half of it)
    cycles_per_min: float  # n1, reciprocating oscillations per minute [cpm]


@dataclass(frozen=True)
class Adjustment:
    """FD phase adjuster (seed 001 pp.308-309): drive shaft N1 → … → roller N4."""
    drive_speed_rpm: float            # N1
    roller_speed_rpm: float           # N4
    roller_torque_Nm: float | None = None      # Tw, torque at the roller
    roller_circumference_mm: float | None = None  # Lw, to state the adjustment on the roller
    max_adjust_per_turn_deg: float | None = None  # wanted resolution per WG turn
    total_phase_deg: float | None = None  # a phase shift of the roller to make [deg]
    drive_torque_Nm: float | None = None       # torque the adjusting drive can give
    min_teeth: int = 16
    max_teeth: int = 120


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
    oscillation: Oscillation | None = None
    use: str = "reducer"  # FD only: "differential" = line shaft on the circular spline S
    adjustment: Adjustment | None = None
    name: str = field(default="", compare=False)
    lubrication_given: bool = field(default=True, compare=False)  # False: the file names none

    def as_dict(self) -> dict[str, Any]:
        out = asdict(self)
        out["cycle"] = [asdict(s) for s in self.cycle]
        return out


def parse_duty(raw: Any, name: str = "") -> Duty:
    """Validate a duty mapping (as loaded from YAML) and return a :class:`Duty`.

    The schema (types, keys, physical bounds) is ``hdcad.schema.DutyIn``; the rules that tie
    fields together (speeds within the maximum, a rest segment standing still) follow here.
    """
    from .schema import DutyIn, validated
    d = validated(DutyIn, raw)
    cycle = tuple(Segment(s.phase, s.torque_Nm, s.time_s, s.speed_rpm, s.wave_generator_rpm)
                  for s in d.cycle)
    if d.use == "reducer" and any(s.wave_generator_rpm for s in d.cycle):
        raise InputError("cycle[].wave_generator_rpm", "applies to use: differential only")
    if d.adjustment is not None and d.use != "differential":
        raise InputError("adjustment", "applies to use: differential only")
    for i, seg in enumerate(cycle):
        if seg.phase == "rest" and seg.speed_rpm != 0:
            raise InputError(f"cycle[{i}].speed_rpm", f"must be 0 in a rest segment "
                                                      f"(got {seg.speed_rpm:g})")
        if seg.speed_rpm > d.max_output_speed_rpm:
            raise InputError(f"cycle[{i}].speed_rpm", f"must be <= max_output_speed_rpm "
                                                      f"{d.max_output_speed_rpm:g} (got "
                                                      f"{seg.speed_rpm:g})")
    if not any(s.speed_rpm > 0 for s in cycle):
        raise InputError("cycle", "needs at least one moving segment (speed_rpm > 0)")
    shock = None
    if d.shock is not None:
        if d.shock.speed_rpm > d.max_output_speed_rpm:
            raise InputError("shock.speed_rpm", f"must be <= max_output_speed_rpm "
                                                f"{d.max_output_speed_rpm:g} (got "
                                                f"{d.shock.speed_rpm:g})")
        shock = Shock(abs(d.shock.torque_Nm), d.shock.time_s, d.shock.speed_rpm, d.shock.count)
    load = d.external_load
    return Duty(
        cycle=cycle, max_output_speed_rpm=d.max_output_speed_rpm,
        max_input_speed_rpm=d.max_input_speed_rpm, shock=shock,
        required_life_h=d.required_life_h, lubrication=d.lubrication, grease=d.grease,
        ambient_C=d.ambient_C, load_inertia_kgm2=d.load_inertia_kgm2,
        external_load=None if load is None else ExternalLoad(
            load.radial_N, load.axial_N, load.Lr_m, load.La_m, load.fw),
        oscillation=None if d.oscillation is None else Oscillation(
            d.oscillation.angle_deg, d.oscillation.cycles_per_min),
        use=d.use, adjustment=None if d.adjustment is None else Adjustment(
            **d.adjustment.model_dump()),
        name=name, lubrication_given="lubrication" in d.model_fields_set,
    )


def load_duty(path: str | Path) -> Duty:
    """Read and validate a duty YAML file (regular file, ≤ 10 MB, UTF-8, safe YAML)."""
    from .safe_io import load_yaml
    path = Path(path)
    return parse_duty(load_yaml(path, "--duty"), name=path.name)
