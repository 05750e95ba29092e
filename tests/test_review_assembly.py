"""The FD-2 review assembly on every catalog size: parts with their neighbours as true-size
bodies, probed the way a design reviewer would (HOUSING_RULES §1-§4). Each probe is also shown
to fail when the feature it guards is taken away, so a pass means something."""

import pytest

cq = pytest.importorskip("cadquery")

from hdcad.catalog import load_catalog  # noqa: E402
from hdcad.checks.review import review_check  # noqa: E402
from hdcad.design_options import DesignOptions  # noqa: E402
from hdcad.geometry import review  # noqa: E402
from hdcad.geometry.fd_casing import FDCasingHalf  # noqa: E402
from hdcad.geometry.fd_review import review_plan  # noqa: E402
from hdcad.geometry.fd_sleeve import FDSleeve  # noqa: E402

CATALOG = load_catalog()
SIZES = FDCasingHalf.sizes(CATALOG)


def _parts(size, options=None):
    options = options or DesignOptions()
    gap = options.running_gap_mm
    parts = []
    for side, flip, z in (("S", True, -gap / 2), ("D", False, gap / 2)):
        for maker in (FDCasingHalf, FDSleeve):
            part = maker(size, CATALOG, options, side=side).build()
            part.flip, part.offset_z_mm = flip, z
            parts.append(part)
    return parts


@pytest.fixture(scope="module", params=SIZES)
def assembled(request):
    parts = _parts(request.param)
    return request.param, parts, review.review_bodies(parts), review_plan(parts)


def test_no_body_overlaps_another(assembled):
    size, parts, bodies, _ = assembled
    assert review.interferences(bodies) == []
    kinds = [b.kind for b in bodies]
    # four bearings (two per half), two lip seals, the running-gap O-ring and two sleeve
    # O-rings, four plugs, two circular splines
    assert kinds.count("bearing") == 4 and kinds.count("seal") == 2
    assert kinds.count("oring") == 3 and kinds.count("plug") == 4


def test_every_bearing_ring_is_stopped_on_both_faces(assembled):
    _, _, bodies, _ = assembled
    rows = review.bearing_stops(bodies)
    assert len(rows) == 4
    for row in rows:
        for face in ("inner_low", "inner_high", "outer_low", "outer_high"):
            assert row[face], (row["bearing"], face)
        # the pair's outer faces are held by the housing and the rings, never only by air:
        # the outer ring's stop on its open side is the casing (shoulder) or a DIN 472 ring
        stops = row["outer_low"] + row["outer_high"]
        assert any("casing_half" in s and "/" not in s or "DIN 472" in s for s in stops)


def test_every_lip_seal_runs_on_its_own_journal_over_its_width(assembled):
    _, _, bodies, _ = assembled
    for row in review.seal_journals(bodies):
        assert row["covered"] >= 0.999 and row["journal"].startswith("sleeve")


def test_screws_engage_and_do_not_bottom(assembled):
    _, _, bodies, _ = assembled
    rows = review.screw_engagements(bodies)
    assert rows
    for row in rows:
        assert row["engaged_min"] - 1e-6 <= row["engaged"] <= row["thread_depth"] + 1e-6


def test_oil_stays_in_and_each_seal_is_needed(assembled):
    """Flood fill on sections through the ports and holes: closed with every seal; open when
    the running-gap O-ring, a lip seal or the plugs are left out."""
    size, _, bodies, plan = assembled
    closed = review.oil_escapes(bodies, plan["seed_zr"], plan["angles"])
    assert not any(closed.values()), closed
    if size not in (25, 100):  # the controls on two sizes keep the suite fast
        return
    port = plan["angles"][:1]
    for kind, name in (("oring", "O-ring ×"), ("seal", "lip seal"), ("plug", "DIN 908")):
        without = [b for b in bodies if not (b.kind == kind and name in b.label)]
        assert any(review.oil_escapes(without, plan["seed_zr"], port).values()), kind


def test_review_check_passes_and_fails_on_the_probes(assembled):
    size, parts, bodies, plan = assembled
    if size != 25:
        return
    result = review.run_review(parts, plan)
    assert review_check(result).status == "pass"
    broken = dict(result, oil_escapes={"30": True})
    check = review_check(broken)
    assert check.status == "fail" and "oil reaches the outside" in check.note


def test_review_step_reimports_with_every_body(tmp_path):
    parts = _parts(25)
    result = review.run_review(parts, review_plan(parts), tmp_path)
    shape = cq.importers.importStep(str(tmp_path / "review_assembly.step"))
    solids = shape.solids().vals()
    assert len(solids) == result["bodies"]
    # the parts keep their volumes through STEP (exact B-rep)
    volumes = sorted(round(s.Volume(), 1) for s in solids)
    for part in parts:
        assert round(part.solid().Volume(), 1) in volumes
    assert (tmp_path / "figures" / "review_section.png").stat().st_size > 10_000


@pytest.mark.parametrize("size", SIZES)
def test_fd0_drive_flanges_mate_with_the_unit_outline(size):
    """Both drive flanges on the FD-0 unit's catalog outline (table 311-1): no overlap, the
    casing screws engage ≥ 1·d and stop short of the M thread depth."""
    from hdcad.geometry.build import build_parts
    from hdcad.models import resolve
    ratio = CATALOG.rows("fd_ratios", size=size)[0]["ratio"]
    parts = build_parts(resolve(f"FD-{size}-{ratio}-0", CATALOG), CATALOG, DesignOptions())
    bodies = review.review_bodies(parts)
    assert review.interferences(bodies) == []
    screws = review.screw_engagements(bodies)
    assert len(screws) == 2 * CATALOG.find("fd0_dimensions", size=size)["L_count"]
    for s in screws:
        assert s["engaged_min"] <= s["engaged"] <= s["thread_depth"]


def test_2a_gr_review_on_the_test_overlay():
    """2A-GR housing, cover and output flange on the invented test overlay (not catalog
    data): no overlap, four bearings stopped on both faces (two-point support of input and
    output), both lip seals on journals, CS screws engaged, oil closed in."""
    from pathlib import Path

    from hdcad.catalog import load_catalog
    from hdcad.geometry.build import build_parts, review_plan
    from hdcad.models import resolve
    overlay = load_catalog(Path(__file__).parent / "data" /
                           "overlay_2a_gr_TEST_DATA_NOT_CATALOG.yaml")
    model = resolve("CSF-40-120-2A-GR", overlay)
    parts = build_parts(model, overlay, DesignOptions())
    result = review.run_review(parts, review_plan(model, parts))
    assert result["interferences"] == []
    assert len(result["bearings"]) == 4
    assert all(row[f] for row in result["bearings"]
               for f in ("inner_low", "inner_high", "outer_low", "outer_high"))
    assert [s["covered"] >= 0.999 for s in result["seals"]] == [True, True]
    assert result["screws"] and all(s["engaged_min"] <= s["engaged"] <= s["thread_depth"]
                                    for s in result["screws"])
    assert not any(result["oil_escapes"].values())
    bodies = review.review_bodies(parts)
    without = [b for b in bodies if b.kind != "seal"]
    assert any(review.oil_escapes(without, review_plan(model, parts)["seed_zr"],
                                  [0.0]).values())
