"""Proof of `hdcad reconcile` on data with hidden effects ("Proof on hidden-effect
data").

The data come from ``reconcile_truth`` (an independent simulator: Masing/Ramberg–Osgood
hysteresis, softplus dead zone, Palmgren loss split, Vogel viscosity, numerically integrated
joint …); the workflow only sees the columns.
Thresholds are the issue's: per kind and effect, ≥ 20 random cases and the named effect
right in ≥ 90 %; no hidden effect → nothing named in ≥ 90 %; with the right effect added,
median RMSE reduction ≥ 50 % and reconciled RMSE ≤ 1.15 × noise RMS in ≥ 90 % of cases;
two effects hidden together are both named (here in ≥ 90 % of ≥ 10 cases).

Each case is generated and reconciled once per session (``run_cases`` caches them and runs
the new ones in two worker processes); the seeds are fixed, so every failure is
reproducible with ``reconcile_truth.make_case``.
"""

from __future__ import annotations

import json
import math
import re
import statistics
from collections import Counter

import numpy as np
import pytest

import reconcile_truth as truth
from reconcile_cases import run_case, run_cases
from hdcad.models import resolve
from hdcad.reconcile import COLUMNS, EFFECT_NAMES, KINDS, read_data

CASES = 20          # issue: "at least 20 random cases per effect"
COMBO_CASES = 10    # task brief: "≥ 90 % of ≥ 10 cases" for two hidden effects
RATE = 0.90         # issue: "in at least 90 % of cases"
RMSE_FACTOR = 1.15  # issue: "within 15 % of the noise RMS"
MEDIAN_GAIN = 0.50  # issue: "median RMSE reduction is at least 50 %"

SINGLE = [(kind, effects[0]) for kind, effects in truth.SINGLE_SCENARIOS]
COMBOS = truth.COMBO_SCENARIOS


def cases(kind: str, effects: tuple[str, ...], count: int) -> list[dict]:
    return run_cases(kind, effects, range(count))


def describe(runs: list[dict], failing: list[dict]) -> str:
    """Confusion row (named sets → count) and the failing seeds with their size k."""
    row = Counter(", ".join(r["named"]) or "(nothing)" for r in runs)
    seeds = ", ".join(f"{r['seed']} ({r['model']}, k={r['truth']['k']:.1f}, named "
                      f"{list(r['named'])}, rmse {r['result']['rmse_after']:.3g} vs noise "
                      f"{r['truth']['noise_rms']:.3g})" for r in failing)
    return f"confusion row {dict(row)}; failing seeds: {seeds}"


def rate(runs: list[dict], ok) -> tuple[float, list[dict]]:
    failing = [r for r in runs if not ok(r)]
    return 1.0 - len(failing) / len(runs), failing


# ======================================================================================
# the criteria
# ======================================================================================

@pytest.mark.parametrize("kind,effect", SINGLE)
def test_hidden_effect_is_named(kind, effect):
    runs = cases(kind, (effect,), CASES)
    share, failing = rate(runs, lambda r: r["named"] == (effect,))
    assert share >= RATE, f"{kind}/{effect}: right in {share:.0%}; " + describe(runs, failing)


@pytest.mark.parametrize("kind", KINDS)
def test_nothing_named_without_hidden_effect(kind):
    runs = cases(kind, (), CASES)
    share, failing = rate(runs, lambda r: r["named"] == ())
    assert share >= RATE, f"{kind}/none: nothing named in {share:.0%}; " + describe(runs,
                                                                                     failing)


@pytest.mark.parametrize("kind,effect", SINGLE)
def test_right_effect_closes_the_gap(kind, effect):
    runs = cases(kind, (effect,), CASES)
    right = [r for r in runs if effect in r["named"]]
    assert right, f"{kind}/{effect}: never named; " + describe(runs, runs)
    gains = [1.0 - r["result"]["rmse_after"] / r["result"]["rmse_before"] for r in right]
    assert statistics.median(gains) >= MEDIAN_GAIN, (
        f"{kind}/{effect}: median RMSE reduction {statistics.median(gains):.0%}; "
        + describe(runs, [r for r, g in zip(right, gains) if g < MEDIAN_GAIN]))
    # A case where the effect was not named counts as a failure here too.
    share, failing = rate(runs, lambda r: effect in r["named"] and r["result"]["rmse_after"]
                          <= RMSE_FACTOR * r["truth"]["noise_rms"])
    assert share >= RATE, (f"{kind}/{effect}: reconciled RMSE ≤ {RMSE_FACTOR} × noise in "
                           f"{share:.0%}; " + describe(runs, failing))


@pytest.mark.parametrize("kind,effects", COMBOS, ids=["+".join(e) for _, e in COMBOS])
def test_two_hidden_effects_are_both_named(kind, effects):
    runs = cases(kind, effects, COMBO_CASES)
    share, failing = rate(runs, lambda r: set(effects) <= set(r["named"]))
    assert share >= RATE, f"{kind}/{'+'.join(effects)}: both named in {share:.0%}; " + \
        describe(runs, failing)


def test_third_harmonic_is_reported_unexplained():
    """A 3-per-revolution error (no candidate has it) is named as unexplained structure.

    Size k in [1, 10] as elsewhere; the entry must name order 3 of the WG revolution.
    """
    runs = cases("transmission", ("te_3x",), 5)

    def names_third(r):
        text = json.dumps(r["result"]["unexplained"], ensure_ascii=False).lower()
        third = re.search(r"\b3\s*(cycle|per|x\b|×)|order 3|\bthird\b|\b3rd\b", text)
        return third and not set(r["named"]) & {"te_1x", "te_2x"}

    share, failing = rate(runs, names_third)
    assert share >= 0.8, (f"3× harmonic reported unexplained in {share:.0%}: "
                          + "; ".join(f"seed {r['seed']}: {r['result']['unexplained']}"
                                      for r in failing) + "; " + describe(runs, failing))


# ======================================================================================
# JSON shape and data path
# ======================================================================================

JSON_KEYS = {"kind", "model", "disagreements", "missing_effects", "rmse_before", "rmse_after",
             "measurement_effects", "nuisances", "equivalent_readings", "noise_rms", "outliers",
             "steps", "unexplained", "notes"}


def _finite(x) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


@pytest.mark.parametrize("kind,effects", [("torsion", ("hysteresis", "backlash")),
                                          ("transmission", ("te_2x",)),
                                          ("efficiency", ("low_load_efficiency",)),
                                          ("vibration", ("te_2x",)), ("torsion", ())])
def test_json_shape(kind, effects):
    run = run_case(kind, effects, 0)
    doc = json.loads(json.dumps(run["result"]))       # must be plain JSON
    assert set(doc) == JSON_KEYS
    assert doc["kind"] == kind and doc["model"] == run["model"]
    assert _finite(doc["rmse_before"]) and _finite(doc["rmse_after"])
    assert doc["rmse_after"] <= doc["rmse_before"] * (1 + 1e-9)
    assert all(name in EFFECT_NAMES for name in doc["missing_effects"])
    assert [s["effect"] for s in doc["steps"]] == doc["missing_effects"]
    for step in doc["steps"]:
        assert set(step) == {"effect", "params", "criterion_gain", "rmse", "form"}
        assert _finite(step["criterion_gain"]) and _finite(step["rmse"])
        assert step["params"], f"{step['effect']} has no fitted parameters"
        for value in step["params"].values():
            assert set(value) == {"value", "unit"} and _finite(value["value"])
            assert isinstance(value["unit"], str)
    for region in doc["disagreements"]:
        assert set(region) == {"where", "rms", "noise_rms"}
        assert isinstance(region["where"], str) and region["where"]
        assert _finite(region["rms"]) and _finite(region["noise_rms"])
    assert isinstance(doc["unexplained"], list)
    if not effects:
        assert doc["missing_effects"] == [] and doc["steps"] == []


@pytest.mark.parametrize("kind", KINDS)
def test_truth_data_round_trips_through_csv(kind, tmp_path):
    """The simulator writes the columns ``read_data`` expects (COLUMNS of the contract)."""
    data, _ = truth.make_case(kind, truth.GH_MODELS[0], (), 0)
    assert tuple(data) == COLUMNS[kind]
    path = tmp_path / f"{kind}.csv"
    table = np.column_stack([data[c] for c in COLUMNS[kind]])
    np.savetxt(path, table, delimiter=",", header=",".join(COLUMNS[kind]), comments="",
               fmt="%.17g")
    read = read_data(kind, path)
    for column in COLUMNS[kind]:
        np.testing.assert_array_equal(read[column], data[column])


# ======================================================================================
# the truth simulator's own physics (independent of the library)
# ======================================================================================

def test_truth_catalog_curve_follows_the_defining_slopes():
    """Twist T1/K1 at T1, T1/K1 + (T2 − T1)/K2 at T2, slopes K1 near zero and K3 above T2
    (052-1/060-1); the printed θ1, θ2 agree to their rounding (3 significant digits)."""
    model = resolve("CSF-32-100-GH", truth.default_catalog())
    t1, t2 = model.get("T1_Nm").value, model.get("T2_Nm").value
    k1, k2 = model.get("K1_Nm_per_rad").value, model.get("K2_Nm_per_rad").value
    theta = truth.catalog_twist(np.array([t1, t2, -t1]), model)
    np.testing.assert_allclose(theta, [t1 / k1, t1 / k1 + (t2 - t1) / k2, -t1 / k1], rtol=1e-6)
    np.testing.assert_allclose(theta[:2], [model.get("theta1_rad").value,
                                           model.get("theta2_rad").value], rtol=0.03)
    d = 1e-3                                   # N·m: inside the segment
    slope1 = (truth.catalog_twist(np.array([0.5 * t1 + d]), model)
              - truth.catalog_twist(np.array([0.5 * t1]), model))[0] / d
    slope3 = (truth.catalog_twist(np.array([1.2 * t2 + d]), model)
              - truth.catalog_twist(np.array([1.2 * t2]), model))[0] / d
    assert slope1 == pytest.approx(1 / model.get("K1_Nm_per_rad").value, rel=1e-4)
    assert slope3 == pytest.approx(1 / model.get("K3_Nm_per_rad").value, rel=1e-4)


def test_truth_hysteresis_loop_orientation_and_loss():
    """Unloading from +T0 leaves a positive twist at T = 0 (B, seed 000 p.020), and the loop
    width at zero torque of a ±rated cycle equals the drawn loss; smaller cycles lose less
    ("almost none at very small torque", seed 000 p.020). Masing: the loop closes at ±T0
    on the backbone."""
    model = resolve("CSF-32-100-GH", truth.default_catalog())
    tr = truth.rated_torque(model)
    t_y, alpha_ro, r = 0.15 * tr, 1.0, 2.5
    loss = 2.9e-4                              # gh_hysteresis, CSF-GH ratio ≥ 80
    amplitude = loss / truth.masing_loss(tr, t_y, alpha_ro, r)

    def width(t0):
        path = truth.torque_path(t0, 2, 8001)
        twist = -amplitude * truth.masing_state(path, t_y, alpha_ro, r)
        half = slice(len(path) // 2, None)     # second cycle: steady loop
        t, w = path[half], twist[half]
        going_down = np.diff(t) < 0
        cross = np.where(np.diff(np.sign(t)) != 0)[0]
        down = [np.interp(0.0, t[i:i + 2][::-1], w[i:i + 2][::-1]) for i in cross
                if going_down[i]]
        up = [np.interp(0.0, t[i:i + 2], w[i:i + 2]) for i in cross if not going_down[i]]
        return down[0] - up[0]

    assert width(tr) == pytest.approx(loss, rel=1e-3)
    assert 0 < width(0.1 * tr) < 0.5 * loss
    path = truth.torque_path(tr, 2, 8001)
    u = truth.masing_state(path, t_y, alpha_ro, r)
    tip = truth.ramberg_osgood_backbone(np.array([tr]), t_y, alpha_ro, r)[0]
    assert u.max() == pytest.approx(tip, rel=1e-6) and u.min() == pytest.approx(-tip, rel=1e-6)


def test_truth_backlash_lost_motion_equals_width():
    """The dead zone adds ±b/2 once the play has closed and nothing at zero torque."""
    b, t_half = 3.4e-5, 1.0                   # gh_backlash CSF-GH 32-100; 1 N·m rounding
    twist = truth.smoothed_dead_zone_twist(np.array([-100.0, -1e-9, 0.0, 1e-9, 100.0]),
                                           b, t_half)
    assert twist[-1] - twist[0] == pytest.approx(b, rel=1e-3)
    assert abs(twist[2]) < 1e-12
    assert np.all(np.diff(twist) >= -1e-15)


def test_truth_low_load_factor_matches_catalog_point():
    """Ke(0.58) of the truth equals the catalog point (ke_curve, graph 023-1) at the
    example's 1000 r/min; Ke = 1 from rated torque up; a faster input drags more, so the
    low-load drop grows with speed (seed 000 p.023: efficiency depends on speed)."""
    row = truth.default_catalog().find("ke_curve", series="CSF", alpha=0.58)
    alpha = np.array([0.58, 1.0, 1.2, 0.1, 0.58])
    speed = np.array([1000.0, 1000.0, 1000.0, 1000.0, 3000.0])
    ke, info = truth.palmgren_load_factor(alpha, speed, row["Ke"], 0.78, 0.6, 0.3)
    assert ke[0] == pytest.approx(row["Ke"], rel=1e-12)
    assert info["ke_at_0.58_1000rpm"] == pytest.approx(row["Ke"], rel=1e-12)
    assert 0 < info["drag_share_at_1000rpm"] < 1 and info["coulomb_loss"] > 0
    assert ke[1] == 1.0 and ke[2] == 1.0 and ke[3] < ke[0]
    assert ke[4] < ke[0]


def test_truth_vogel_viscosity_is_vg68_like_and_warm_oil_loses_less():
    """ν(40 °C), ν(100 °C) are met; ν falls faster than exponentially near 0 °C (Vogel's
    curvature); η rises with temperature and equals η0 at 20 °C (seed 000 p.023)."""
    nu = truth.vogel_viscosity(np.array([0.0, 20.0, 40.0, 100.0]), 68.0, 8.8, 95.0)
    assert nu[2] == pytest.approx(68.0, rel=1e-12) and nu[3] == pytest.approx(8.8, rel=1e-12)
    assert math.log(nu[0] / nu[1]) > math.log(nu[1] / nu[2])
    f = truth.vogel_temperature_factor(np.array([0.0, 20.0, 40.0]), 0.78, 0.5, 68.0, 8.8,
                                       95.0, 2.0 / 3.0)
    assert f[1] == pytest.approx(1.0, abs=1e-12) and f[0] < f[1] < f[2]


def test_truth_vibration_resonates_near_the_catalog_formula():
    """The envelope of a te_2x run-up peaks near N = f/2·60, f = √(K/J)/2π (seed 000
    p.021); a swept resonance peaks a little late, so ±15 %."""
    data, hidden = truth.make_case("vibration", "CSF-32-100-GH", ("te_2x",), 1)
    k, j = hidden["stiffness_Nm_per_rad"], hidden["load_inertia_kgm2"]
    n_res = math.sqrt(k / j) / (2 * math.pi) / 2 * 60
    y = data["output_vibration_rad"]
    envelope = np.convolve(y * y, np.ones(200) / 200, mode="same")
    peak = data["input_speed_rpm"][np.argmax(envelope)]
    assert peak == pytest.approx(n_res, rel=0.15)


def test_truth_noise_has_the_stated_rms():
    noise, info = truth.coloured_noise(20000, 3e-6, np.random.default_rng(7))
    assert truth.rms(noise) == pytest.approx(3e-6, rel=1e-12)
    lag1 = np.corrcoef(noise[1:], noise[:-1])[0, 1]
    # AR(1) share s with coefficient φ: lag-1 correlation s·φ (white part uncorrelated).
    assert lag1 == pytest.approx(info["coloured_share"] * info["ar1_coefficient"], abs=0.03)
