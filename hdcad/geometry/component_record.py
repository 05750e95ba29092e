"""The record of a CSF/CSG-2A-GR part set: dimensions of each part and the bought parts each
holds (bill of materials)."""

from __future__ import annotations

from .component_housing import MOUNT_SPIGOT_MM, MOUNT_START_DEG, SPIGOT_MM
from .part import BoltCircle
from .standards import ISO_273_MEDIUM_MM

def purchased(h, part: str) -> list[dict]:
    """Bought parts each part holds (bill of materials)."""
    def bearing(name, d, big_d, b, qty, note):
        return {"item": "bearing", "designation": f"{name} (ISO 15, {d:g}×{big_d:g}×{b:g})",
                "quantity": qty, "note": note}

    def seal(d, seal_dims, note):
        return {"item": "seal", "designation": f"rotary shaft lip seal {d:g}×"
                f"{seal_dims[0]:g}×{seal_dims[1]:g} (ISO 6194-1 / DIN 3760)",
                "quantity": 1, "note": note}
    if part == "housing":
        return [bearing(h.out_bearing, h.out_d, h.out_D, h.out_B, 2,
                        "two-point support of the output flange journal"),
                seal(h.out_d, h.out_seal, "output shaft")] + rings(h, "out")
    if part == "input_cover":
        return [bearing(h.in_bearing, h.in_d, h.in_D, h.in_B, 2,
                        "two-point support of the input shaft (guideline 5)"),
                seal(h.in_d, h.in_seal, "input shaft")] + rings(h, "in")
    return []

def rings(h, side: str) -> list[dict]:
    r = h.retention[side]
    return [{"item": "retaining ring", "designation": f"{ring.standard} {ring.d1:g}×"
             f"{ring.s:g}", "quantity": 1, "note": note}
            for ring, note in ((r.ring_bore, "outer rings, gear side"),
                               (r.ring_shaft, "inner rings, outer side"))] + [
            {"item": "spacer", "designation": f"spacer rings {r.bearing.d:g}/"
             f"{r.bearing.D:g} × {r.bearing.B:g} (inner and outer)", "quantity": 2,
             "note": "turned to the bearing width; between the pair"}]

def housing_dims(h) -> dict[str, float]:
    o = h.outline
    dims = {"outer_diameter_mm": h.mount_od, "body_diameter_mm": h.housing_od,
            "pilot_recess_mm": o["cs_outer_diameter_mm"],
            "pilot_depth_mm": h.recess_depth, "z_min_mm": -h.recess_depth,
            "z_max_mm": h.z_out + MOUNT_SPIGOT_MM,
            "overall_length_mm": h.z_out + MOUNT_SPIGOT_MM + h.recess_depth,
            "mounting_flange_mm": h.mount_od, "mounting_thickness_mm": h.mount_t,
            "mounting_spigot_mm": h.mount_spigot, "output_face_z_mm": h.z_out,
            "bearing_pair_z_mm": h.zb, "shoulder_z_mm": h.z_shoulder,
            "fs_outer_diameter_mm": o["fs_outer_diameter_mm"],
            "fs_length_mm": o["fs_length_mm"], "seal_shaft_mm": h.out_d,
            "cavity_diameter_mm": h.cavity_d, "cavity_z0_mm": 0.0,
            "cavity_z1_mm": h.z_wall, "diaphragm_axial_clearance_mm": h.cavity_beyond,
            "bearing_seat_mm": h.out_D, "bearing_seat_depth_mm": h.bearing_len,
            "seal_recess_mm": h.out_seal[0], "seal_recess_depth_mm": h.out_seal_depth,
            "tap_drill_mm": h.cs_tap, "thread_depth_mm": h.cs_depth,
            "drill_depth_mm": h.cs_drill}
    for column in ("oil_level_from_axis_mm", "grease_g"):
        if h.rec.get(column) is not None:
            dims[column] = h.rec[column]
    return dims

def cover_dims(h) -> dict[str, float]:
    return {"outer_diameter_mm": h.housing_od,
            "spigot_diameter_mm": h.outline["cs_outer_diameter_mm"],
            "spigot_length_mm": SPIGOT_MM, "thickness_mm": h.cover_t,
            "cavity_diameter_mm": h.cover_cavity_d,
            "cavity_depth_mm": h.cover_cavity_depth, "bearing_seat_mm": h.in_D,
            "bearing_seat_depth_mm": h.in_shoulder - h.cover_cavity_depth,
            "bearing_pair_z_mm": h.zb_in, "seal_shaft_mm": h.in_d,
            "seal_recess_mm": h.in_seal[0], "seal_recess_depth_mm": h.in_seal_depth,
            "clearance_hole_mm": h.clearance, "counterbore_diameter_mm": h.cbore,
            "counterbore_depth_mm": h.cbore_depth, "input_shaft_mm": h.input_shaft}

def flange_dims(h) -> dict[str, float]:
    boss = h.outline["fs_boss_diameter_mm"]
    return {"outer_diameter_mm": boss, "flange_diameter_mm": boss,
            "flange_thickness_mm": h.flange_t, "diaphragm_radius_mm": h.flange_r,
            "journal_diameter_mm": h.out_d,
            "overall_length_mm": h.flange_t + h.journal_len,
            "tap_drill_mm": h.fs_tap, "thread_depth_mm": h.fs_depth,
            "drill_depth_mm": h.fs_drill}


def cs_circle(h) -> BoltCircle:
    # the CS screws thread into the housing; its material ring runs from the cavity to
    # the housing outside diameter
    return BoltCircle("cs_screws", h.outline["cs_bolt_circle_mm"], h.cs_count,
                      h.cs_tap, h.cs_thread, "tapped", h.cs_depth,
                      annulus_inner_mm=h.cavity_d, annulus_outer_mm=h.housing_od,
                      in_bom=False)

def cover_circle(h) -> BoltCircle:
    # counterbored clearance holes; each screw clamps cover + CS and threads into the
    # housing's tapped holes (cs_screws)
    return BoltCircle("cs_screws_cover", h.outline["cs_bolt_circle_mm"], h.cs_count,
                      h.clearance, h.cs_thread, "clearance", h.cs_depth,
                      annulus_inner_mm=max(h.in_D, h.in_seal[0]),
                      annulus_outer_mm=h.housing_od,
                      grip_mm=h.cover_t - h.cbore_depth + h.outline["cs_width_mm"])

def mount_circle(h) -> BoltCircle:
    """Screws from the input side through the mounting flange into the machine frame
    (the frame's thread depth is the user's: grip = flange thickness)."""
    return BoltCircle("mounting", h.mount_bc, h.mount_count,
                      ISO_273_MEDIUM_MM[h.mount_thread], h.mount_thread, "clearance",
                      None, annulus_inner_mm=h.housing_od,
                      annulus_outer_mm=h.mount_od, grip_mm=h.mount_t,
                      start_angle_deg=MOUNT_START_DEG)

def fs_circle(h) -> BoltCircle:
    # blind tapped holes in a solid disc (no bore: inner edge Ø0), outer edge = the
    # FS-boss flange
    return BoltCircle("fs_screws", h.outline["fs_bolt_circle_mm"], h.fs_count,
                      h.fs_tap, h.fs_thread, "tapped", h.fs_depth,
                      annulus_inner_mm=0.0,
                      annulus_outer_mm=h.outline["fs_boss_diameter_mm"])
