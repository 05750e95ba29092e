"""Design options for the generated housings and flanges (YAML), with documented defaults.

Every default is a design choice, not catalog data; the calculation sheet lists the options
used. Bad values raise InputError naming the key and what is allowed.
"""

from __future__ import annotations

from dataclasses import dataclass, asdict, field
from pathlib import Path
from typing import Any



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
    rules: dict = field(default_factory=dict)  # hdcad's own rules changed (checks/rules.py)
    drive: dict = field(default_factory=dict)  # FD-0 drive flange: key | bolts | pins
    motor: dict = field(default_factory=dict)  # GH: the user's motor flange and shaft
    given: tuple[str, ...] = ()  # the options the design file set (the rest are defaults)

    @property
    def check_rules(self):
        from .checks.rules import Rules
        return Rules(**self.rules)

    @property
    def density_kg_m3(self) -> float:
        return MATERIALS[self.material]

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


def parse_options(raw: Any) -> DesignOptions:
    """Validate a design-options mapping (schema ``hdcad.schema.DesignOptionsIn``)."""
    from .schema import DesignOptionsIn, validated
    if raw is None:
        return DesignOptions()
    checked = validated(DesignOptionsIn, raw, "")
    values = {k: getattr(checked, k) for k in checked.model_fields_set}
    if values.get("drive") is not None:
        drive = values["drive"]
        if drive.kind in ("bolts", "pins") and drive.circle_mm is None:
            from .errors import InputError
            raise InputError("drive.circle_mm", f"required for drive kind {drive.kind}")
        values["drive"] = drive.model_dump()
    if values.get("motor") is not None:
        values["motor"] = values["motor"].model_dump()
    if values.get("rules") is not None:
        values["rules"] = {k: getattr(values["rules"], k)
                           for k in values["rules"].model_fields_set}
    if values.get("motor_flange") is not None:
        values["motor_flange"] = values["motor_flange"].strip().upper()
    return DesignOptions(**values, given=tuple(sorted(values)))


def load_options(path: str | Path | None) -> DesignOptions:
    """Read and validate a design-options YAML file (None: the defaults)."""
    from .safe_io import load_yaml
    if path is None:
        return DesignOptions()
    return parse_options(load_yaml(Path(path), "--design"))
