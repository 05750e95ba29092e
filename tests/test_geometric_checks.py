"""Geometric checks (input bore + key, bolt circles) against hand calculations, and the
standard data tables they use."""

import csv
import math

import pytest
import yaml

from hdcad.catalog import table_name
from hdcad.checks.bolts import bolt_pattern, permissible_preload_N
from hdcad.checks.input_bore import input_bore, select_key
from hdcad.resources import catalog_dir

CATALOG = catalog_dir()
STANDARD_FILES = {
    "iso_metric_thread_iso261_iso724.csv": "iso_metric_thread_iso261_iso724",
    "socket_head_iso4762.csv": "socket_head_iso4762",
    "clearance_hole_iso273.csv": "clearance_hole_iso273",
    "parallel_key_jisb1301.csv": "parallel_key_jisb1301",
    "bolt_property_iso898-1.csv": "bolt_property_iso898-1",
}


def _rows(catalog, size):
    return catalog.find("wg_hub_bore", size=size), catalog.find("wg_plug_bore", size=size)


# ---------------------------------------------------------------- input bore -------------
def test_standard_bore_passes_and_key_stresses_match_hand_calculation(catalog):
    # size 32 (table 027-1): standard 14 H7, pilot 6, max 15; d = 14 → JIS key 5 × 5, t1 = 3
    r = input_bore(14, 32, 20.0, *_rows(catalog, 32))
    assert r.status == "pass" and r.id == "input_bore" and r.family == "geometry"
    assert (r.value, r.limit, r.sense) == (14, 15, "<=")
    key = r.details["key"]
    assert (key["b_mm"], key["h_mm"], key["t1_mm"], key["t2_mm"]) == (5, 5, 3.0, 2.3)
    assert key["length_mm"] == 21  # default 1.5·d
    # τ = 2T/(d·b·l) = 2·20 000 N·mm / (14·5·21 mm³); p = 2T/(d·(h − t1)·l) = 40 000/(14·2·21)
    assert key["tau_MPa"] == pytest.approx(40000 / 1470)   # 27.21 MPa
    assert key["p_MPa"] == pytest.approx(40000 / 588)      # 68.03 MPa
    assert key["tau_allow_MPa"] == 86.25 and key["p_allow_MPa"] == 172.5
    assert "86.25" in r.note and "172.5" in r.note and "standard H7" in r.note


def test_rebored_hub_up_to_max_passes(catalog):
    r = input_bore(15, 32, 5.0, *_rows(catalog, 32))
    assert r.status == "pass" and r.limit == 15 and r.margin == 0 and "rebored" in r.note


def test_bore_between_hub_max_and_plug_bore_passes_without_oldham(catalog):
    # 15 < 20: direct plug mounting; key 6 × 6 (t2 = 2.8); φV' = 36 (027-2) includes the keyway
    r = input_bore(20, 32, 20.0, *_rows(catalog, 32))
    assert r.status == "pass" and r.details["regime"] == "plug"
    assert r.limit == pytest.approx(36 - 2.8)
    assert "Oldham coupling is lost" in r.note
    # key bearing length bounded by the minimum plug thickness 13.7 mm (1.5·d = 30 mm)
    key = r.details["key"]
    assert key["length_mm"] == 13.7
    assert key["tau_MPa"] == pytest.approx(2 * 20000 / (20 * 6 * 13.7))
    assert key["p_MPa"] == pytest.approx(2 * 20000 / (20 * (6 - 3.5) * 13.7))


def test_bore_above_plug_bore_fails(catalog):
    hub, plug = _rows(catalog, 32)
    r = input_bore(40, 32, 20.0, hub, plug)
    assert r.status == "fail" and r.limit == pytest.approx(36 - 3.3) and r.margin < 0
    # the keyway depth counts against φV' by default; the looser reading allows d = φV'
    assert input_bore(36, 32, 20.0, hub, plug).status == "fail"
    assert input_bore(36, 32, 20.0, hub, plug, plug_limit_includes_keyway=False).status == "pass"
    assert input_bore(37, 32, 20.0, hub, plug, plug_limit_includes_keyway=False).status == "fail"


def test_bore_below_pilot_fails(catalog):
    r = input_bore(5, 32, 1.0, *_rows(catalog, 32))  # pilot bore 6 mm
    assert r.status == "fail" and r.sense == ">=" and r.limit == 6


def test_missing_rows_are_not_evaluated(catalog):
    hub, plug = _rows(catalog, 32)
    r = input_bore(14, 33, 20.0, None, None)
    assert r.status == "not_evaluated" and "wg_hub_bore" in r.note and "027-1" in r.note
    r = input_bore(20, 32, 20.0, hub, None)
    assert r.status == "not_evaluated" and "wg_plug_bore" in r.note and "027-2" in r.note
    # a bore within the hub range does not need the plug table
    assert input_bore(14, 32, 20.0, hub, None).status == "pass"
    # size 11: standard bore 5 mm, no JIS B 1301 key below 6 mm
    r = input_bore(5, 11, 0.5, *_rows(catalog, 11))
    assert r.status == "not_evaluated" and "parallel key" in r.note


def test_overstressed_key_fails_with_bore_in_range(catalog):
    r = input_bore(14, 32, 200.0, *_rows(catalog, 32), key_length_mm=10)
    # τ = 400 000/(14·5·10) = 571 MPa
    assert r.details["key"]["tau_MPa"] == pytest.approx(400000 / 700)
    assert r.status == "fail" and r.margin < 0 and "overstressed" in r.note


@pytest.mark.parametrize("d, key", [(6, (2, 2)), (8, (2, 2)), (8.5, (3, 3)), (12, (4, 4)),
                                    (30, (8, 7)), (95, (25, 14)), (110, (28, 16))])
def test_key_selection_boundaries(catalog, d, key):
    row = select_key(d, catalog.rows("parallel_key_jisb1301"))
    assert (row["b_mm"], row["h_mm"]) == key
    assert select_key(5, catalog.rows("parallel_key_jisb1301")) is None


def test_key_table_matches_fd_keyways(catalog):
    """Seed 001 tables 311-1 / 312-1: keyway width = b and bore + hub depth = bore + t2."""
    for table, bore, width, depth in (("fd0_dimensions", "N_H7_mm", "O_JS9_mm", "P_mm"),
                                      ("fd2_dimensions", "L_H7_mm", "M_mm", "N_mm")):
        for row in catalog.rows(table):
            key = select_key(row[bore], catalog.rows("parallel_key_jisb1301"))
            assert key["b_mm"] == row[width], (table, row["size"])
            assert row[bore] + key["t2_mm"] == pytest.approx(row[depth]), (table, row["size"])


# ---------------------------------------------------------------- bolt pattern -----------
BASE = dict(name="output flange", circle_diameter_mm=60, count=8, thread="M6",
            hole_kind="clearance", annulus_inner_mm=40, annulus_outer_mm=80,
            engagement_mm=9, bolt_class="8.8", friction=0.15, torque_to_carry_Nm=100,
            safety_factor=1.5)


def test_bolt_capacity_equals_hand_calculation_of_vdi_formula():
    r = bolt_pattern(**BASE, tightening=10.0)
    # M6: P = 1, d2 = 5.350 (ISO 724); D_Km = (dw 9.38 + d_h 6.6)/2 = 7.99 (ISO 4762, ISO 273)
    # F_M = 10 000 N·mm / (0.16·1 + 0.58·5.35·0.12 + 0.12·7.99/2) = 10 000 / 1.01176 = 9884 N
    k = 0.16 * 1 + 0.58 * 5.350 * 0.12 + 0.12 * 7.99 / 2
    f_m = 10000 / k
    assert k == pytest.approx(1.01176)
    assert r.details["F_M_N"] == pytest.approx(f_m)
    # T_cap = n·F_M·µT·D/2 = 8·9884·0.15·0.030 m = 355.8 N·m ≥ 1.5·100
    cap = r.details["criteria"]["torque_capacity"]
    assert cap["value"] == pytest.approx(8 * f_m * 0.15 * 0.030)
    assert cap["value"] == pytest.approx(355.8, abs=0.1)
    assert cap["limit"] == 150 and cap["sense"] == ">=" and r.status == "pass"
    # the row shows the criterion with the least margin: all pass here
    gov = r.details["criteria"][r.details["governing"]]
    assert (r.value, r.limit, r.sense) == (gov["value"], gov["limit"], gov["sense"])
    assert gov["margin"] == min(c["margin"] for c in r.details["criteria"].values()
                                if c["margin"] is not None)
    assert "output flange" in r.title and r.details["name"] == "output flange"
    assert set(r.details["criteria"]) == {"edge_inner", "edge_outer", "head_room", "engagement",
                                          "assembly_stress", "torque_capacity"}


def test_default_tightening_is_90_percent_of_proof_stress():
    r = bolt_pattern(**BASE)
    # VDI 2230 R7: F_Mzul = 0.9·Rp0.2·As / √(1 + 3·[1.5·(d2/d0)·(P/(π·d2) + 1.155·µG)]²)
    d2, d3, p, As = 5.350, 4.773, 1.0, 20.1
    d0 = (d2 + d3) / 2
    f_zul = 0.9 * 640 * As / math.sqrt(1 + 3 * (1.5 * d2 / d0 * (p / (math.pi * d2)
                                                                 + 1.155 * 0.12)) ** 2)
    # d0 = 5.0615, [1.5·1.0570·(0.05950 + 0.1386)]² = 0.09865, √1.29596 = 1.1384
    assert f_zul == pytest.approx(11577.6 / 1.1384, rel=1e-4)  # 10.17 kN
    assert r.details["F_M_N"] == pytest.approx(f_zul)
    assert r.details["M_A_Nm"] == pytest.approx(f_zul * 1.01176 / 1000, rel=1e-5)
    assert permissible_preload_N(As, d2, d3, p, 640) == pytest.approx(f_zul)
    assert "assembly_stress" not in r.details["criteria"]


def test_crowded_bolt_circle_fails_on_head_room():
    # 16 × M6 on φ40: chord 40·sin(π/16) = 7.80 mm < dk 10 mm (ISO 4762)
    r = bolt_pattern(**{**BASE, "circle_diameter_mm": 40, "count": 16, "annulus_inner_mm": 20,
                        "annulus_outer_mm": 60, "hole_kind": "tapped",
                        "torque_to_carry_Nm": 10})
    head = r.details["criteria"]["head_room"]
    assert head["value"] == pytest.approx(40 * math.sin(math.pi / 16)) and head["limit"] == 10
    assert head["status"] == "fail" and r.status == "fail" and "head_room" in r.note
    others = {k: c["status"] for k, c in r.details["criteria"].items() if k != "head_room"}
    assert set(others.values()) == {"pass"}
    # the row shows the failing criterion, not the sufficient torque capacity
    assert r.details["governing"] == "head_room" and r.value < r.limit and r.unit == "mm"
    assert r.details["criteria"]["torque_capacity"]["status"] == "pass"


def test_short_engagement_fails():
    r = bolt_pattern(**{**BASE, "hole_kind": "tapped", "engagement_mm": 9},
                     tapped_material="aluminium")
    eng = r.details["criteria"]["engagement"]
    assert (eng["value"], eng["limit"], eng["status"]) == (9, 12, "fail")  # 2.0·d
    assert r.status == "fail"
    steel = bolt_pattern(**{**BASE, "engagement_mm": 6}, tapped_material="steel")
    cast_iron = bolt_pattern(**{**BASE, "engagement_mm": 7}, tapped_material="cast_iron")
    assert steel.status == "pass" and cast_iron.status == "fail"  # 1.0·d = 6, 1.25·d = 7.5


def test_hole_too_close_to_edge_fails():
    # clearance hole 6.6 (ISO 273 medium): centre-to-edge ≥ 1.2·6.6 = 7.92 mm; (75 − 60)/2 = 7.5
    r = bolt_pattern(**{**BASE, "annulus_outer_mm": 75})
    edge = r.details["criteria"]["edge_outer"]
    assert edge["limit"] == pytest.approx(7.92) and edge["value"] == 7.5
    assert edge["status"] == "fail" and r.status == "fail"


def test_overtightening_fails_and_low_capacity_fails():
    r = bolt_pattern(**BASE, tightening=20.0)  # F_M = 19.8 kN > F_Mzul = 10.17 kN
    assert r.details["criteria"]["assembly_stress"]["status"] == "fail" and r.status == "fail"
    r = bolt_pattern(**{**BASE, "torque_to_carry_Nm": 1000})
    assert r.status == "fail" and r.value < r.limit and r.margin < 0


def test_missing_engagement_is_reported_not_failed():
    r = bolt_pattern(**{**BASE, "engagement_mm": None})
    assert r.details["criteria"]["engagement"]["status"] == "not_evaluated"
    assert r.status == "pass" and "not evaluated: engagement" in r.note


def test_missing_standard_rows_are_not_evaluated():
    r = bolt_pattern(**{**BASE, "thread": "M7"})
    assert r.status == "not_evaluated" and "iso_metric_thread_iso261_iso724" in r.note
    r = bolt_pattern(**{**BASE, "bolt_class": "4.6"})
    assert r.status == "not_evaluated" and "bolt_property_iso898-1" in r.note


# ---------------------------------------------------------------- standard tables --------
def _sources():
    return yaml.safe_load((CATALOG / "SOURCES.checks_standards.yaml").read_text(encoding="utf-8"))


@pytest.mark.parametrize("file", sorted(STANDARD_FILES))
def test_standard_tables_have_sources_and_load(catalog, file):
    meta = _sources()[file]
    assert meta["seed"] and meta["tables"] and meta["title"] and meta["notes"]
    assert table_name(file[:-4]) == STANDARD_FILES[file]
    assert catalog.rows(STANDARD_FILES[file])


def _csv(name):
    with (CATALOG / name).open(encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def test_thread_table_follows_iso_724_and_iso_898_1():
    rows = _csv("iso_metric_thread_iso261_iso724.csv")
    assert [r["thread"] for r in rows][0] == "M3" and rows[-1]["thread"] == "M24"
    for r in rows:
        d, p = float(r["d_mm"]), float(r["pitch_mm"])
        d2, d3, As = float(r["d2_mm"]), float(r["d3_mm"]), float(r["As_mm2"])
        assert r["thread"] == f"M{d:g}"
        assert abs(d2 - (d - 0.6495 * p)) <= 0.01, r
        assert abs(d3 - (d - 1.2269 * p)) <= 0.01, r
        assert As == pytest.approx(math.pi / 4 * ((d2 + d3) / 2) ** 2, rel=0.005), r
        assert d3 < float(r["tap_drill_mm"]) < d


def test_other_standard_tables_are_consistent(catalog):
    threads = [r["thread"] for r in catalog.rows("iso_metric_thread_iso261_iso724")]
    for table in ("socket_head_iso4762", "clearance_hole_iso273"):
        assert [r["thread"] for r in catalog.rows(table)] == threads
    for r in catalog.rows("socket_head_iso4762"):
        d = float(r["thread"][1:])
        assert r["k_mm"] == d and r["dw_mm"] < r["dk_mm"]  # ISO 4762: k max = d
    for r in catalog.rows("clearance_hole_iso273"):
        assert float(r["thread"][1:]) < r["fine_mm"] < r["medium_mm"] < r["coarse_mm"]
    keys = catalog.rows("parallel_key_jisb1301")
    for a, b in zip(keys, keys[1:]):
        assert a["shaft_max_mm"] == b["shaft_min_mm"] and a["b_mm"] < b["b_mm"]
    for k in keys:
        # the key protrudes h − t1 from the shaft: less than t1 (so the hub side governs the
        # side pressure) and not more than the hub keyway depth t2
        assert k["h_mm"] - k["t1_mm"] < k["t1_mm"] and k["h_mm"] - k["t1_mm"] <= k["t2_mm"]
    classes = {r["kind"]: r for r in catalog.rows("bolt_property_iso898-1")}
    assert {"8.8", "10.9", "12.9"} <= set(classes)
    for r in catalog.rows("bolt_property_iso898-1"):
        assert r["Rp02_MPa"] < r["Rm_MPa"]
