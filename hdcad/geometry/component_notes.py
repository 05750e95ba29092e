"""The notes a CSF/CSG-2A-GR housing set prints: sources, guidelines of seed 000 p.024, and
every design choice with its reason."""

from __future__ import annotations

from .component_housing import (AXIAL_GAP_MM, FLANGE_STEP_MM, HOUSING, OUTLINE, SPIGOT_MM,
                                TAPPED_DEPTH_FACTOR, WALL_ALLOWANCE_MM)
from .housing_common import EDGE_MARGIN_MM


def notes(h) -> list[str]:
    o, rec = h.outline, h.rec
    return [
        f"{h.label}: every gear dimension from the overlay tables {OUTLINE} and "
        f"{HOUSING} (source: {o['source']}); the seeds have no outline or recommended-"
        "housing table for the component types",
        f"design guidelines seed 000 p.024: (1) CS pilot recess Ø{o['cs_outer_diameter_mm']:g}"
        " H7 and all bearing seats turned in the housing and cover that hold it; (4) inner "
        f"wall Ø{h.cavity_d:g} = max(recommended FS wall Ø{rec['fs_wall_diameter_mm']:g}, "
        f"diaphragm side Ø{rec['diaphragm_side_diameter_mm']:g}) + {WALL_ALLOWANCE_MM:g} mm "
        f"allowance; end wall {h.cavity_beyond:g} mm beyond the FS diaphragm (recommended "
        f"≥ {rec['diaphragm_side_depth_mm']:g}, flange {h.flange_t:g} + running gap "
        f"{AXIAL_GAP_MM:g}); (5) two output bearings; (6) output flange Ø"
        f"{o['fs_boss_diameter_mm']:g} = FS boss, radius R{h.flange_r:g} on its "
        f"diaphragm side; (7) cover cavity Ø{h.cover_cavity_d:g} × "
        f"{h.cover_cavity_depth:g} clears the C-ring hook (r {o['cring_hook_radius_mm']:g}, "
        f"{o['cring_protrusion_mm']:g} mm proud of the CS) by ≥ "
        f"{rec['cring_clearance_min_mm']:g} mm + {WALL_ALLOWANCE_MM:g} mm allowance",
        h.retention["out"].text(f"output (2 × {h.out_bearing}, the largest 60xx bore ≤ FS "
                                f"boss − 2 × {FLANGE_STEP_MM:g} mm; span 2B, not computed "
                                "from the moment load: check it)"),
        h.retention["in"].text(f"input shaft Ø{h.input_shaft:g} ({h.input_rule}) on "
                               f"2 × {h.in_bearing} (guideline 5: two-point support; the pair "
                               "takes the WG thrust, guideline 2, p.027); the user's shaft "
                               "needs the collar and the ring groove drawn in the review "
                               "assembly"),
        f"mounting flange Ø{h.mount_od:g} × {h.mount_t:g} at the output end: "
        f"{h.mount_count} × {h.mount_thread} (ISO 273 medium holes on Ø{h.mount_bc:g}, heads on "
        f"the input side clear of the Ø{h.housing_od:g} body, hole centres ≥ 1.5·d from the "
        f"edge), centring spigot Ø{h.mount_spigot:g} g6 × {h.mount_spigot_len:g} for a frame "
        "bore H7; the frame's thread depth is the user's",
        f"CS screws {h.cs_count} × {h.cs_thread} on φ{o['cs_bolt_circle_mm']:g}: from "
        f"the cover's outer face (clearance Ø{h.clearance:g} ISO 273 medium, counterbore "
        f"Ø{h.cbore:g} DIN 974-1 × {h.cbore_depth:g}) through the CS holes into the "
        f"housing, tapped {h.cs_thread} × {h.cs_depth:g} (tap drill Ø{h.cs_tap:g} "
        f"ISO 2306, drilled {h.cs_drill:g}); the CS is clamped between the housing "
        "shoulder and the cover spigot; the CS holes must be through holes (check the "
        "outline drawing)",
        f"FS screws {h.fs_count} × {h.fs_thread} on φ{o['fs_bolt_circle_mm']:g}: "
        f"from inside the cup into the output flange, tapped × {h.fs_depth:g} (tap drill "
        f"Ø{h.fs_tap:g}, drilled {h.fs_drill:g}); thread depth {TAPPED_DEPTH_FACTOR:g}"
        "·d (design value: the least engagement of an aluminium part)",
        f"housing Ø{h.housing_od:g} = CS φ + 2 × wall_mm; cover spigot {SPIGOT_MM:g} mm; "
        f"bolt-circle ligaments ≥ {EDGE_MARGIN_MM:g} mm; output journal sticks out "
        f"{h.out_d:g} mm (= its diameter) for the user's load",
    ]
