"""FD-…-2 casing halves and sleeves: build every size, export STEP, re-import it and measure
the solid against the layout and the standards' rules (HOUSING_RULES §1-§4)."""

import copy
import math

import pytest

cq = pytest.importorskip("cadquery")

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.design_options import DesignOptions  # noqa: E402
from hdcad.geometry.drawing.measure import axial_features, cylinder_faces, z_cylinders  # noqa: E402
from hdcad.geometry.fd_casing import FDCasingHalf  # noqa: E402
from hdcad.geometry.fd_layout import WALL_MIN_MM  # noqa: E402
from hdcad.geometry.fd_sleeve import FDSleeve  # noqa: E402
from hdcad.geometry.part import export_step  # noqa: E402

TOL = 0.01  # mm: STEP keeps the exact B-rep; a re-imported diameter agrees to rounding
SIZES = FDCasingHalf.sizes(load_catalog())


@pytest.fixture(scope="module")
def catalog():
    return load_catalog()


def _round_trip(part, folder):
    path = folder / f"{part.name}.step"
    export_step(part, path)
    shape = cq.importers.importStep(str(path)).val()
    assert len(shape.Solids()) == 1 and shape.isValid()
    return shape


_BUILT: dict = {}


@pytest.fixture(scope="module")
def built(catalog, tmp_path_factory):
    """(half, part, STEP path, re-imported shape) of a casing half with the default options,
    built and exported once per size and side for the tests that only read it."""
    def get(size, side):
        if (size, side) not in _BUILT:
            half = FDCasingHalf(size, catalog, DesignOptions(), side=side)
            part = half.build()
            folder = tmp_path_factory.mktemp(f"fd{size}{side}")
            shape = _round_trip(part, folder)
            _BUILT[size, side] = (half, part, folder / f"{part.name}.step", shape)
        return _BUILT[size, side]
    return get


def _feature(shape, diameter):
    """The on-axis turned surface of ``diameter`` (merged faces) that reaches furthest in +z
    (a groove splits a bore into two surfaces), or None."""
    found = [c for c in axial_features(z_cylinders(shape)) if abs(c.diameter - diameter) <= TOL]
    return max(found, key=lambda c: c.z1, default=None)


def _holes_on_circle(shape, circle_d, hole_d):
    return {(round(c.x, 3), round(c.y, 3)) for c in z_cylinders(shape)
            if abs(c.diameter - hole_d) <= TOL
            and abs(math.hypot(c.x, c.y) - circle_d / 2) <= TOL}


def _radial_holes(shape, diameter):
    """Cylindrical faces of ``diameter`` whose axis is perpendicular to Z (radial ports)."""
    return [face for face, r, _, along_z in cylinder_faces(shape)
            if along_z < 1e-9 and abs(2 * r - diameter) <= TOL]


@pytest.mark.parametrize("side", ["S", "D"])
@pytest.mark.parametrize("size", SIZES)
def test_casing_half_measured_from_step(size, side, built):
    half, part, _, shape = built(size, side)
    lay = half.lay
    box = shape.BoundingBox()
    assert box.xlen == pytest.approx(lay.outer_d, abs=TOL)
    assert box.zmax == pytest.approx(lay.thickness, abs=TOL)
    # the S half starts at its face; the D half's running spigot reaches past the gap
    spigot = lay.gap_seal_length + DesignOptions().running_gap_mm
    assert box.zmin == pytest.approx(0.0 if side == "S" else -spigot, abs=TOL)

    b = lay.bearing
    seat = _feature(shape, b.D)
    assert seat.z1 == pytest.approx(lay.shoulder_z, abs=TOL)        # shoulder at the pair's end
    assert seat.z1 - seat.z0 == pytest.approx(2 * b.B, abs=TOL)  # two bearings seated
    assert seat.z0 == pytest.approx(lay.bearing_z, abs=TOL)      # above the ring groove
    groove = _feature(shape, lay.bore_ring.d2)                      # DIN 472 groove
    assert groove.z1 == pytest.approx(lay.bearing_z, abs=TOL)
    assert groove.z1 - groove.z0 == pytest.approx(lay.bore_ring.m, abs=TOL)
    seal = _feature(shape, lay.seal.d2)                             # lip-seal bore
    assert seal.z0 == pytest.approx(lay.shoulder_z, abs=TOL)
    assert seal.z1 - seal.z0 >= lay.seal.b + 0.3 - TOL
    assert _feature(shape, half.fd2["A_g7_mm"]) is not None         # spline pilot
    recess = _feature(shape, lay.gear_recess_d)                     # gear spigot recess
    assert recess is not None and lay.gear_recess_d <= half.fd0["B_H7_mm"]
    cbores = [c for c in z_cylinders(shape) if abs(c.diameter - half.cbore) <= TOL]
    assert cbores  # a 3 mm steel wall from each counterbore to the recess and its lead-in
    for c in cbores:
        wall = math.hypot(c.x, c.y) - c.diameter / 2 - lay.gear_recess_d / 2 - 0.5
        assert wall >= WALL_MIN_MM - TOL, (size, side, wall)
    gap = _feature(shape, lay.gap_journal)                          # running-gap seal
    assert gap is not None
    if side == "S":  # the bore takes the D spigot; its groove holds the O-ring (rod type)
        assert gap.z1 == pytest.approx(lay.s_bore_depth, abs=TOL)
        gland = _feature(shape, lay.gap_journal + 2 * lay.gap_gland.radial_depth)
        assert gland.z1 - gland.z0 == pytest.approx(lay.gap_gland.radial_width, abs=TOL)

    screws, gear = part.bolt_circles
    assert len(_holes_on_circle(shape, screws.diameter_mm, screws.hole_diameter_mm)) == \
        screws.count
    gear_holes = _holes_on_circle(shape, gear.diameter_mm, gear.hole_diameter_mm)
    assert len(gear_holes) == gear.count
    # HOUSING_RULES §4: hole centres ≥ 1.5·d from the outer surface they sit under
    assert _feature(shape, lay.body_d) is not None
    d = float(gear.thread.lstrip("M"))
    for x, y in gear_holes:
        assert lay.body_d / 2 - math.hypot(x, y) >= 1.5 * d - TOL
    # each tapped hole starts with a 90° countersink at the outer face (Ø 1.05·d)
    cones = [f for f in shape.Faces() if f.geomType() == "CONE"
             and f.BoundingBox().zmax == pytest.approx(lay.thickness, abs=TOL)
             and any(math.dist((f.Center().x, f.Center().y), h) < 0.1 for h in gear_holes)]
    assert len(cones) == gear.count
    for f in cones:
        box = f.BoundingBox()
        assert box.xlen == pytest.approx(1.05 * d, abs=0.02)
    # two radial oil ports: tap drill and spot face, at the port height
    drills = _radial_holes(shape, lay.port.tap_drill)
    spots = _radial_holes(shape, lay.port.spot_face)
    assert len(spots) == 2 and len(drills) >= 2
    for face in spots:
        assert face.Center().z == pytest.approx(lay.port_z, abs=0.05)


@pytest.mark.parametrize("size", SIZES)
def test_bearing_abutments_and_retention_follow_din_5418(size, catalog):
    lay = FDCasingHalf(size, catalog, DesignOptions(), side="S").lay
    b = lay.bearing
    # the outer-ring shoulder (seal-bore step) touches the outer ring only
    assert lay.seal.d2 <= b.housing_shoulder_max
    assert lay.seal.d2 > (b.land_d1 or b.d) + 1.0
    # the sleeve collar carries the inner ring: at least d_a,min, clear of the outer ring
    assert b.shaft_shoulder_min <= lay.collar_d < b.D - 2 * b.h
    # DIN 471/472 rings sized for the journal and the seat
    assert (lay.shaft_ring.d1, lay.bore_ring.d1) == (b.d, b.D)
    # the port window keeps max(3 mm, 0.5 d) to the pilot recess and to the ring groove
    lig = lay.port.ligament_min
    assert lay.port_z - lay.port.tap_drill / 2 - lay.pilot_depth >= lig - 1e-9
    assert lay.bearing_z - lay.bore_ring.m - (lay.port_z + lay.port.tap_drill / 2) >= lig - 1e-9
    # the ports reach level A and the running-gap seal leaves the S spline a pilot
    assert lay.port_radius >= lay.level
    assert lay.pilot_depth - lay.s_bore_depth >= 3.0
    # walls: running-gap spigot and the rim around the gap bore
    assert (lay.gap_journal - lay.spigot_id) / 2 >= WALL_MIN_MM - 1e-9
    assert (lay.outer_d - lay.gap_groove_d) / 2 >= WALL_MIN_MM - 1e-9


@pytest.mark.parametrize("size", SIZES)
def test_sleeve_measured_from_step(size, catalog, tmp_path):
    sleeve = FDSleeve(size, catalog, DesignOptions(), side="D")
    lay, part = sleeve.lay, sleeve.build()
    shape = _round_trip(part, tmp_path)
    journal = [c for c in axial_features(z_cylinders(shape))
               if abs(c.diameter - lay.bearing.d) <= TOL]
    under_bearings, seal_track = journal[0], journal[-1]  # split by the DIN 471 groove
    assert under_bearings.z0 == pytest.approx(lay.bearing_z, abs=TOL)
    assert under_bearings.z1 == pytest.approx(lay.shoulder_z, abs=TOL)
    # the seal track runs under the whole lip seal (its own diameter, its width)
    assert seal_track.z0 <= lay.seal_outer_z - lay.seal.b + TOL
    assert seal_track.z1 >= lay.seal_outer_z - TOL
    collar = _feature(shape, lay.collar_d)
    assert collar.z1 == pytest.approx(lay.bearing_z, abs=TOL)
    assert _feature(shape, lay.shaft_ring.d2) is not None            # DIN 471 groove
    assert _feature(shape, lay.shaft_d) is not None                  # bore on the shaft
    assert _feature(shape, lay.shaft_d + 2 * lay.shaft_gland.radial_depth) is not None
    fits = {f.code for f in part.fits}
    assert {"k5", "h11", "H7"} <= fits


@pytest.mark.parametrize("size", [25, 100])
def test_fits_carry_iso_286_deviations(size, built):
    part = built(size, "S")[1]
    codes = {f.code: f for f in part.fits}
    assert {"M7", "H7", "H8"} <= set(codes)
    seat = codes["M7"]
    assert seat.deviations_um[0] == 0.0 and seat.deviations_um[1] < 0  # M7: 0 / −IT7
    if size == 25:  # ISO 286-2: M7 on Ø55 is 0/−30 µm, H8 on Ø42 is +39/0 µm
        assert seat.deviations_um == (0.0, -30)
        assert next(f for f in part.fits if f.code == "H8" and f.nominal_mm == 42
                    ).deviations_um == (39, 0.0)


def test_unknown_size_names_the_allowed_sizes(catalog):
    with pytest.raises(ValueError, match="allowed sizes: 20, 25, 32"):
        FDCasingHalf(33, catalog, DesignOptions())
    with pytest.raises(ValueError, match="allowed: S, D"):
        FDCasingHalf(20, catalog, DesignOptions(), side="X")


def test_bolt_circle_that_does_not_fit_raises(catalog):
    bad = copy.deepcopy(catalog)  # deep copy: the shipped rows are shared between catalogs
    bad.find("fd2_dimensions", size=40)["I_mm"] = 140.0  # holes beyond the Ø135 spline
    with pytest.raises(ValueError, match="spline_screws.*annulus"):
        FDCasingHalf(40, bad, DesignOptions())
    bad.find("fd0_dimensions", size=50)["L_count"] = 60  # 60 × M10 on Ø155 overlap
    with pytest.raises(ValueError, match="gear_mount.*overlap"):
        FDCasingHalf(50, bad, DesignOptions())


def test_a_running_gap_that_eats_the_pilot_raises(catalog):
    with pytest.raises(ValueError, match="pilot"):
        FDCasingHalf(20, catalog, DesignOptions(running_gap_mm=20.0))


@pytest.mark.parametrize("size", SIZES)
def test_gear_recess_leaves_way_for_a_wall_and_says_so(size, catalog):
    """Where catalog φI and φB would leave less than the 3 mm steel wall between the
    spline-screw counterbores and the gear recess (FD-20: 0.75, FD-25: 1.0, FD-32: 2.5 mm),
    the recess shrinks to the largest whole mm that keeps it (lead-in included) and the part
    notes say so; elsewhere it is FD-0 φB."""
    half = FDCasingHalf(size, catalog, DesignOptions(), side="S")
    fd2, fd0, lay = half.fd2, half.fd0, half.lay
    lip = (fd2["I_mm"] - half.cbore - fd0["B_H7_mm"]) / 2 - 0.5
    said = any("instead of FD-0 φB" in n for n in half.build().notes)
    assert said == (lip < WALL_MIN_MM) == (lay.gear_recess_d < fd0["B_H7_mm"])
    if said:
        assert (fd2["I_mm"] - half.cbore - lay.gear_recess_d) / 2 - 0.5 >= WALL_MIN_MM
        assert (fd2["I_mm"] - half.cbore - lay.gear_recess_d - 2) / 2 - 0.5 < WALL_MIN_MM


@pytest.mark.parametrize("size", SIZES)
def test_lightening_groove_keeps_walls_and_reports_the_mass_saved(size, built):
    """HOUSING_RULES §4: pockets where material carries nothing, mass before and after. The
    groove floor is a turned surface of the stated Ø between z0 and z1; it stays a steel wall
    (3 mm) from the spline-screw clearance holes and the port spot faces; the volume it took
    is the re-imported solid's volume difference to the same half built without it."""
    half, part, _, shape = built(size, "S")
    relief, lay = half.relief, half.lay
    if relief is None:  # FD-20: the port spot faces and counterbores leave < RELIEF_MIN_MM
        assert size == 20
        return
    floor = _feature(shape, relief.floor_d)
    assert floor is not None
    assert floor.z0 >= relief.z0 - TOL and floor.z1 <= relief.z1 + TOL
    holes = [c for c in z_cylinders(shape) if abs(c.diameter - half.clearance) <= TOL]
    assert holes
    d = float(half.screw.lstrip("M"))
    for c in holes:  # wall over each clearance hole and its centre 1.5·d deep (HOUSING_RULES §4)
        assert relief.floor_d / 2 - (math.hypot(c.x, c.y) + c.diameter / 2) >= WALL_MIN_MM - TOL
        assert relief.floor_d / 2 - math.hypot(c.x, c.y) >= 1.5 * d - TOL
    spot = lay.port_z + lay.port.spot_face / 2
    assert relief.z0 - spot >= lay.port.ligament_min - TOL   # HOUSING_RULES §2 port ligament
    plain = copy.copy(half)
    plain.relief = None
    full = plain.build().solid().Volume()
    assert part.pockets_mm3 == pytest.approx(full - shape.Volume(), rel=1e-3)
    # worth the turning: ≥ 2.5 % of the half (FD-65 saves 2.8 % since its gear_mount holes
    # are drilled 3·P past the thread depth)
    assert part.pockets_mm3 > 0.025 * full


@pytest.mark.parametrize("size", SIZES)
def test_every_size_draws_from_its_step(size, built, tmp_path):
    """The drawing checks every stated dimension against the STEP faces; a size whose
    record names a face the solid lacks (e.g. a step that vanishes when the body keeps the
    outer Ø) would stop the design with an internal error."""
    from hdcad.geometry.drawing import part_drawing
    for side in ("S", "D"):
        _, part, path, _ = built(size, side)
        result = part_drawing(path, part, tmp_path / f"{part.name}.svg")
        assert result["views"][1]["section"] == "A–A"
        assert result["dimensions"]
