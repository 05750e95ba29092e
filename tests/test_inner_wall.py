"""`inner_wall_clearance`: the not-evaluated branches and the distance measurement on shapes
whose distance is known analytically."""

import math

import numpy as np
import pytest

cq = pytest.importorskip("cadquery")
trimesh = pytest.importorskip("trimesh")

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.geometry.clearance import (MESH_TOLERANCE_MM, clearance_mm,  # noqa: E402
                                      fs_deflection_mm, inner_wall_clearance,
                                      points_to_mesh_mm)
from hdcad.models import resolve  # noqa: E402


@pytest.fixture(scope="module")
def shipped():
    return load_catalog()


@pytest.mark.parametrize("code, words", [
    ("FD-25-80-2", "no flexspline outline"),
    ("FD-25-80-0", "no flexspline outline"),
    ("CSF-45-120-GH", "closed unit"),
    ("CSG-65-100-GH", "motor adapter flange has no wall near the flexspline"),
])
def test_other_families_are_not_evaluated_with_the_reason(shipped, code, words):
    result = inner_wall_clearance(resolve(code, shipped), [], shipped)
    assert result.id == "inner_wall_clearance" and result.status == "not_evaluated"
    assert words in result.note and result.note.startswith("not evaluated:")


def test_component_set_without_overlay_rows_names_the_tables(shipped):
    result = inner_wall_clearance(resolve("CSF-40-120-2A-GR", shipped), [], shipped)
    assert result.status == "not_evaluated"
    assert "component_outline" in result.note and "component_housing" in result.note


def test_standard_deflection_is_one_module():
    # w0 = κ·m, κ = 1, m = d/Z_F, Z_F = 2R: d = 80 mm, R = 50 → Z_F = 100, m = 0.8 mm
    assert fs_deflection_mm(80.0, 50) == pytest.approx(0.8)


def _tube(inner_r, outer_r, z0, z1):
    return (cq.Solid.makeCylinder(outer_r, z1 - z0, cq.Vector(0, 0, z0))
            .cut(cq.Solid.makeCylinder(inner_r, z1 - z0, cq.Vector(0, 0, z0))))


def test_coaxial_cylinders_radial_gap():
    # solid cylinder r = 20 inside a tube of bore r = 23, longer at both ends: the gap is
    # 23 − 20 = 3 mm. The bore's facets lie up to one deflection inside the bore, the
    # cylinder's rim vertices lie on its surface: the mesh distance is 3 − [0, 2·deflection].
    envelope = cq.Solid.makeCylinder(20, 30)
    wall = _tube(23, 30, -5, 35)
    distance, tolerance = clearance_mm(envelope, [wall])
    assert tolerance == MESH_TOLERANCE_MM
    assert 3.0 - 2 * tolerance <= distance <= 3.0 + 1e-9


def test_end_wall_governs_when_it_is_closer():
    # same cylinder, tube bore r = 30 (gap 10) closed by a plate 4 mm above the top face:
    # the axial gap, 4 mm, governs (plane faces mesh exactly)
    envelope = cq.Solid.makeCylinder(20, 30)
    walls = [_tube(30, 35, -5, 34), cq.Solid.makeCylinder(35, 5, cq.Vector(0, 0, 34))]
    distance, _ = clearance_mm(envelope, walls)
    assert distance == pytest.approx(4.0, abs=1e-6)


def test_small_gap_refines_the_mesh():
    # gap 0.1 mm < 10 × default deflection: the mesh is refined to gap/20 and the result
    # still lies within 2 deflections of the analytic value
    envelope = cq.Solid.makeCylinder(20, 10)
    distance, tolerance = clearance_mm(envelope, [_tube(20.1, 25, -2, 12)])
    assert tolerance < MESH_TOLERANCE_MM and distance >= 10 * tolerance
    assert distance == pytest.approx(0.1, abs=2 * tolerance)


def test_overlap_is_zero():
    envelope = cq.Solid.makeCylinder(20, 30)
    distance, _ = clearance_mm(envelope, [_tube(19, 30, 0, 30)])
    assert distance == 0.0


def test_point_to_triangle_distance_is_exact():
    # unit right triangle in z = 0; point above its interior at height 2 → 2; point beyond
    # the hypotenuse's midpoint (0.5, 0.5) along its normal by √2/2 at z = 0 → √2/2
    mesh = trimesh.Trimesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]], process=False)
    assert points_to_mesh_mm(np.array([[0.2, 0.2, 2.0]]), mesh) == pytest.approx(2.0)
    assert points_to_mesh_mm(np.array([[1.0, 1.0, 0.0]]), mesh) == \
        pytest.approx(math.sqrt(2) / 2)
