"""The record of a motor adapter plate: dimensions, notes, fits, bought parts and the
neighbour bodies of the review assembly (the gear head's motor flange side and the motor)."""

from __future__ import annotations

from .part import GeometricTolerance, Neighbour
from .primitives import cylinder, ring_points
from .standards import review_minor_diameter

MATERIALS = {"steel": "S235JR (EN 10025-2)", "aluminium": "EN AW-6082 T6 (EN 573-3)",
             "cast_iron": "EN-GJL-250 (EN 1561)"}
MOTOR_BODY_MM = 80.0   # modelled motor length behind its flange (an envelope, not data)
FLANGE_BODY_MM = 15.0  # modelled depth of the gear head's flange behind its motor face


def adapter_record(a) -> dict:
    length, engaged = a.screw_length()
    return {"dimensions": _dimensions(a), "bolt_circles": a.bolt_circles(),
            "notes": _notes(a, length, engaged), "fits": a.fits(),
            "tolerances": [GeometricTolerance("gear-head face", "datum", None, "A", "ISO 5459"),
                           GeometricTolerance("spigot Ø" + f"{a.row['pilot_H7_mm']:g}",
                                              "datum", None, "B", "ISO 5459"),
                           GeometricTolerance("motor face", "parallelism", 0.02, "A",
                                              "HOUSING_RULES §4"),
                           GeometricTolerance("motor pilot recess", "coaxiality", 0.03, "B",
                                              "HOUSING_RULES §4: pilot runout ≤ 0.02-0.03")],
            "purchased": [{"item": "screw", "designation": f"ISO 4762 {a.row['thread']}×"
                           f"{length if length else '?'}", "quantity": 4,
                           "note": f"plate to flange {a.row['flange_code']}"}]
            + [{"item": "O-ring", "designation": f"O-ring ID ≈ {d_in:.0f} × {a.gland.d2:g} "
                "(ISO 3601-1: the nearest size at or below)", "quantity": 1,
                "note": f"static seal, {face}"}
               for face, d_in in a.face_glands.items()],
            "neighbours": (a.neighbour_screws() + [_flange_body(a), _motor_body(a)]
                           + a.face_orings()),
            "material": MATERIALS[a.options.material]}


def _dimensions(a) -> dict:
    kind, size = a.outline
    dims = {"square_mm" if kind == "square" else "outer_diameter_mm": size,
            "thickness_mm": a.thickness, "overall_length_mm": a.thickness + a.spigot,
            "spigot_diameter_mm": a.row["pilot_H7_mm"], "spigot_length_mm": a.spigot,
            "pilot_recess_mm": a.motor.pilot_diameter_mm, "pilot_recess_depth_mm": a.recess,
            "bore_mm": a.bore, "counterbore_depth_mm": a.cbore_depth,
            "motor_shift_mm": a.thickness}
    return dims


def _notes(a, length, engaged) -> list[str]:
    row, m = a.row, a.motor
    code = row["flange_code"]
    notes = [
        f"flange code {code} (seed 003 table {row['table']}): pilot A Ø{row['pilot_H7_mm']:g} "
        f"H7, bolt circle C Ø{row['bolt_circle_mm']:g}, D {row['thread']}×"
        f"{row['thread_depth_mm']:g}, coupling bore F {row['coupling_bore_min_mm']:g}-"
        f"{row['coupling_bore_max_mm']:g}; the motor does not bolt on directly: "
        + "; ".join(a.mismatch_text),
        f"spigot Ø{row['pilot_H7_mm']:g} g6 × {a.spigot:g} into pilot A (at most B − 0.5 "
        "where B is printed)",
        f"4 × ISO 4762 {row['thread']}×{length or '?'} into the flange's D threads (hole count "
        f"not in the seeds: 4 assumed, on the diagonals), clearance Ø{a.flange_hole:g} "
        f"(ISO 273 medium), counterbore Ø{a.cbore:g} × {a.cbore_depth:g} from the motor face"
        + (" (below the motor recess floor: the motor spigot covers them)"
           if a.cbore_from_recess else "") + f"; engagement {engaged:g} mm of "
        f"{row['thread_depth_mm']:g}",
        f"motor side: pilot recess Ø{m.pilot_diameter_mm:g} H7 × {a.recess:g} (motor pilot "
        f"{m.pilot_length_mm:g} + 0.5), {m.bolt_count} × {m.bolt_thread} "
        + (f"tapped {a.motor_thread_depth:g} deep (≥ 1.5·d)" if a.motor_thread_depth else
           "clearance holes (the motor's flange is tapped)")
        + f" on Ø{m.bolt_circle_mm:g}, clocked {a.motor_start:g}° to clear the flange screws",
        f"the plate moves the motor {a.thickness:g} mm back from the flange face: its shaft "
        f"(Ø{m.shaft_diameter_mm:g} × {m.shaft_length_mm:g}) reaches {a.thickness:g} mm less "
        "far into the input coupling (motor_shaft_reach check)",
    ]
    for face, d_in in a.face_glands.items():
        notes.append(f"{face}: O-ring × {a.gland.d2:g} in a face groove Ø{d_in:g}-"
                     f"{d_in + 2 * a.gland.face_width:g} × {a.gland.face_depth:g} deep "
                     "(ISO 3601-2 proportions; seed 000 p.028 asks for O-ring or sealant on "
                     "flange faces)")
    for face in {"gear-head face", "motor face"} - set(a.face_glands):
        notes.append(f"{face}: no room for a face groove: seal with liquid gasket "
                     "(seed 000 p.028)")
    return notes


def _flange_body(a) -> Neighbour:
    """The gear head's motor flange, motor side only (what the seeds give): a plate behind
    the face z = 0 with pilot A × B and the four D holes (tap-drill Ø)."""
    row = a.row
    kind, size = a.outline
    depth = row.get("pilot_depth_mm") or a.spigot + 0.5
    outer = row.get("square_mm") or size
    body = cylinder(outer * 1.0, -FLANGE_BODY_MM, 0.0)
    minor = review_minor_diameter(row["thread"])
    holes = [cylinder(minor, -row["thread_depth_mm"], 0.5, x, y)
             for x, y in ring_points(row["bolt_circle_mm"], 4, 45.0)]
    body = body.cut(cylinder(row["pilot_H7_mm"], -depth, 0.5),
                    cylinder(row["coupling_bore_max_mm"] + 2, -FLANGE_BODY_MM - 1, 0.5), *holes)
    return Neighbour("gear", f"gear-head motor flange {row['flange_code']} (motor side)",
                     {"A": row["pilot_H7_mm"]}, 0.0, body=body.Solids()[0],
                     turns_with="frame")


def _motor_body(a) -> Neighbour:
    """Motor envelope on the motor face: spigot, body (square or round), shaft."""
    m, t = a.motor, a.thickness
    if m.square_mm:
        import cadquery as cq
        s = m.square_mm
        housing = cq.Solid.makeBox(s, s, MOTOR_BODY_MM, cq.Vector(-s / 2, -s / 2, t))
    else:
        housing = cylinder(m.bolt_circle_mm + 3 * a.d_motor, t, t + MOTOR_BODY_MM)
    body = housing.fuse(cylinder(m.pilot_diameter_mm, t - m.pilot_length_mm, t + 0.01),
                        cylinder(m.shaft_diameter_mm, t - m.shaft_length_mm, t + 0.01))
    return Neighbour("motor", "motor envelope", {"pilot": m.pilot_diameter_mm}, t,
                     body=body.Solids()[0], turns_with="frame")

