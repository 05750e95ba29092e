"""Design options for the generated housings and flanges (YAML), with documented defaults.

Every default is a design choice, not catalog data; the calculation sheet lists the options
used. Bad values raise InputError naming the key and what is allowed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, asdict, field
from pathlib import Path
from typing import Any


from .errors import InputError

# Density [kg/m³] of common housing materials (handbook values: EN 10025 structural steel,
# EN 573 aluminium alloys, EN 1561 grey cast iron).
MATERIALS = {"steel": 7850.0, "aluminium": 2700.0, "cast_iron": 7200.0}
# ISO 898-1 property classes: (proof stress Rp0.2 [MPa]) used for preload (VDI 2230-style, 90 %).
BOLT_CLASSES = ("8.8", "10.9", "12.9")
AXES = ("horizontal", "vertical")


@dataclass(frozen=True)
class DesignOptions:
    motor_flange: str | None = None      # GH flange code (e.g. KG); None = first in the table
    input_shaft_mm: float | None = None  # motor / input shaft diameter; None = standard bore
    material: str = "steel"              # structural steel: the FD casings carry gears
    wall_mm: float = 8.0                 # housing wall and flange plate thickness
    bolt_class: str = "12.9"
    axis: str = "horizontal"
    friction_coefficient: float = 0.15   # joint faces, dry machined steel/aluminium (VDI 2230 range 0.1-0.2)
    bolt_safety_factor: float = 1.5      # on the momentary max torque for the bolted joints
    running_gap_mm: float = 1.0          # axial gap between the two rotating FD casing halves
    input_thrust_capacity_N: float | None = None  # axial capacity of the user's input support
    extra: dict = field(default_factory=dict)
    given: tuple[str, ...] = ()  # the options the design file set (the rest are defaults)

    @property
    def density_kg_m3(self) -> float:
        return MATERIALS[self.material]

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


_NUMBERS = {"input_shaft_mm": (1.0, 200.0), "wall_mm": (2.0, 60.0),
            "friction_coefficient": (0.05, 0.5), "bolt_safety_factor": (1.0, 5.0),
            "running_gap_mm": (0.2, 5.0), "input_thrust_capacity_N": (0.0, 1e7)}
_CHOICES = {"material": tuple(MATERIALS), "bolt_class": BOLT_CLASSES, "axis": AXES}


def parse_options(raw: Any) -> DesignOptions:
    if raw is None:
        return DesignOptions()
    if not isinstance(raw, dict):
        raise InputError("design", "must be a mapping of option: value")
    allowed = set(_NUMBERS) | set(_CHOICES) | {"motor_flange"}
    values: dict[str, Any] = {}
    for key, value in raw.items():
        if key not in allowed:
            raise InputError(str(key), f"unknown design option; allowed: {', '.join(sorted(allowed))}")
        if key in _NUMBERS:
            low, high = _NUMBERS[key]
            ok = (isinstance(value, (int, float)) and not isinstance(value, bool)
                  and math.isfinite(value) and low <= value <= high)
            if not ok:
                raise InputError(key, f"must be a number in [{low:g}, {high:g}] (got {value!r})")
            values[key] = float(value)
        elif key in _CHOICES:
            if str(value) not in _CHOICES[key]:
                raise InputError(key, f"must be one of {', '.join(_CHOICES[key])} (got {value!r})")
            values[key] = str(value)
        else:
            if not isinstance(value, str) or not value.strip():
                raise InputError(key, f"must be a flange code such as KG (got {value!r})")
            values[key] = value.strip().upper()
    return DesignOptions(**values, given=tuple(sorted(values)))


def load_options(path: str | Path | None) -> DesignOptions:
    """Read and validate a design-options YAML file (None: the defaults)."""
    from .safe_io import load_yaml
    if path is None:
        return DesignOptions()
    return parse_options(load_yaml(Path(path), "--design"))
