"""The shipped catalog: every table parses, has a source, and its dual-unit columns agree."""

import csv
import math
from decimal import Decimal
from pathlib import Path

import pytest
import yaml

from hdcad.catalog import load_catalog, table_name
from hdcad.errors import InputError
from hdcad.models import list_models, resolve
from hdcad.resources import catalog_dir

CATALOG = catalog_dir()
CSV_FILES = sorted(CATALOG.glob("*.csv"))
SOURCES = {}
for _path in CATALOG.glob("SOURCES*.yaml"):
    SOURCES.update(yaml.safe_load(_path.read_text(encoding="utf-8")))
EXCEPTIONS = yaml.safe_load((Path(__file__).parent / "data" / "dual_unit_exceptions.yaml")
                            .read_text(encoding="utf-8"))
KGF = 9.80665
ARCMIN = math.pi / 10800
# (SI suffix, other suffix, SI value per unit of the other)
PAIRS = [("_Nm_per_rad", "_kgfm_per_arcmin", KGF / ARCMIN), ("_Nm", "_kgfm", KGF),
         ("_cNm", "_kgfcm", KGF), ("_rad", "_arcmin", ARCMIN), ("_rad", "_arcsec", ARCMIN / 60)]
SEED_DIR = Path(__file__).resolve().parents[2] / "shared" / "seeds"


def _ulp(text: str) -> float:
    """One unit in the last significant printed digit (an integer's trailing zeros are not
    significant: the seed prints 105 kgf·m as 1030 N·m)."""
    number = Decimal(text)
    exponent = number.as_tuple().exponent
    if exponent == 0 and number != 0:
        digits = text.strip().lstrip("-")
        exponent = len(digits) - len(digits.rstrip("0"))
    return float(Decimal(10) ** exponent)


def _pairs(columns):
    for si_suffix, other_suffix, factor in PAIRS:
        for col in columns:
            if col.endswith(other_suffix):
                si = col[: -len(other_suffix)] + si_suffix
                if si in columns:
                    yield si, col, factor


def _excepted(path, row, si, other):
    return any(e["file"] == path.name and {si, other} == set(e["columns"])
               and all(row.get(k) == v for k, v in e["match"].items()) for e in EXCEPTIONS)


@pytest.mark.parametrize("path", CSV_FILES, ids=lambda p: p.name)
def test_every_table_has_a_source(path):
    meta = SOURCES.get(path.name)
    assert meta, f"{path.name} has no entry in catalog/SOURCES*.yaml"
    assert meta["seed"] and (meta.get("tables") or meta.get("pages")) and meta["title"]
    if SEED_DIR.is_dir() and not meta.get("standard"):
        seeds = meta["seed"] if isinstance(meta["seed"], list) else [meta["seed"]]
        assert all((SEED_DIR / s).is_file() for s in seeds), meta["seed"]


@pytest.mark.parametrize("path", CSV_FILES, ids=lambda p: p.name)
def test_dual_unit_columns_agree(path):
    with path.open(encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    checked = 0
    for row in rows:
        for si, other, factor in _pairs(list(row)):
            a, b = row[si], row[other]
            if not a or not b or _excepted(path, row, si, other):
                continue
            tolerance = 0.5 * _ulp(b) * factor + 0.5 * _ulp(a) + 1e-12
            assert abs(float(a) - float(b) * factor) <= tolerance, (path.name, row, si, other)
            checked += 1
    if any(True for _ in _pairs(rows[0] if rows else {})):
        assert checked > 0


def test_exceptions_are_real():
    """Each listed dual-unit exception still disagrees (so the list cannot hide fixed rows)."""
    for e in EXCEPTIONS:
        with (CATALOG / e["file"]).open(encoding="utf-8") as fh:
            rows = [r for r in csv.DictReader(fh)
                    if all(r.get(k) == v for k, v in e["match"].items())]
        si, other = e["columns"]
        assert rows and any(abs(float(r[si]) - float(r[other]) * KGF) > 0.5 * _ulp(r[other]) * KGF
                            + 0.5 * _ulp(r[si]) for r in rows if r[si] and r[other])


def test_known_seed_errors_are_corrected(catalog):
    row = catalog.find("gh_stiffness", series="CSG-GH", size=45, ratio_min=50)
    assert row["K2_Nm_per_rad"] == 200000  # seed prints 2.0 ×10⁴; 6.0 kgf·m/arc-min says 20
    corrections = [c for m in SOURCES.values() for c in (m.get("corrections") or [])]
    assert any("45" in str(c) and "K2" in str(c) for c in corrections)


def test_table_names():
    assert table_name("fd_rated_torque_310-1") == "fd_rated_torque"
    assert table_name("gh_hysteresis_052_060") == "gh_hysteresis"
    assert table_name("gh_motor_flange") == "gh_motor_flange"


def test_fd_ratios_match_rating_table(catalog):
    ratios = {(r["size"], r["ratio"]) for r in catalog.rows("fd_ratios")}
    rated = {(r["size"], r["ratio"]) for r in catalog.rows("fd_rated_torque")}
    assert ratios == rated


def test_every_model_resolves(catalog):
    codes = list_models(catalog)
    assert len(codes) > 100
    for code in codes:
        assert resolve(code, catalog).code == code


@pytest.mark.parametrize("code, words", [
    ("FD-25-99-2", "ratios: 80, 100, 120, 160, 200"),
    ("FD-33-80-0", "sizes in the catalog: 20, 25, 32, 40, 50, 65, 80, 100"),
    ("CSF-45-70-GH", "ratios: 50, 80, 100, 120, 160"),
    ("CSG-40-120-2A-GR", "CSG-2A-GR has no size 40"),
    ("XYZ-1", "not a model code"),
])
def test_unknown_models_list_what_exists(catalog, code, words):
    with pytest.raises(InputError) as info:
        resolve(code, catalog)
    assert words in str(info.value) and str(info.value).startswith("model:")


def _overlay(tmp_path, text):
    path = tmp_path / "overlay.yaml"
    path.write_text(text, encoding="utf-8")
    return path


def test_overlay_adds_main_bearing_and_component_rows(tmp_path):
    path = _overlay(tmp_path, """
source: test fixture (made-up values, not catalog data)
tables:
  main_bearing:
    - {model: CSF-45-120-GH, bearing_type: cross_roller, dp_m: 0.1, R_m: 0.02, C_N: 40000,
       Co_N: 60000, Mc_Nm: 800}
  component_ratings:
    - {series: CSG, size: 40, ratio: 100, rated_torque_Nm: 300}
""")
    cat = load_catalog(path)
    assert cat.find("main_bearing", model="CSF-45-120-GH")["C_N"] == 40000
    model = resolve("CSG-40-100-2A-GR", cat)
    assert float(model.get("rated_torque_Nm")) == 300
    assert "test fixture" in model.get("rated_torque_Nm").source
    assert cat.revision != load_catalog().revision


@pytest.mark.parametrize("body, words", [
    ("tables: {}", "source"),
    ("source: x\ntables: {nonsense: []}", "unknown table"),
    ("source: x\ntables: {gh_ratings: [{series: CSF-GH, size: 20, ratio: 50, bogus_Nm: 1}]}",
     "unknown key"),
    ("source: x\ntables: {gh_ratings: [{series: CSF-GH, size: 20, ratio: 50, "
     "rated_torque_2000_Nm: -3}]}", "> 0"),
    ("source: x\ntables: {gh_ratings: [{series: CSF-GH, size: 20, "
     "rated_torque_2000_Nm: 3}]}", "required"),
    ("source: x\ntables: {main_bearing: [{model: A, C_N: abc}]}", "must be a number"),
    ("source: [unclosed", "not valid YAML"),
    ("source: x\ntables: {gh_input_interface: [{series: CSF-GH, size: 45, pilot_diameter_mm: 100, "
     "pilot_kind: spigot, pilot_depth_mm: 5, bolt_circle_mm: 122, bolt_count: 4, "
     "bolt_thread: M8, oring_d1_d2_mm: '104x2.5'}]}", "ISO 3601 cross-sections 1.78, 2.62"),
])
def test_bad_overlays_are_rejected(tmp_path, body, words):
    with pytest.raises(InputError) as info:
        load_catalog(_overlay(tmp_path, body))
    assert words in str(info.value)
    assert "\n" not in str(info.value)
