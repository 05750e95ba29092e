"""Oil level in a generated housing: inside the cavity, reaching the gear, below the seals.

References
----------
Seed 001 p.315, table 315-1: FD oil level A (mm). Figure 315-1, which gives its datum, is
lost; hdcad reads A as the distance from the axis down to the oil surface with the axis
horizontal at standstill, and prints this assumption.
Seed 000 p.018: oil ISO VG68; change after the first 100 h, then every 1000 h or 6 months.

The level is the gear maker's level: at A the maker's own condition (the wave-generator
bearing and the teeth are wetted) holds by definition of the table. The housing must
realise it: the cavity reaches below the level, and the shaft-seal lips stay above it so
that the seals do not stand in oil at rest.
"""

from __future__ import annotations

import math

from .lubrication import Criterion
from .record import CheckResult, Quantity, FAIL, NOT_EVALUATED, PASS, margin_of

TITLE = "Oil level and oil volume"
FORMULA = ("A < r_cavity (level inside the cavity);  A ≥ d_seal/2 (seal lips above the oil);  "
           "no opening below y = −A;  V_oil = volume of the cavity below y = −A")


def oil_level(lubrication: str, level_mm: float | None, level_source: str, axis: str,
              cavity_depth_mm: float | None, seal_shaft_mm: float | None,
              oil_volume_mL: float | None, volume_note: str = "",
              plug_radius_mm: float | None = None,
              support_bearing_od_mm: float | None = None,
              openings: list[str] | None = None) -> CheckResult:
    """Whether the housing holds the oil at level A [mm below the axis].

    ``cavity_depth_mm``: how far the cavity reaches below the axis [mm];
    ``seal_shaft_mm``: shaft diameter at the seal lips [mm]; ``oil_volume_mL``: cavity
    volume below the level [mL]; ``plug_radius_mm``: radius of an axial level hole [mm];
    ``support_bearing_od_mm``: outside diameter of a support bearing in the housing [mm]
    (reported: whether the bath reaches it; the catalog level is set for the gear);
    ``openings``: gaps in the cavity wall below the level, as the geometry found them.
    """
    inputs = {"A": Quantity(level_mm, "mm", level_source), "axis": Quantity(axis),
              "r_cavity": Quantity(cavity_depth_mm, "mm", "generated housing"),
              "d_seal": Quantity(seal_shaft_mm, "mm", "generated housing"),
              "V_oil": Quantity(oil_volume_mL, "mL", "generated housing")}
    if lubrication != "oil":
        return _not_evaluated(inputs, f"{lubrication} lubrication in the duty: no oil level applies")
    if level_mm is None:
        return _not_evaluated(inputs, "oil level for this model missing from the catalog "
                                      "(FD: table 315-1; component sets: overlay "
                                      "component_housing.oil_level_from_axis_mm)")
    if axis != "horizontal":
        return _not_evaluated(inputs, "oil level for a vertical axis (table 315-1 gives the "
                                      "level with the axis horizontal)")
    if cavity_depth_mm is None:
        return _not_evaluated(inputs, "an oil cavity in the generated parts (this family's "
                                      "lubricant is held by the gear itself)")
    criteria = [_inside(level_mm, cavity_depth_mm), _seals(level_mm, seal_shaft_mm),
                _sealed(openings or []), _plug(level_mm, plug_radius_mm)]
    failed = [c for c in criteria if c.status == FAIL]
    notes = [c.text for c in criteria]
    if support_bearing_od_mm is not None:
        reached = level_mm < support_bearing_od_mm / 2
        notes.append(f"the support bearings (Ø{support_bearing_od_mm:g}) "
                     + ("dip into the bath" if reached else
                        "stay above the bath: they live on splash oil or their own grease "
                        "(sealed bearings)"))
    if oil_volume_mL is not None:
        notes.append(f"oil volume to level A: {oil_volume_mL:.0f} mL{volume_note}")
    return CheckResult("oil_level", TITLE, "lubrication", FORMULA, inputs, level_mm,
                       cavity_depth_mm, "mm", "<=", FAIL if failed else PASS,
                       f"{level_source}; seed 000 p.018", "; ".join(notes),
                       _margin(level_mm, cavity_depth_mm, failed),
                       {"criteria": [c.__dict__ for c in criteria],
                        "oil_volume_mL": oil_volume_mL})


def _margin(level: float, depth: float, failed: list[Criterion]) -> float | None:
    """Margin of the level against the cavity; none when another criterion decides the fail
    (a positive margin beside FAIL would mislead)."""
    if failed and all(c.name != "inside cavity" for c in failed):
        return None
    return margin_of(level, depth, "<=")


def _not_evaluated(inputs: dict, missing: str) -> CheckResult:
    return CheckResult("oil_level", TITLE, "lubrication", FORMULA, inputs, None, None, "mm",
                       "", NOT_EVALUATED, "seed 001 table 315-1", f"not evaluated: {missing}")


def _inside(level: float, depth: float) -> Criterion:
    ok = level < depth
    return Criterion("inside cavity", PASS if ok else FAIL,
                     f"level A = {level:g} mm {'lies inside' if ok else 'is below'} the cavity "
                     f"(which reaches {depth:g} mm below the axis)")


def _seals(level: float, seal_shaft: float | None) -> Criterion:
    if seal_shaft is None:
        return Criterion("seals", PASS, "no shaft seal in the generated parts")
    ok = level >= seal_shaft / 2
    return Criterion("seals", PASS if ok else FAIL,
                     f"seal lips on Ø{seal_shaft:g} reach {seal_shaft / 2:g} mm below the axis: "
                     + ("above the oil" if ok else "they stand in oil at rest"))


def _sealed(openings: list[str]) -> Criterion:
    if openings:
        return Criterion("sealed", FAIL, "the oil would run out: " + "; ".join(openings))
    return Criterion("sealed", PASS, "no opening in the cavity wall below the level (static "
                                     "joints between parts that do not move are closed by the "
                                     "O-ring or liquid gasket each part's notes name, seed 000 "
                                     "p.028: the probe treats them as sealed)")


def _plug(level: float, plug_radius: float | None) -> Criterion:
    if plug_radius is None:
        return Criterion("level hole", PASS, "no level hole: fill by the volume given")
    if plug_radius < level:
        return Criterion("level hole", FAIL,
                         f"the level port opens at radius {plug_radius:g} mm, inside level A = "
                         f"{level:g} mm: it cannot show the level")
    turn = math.degrees(math.acos(level / plug_radius))
    return Criterion("level hole", PASS,
                     f"the level port opens at radius {plug_radius:g} mm ≥ A: turned "
                     f"{turn:.1f}° from the bottom its opening stands A = {level:g} mm below "
                     "the axis; fill through the other port until oil runs out there")
