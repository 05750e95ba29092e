"""Check functions against hand calculations and the rules the seeds state."""

import math
from fractions import Fraction

import pytest

from hdcad.checks.fd import momentary_allowance, rating_at_speed
from hdcad.checks.lubrication import duty_ratio_pct, longest_continuous_run_s
from hdcad.checks.main_bearing import main_bearing
from hdcad.checks.run import run_checks
from hdcad.checks.stiffness import StiffnessCurve, torsional_resonance
from hdcad.checks.strength import shock_count
from hdcad.duty import ExternalLoad, Segment, Shock, parse_duty
from hdcad.models import resolve
from conftest import duty_dict


def _fd_table(catalog, size, ratio):
    return resolve(f"FD-{size}-{ratio}-2", catalog).fd_torque_by_speed


@pytest.mark.parametrize("speed, expected_row", [
    (100, 500), (500, 500), (501, 600), (1000, 1150), (1450, 1450), (3500, 3500)])
def test_fd_rating_next_higher_listed_speed(catalog, speed, expected_row):
    table = _fd_table(catalog, 25, 120)
    datum, rule = rating_at_speed(table, speed)
    assert datum is dict(table)[expected_row] and f"{expected_row:g} r/min row used" in rule


def test_fd_rating_outside_table_is_unknown(catalog):
    assert rating_at_speed(_fd_table(catalog, 25, 120), 3600)[0] is None
    datum, rule = rating_at_speed(_fd_table(catalog, 65, 104), 2000)  # 2850/3500 printed '—'
    assert datum is None and "1750 r/min" in rule


def test_fd_momentary_is_twice_the_1450_rating(catalog):
    # seed 001 table 310-1: FD-25-80 at 1450 r/min = 57 N·m; note 3: 200 %
    assert float(momentary_allowance(_fd_table(catalog, 25, 80))) == 114


def test_fd_oil_allows_faster_input_than_grease(catalog):
    raw = duty_dict()
    raw["lubrication"] = "oil"
    model = resolve("FD-25-80-0", catalog)
    ev = run_checks(model, parse_duty(raw), catalog)
    assert ev.check("max_input_speed").limit == 5000  # table 313-3
    assert ev.check("lubrication").status == "pass" and "15 mm" in ev.check("lubrication").note


def test_duty_ratio_and_continuous_run():
    cycle = [Segment("start", 1, 60, 5), Segment("steady", 1, 540, 5),
             Segment("rest", 0, 5400, 0)]
    assert duty_ratio_pct(cycle) == pytest.approx(10.0)
    assert longest_continuous_run_s(cycle) == 600
    wrap = [Segment("steady", 1, 400, 5), Segment("rest", 0, 10, 0), Segment("start", 1, 300, 5)]
    assert longest_continuous_run_s(wrap) == 700  # the run continues into the next cycle
    assert longest_continuous_run_s(wrap[:1]) == math.inf


def test_shock_count_without_count_reports_ns():
    result = shock_count(Shock(500, 0.15, 14, None), 120)
    assert result.status == "not_evaluated" and round(result.value) == 1190
    assert "shock.count" in result.note


def test_main_bearing_against_hand_calculation():
    """Hand calculation of seed 000 pp.030-034 with made-up bearing data (test fixture)."""
    cycle = [Segment("steady", 100, 1.0, 10), Segment("rest", 0, 1.0, 0)]
    load = ExternalLoad(radial_N=2000, axial_N=500, Lr_m=0.05, La_m=0.02, fw=1.5)
    bearing = {"dp_m": 0.1, "R_m": 0.02, "C_N": 40000, "Co_N": 60000, "Mc_Nm": 800,
               "bearing_type": "cross_roller", "source": "test fixture"}
    m_max = 2000 * (0.05 + 0.02) + 500 * 0.02  # 150 N·m
    radial_equiv = 2000 + 2 * (2000 * 0.07 + 500 * 0.02) / 0.1  # 5000 N; 500/5000 ≤ 1.5
    pc = 1.0 * radial_equiv + 0.45 * 500
    nav = 10 * 1.0 / 2.0
    l10 = 1e6 / (60 * nav) * (40000 / (1.5 * pc)) ** (10 / 3)
    po = 2000 + 2 * m_max / 0.1 + 0.44 * 500
    result = main_bearing(cycle, load, bearing, 7000)
    assert result.details["Mmax_Nm"] == pytest.approx(m_max)
    assert result.details["Pc_N"] == pytest.approx(pc)
    assert result.details["criteria"]["life"]["value"] == pytest.approx(l10)
    assert result.details["fs"] == pytest.approx(60000 / po)
    assert result.status == ("pass" if l10 >= 7000 else "fail")
    weak = main_bearing(cycle, load, dict(bearing, Mc_Nm=100), 1)
    # Mmax 150 > Mc 100: the row shows the moment, the criterion that fails
    assert weak.status == "fail" and weak.details["governing"] == "moment"
    assert (weak.value, weak.limit) == (pytest.approx(m_max), 100)


def test_oscillating_life_formula_033_1():
    """Seed 000 p.033, formula 033-1: Loc = 10⁶/(60·n1)·(90/θ)·(C/(fw·Pc))^(10/3), θ = angle/2;
    made-up bearing data (test fixture), 20 oscillations per minute over 40°."""
    from types import SimpleNamespace
    cycle = [Segment("steady", 100, 1.0, 10)]
    load = ExternalLoad(radial_N=2000, axial_N=500, Lr_m=0.05, La_m=0.02, fw=1.5)
    bearing = {"dp_m": 0.1, "R_m": 0.02, "C_N": 40000, "Co_N": 60000, "Mc_Nm": 800,
               "bearing_type": "cross_roller", "source": "test fixture"}
    pc = 1.0 * (2000 + 2 * (2000 * 0.07 + 500 * 0.02) / 0.1) + 0.45 * 500
    loc = 1e6 / (60 * 20) * (90 / 20) * (40000 / (1.5 * pc)) ** (10 / 3)
    swing = main_bearing(cycle, load, bearing, 7000,
                         oscillation=SimpleNamespace(angle_deg=40, cycles_per_min=20))
    assert swing.details["criteria"]["life"]["value"] == pytest.approx(loc)
    small = main_bearing(cycle, load, bearing, 7000,
                         oscillation=SimpleNamespace(angle_deg=4, cycles_per_min=20))
    assert "fretting" in small.note  # angle ≤ 5°: the seed's note under figure 033-1


def test_main_bearing_needs_overlay_data(catalog):
    raw = duty_dict()
    raw["external_load"] = {"radial_N": 2000, "axial_N": 500, "Lr_m": 0.05, "La_m": 0.02}
    ev = run_checks(resolve("CSF-45-120-GH", catalog), parse_duty(raw), catalog)
    assert ev.check("main_bearing").status == "not_evaluated"
    assert "overlay" in ev.check("main_bearing").note


def test_resonance_hand_calculation():
    curve = StiffnessCurve(K1=1.0e4, T1=10, K2=2.0e4, T2=50, K3=3.0e4)
    cycle = [Segment("steady", 30, 1, 10)]
    j = 0.5
    f = math.sqrt(2.0e4 / j) / (2 * math.pi)  # 30 N·m lies in segment 2 → K2
    n_res = f / 2 * 60
    ratio = n_res / 10  # steady input speed exactly at resonance
    result = torsional_resonance(cycle, ratio, curve, j, "test")
    assert result.status == "fail" and result.value == pytest.approx(0.0, abs=1e-9)
    far = torsional_resonance(cycle, ratio * 2, curve, j, "test")
    assert far.status == "pass" and far.value == pytest.approx(1.0)
    edge = torsional_resonance(cycle, ratio * 1.19, curve, j, "test")
    assert edge.status == "fail"


def test_twist_curve_segments():
    curve = StiffnessCurve(K1=1.0e4, T1=10, K2=2.0e4, T2=50, K3=4.0e4)
    assert curve.twist(5) == pytest.approx(5e-4)
    assert curve.twist(30) == pytest.approx(1e-3 + 20 / 2e4)
    assert curve.twist(-60) == pytest.approx(-(1e-3 + 40 / 2e4 + 10 / 4e4))


def test_fd_gear_pairs_table_gives_unit_ratio(catalog):
    """Table 308-1 lists tooth sets with i = i_D·(Z1·Z3)/(Z2·Z4) = 1 (seed 001 p.308).

    One printed fraction (R = 128, 33·43/(32·40)) gives 11/10: a misprint in the seed
    (44 instead of 40 gives 1); it is kept as printed and must stay the only exception.
    """
    off = []
    for row in catalog.rows("fd_gear_pairs"):
        i = Fraction(row["R"], row["R"] + 1) * Fraction(row["z_num1"] * row["z_num2"],
                                                        row["z_den1"] * row["z_den2"])
        if i != 1:
            off.append((row["R"], row["z_num1"], row["z_num2"], row["z_den1"], row["z_den2"]))
    assert off == [(128, 33, 43, 32, 40)]


def test_gear_head_oil_is_a_case_to_confirm_not_a_failure(catalog):
    # seed 000 p.016: gear heads ship grease-filled; other lubrication is a "consult us"
    # case, not a forbidden one: warn, and the design does not fail on it
    raw = duty_dict()
    raw["lubrication"] = "oil"
    ev = run_checks(resolve("CSF-45-120-GH", catalog), parse_duty(raw), catalog)
    assert ev.check("lubrication").status == "warn" and ev.all_passed
    assert "to confirm with the maker" in ev.verdict and "consult" in ev.check("lubrication").note


def test_ambient_outside_grease_range_fails(catalog):
    raw = duty_dict()
    raw["ambient_C"] = 55
    ev = run_checks(resolve("CSF-45-120-GH", catalog), parse_duty(raw), catalog)
    assert ev.check("lubrication").status == "fail" and "0…40" in ev.check("lubrication").note
