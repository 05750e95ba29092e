"""Housing, input cover and output flange of a CSF/CSG-…-2A-GR cup-type component set.

The seeds hold the design guidelines (seed 000 p.024) but no outline or recommended-housing
table for the component types, so every gear dimension comes from a catalog overlay:
``component_outline`` (circular spline CS, flexspline FS, wave generator WG, C-ring) and
``component_housing`` (recommended inner wall); column meanings in catalog/README.md.

cq_warehouse style: ``ComponentSetHousing.sizes(catalog, series)`` lists the sizes both
tables offer; ``ComponentSetHousing(series, size, catalog, options)`` checks the request and
raises ValueError naming what is allowed; ``build(part)`` returns one :class:`Part`
(``PARTS``), ``build_all()`` the three parts placed for the assembly.

Assembly coordinates: axis Z, z = 0 at the CS face on the diaphragm (output) side, output
towards +z. The guidelines of p.024 this design follows: (1) input shaft, CS, output shaft
and case concentric: the CS is centred in the housing's pilot recess, the input and output
bearing seats are turned in the same parts that hold that recess; (4) case inner wall at the
recommended diameter around the FS; (5) two-point support of the output (two bearings); (6)
the flange bolted to the FS is not larger than the FS boss and has a radius on its diaphragm
side; (7) the C-ring hook of the WG hub clears the case.

* housing (output side), z = −(CS width + spigot) … z_out:
  CS pilot recess Ø CS φ (H7) over the CS width plus the cover's spigot; cavity Ø ≥ the
  recommended FS wall and diaphragm-side diameters from z = 0 to the end wall, which stands
  at least the recommended diaphragm-side depth beyond the FS diaphragm; two 60xx output
  bearings with a spacer in one bore opening towards the cavity, a shoulder, a lip seal from
  the outer face; tapped holes on the CS bolt circle (the CS screws come from the input side
  through the cover and the CS).
* input cover, z = −CS width … −(CS width + thickness): spigot Ø CS φ into the housing
  recess, clamping the CS against the housing shoulder; a cavity clearing the C-ring hook,
  the WG hub and the deformed FS end; one 60xx bearing and a lip seal for the input shaft;
  counterbored clearance holes for the CS screws.
* output flange, z = FS length …: disc Ø FS boss bolted to the FS (screws from inside the
  cup into tapped holes), radius on the diaphragm-side edge, journal through the two output
  bearings and the seal.
"""

from __future__ import annotations

import cadquery as cq

from ..catalog import Catalog
from ..design_options import DesignOptions
from .housing_common import (BEARING_TABLE, CBORE_SINK_MM, EDGE_FACTOR, MIN_FLOOR_MM,
                             PILOT_LEAD_IN_MM, TAP_RUNOUT_PITCHES,
                             SEAL_TABLE, bearing_dimensions, check_ring, seal_dimensions)
from .component_review import (cover_fits, cover_neighbours, flange_fits, flange_neighbours,
                               housing_fits, housing_neighbours)
from .component_support import Retention
from .features import (blind_hole, countersink, countersink_depth, drill_point, lead_in,
                       screw_and_grip, shaft_lead_in)
from .part import BoltCircle, Part
from .primitives import cylinder, ring_points, single_solid
from .standards import (DIN_974_1_CBORE_MM, ISO_261_PITCH_MM, ISO_273_MEDIUM_MM,
                        ISO_4762_HEAD_MM, TAP_DRILL_MM, thread_diameter)
from ..checks.bolts import MIN_ENGAGEMENT

OUTLINE, HOUSING = "component_outline", "component_housing"
SERIES = ("CSF", "CSG")
PARTS = ("housing", "input_cover", "output_flange")
CASE_PARTS = ("housing", "input_cover")  # stationary walls around the gear
NEEDED = {OUTLINE: ("cs_outer_diameter_mm", "cs_width_mm", "cs_bolt_circle_mm",
                    "cs_bolt_count", "cs_bolt_thread", "fs_outer_diameter_mm", "fs_length_mm",
                    "fs_boss_diameter_mm", "fs_bolt_circle_mm", "fs_bolt_count",
                    "fs_bolt_thread", "cring_hook_radius_mm", "cring_protrusion_mm"),
          HOUSING: ("fs_wall_diameter_mm", "diaphragm_side_diameter_mm",
                    "diaphragm_side_depth_mm", "cring_clearance_min_mm")}
HUB_TABLE = "wg_hub_bore"  # seed 000 table 027-1: standard WG hub bore if the outline has none

# ---------------------------------------------------------------------------------------------
# Design choices (not catalog or standard data); each is printed in the Part notes.
# ---------------------------------------------------------------------------------------------
WALL_ALLOWANCE_MM = 0.5     # added to every recommended diameter/depth: the machined wall
#                             must never fall inside the recommended value
SPIGOT_MM = 3.0             # cover spigot into the housing's CS recess (centres the cover)
TAPPED_DEPTH_FACTOR = 2.0   # thread depth = 2·d: covers the least engagement of an aluminium
#                             housing (2·d, hdcad.checks.bolts) as well as steel (1·d)
FLANGE_STEP_MM = 3.0        # journal at least 3 mm radially inside the FS-boss flange
AXIAL_GAP_MM = 1.0          # running gap: flange ↔ end wall, WG hub ↔ cover
DEFAULT_FLANGE_RADIUS_MM = 1.0  # p.024 guideline 6 asks for a radius; its size is in the
#                                 catalog's recommended dimensions (overlay column), else this
RIM_MM = 3.0                # wall of the mounting spigot around the seal bore
MOUNT_SPIGOT_MM = 3.0       # centring spigot into the machine frame
MOUNT_START_DEG = 15.0      # mounting holes clocked off the CS screws
MOUNT_THREADS = {"M3": "M4", "M4": "M5", "M5": "M6", "M6": "M8", "M8": "M10", "M10": "M12",
                 "M12": "M16", "M14": "M16", "M16": "M20"}
MATERIALS = {"steel": "S355J2 (EN 10025-2)", "aluminium": "EN AW-6082 T6 (EN 573-3)",
             "cast_iron": "EN-GJL-250 (EN 1561)"}
COLORS = {"housing": (0.62, 0.66, 0.72), "input_cover": (0.52, 0.58, 0.68),
          "output_flange": (0.80, 0.62, 0.30)}


def _missing(row: dict | None, table: str) -> list[str]:
    return list(NEEDED[table]) if row is None else [c for c in NEEDED[table]
                                                    if row.get(c) is None]


def _bearing_rows(catalog: Catalog) -> list[tuple[float, str]]:
    """(bore d, designation) of the 60xx bearings that have a lip seal for their bore."""
    seals = {r["d1_mm"] for r in catalog.rows(SEAL_TABLE)}
    return sorted((r["d_mm"], r["model"]) for r in catalog.rows(BEARING_TABLE)
                  if r["d_mm"] in seals)


def bearing_for_shaft(catalog: Catalog, shaft_mm: float, largest: bool = False) -> str:
    """Designation of the 60xx bearing (with a seal in the catalog) for a shaft [mm].

    ``largest=False``: the smallest bore d ≥ shaft (the journal steps up to the bearing);
    ``largest=True``: the largest bore d ≤ shaft (the journal is at most that wide).
    """
    rows = _bearing_rows(catalog)
    fits = ([m for d, m in rows if d <= shaft_mm + 1e-9] if largest
            else [m for d, m in rows if d >= shaft_mm - 1e-9])
    if not fits:
        bores = ", ".join(f"{d:g}" for d, _ in rows)
        raise ValueError(f"no 60xx bearing with a lip seal in the catalog for a "
                         f"{shaft_mm:g} mm shaft; bores with seals: {bores}")
    return fits[-1] if largest else fits[0]


class ComponentSetHousing:
    """Housing, input cover and output flange of one CSF/CSG-2A-GR size; see module doc."""

    def __init__(self, series: str, size: int, catalog: Catalog,
                 options: DesignOptions | None = None):
        self.options = options or DesignOptions()
        if series not in SERIES:
            raise ValueError(f"series {series!r} has no cup-type component set; allowed: "
                             f"{', '.join(SERIES)}")
        missing = self.missing_tables(catalog, series, size)
        if missing:
            sizes = ", ".join(map(str, self.sizes(catalog, series))) or "none"
            raise ValueError(f"{series}-{size}-2A-GR needs rows in {', '.join(missing)} "
                             f"(catalog overlay); sizes with both tables: {sizes}")
        self.series, self.size, self.catalog = series, size, catalog
        self.label = f"{series}-{size}-2A-GR"
        self.outline = catalog.find(OUTLINE, series=series, size=size)
        self.rec = catalog.find(HOUSING, series=series, size=size)
        for table, row in ((OUTLINE, self.outline), (HOUSING, self.rec)):
            lacking = _missing(row, table)
            if lacking:
                raise ValueError(f"{self.label}: the {table} row lacks {', '.join(lacking)}")
        self._screws()
        self._bearings(catalog)
        self._layout()
        self._check()

    # -- catalog look-ups ---------------------------------------------------------------------
    @staticmethod
    def missing_tables(catalog: Catalog, series: str, size: int) -> list[str]:
        """Overlay tables that lack a row for ``series`` ``size``."""
        return [t for t in (OUTLINE, HOUSING) if catalog.find(t, series=series, size=size) is None]

    @staticmethod
    def sizes(catalog: Catalog, series: str) -> list[int]:
        found = [{r["size"] for r in catalog.rows(t, series=series)} for t in (OUTLINE, HOUSING)]
        return sorted(found[0] & found[1])

    # -- dimensions ------------------------------------------------------------------------------
    def _screws(self) -> None:
        o = self.outline
        self.cs_thread, self.fs_thread = o["cs_bolt_thread"], o["fs_bolt_thread"]
        self.cs_d, self.fs_d = thread_diameter(self.cs_thread), thread_diameter(self.fs_thread)
        self.cs_count, self.fs_count = int(o["cs_bolt_count"]), int(o["fs_bolt_count"])
        self.cs_tap, self.fs_tap = TAP_DRILL_MM[self.cs_thread], TAP_DRILL_MM[self.fs_thread]
        self.cs_depth = TAPPED_DEPTH_FACTOR * self.cs_d
        self.fs_depth = TAPPED_DEPTH_FACTOR * self.fs_d
        self.cs_drill = self.cs_depth + TAP_RUNOUT_PITCHES * ISO_261_PITCH_MM[self.cs_thread]
        self.fs_drill = self.fs_depth + TAP_RUNOUT_PITCHES * ISO_261_PITCH_MM[self.fs_thread]
        self.clearance = ISO_273_MEDIUM_MM[self.cs_thread]
        self.cbore = DIN_974_1_CBORE_MM[self.cs_thread]
        self.cbore_depth = ISO_4762_HEAD_MM[self.cs_thread][1] + CBORE_SINK_MM

    def _bearings(self, catalog: Catalog) -> None:
        o = self.outline
        shaft, rule = self.options.input_shaft_mm, "input_shaft_mm (design option)"
        if shaft is None:
            shaft, rule = o.get("wg_hub_bore_mm"), "WG hub bore (component_outline)"
        if shaft is None:
            hub = catalog.find(HUB_TABLE, size=self.size)
            shaft, rule = (hub or {}).get("standard_H7_mm"), "standard WG hub bore (027-1)"
        if shaft is None:
            raise ValueError(f"{self.label}: no input shaft diameter (input_shaft_mm, "
                             "wg_hub_bore_mm or table 027-1)")
        self.input_shaft, self.input_rule = float(shaft), rule
        try:
            self.in_bearing = bearing_for_shaft(catalog, self.input_shaft)
            self.out_bearing = bearing_for_shaft(
                catalog, o["fs_boss_diameter_mm"] - 2 * FLANGE_STEP_MM, largest=True)
            self.in_d, self.in_D, self.in_B = bearing_dimensions(catalog, self.in_bearing)
            self.out_d, self.out_D, self.out_B = bearing_dimensions(catalog, self.out_bearing)
            self.in_seal = seal_dimensions(catalog, self.in_d)
            self.out_seal = seal_dimensions(catalog, self.out_d)
            self.retention = {side: Retention(catalog, b) for side, b in
                              (("out", self.out_bearing), ("in", self.in_bearing))}
        except ValueError as exc:
            raise ValueError(f"{self.label}: {exc}") from None

    def _layout(self) -> None:
        o, h, wall = self.outline, self.rec, self.options.wall_mm
        self.housing_od = o["cs_outer_diameter_mm"] + 2 * wall
        self.cavity_d = (max(h["fs_wall_diameter_mm"], h["diaphragm_side_diameter_mm"])
                         + WALL_ALLOWANCE_MM)
        self.recess_depth = o["cs_width_mm"] + SPIGOT_MM
        # output flange: the tapped FS-screw holes plus a floor set its thickness
        self.flange_t = self.fs_drill + drill_point(self.fs_tap) + MIN_FLOOR_MM
        self.flange_r = h.get("output_flange_radius_mm") or DEFAULT_FLANGE_RADIUS_MM
        self.cavity_beyond = max(h["diaphragm_side_depth_mm"] + WALL_ALLOWANCE_MM,
                                 self.flange_t + AXIAL_GAP_MM)
        self.z_wall = o["fs_length_mm"] + self.cavity_beyond
        out = self.retention["out"]
        # DIN 472 groove n from the cavity, two bearings with a spacer of width B between,
        # the step to the seal bore as the outer-ring shoulder, a DIN 471 ring, the seal
        self.zb = self.z_wall + out.ring_bore.n + out.ring_bore.m
        self.z_shoulder = self.zb + 3 * self.out_B
        self.bearing_len = self.z_shoulder - self.z_wall
        self.out_seal_depth = out.seal_stack
        self.z_out = self.z_shoulder + out.shoulder_len + self.out_seal_depth
        self.journal_len = self.z_out - o["fs_length_mm"] + self.out_d  # stick-out d
        self._mount_layout()
        # input cover, measured from the CS input face outwards
        self.cover_cavity_d = max(h["fs_wall_diameter_mm"],
                                  2 * (o["cring_hook_radius_mm"] + h["cring_clearance_min_mm"])
                                  ) + WALL_ALLOWANCE_MM
        self.cover_cavity_depth = max(
            o["cring_protrusion_mm"] + h["cring_clearance_min_mm"],
            (o.get("wg_protrusion_mm") or 0.0) + AXIAL_GAP_MM) + WALL_ALLOWANCE_MM
        inp = self.retention["in"]
        self.zb_in = self.cover_cavity_depth + inp.ring_bore.n + inp.ring_bore.m
        self.in_shoulder = self.zb_in + 3 * self.in_B
        self.in_seal_depth = inp.seal_stack
        self.cover_t = max(self.in_shoulder + inp.shoulder_len + self.in_seal_depth,
                           SPIGOT_MM + self.cbore_depth + MIN_FLOOR_MM)
        self._sink_counterbores()

    @property
    def cs_engagement_min(self) -> float:
        """Least engagement of the CS screws from the housing face [mm]: the material's k·d
        below the entry countersink."""
        return (MIN_ENGAGEMENT[self.options.material] * self.cs_d
                + countersink_depth(self.cs_d, self.cs_tap))

    def _sink_counterbores(self) -> None:
        """Counterbores sunk so that an existing ISO 4762 length clamps cover and CS and
        engages the housing thread between the least engagement and its depth."""
        width, head = self.outline["cs_width_mm"], self.cbore_depth
        grip_max = self.cover_t - head + width
        self.cs_length, grip = screw_and_grip(self.cs_thread, grip_max, self.cs_depth,
                                              self.cs_engagement_min)
        if self.cs_length is None:
            raise ValueError(f"{self.label}: no ISO 4762 {self.cs_thread} length reaches "
                             f"through the cover and the CS ({grip_max:.1f} mm)")
        self.cbore_depth = self.cover_t + width - grip

    def _mount_layout(self) -> None:
        """Mounting flange to the machine frame at the output end: ISO 4762 screws through
        ISO 273 holes, heads on the input side clear of the housing body, a centring spigot
        g6 around the seal bore on the output face."""
        d = self.cs_d
        # one size above the CS screws, twelve of them: the frame joint carries the full
        # output torque (the bolt_pattern check says whether it does)
        self.mount_thread = MOUNT_THREADS.get(self.cs_thread, self.cs_thread)
        d = thread_diameter(self.mount_thread)
        self.mount_t = max(self.options.wall_mm, 1.5 * d)
        offset = max(ISO_4762_HEAD_MM[self.mount_thread][0] / 2 + 1.0, EDGE_FACTOR * d) + 1.0
        self.mount_bc = self.housing_od + 2 * offset
        self.mount_od = self.mount_bc + 2 * EDGE_FACTOR * d
        self.mount_count = 12
        self.mount_spigot = self.out_seal[0] + 2 * RIM_MM

    def _check(self) -> None:
        o, h, label = self.outline, self.rec, self.label
        cs_od = o["cs_outer_diameter_mm"]
        # (inner feature, Ø, outer feature, Ø): each inner one must fit inside its outer one
        nested = [("FS outside diameter", o["fs_outer_diameter_mm"], "recommended FS wall",
                   h["fs_wall_diameter_mm"]),
                  ("housing cavity", self.cavity_d, "CS outside diameter (shoulder)", cs_od),
                  ("cover cavity", self.cover_cavity_d, "CS outside diameter (spigot)", cs_od),
                  ("output bearing seat", self.out_D, "housing cavity", self.cavity_d),
                  ("FS-boss flange + running gap", o["fs_boss_diameter_mm"] + 2 * AXIAL_GAP_MM,
                   "housing cavity", self.cavity_d),
                  ("input bearing seat", self.in_D, "cover cavity", self.cover_cavity_d)]
        for inner_name, inner, outer_name, outer in nested:
            if inner >= outer:
                raise ValueError(f"{label}: {inner_name} Ø{inner:g} does not fit inside the "
                                 f"{outer_name} Ø{outer:g}")
        check_ring(f"{label} housing cs_screws", o["cs_bolt_circle_mm"], self.cs_count,
                    self.cs_d, self.cavity_d, cs_od)
        check_ring(f"{label} input_cover cs_screws", o["cs_bolt_circle_mm"], self.cs_count,
                    self.clearance, self.cover_cavity_d, cs_od)
        check_ring(f"{label} input_cover counterbores", o["cs_bolt_circle_mm"], self.cs_count,
                    self.cbore, max(self.in_D, self.in_seal[0]), self.housing_od)
        check_ring(f"{label} output_flange fs_screws", o["fs_bolt_circle_mm"], self.fs_count,
                    self.fs_d, 0.0, o["fs_boss_diameter_mm"])

    # -- solids ------------------------------------------------------------------------------
    def build(self, part: str = "housing") -> Part:
        """One part, in its own coordinates (see :meth:`build_all` for the placement)."""
        builders = {"housing": self._housing, "input_cover": self._input_cover,
                    "output_flange": self._output_flange}
        if part not in builders:
            raise ValueError(f"part {part!r} is not a {self.label} part; allowed: "
                             f"{', '.join(PARTS)}")
        return builders[part]()

    def build_all(self) -> list[Part]:
        """The three parts placed coaxially in assembly coordinates."""
        housing, cover, flange = (self.build(p) for p in PARTS)
        cover.flip, cover.offset_z_mm = True, -self.outline["cs_width_mm"]
        flange.offset_z_mm = self.outline["fs_length_mm"]
        return [housing, cover, flange]

    def _housing(self) -> Part:
        o, out = self.outline, self.retention["out"]
        z0, z1 = -self.recess_depth, self.z_out
        body = cylinder(self.housing_od, z0, z1).fuse(
            cylinder(self.mount_od, z1 - self.mount_t, z1),
            cylinder(self.mount_spigot, z1 - 0.01, z1 + MOUNT_SPIGOT_MM))
        cutters = [cylinder(o["cs_outer_diameter_mm"], z0 - 1, 0),
                   lead_in(o["cs_outer_diameter_mm"], z0, PILOT_LEAD_IN_MM, inward=True),
                   shaft_lead_in(self.mount_spigot, z1 + MOUNT_SPIGOT_MM, PILOT_LEAD_IN_MM),
                   cylinder(self.cavity_d, -1, self.z_wall),
                   cylinder(self.out_D, self.z_wall - 1, self.z_shoulder),
                   out.ring_bore.groove(self.zb - out.ring_bore.m)]
        cutters += out.seal_bore(self.z_shoulder, z1 + MOUNT_SPIGOT_MM)
        cutters += [c for x, y in ring_points(o["cs_bolt_circle_mm"], self.cs_count, 0.0)
                    for c in (blind_hole(self.cs_tap, 0.0, self.cs_drill, x, y, into=1),
                              countersink(thread_diameter(self.cs_thread), 0.0, x, y, into=1))]
        cutters += [cylinder(ISO_273_MEDIUM_MM[self.mount_thread], z1 - self.mount_t - 1,
                             z1 + 1, x, y)
                    for x, y in ring_points(self.mount_bc, self.mount_count, MOUNT_START_DEG)]
        shape = single_solid(body, cutters, self.label)
        return Part("housing", shape, COLORS["housing"], dimensions=self._housing_dims(),
                    bolt_circles=[self._cs_circle(), self._mount_circle()],
                    notes=self._notes(), purchased=self._purchased("housing"),
                    fits=housing_fits(self), neighbours=housing_neighbours(self),
                    turns_with="case", material=MATERIALS[self.options.material])

    def _input_cover(self) -> Part:
        o, t, depth, inp = self.outline, self.cover_t, self.cover_cavity_depth, \
            self.retention["in"]
        body = cylinder(o["cs_outer_diameter_mm"], 0, SPIGOT_MM).fuse(
            cylinder(self.housing_od, SPIGOT_MM, t))
        cutters = [cylinder(self.cover_cavity_d, -1, depth),
                   shaft_lead_in(o["cs_outer_diameter_mm"], 0.0, PILOT_LEAD_IN_MM, towards=-1),
                   cylinder(self.in_D, depth - 1, self.in_shoulder),
                   inp.ring_bore.groove(self.zb_in - inp.ring_bore.m)]
        cutters += inp.seal_bore(self.in_shoulder, t)
        for x, y in ring_points(o["cs_bolt_circle_mm"], self.cs_count, 0.0):
            cutters += [cylinder(self.clearance, -1, t + 1, x, y),
                        cylinder(self.cbore, t - self.cbore_depth, t + 1, x, y)]
        shape = single_solid(body, cutters, self.label)
        return Part("input_cover", shape, COLORS["input_cover"],
                    dimensions=self._cover_dims(), bolt_circles=[self._cover_circle()],
                    notes=self._notes(), purchased=self._purchased("input_cover"),
                    fits=cover_fits(self), neighbours=cover_neighbours(self),
                    turns_with="case", material=MATERIALS[self.options.material])

    def _output_flange(self) -> Part:
        o = self.outline
        boss, out, fs = o["fs_boss_diameter_mm"], self.retention["out"], o["fs_length_mm"]
        collar_end = self.zb - fs
        body = (cq.Workplane("XY").circle(boss / 2).extrude(self.flange_t)
                .faces("<Z").edges().fillet(self.flange_r)
                .faces(">Z").workplane().circle(out.collar_d / 2)
                .extrude(collar_end - self.flange_t)
                .faces(">Z").workplane().circle(self.out_d / 2)
                .extrude(self.journal_len - (collar_end - self.flange_t)))
        cutters = [c for x, y in ring_points(o["fs_bolt_circle_mm"], self.fs_count, 0.0)
                   for c in (blind_hole(self.fs_tap, 0.0, self.fs_drill, x, y, into=1),
                             countersink(thread_diameter(self.fs_thread), 0.0, x, y, into=1))]
        cutters.append(out.ring_shaft.groove(self.z_shoulder - fs))
        shape = single_solid(body.val(), cutters, self.label)
        return Part("output_flange", shape, COLORS["output_flange"],
                    dimensions=self._flange_dims(), bolt_circles=[self._fs_circle()],
                    notes=self._notes(), fits=flange_fits(self),
                    neighbours=flange_neighbours(self), turns_with="output",
                    material="C45 (EN ISO 683-1), seal track ≥ 45 HRC")

    @property
    def mount_spigot_len(self) -> float:
        return MOUNT_SPIGOT_MM

    # -- records -----------------------------------------------------------------------------
    def _notes(self) -> list[str]:
        from .component_notes import notes
        return notes(self)

    # -- records (hdcad.geometry.component_record) ---------------------------------------------
    def _purchased(self, part: str) -> list[dict]:
        from .component_record import purchased
        return purchased(self, part)

    def _housing_dims(self) -> dict[str, float]:
        from .component_record import housing_dims
        return housing_dims(self)

    def _cover_dims(self) -> dict[str, float]:
        from .component_record import cover_dims
        return cover_dims(self)

    def _flange_dims(self) -> dict[str, float]:
        from .component_record import flange_dims
        return flange_dims(self)

    def _cs_circle(self) -> BoltCircle:
        from .component_record import cs_circle
        return cs_circle(self)

    def _cover_circle(self) -> BoltCircle:
        from .component_record import cover_circle
        return cover_circle(self)

    def _mount_circle(self) -> BoltCircle:
        from .component_record import mount_circle
        return mount_circle(self)

    def _fs_circle(self) -> BoltCircle:
        from .component_record import fs_circle
        return fs_circle(self)
