"""Neighbour bodies of the FD-2 casing halves and sleeves for the review assembly: bearings,
retaining rings, seals, O-rings, plugs, spline screws, the circular splines, the WG hub and
the user's shaft, each true-size in its part's frame."""

from __future__ import annotations

from ..checks.bolts import MIN_ENGAGEMENT
from .features import annulus, screw_body
from .part import Neighbour
from .primitives import cylinder, ring_points
from .standards import review_minor_diameter, thread_diameter


def casing_neighbours(half) -> list[Neighbour]:
    lay = half.lay
    b, ring, seal = lay.bearing, lay.bore_ring, lay.seal
    out = [b.neighbour(z) for z in (lay.bearing_z, lay.bearing_z + b.B)]
    out += [ring.neighbour(lay.bearing_z - ring.s), seal.neighbour(lay.seal_outer_z - seal.b)]
    out += [Neighbour("plug", f"DIN 908 {lay.port.thread}", {"d": lay.port.d}, lay.port_z,
                      body=lay.port.body(lay.body_d / 2, lay.port_z, a))
            for a in half.port_angles]
    out += _spline_screws(half)
    out.append(_circular_spline(half))
    if half.side == "S":
        z_mid, gland = lay.gap_groove_z, lay.gap_gland
        out.append(Neighbour("oring", f"O-ring ×{gland.d2:g}", {"d2": gland.d2}, z_mid,
                             body=gland.ring_in_bore(lay.gap_journal, z_mid)))
        out += _hub_and_shaft(half)
    return out


def _spline_screws(half) -> list[Neighbour]:
    """ISO 4762 screws: head true size on the counterbore floor, the shank at the thread's
    minor (tap-drill) diameter so that a screw in its tapped hole does not count as
    interference."""
    lay, fd2 = half.lay, half.fd2
    d = thread_diameter(half.screw)
    seat = lay.thickness - half.cbore_depth
    tip = seat - half.screw_length
    engaged = lay.pilot_depth - tip
    dims = {"d": d, "l": half.screw_length, "grip": half.grip, "engaged": engaged,
            "thread_depth": fd2["K_depth_mm"], "engaged_min": MIN_ENGAGEMENT["steel"] * d}
    out = []
    for x, y in ring_points(fd2["I_mm"], fd2["J_count"], 0.0):
        out.append(Neighbour("screw", f"ISO 4762 {half.screw}×{half.screw_length}", dims,
                             seat, xy_mm=(x, y),
                             body=screw_body(half.screw, seat, half.screw_length, x, y)))
    return out


def _circular_spline(half) -> Neighbour:
    """The circular spline as its catalog outline (φA g7 × B) with its K-deep tapped holes
    (tap-drill Ø); the bore is taken as FD-2 φS (its meaning is in the lost figure 312-1: used
    for this outline only)."""
    fd2, lay, gap = half.fd2, half.lay, half.options.running_gap_mm
    z0, z1 = fd2["C_mm"] / 2 - gap / 2, lay.pilot_depth
    minor = review_minor_diameter(half.screw)
    body = annulus(fd2["S_mm"], fd2["A_g7_mm"], z0, z1)
    holes = [cylinder(minor, z1 - fd2["K_depth_mm"], z1 + 1, x, y)
             for x, y in ring_points(fd2["I_mm"], fd2["J_count"], 0.0)]
    return Neighbour("gear", f"circular spline {half.side}",
                     {"A": fd2["A_g7_mm"], "B": fd2["B_mm"]}, z0,
                     body=body.cut(*holes).Solids()[0])


def _hub_and_shaft(half) -> list[Neighbour]:
    """WG hub (φH × E around the mid-plane) and the user's shaft φL through both halves."""
    fd2, lay, gap = half.fd2, half.lay, half.options.running_gap_mm
    mid = -gap / 2
    hub = annulus(fd2["L_H7_mm"], fd2["H_mm"], mid - fd2["E_mm"] / 2, mid + fd2["E_mm"] / 2)
    reach = lay.thickness + 5
    shaft = cylinder(fd2["L_H7_mm"], -reach - gap, reach)
    return [Neighbour("gear", "wave-generator hub", {"H": fd2["H_mm"], "E": fd2["E_mm"]}, mid,
                      body=hub, turns_with="shaft"),
            Neighbour("shaft", "user's shaft", {"d": fd2["L_H7_mm"]}, -reach - gap,
                      body=shaft, turns_with="shaft")]


def sleeve_neighbours(sleeve) -> list[Neighbour]:
    lay = sleeve.lay
    ring, gland = lay.shaft_ring, lay.shaft_gland
    return [ring.neighbour(lay.shoulder_z),
            Neighbour("oring", f"O-ring {lay.shaft_d:g}×{gland.d2:g}", {"d2": gland.d2},
                      sleeve.oring_z, body=gland.ring_in_bore(lay.shaft_d, sleeve.oring_z))]


def review_plan(parts) -> dict:
    """Seed point and section angles of the FD-2 review: the seed lies between the WG hub
    and the circular splines on the mid-plane; sections through the first port (and the one
    opposite), the spline screws and the gear holes."""
    half = next(p for p in parts if p.name == "casing_half_D")  # not turned: its own angles
    d = half.dimensions
    port = d["oil_port_angles_deg"]
    angles = [port, port + 180.0, 0.0, d["gear_start_deg"]]
    return {"seed_zr": (0.0, d["oil_probe_r_mm"]), "angles": angles,
            "title": f"FD-2 review assembly: section through the oil ports ({port:g}° / "
                     f"{port + 180:g}°)"}
