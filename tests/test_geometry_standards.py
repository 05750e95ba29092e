"""The geometry's standard dimensions agree with the catalog's standard tables."""

import pytest

pytest.importorskip("cadquery")

from hdcad.geometry.standards import (ISO_261_PITCH_MM, ISO_273_MEDIUM_MM,  # noqa: E402
                                      ISO_4762_HEAD_MM, TAP_DRILL_MM)


def test_geometry_constants_match_catalog_tables(catalog):
    threads = {r["thread"]: r for r in catalog.rows("iso_metric_thread_iso261_iso724")}
    holes = {r["thread"]: r for r in catalog.rows("clearance_hole_iso273")}
    heads = {r["thread"]: r for r in catalog.rows("socket_head_iso4762")}
    for thread, pitch in ISO_261_PITCH_MM.items():
        assert threads[thread]["pitch_mm"] == pitch
        assert threads[thread]["tap_drill_mm"] == TAP_DRILL_MM[thread]
        assert holes[thread]["medium_mm"] == ISO_273_MEDIUM_MM[thread]
        assert (heads[thread]["dk_mm"], heads[thread]["k_mm"]) == ISO_4762_HEAD_MM[thread]
