"""Bill of materials of a generated design: screws, bought parts, lubricant.

Screw length for a clearance bolt circle: the shortest ISO 4762 preferred length that
reaches the least engagement the bolt_pattern check asked for (k_m·d) past the grip,
and no longer than grip + tapped depth (the screw must not bottom in its hole).
The tightening torque M_A is the one the bolt_pattern check used (VDI 2230).

References
----------
ISO 4762:2004 (hexagon socket head cap screws, preferred lengths). Seed 000 p.016 (unit and
gear-head types ship grease-filled), p.018 (oil ISO VG68). Seed 001 p.315 (FD oil level A).
"""

from __future__ import annotations

from dataclasses import dataclass, asdict

from ..checks.bolts import MIN_ENGAGEMENT
from ..geometry.standards import ISO_4762_LENGTHS_MM, thread_diameter


@dataclass
class BomRow:
    item: str          # screws | bearing | seal | o-ring | plug | lubricant
    designation: str
    quantity: str
    part: str          # the generated part it belongs to (or "assembly")
    note: str = ""

    def as_dict(self) -> dict:
        return asdict(self)


def screw_designation(size: str, bolt_class: str) -> str:
    """ISO 4762 designation as ordered: ``ISO 4762 M5×16 – 12.9`` (thread × length – class)."""
    return f"ISO 4762 {size} – {bolt_class}"


def screw_length_mm(thread: str, grip_mm: float, tapped_depth_mm: float,
                    min_engagement_mm: float | None = None) -> float | None:
    """Shortest ISO 4762 length that engages ``min_engagement_mm`` (default: steel, the
    bolt_pattern check's k_m·d) and does not bottom; None if no preferred length fits."""
    low = grip_mm + _engagement(thread, min_engagement_mm)
    high = grip_mm + tapped_depth_mm
    return next((float(l) for l in ISO_4762_LENGTHS_MM if low <= l <= high), None)


def _next_length(least_mm: float) -> float | None:
    """The shortest ISO 4762 preferred length of at least ``least_mm``."""
    return next((float(l) for l in ISO_4762_LENGTHS_MM if l >= least_mm), None)


def _engagement(thread: str, min_engagement_mm: float | None) -> float:
    if min_engagement_mm is not None:
        return min_engagement_mm
    return MIN_ENGAGEMENT["steel"] * thread_diameter(thread)


def _no_length_hint(thread: str, grip_mm: float, min_engagement_mm: float) -> str:
    """What to do when no preferred length fits: the counterbore depth that makes one fit."""
    low = grip_mm + min_engagement_mm
    shorter = max((l for l in ISO_4762_LENGTHS_MM if l < low), default=None)
    text = (f"no ISO 4762 preferred length between grip + {min_engagement_mm:g} mm "
            "engagement and grip + thread depth")
    if shorter is None:
        return text
    return (f"{text}: deepen the counterbores by {low - shorter:.1f} mm for "
            f"{thread}×{shorter:g}, or use a special length")


def screw_rows(part_name: str, circles: list[dict], joints: dict[str, dict],
               bolt_class: str) -> list[BomRow]:
    """One row per bolt circle: length for clearance holes with a known grip, else the rule.

    ``joints`` maps "part/circle" to its bolt_pattern record: the tightening torque M_A and
    the least engagement come from there, so the BOM asks what the check asked.
    """
    rows = []
    for c in circles:
        if not c.get("in_bom", True):
            continue
        joint = joints.get(f"{part_name}/{c['name']}", {})
        torque = joint.get("inputs", {}).get("M_A", {}).get("value")
        m_min = _engagement(c["thread"], joint.get("details", {}).get("criteria", {})
                            .get("engagement", {}).get("limit"))
        ma = f"; tighten to M_A = {torque:.1f} N·m (VDI 2230, µ = 0.12)" if torque else ""
        if c["kind"] == "clearance" and c.get("grip_mm") is not None and c["depth_mm"] is None:
            # into a part hdcad does not make (the gear head): its tapped depth is unknown
            low = c["grip_mm"] + m_min
            size = f"{c['thread']}×{_next_length(low):g}" if _next_length(low) else \
                f"{c['thread']}×L"
            rows.append(BomRow("screws", screw_designation(size, bolt_class), str(c["count"]),
                               part_name, f"{c['name']} on Ø{c['diameter_mm']:g}; grip "
                               f"{c['grip_mm']:.1f} mm + {m_min:g} mm engagement: the shortest "
                               "ISO 4762 length; check it against the tapped depth of the "
                               f"mating part (not in the catalog){ma}"))
        elif c["kind"] == "clearance" and c.get("grip_mm") is not None:
            length = screw_length_mm(c["thread"], c["grip_mm"], c["depth_mm"] or 0.0, m_min)
            size = f"{c['thread']}×{length:g}" if length else f"{c['thread']}×?"
            hint = "" if length else "; " + _no_length_hint(c["thread"], c["grip_mm"], m_min)
            rows.append(BomRow("screws", screw_designation(size, bolt_class), str(c["count"]),
                               part_name, f"{c['name']} on Ø{c['diameter_mm']:g}; grip "
                               f"{c['grip_mm']:.1f} mm, thread depth {c['depth_mm']:g} mm"
                               + hint + ma))
        else:
            holes = "tapped holes" if c["kind"] == "tapped" else "clearance holes"
            rows.append(BomRow("screws", screw_designation(f"{c['thread']}×L", bolt_class),
                               str(c["count"]), part_name,
                               f"{c['name']}: {holes} on Ø{c['diameter_mm']:g}, thread depth "
                               f"{c['depth_mm']:g} mm; L = grip of the mating part (gear, motor "
                               f"or flexspline flange) + {m_min:g} … {c['depth_mm']:g} mm, the "
                               f"next ISO 4762 preferred length{ma}"))
    return rows


def lubricant_row(family: str, lubrication: str, grease: str, oil_volume_mL: float | None,
                  level_mm: float | None, grease_g: float | None = None) -> BomRow:
    if family == "GH":
        return BomRow("lubricant", "grease (factory fill)", "—", "gear head",
                      "gear heads ship grease-filled (seed 000 p.016); no fill by the user")
    if lubrication == "oil":
        amount = f"≤ {oil_volume_mL:.0f} mL" if oil_volume_mL is not None else "not in catalog"
        level = f"fill to level A = {level_mm:g} mm (table 315-1)" if level_mm else ""
        return BomRow("lubricant", "oil ISO VG68", amount, "assembly",
                      "; ".join(x for x in (level, "change after 100 h, then every 1000 h or "
                                            "6 months (seed 000 p.018)") if x))
    if grease_g is not None:
        return BomRow("lubricant", f"grease {grease}", f"{grease_g:g} g", "assembly",
                      "amount from the overlay table component_housing (grease_g)")
    return BomRow("lubricant", f"grease {grease}", "not in catalog", "assembly",
                  "grease amounts for this type are not in the seeds; add them via overlay")


JOINT_SEALING = {
    "FD-2": ("rotary seal across the running gap", "not generated",
             "the casing halves turn relative to each other: seal the gap between them (see "
             "the oil_level check); the spline-to-casing faces take liquid gasket"),
    "2A-GR": ("liquid gasket or O-rings", "not generated",
              "static joints cover–circular spline–housing and flange–flexspline: liquid "
              "gasket, or add O-ring grooves (ISO 3601) to the design"),
}


def sealing_row(family: str) -> BomRow | None:
    """O-rings and gaskets: what the joints of this family need (hdcad models none)."""
    if family not in JOINT_SEALING:
        return None
    designation, quantity, note = JOINT_SEALING[family]
    return BomRow("o-ring / gasket", designation, quantity, "assembly", note)


def bill_of_materials(parts: list[dict], checks: list[dict], family: str, lubrication: str,
                      grease: str, bolt_class: str, grease_g: float | None = None
                      ) -> list[BomRow]:
    """BOM rows from the results.json parts and check records."""
    joints = {c["details"].get("name"): c for c in checks if c["id"] == "bolt_pattern"}
    rows: list[BomRow] = []
    for part in parts:
        rows += screw_rows(part["name"], part["bolt_circles"], joints, bolt_class)
        rows += [BomRow(p["item"], p["designation"], str(p["quantity"]), part["name"],
                        p.get("note", "")) for p in part.get("purchased", [])]
    oil = next((c for c in checks if c["id"] == "oil_level"), None)
    volume = oil["details"].get("oil_volume_mL") if oil else None
    level = oil["inputs"].get("A", {}).get("value") if oil else None
    sealing = sealing_row(family)
    rows += [sealing] if sealing else []
    rows.append(lubricant_row(family, lubrication, grease, volume, level, grease_g))
    return rows
