"""STEP files name their products after the parts, so a CAD tree shows "motor_flange"."""

from __future__ import annotations

import re

import pytest

cq = pytest.importorskip("cadquery")

from hdcad.design_options import DesignOptions  # noqa: E402
from hdcad.geometry.build import build_parts  # noqa: E402
from hdcad.geometry.part import export_assembly, export_step  # noqa: E402
from hdcad.models import resolve  # noqa: E402

PRODUCT = re.compile(r"PRODUCT\('([^']*)'")


@pytest.mark.parametrize("code", ["CSF-45-120-GH", "FD-25-80-2"])
def test_part_and_assembly_products_carry_the_part_names(catalog, tmp_path, code):
    parts = build_parts(resolve(code, catalog), catalog, DesignOptions())
    for part in parts:
        path = tmp_path / f"{part.name}.step"
        export_step(part, path)
        assert PRODUCT.findall(path.read_text()) == [part.name]
        back = cq.importers.importStep(str(path)).val()
        assert len(back.Solids()) == 1
        assert back.Volume() == pytest.approx(part.shape.val().Volume(), rel=1e-6)
    export_assembly(parts, tmp_path / "assembly.step")
    names = PRODUCT.findall((tmp_path / "assembly.step").read_text())
    assert set(names) == {"assembly"} | {p.name for p in parts}
