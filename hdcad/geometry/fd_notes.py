"""The notes an FD-2 casing half and its sleeve print: what each feature is, which table or
standard gives it, and every design choice with its reason."""

from __future__ import annotations

from .fd_layout import (GLAND_LAND_MM, LEVEL_MARGIN_MM, SEAL_SET_BACK_MM, SPIGOT_CLEARANCE_MM,
                        SPIGOT_DEPTH_MM, WALL_MIN_MM)
from .housing_common import CBORE_SINK_MM


def casing_notes(half) -> list[str]:
    return _source_notes(half) + _support_notes(half) + _seal_notes(half) + _oil_notes(half)


def _source_notes(half) -> list[str]:
    fd0, fd2, lay = half.fd0, half.fd2, half.lay
    notes = [
        f"seed 001 p.315: casings and bearings of an FD-2 differential follow the FD-0 unit; "
        f"gear spigot recess Ø{lay.gear_recess_d:g} H7 (FD-0 φB {fd0['B_H7_mm']:g}), "
        f"{fd0['L_count']} × "
        f"{half.gear_thread}×{fd0['M_depth_mm']:g} on φK {fd0['K_mm']:g} (table 311-1); pilot "
        f"recess Ø{fd2['A_g7_mm']:g} H7 for the spline's φA g7, {fd2['J_count']} × "
        f"{half.screw} spline screws on φI {fd2['I_mm']:g} (table 312-1)",
        f"outer Ø{lay.outer_d:g}: FD-0 φA {fd0['A_mm']:g}, or the running-gap seal journal "
        f"groove Ø{lay.gap_groove_d:g} + 2 × {WALL_MIN_MM:g} mm wall if larger, over the first "
        f"{lay.front_length:g} mm; behind it the body steps down to Ø{lay.body_d:g} (FD-0 φA, or "
        f"what the gear holes and counterbores need with {WALL_MIN_MM:g} mm walls)",
        f"spline screws ISO 4762 {half.screw}×{half.screw_length} in Ø{half.clearance:g} "
        f"clearance holes (ISO 273 medium), counterbored Ø{half.cbore:g} (DIN 974-1) × "
        f"{half.cbore_depth:.2f} from the outer face so that an existing length fits (grip "
        f"{half.grip:.2f} mm, head ≥ {CBORE_SINK_MM:g} mm below the gear face); sealing "
        "thread-locker on the screws (seed 000 p.028)",
        f"gear_mount {half.gear_thread}×{fd0['M_depth_mm']:g} (thread depth of table 311-1), "
        f"drilled Ø{half.tap_drill:g} × {half.gear_drill_depth:g} (thread + 3·P run-out), at {half._gear_start_deg():g}° + k·pitch (half a pitch off the "
        "spline screws)",
        f"gear/pulley spigot recess Ø{lay.gear_recess_d:g} H7 × {SPIGOT_DEPTH_MM:g} mm: depth "
        "a design value (no standard depth)",
    ]
    if lay.gear_recess_d < fd0["B_H7_mm"]:
        notes.append(f"gear recess Ø{lay.gear_recess_d:g} instead of FD-0 φB "
                     f"{fd0['B_H7_mm']:g}: with φB the spline-screw counterbores on φI "
                     f"{fd2['I_mm']:g} would leave "
                     f"{(fd2['I_mm'] - half.cbore - fd0['B_H7_mm']) / 2:g} mm of wall, below the "
                     f"{WALL_MIN_MM:g} mm a machined steel wall needs; the user's gear centres "
                     "on this smaller spigot (not interchangeable with an FD-0 unit's gear)")
    if lay.unit_width > fd0["D_mm"]:
        notes.append(f"the unit is {lay.unit_width:g} mm wide instead of FD-0 D "
                     f"{fd0['D_mm']:g} mm: two bearings per half, the oil-port window, the "
                     "retaining rings and the lip seal need the room (FD-0's own arrangement is "
                     "in the lost figure 311-1)")
    if half.relief is not None:
        notes.append(half.relief.text() + f": ≥ {WALL_MIN_MM:g} mm and 1.5·d over the "
                     "spline-screw clearance holes, the port ligament "
                     f"{half.lay.port.ligament_min:g} mm from the spot faces, "
                     f"{WALL_MIN_MM:g} mm from the counterbores and gear holes of the outer "
                     "face (pockets where material carries nothing; mass before and after in "
                     "results.json)")
    return notes


def _support_notes(half) -> list[str]:
    lay = half.lay
    b, ring = lay.bearing, lay.bore_ring
    land = f"d1 ≈ {b.land_d1:g}" if b.land_d1 else "the inner-ring land"
    return [
        f"two-point support: a pair of {b.text()} per half (table 313-2 row IV: four support "
        f"bearings per unit), outer rings in Ø{b.D:g} M7 (the outer ring turns relative to "
        f"its load) over {2 * b.B:g} mm",
        f"outer rings located: spline side by a {ring.text()}; outer side by the step to the "
        f"seal bore Ø{lay.seal.d2:g}, which lies between {land} + 1 and D_a,max = "
        f"{b.housing_shoulder_max:g} (DIN 5418, h = {b.h:g} for r {b.r_s:g}): it touches "
        "the outer ring only",
        f"inner rings on the journal sleeve (Ø{b.d:g} k5): collar Ø{lay.collar_d:g} ≥ d_a,min "
        f"{b.shaft_shoulder_min:g} on the spline side, {lay.shaft_ring.text()} on the outer "
        "side; the sleeve butts against the WG hub end (the FD-2 hub φH stands out only "
        f"{(half.fd2['E_mm'] - half.fd2['D_mm']) / 2:g} mm, table 312-1)",
        "assembly: seal into its bore from outside; bearings pressed onto the sleeve against "
        "the collar, DIN 471 ring fitted; sleeve with bearings pushed into the seat from the "
        "spline side (the journal enters the seal from the lip side); DIN 472 ring; spline",
    ]


def _seal_notes(half) -> list[str]:
    lay, gap = half.lay, half.options.running_gap_mm
    gland = lay.gap_gland
    where = ("in a groove of this half's bore, sealing on" if half.side == "S" else
             "in the S half's bore groove, sealing on this half's spigot")
    return [
        f"pilot depth {lay.pilot_depth:g} = FD-2 B + C/2 − running_gap/2: the halves turn "
        f"relative to each other and stand running_gap_mm = {gap:g} mm apart",
        f"running-gap seal: the D half's spigot (inner Ø{lay.spigot_id:g}, "
        f"{SPIGOT_CLEARANCE_MM:g} mm clear of the S spline) reaches {lay.gap_seal_length:g} mm "
        f"into the S half's Ø{lay.gap_journal:g} H8 bore; "
        + gland.text(where, lay.gap_journal)
        + f", lands {WALL_MIN_MM:g} mm at the face and {GLAND_LAND_MM:g} mm inside. The halves turn slowly against each other (output "
        "speed, or about line-shaft speed / (R + 1) in differential use), so an O-ring as a "
        "slow rotary seal fits in the FD-0 outline where a lip seal would not; the "
        "gap_seal_speed check compares its surface speed with hdcad's limit",
        f"S spline located by its pilot over {lay.pilot_depth - lay.s_bore_depth:.1f} mm "
        "(the rest of the recess is the running-gap bore)" if half.side == "S" else
        "D spline located by its pilot over the full recess depth",
        lay.seal.text() + "; outboard of the bearings, set back "
        f"{SEAL_SET_BACK_MM:g} mm below the spigot-recess floor so that the sleeve's seal "
        "track covers its whole width",
        "spline-to-casing faces: liquid gasket (seed 000 p.028 allows O-ring or sealant): the "
        "face ring between the spline teeth and the screws is too narrow for an O-ring gland",
    ]


def _oil_notes(half) -> list[str]:
    lay = half.lay
    a, r = lay.level, lay.port_radius
    a0, a1 = half.port_angles
    return [
        lay.port.text() + f"; two ports, radial, at {a0:g}° and {a1:g}°, z = {lay.port_z:g} "
        f"(ligaments ≥ {lay.port.ligament_min:g} mm to the pilot recess and the ring groove), "
        "reached from outside the machine at any time (nothing mates with the rim)",
        f"oil level A = {a:g} mm (table 315-1; figure 315-1 is lost) read as the distance from "
        "the axis down to the oil surface, axis horizontal, at standstill",
        f"the ports open into the cavity at radius {r:g} (the seat bore, or a relief "
        f"{LEVEL_MARGIN_MM:g} mm below A): to set level A turn one port {lay.level_turn_deg:.1f}° "
        "from the bottom, open it and fill through the other (at the top) until oil runs out; "
        "to drain turn a port to the bottom (oil in the tooth spaces beyond this radius stays: "
        "flush)",
    ]


def sleeve_notes(sleeve) -> list[str]:
    lay = sleeve.lay
    b = lay.bearing
    return [
        f"journal sleeve: the FD-2 WG hub φH {sleeve.fd2['H_mm']:g} stands out only "
        f"{(sleeve.fd2['E_mm'] - sleeve.fd2['D_mm']) / 2:g} mm beyond the spline face, less "
        f"than one bearing width {b.B:g}, so the sleeve carries the bearing pair (HOUSING_RULES "
        "§1 inner-ring journal)",
        f"bore Ø{lay.shaft_d:g} H7 on the user's shaft (= WG hub bore φL, table 312-1), "
        "g6 slide; the shaft holds the sleeve against the WG hub end with a DIN 471 ring or a "
        "KM nut outboard; the shaft's keyway must end inside the WG hub, before the sleeve's "
        "O-ring",
        lay.shaft_gland.text("in the bore", lay.shaft_d) + ": keeps oil from running along "
        "the shaft",
        f"journal Ø{b.d:g} k5 under the bearings; seal track Ø{b.d:g} h11 beyond the ring "
        "groove, plunge-ground Ra 0.2-0.8 without lay, ≥ 45 HRC, lead-in chamfer 20° at the "
        "outer end (ISO 6194-1)",
        f"collar Ø{lay.collar_d:g} (≥ d_a,min {b.shaft_shoulder_min:g}, DIN 5418) carries the "
        f"inner rings; {lay.shaft_ring.text()}",
    ]
