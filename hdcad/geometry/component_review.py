"""Neighbour bodies of the CSF/CSG-2A-GR parts for the review assembly (each in its part's
frame), their fits, and the oil probe's plan: bearings, spacers, retaining rings, lip seals,
the CS screws, the circular spline and the flexspline as outlines (overlay
component_outline), and the user's input shaft as it must be made (collar and ring)."""

from __future__ import annotations

from .component_support import pair_fits
from .features import annulus, screw_body, screw_for_grip
from .iso286 import iso286_fit
from .part import Neighbour
from .primitives import cylinder, ring_points


FS_WALL_MM = 1.0   # the flexspline drawn as a 1 mm shell of its outside Ø: an outline only


def _pair(r, z0: float) -> list[Neighbour]:
    """Bearings at z0 and z0 + 2B, the outer spacer between, the DIN 472 ring below z0."""
    b, ring = r.bearing, r.ring_bore
    out = [b.neighbour(z) for z in (z0, z0 + 2 * b.B)]
    out.append(Neighbour("spacer", "outer spacer", {"B": b.B}, z0 + b.B,
                         body=annulus(b.D - 2 * b.h, b.D, z0 + b.B, z0 + 2 * b.B)))
    out.append(ring.neighbour(z0 - ring.s))
    return out


def _inner(r, z0: float, z_ring: float, group: str) -> list[Neighbour]:
    b, ring = r.bearing, r.ring_shaft
    return [Neighbour("spacer", "inner spacer", {"B": b.B}, z0 + b.B, turns_with=group,
                      body=annulus(b.d, b.d + 2 * b.h, z0 + b.B, z0 + 2 * b.B)),
            ring.neighbour(z_ring, turns_with=group)]


def housing_neighbours(h) -> list[Neighbour]:
    o, r = h.outline, h.retention["out"]
    seal_z = h.z_out + h.mount_spigot_len - r.seal.b
    out = _pair(r, h.zb) + [r.seal.neighbour(seal_z)]
    cs = annulus(o["fs_outer_diameter_mm"] + 1.0, o["cs_outer_diameter_mm"], -o["cs_width_mm"],
                 0.0)
    holes = [cylinder(h.cs_d + 0.5, -o["cs_width_mm"] - 1, 1, x, y)
             for x, y in ring_points(o["cs_bolt_circle_mm"], h.cs_count, 0.0)]
    out.append(Neighbour("gear", "circular spline (outline)", {}, -o["cs_width_mm"],
                         body=cs.cut(*holes).Solids()[0]))
    fs, d = o["fs_length_mm"], o["fs_outer_diameter_mm"]
    cup = annulus(d - 2 * FS_WALL_MM, d, -o["cs_width_mm"], fs - FS_WALL_MM).fuse(
        cylinder(d, fs - FS_WALL_MM - 0.01, fs))
    out.append(Neighbour("gear", "flexspline (outline)", {}, -o["cs_width_mm"],
                         body=cup.Solids()[0], turns_with="output"))
    return out


def flange_neighbours(h) -> list[Neighbour]:
    r, fs = h.retention["out"], h.outline["fs_length_mm"]
    return _inner(r, h.zb - fs, h.z_shoulder - fs, "output")


def cover_neighbours(h) -> list[Neighbour]:
    r, t = h.retention["in"], h.cover_t
    out = _pair(r, h.zb_in) + [r.seal.neighbour(t - r.seal.b)]
    out += _cs_screws(h)
    out += _input_shaft(h)
    return out


def _cs_screws(h) -> list[Neighbour]:
    """CS screws from the cover's outer face through cover and CS into the housing."""
    o, thread = h.outline, h.cs_thread
    grip = h.cover_t - h.cbore_depth + o["cs_width_mm"]
    m_min = h.cs_engagement_min
    length, _ = screw_for_grip(thread, grip, h.cs_depth, m_min)
    if length is None:
        return []
    seat = h.cover_t - h.cbore_depth
    dims = {"d": h.cs_d, "l": length, "grip": grip, "engaged": length - grip,
            "thread_depth": h.cs_depth, "engaged_min": m_min}
    return [Neighbour("screw", f"ISO 4762 {thread}×{length}", dims, seat, xy_mm=(x, y),
                      body=screw_body(thread, seat, length, x, y))
            for x, y in ring_points(o["cs_bolt_circle_mm"], h.cs_count, 0.0)]


def _input_shaft(h) -> list[Neighbour]:
    """The user's input shaft as the cover's bearings need it: Ø d through the pair, a
    collar ≥ d_a,min on the gear side, a DIN 471 groove and ring outboard."""
    o, r = h.outline, h.retention["in"]
    b = r.bearing
    z0 = (o.get("wg_protrusion_mm") or 0.0) - (o.get("wg_hub_width_mm") or o["cs_width_mm"])
    shaft = cylinder(b.d, z0, h.cover_t + b.d).fuse(
        cylinder(r.collar_d, h.cover_cavity_depth, h.zb_in))
    shaft = shaft.cut(r.ring_shaft.groove(h.in_shoulder)).Solids()[0]
    return [Neighbour("shaft", "user's input shaft (as required)", {"d": b.d}, z0,
                      body=shaft, turns_with="input")] + _inner(r, h.zb_in, h.in_shoulder,
                                                                "input")[:2]


def housing_fits(h) -> list:
    o = h.outline
    return [iso286_fit(h.catalog, "CS pilot recess", o["cs_outer_diameter_mm"], "H7",
                       "circular spline outside Ø", "catalog pilot (guideline 1)"),
            iso286_fit(h.catalog, "mounting spigot", h.mount_spigot, "g6",
                       "machine frame bore H7", "centres the housing on the frame")
            ] + pair_fits(h.catalog, h.retention["out"], "output", False)


def cover_fits(h) -> list:
    return [iso286_fit(h.catalog, "cover spigot", h.outline["cs_outer_diameter_mm"], "g6",
                       "housing CS recess H7", "centres the cover")
            ] + pair_fits(h.catalog, h.retention["in"], "input", False)


def flange_fits(h) -> list:
    return pair_fits(h.catalog, h.retention["out"], "output", True)


def review_plan(parts) -> dict:
    housing = next(p for p in parts if p.name == "housing").dimensions
    r = (housing["fs_outer_diameter_mm"] + housing["cavity_diameter_mm"]) / 4
    return {"seed_zr": (housing["fs_length_mm"] / 2, r), "angles": [0.0, 15.0],
            "title": "2A-GR review assembly: housing, cover, output flange with bearings, "
                     "seals, CS screws and the gear outline"}
