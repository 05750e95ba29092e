"""How reconcile picks between readings: an ambiguous second effect is left unnamed, a
hysteresis + housing spring pair that reads the same as one slip element in series says so,
and a backlash taken up over a wide torque band is weighed against a stiffening spring.

The Preisach cases come from suite C (``truths/truth_c.py``), written by a helper from the
contract only: a weighted sum of relays (Mayergoyz 1986) whose output adds to the gear's
twist, so the loop carries its own slip compliance. Friction in parallel (Bouc–Wen) plus a
spring of compliance z_sat/T_s is term for term that series element; reconcile fits the pair
with a spring equal to the loop's z_sat/T_s (to 2 %, seed 7), so both readings are reported.
The Bouc–Wen + housing pair of suite B (``truths/truth_b.py``, the session's shared sample
``truth_runs``) has a spring of its own: no series reading.
"""

from __future__ import annotations

import pytest
from truth_runs import bench, case_run, named_case, suite_cases, suite_path

from hdcad.reconcile.search import Candidate, Gate, _unless_ambiguous, ambiguous_second


def _cand(effects, dbic, passes=True):
    return Candidate(tuple(effects), fit=None, gate=Gate(dbic, 0.5, 10.0, 0.9), passes=passes)


def test_a_second_that_a_rival_explains_about_as_well_is_not_named():
    single = _cand(["hysteresis"], 800.0)
    best = _cand(["hysteresis", "housing_compliance"], 1000.0)
    rival = _cand(["hysteresis", "backlash"], 960.0)         # within 5 % of the best
    passing = [single, best, rival]
    assert ambiguous_second(best, passing) == ("hysteresis", ("housing_compliance",
                                                              "backlash"))
    chosen = _unless_ambiguous(best, passing)
    assert chosen.effects == ("hysteresis",)
    assert chosen.undecided == ("housing_compliance", "backlash")


def test_a_clearly_better_second_or_a_failing_rival_keeps_the_pair():
    single = _cand(["hysteresis"], 800.0)
    best = _cand(["hysteresis", "housing_compliance"], 1000.0)
    for rival in (_cand(["hysteresis", "backlash"], 900.0),):   # 10 % below: decided
        assert _unless_ambiguous(best, [single, best, rival]) is best
    # a rival pair that does not pass its gates is not in the passing list
    assert _unless_ambiguous(best, [single, best]) is best
    # the shared member must pass alone to fall back to it
    rival = _cand(["hysteresis", "backlash"], 990.0)
    assert _unless_ambiguous(best, [best, rival]) is best


def _preisach_cases():
    """Suite C's Preisach singles at seed 7, 2 per cell (the shared sample has one)."""
    return [c for c in suite_cases(suite_path("c"), 7, 2)
            if c.kind == "torsion" and c.category == "single" and "preisach" in c.name]


def _series_reading(result) -> bool:
    return any(r.get("reading") == "series_slip" for r in result["equivalent_readings"])


@pytest.mark.parametrize("index", [0, 1])
def test_preisach_loop_is_named_as_one_series_slip_element(index):
    """A Preisach loop adds its slip to the gear's twist: the hysteresis + housing spring
    pair fits it with the spring at the loop's own slip compliance, so the simpler reading
    (one hysteresis, in series) is named and the pair is reported as the other reading."""
    cases = _preisach_cases()
    assert len(cases) == 2
    result = bench.reconcile_case(cases[index])
    assert result["missing_effects"] == ["hysteresis"]
    assert _series_reading(result)
    reading = next(r for r in result["equivalent_readings"] if r.get("reading") == "series_slip")
    assert reading["alternative"] == ["hysteresis", "housing_compliance"]
    assert result["rmse_after"] <= 1.2 * cases[index].noise_rms


def test_a_housing_spring_of_its_own_gets_no_series_reading():
    _, result = case_run("b", "b-torsion-pair-hysteresis+housing_compliance-boucwen1-000")
    assert set(result["missing_effects"]) == {"hysteresis", "housing_compliance"}
    assert not _series_reading(result)


def test_a_spring_that_takes_the_gear_beyond_its_spread_is_named_beside_a_backlash():
    """Suite J's keyed shaft in a press fit (Volkersen shear lag, 13 % of the gear's
    compliance) beside a thermal-clearance play, seed 11: with the play alone the gear reads
    11.6 % softer than the catalog, beyond its ±10 % spread; the spring adds ΔBIC 114 but
    only a sliver of what the play leaves once the scale sits at its bound, so the share
    rule had dropped it. The spring is named, and the report still says that a gear that
    much softer reads the same."""
    case, result = case_run(
        "j", "j-torsion-pair-backlash-housing_compliance-thermalclearance-shearlag-000")
    assert set(result["missing_effects"]) == set(case.gear_effects) == {"backlash",
                                                                         "housing_compliance"}
    stiffness = next(n for n in result["nuisances"] if n["name"] == "stiffness_scale")
    assert not stiffness["within_spread"]
    assert any(r.get("nuisance") == "stiffness_scale" for r in result["equivalent_readings"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms


@pytest.mark.parametrize("suite,name", [
    ("k", "k-torsion-pair-backlash-housing-compliance-gravity-biased-oldham-tolerance-ring-000"),
    ("k", "k-torsion-pair-backlash-housing-compliance-lognormal-engagement-vlasov-bracket-000"),
    ("j", "j-torsion-pair-backlash-housing_compliance-thermalclearance-shearlag-001"),
])
def test_a_linear_spring_beside_a_backlash_is_named_by_its_shape(suite, name):
    """Backlash + linear housing spring pairs of suites K and J (seed 7, 2 per cell) whose
    gear, with the backlash alone, reads inside the stiffness spread: the spring adds
    ΔBIC 42–78 over the backlash but explains only 0.04–0.06 noise variances, under the
    0.1 a first effect must explain, so only the backlash was named. A spring adds the same
    compliance at every torque and the scale adds in proportion to the gear's, a shape the
    clean cases never took (ΔBIC ≤ 7.2): the spring is named, within 1.2σ."""
    case = named_case(suite, name, 7)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["backlash", "housing_compliance"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    assert _softer_gear_reading(result)


def _softer_gear_reading(result, within: bool = True) -> bool:
    """The other reading of a named spring: a softer gear; inside the spread, told from the
    spring only by its shape."""
    return any(r.get("nuisance") == "stiffness_scale"
               and ("told apart only by how the compliance runs" in r["text"]) == within
               for r in result["equivalent_readings"])


@pytest.mark.parametrize("suite,name,within", [
    ("b", "b-torsion-single-housing_compliance-series-000", True),   # ΔBIC 25, 0.049 variances
    ("h", "h-torsion-single-housing-bredt-002", False),              # ΔBIC 138, 0.056 variances
])
def test_a_linear_spring_alone_is_named_by_its_shape(suite, name, within):
    """Housing-spring singles of suites B and H (seed 7, 2 per cell; without the spring the
    gear reads 6.5 % and 10.6 % softer, the scale held at its 10 % spread): the spring lowers
    the BIC by 25 and 138 over the scale but explains only about 0.05 noise variances, and
    nothing was named. Named by its shape now, with the softer gear given as the other
    reading (inside the spread: told from the spring only by its shape); clean cases never
    gave that shape ΔBIC above 7.2."""
    case = named_case(suite, name, 7)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["housing_compliance"]
    assert _softer_gear_reading(result, within)
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_a_spring_is_named_by_its_shape_only_alone_or_beside_a_backlash():
    """The rule itself: ΔBIC > 10 and a cross-validated error that falls, for a housing
    spring alone or beside a backlash; not beside a loop (whose backbone a spring stands in
    for), not for another effect, not at ΔBIC 10 or a CV error that does not fall."""
    from hdcad.reconcile.springs import by_its_shape
    small = Gate(delta_bic=11.0, cv_gain=0.003, explained=0.03, share=1.0)
    assert by_its_shape("housing_compliance", None, small)
    assert by_its_shape("housing_compliance", "backlash", small)
    assert not by_its_shape("housing_compliance", "hysteresis", small)
    assert not by_its_shape("backlash", "housing_compliance", small)
    assert not by_its_shape("housing_compliance", "backlash",
                            Gate(delta_bic=10.0, cv_gain=0.003, explained=0.03, share=1.0))
    assert not by_its_shape("housing_compliance", "backlash",
                            Gate(delta_bic=40.0, cv_gain=0.0, explained=0.03, share=1.0))


@pytest.mark.parametrize("suite,name,named", [
    ("l", "l-torsion-single-backlash-twolock-000", ["backlash"]),       # the spring: ΔBIC −2.0
    ("k", "k-torsion-single-backlash-wear-grown-001", ["backlash"]),    # ΔBIC 8.8
    # the known wrong second: a quintic dead zone preloaded by a slider's weight, beside which
    # a spring lowers the BIC by 11.2 (the rule's cost, measured)
    ("k", "k-torsion-single-backlash-gravity-biased-oldham-001", ["backlash", "housing_compliance"]),
])
def test_a_backlash_single_s_spring_follows_the_rule(suite, name, named):
    """Backlash singles (seed 7, 2 per cell): a linear spring beside them lowers the BIC by
    less than 10 and is not named, or by 11.2 and is (a wrong second the rule accepts)."""
    result = bench.reconcile_case(named_case(suite, name, 7))
    assert result["missing_effects"] == named


def test_a_modulated_first_error_does_not_hide_a_second_harmonic():
    """Suite C's AM + AM transmission pair (seed 7): at the naming order te_1x leaves its
    own modulation (4σ), and te_2x explains too little of that to pass the share rule.
    Against te_1x with its modulation followed (order by BIC) te_2x still earns its place:
    both named, and the residual at the noise (1.2σ, the suites' acceptance bar)."""
    case = named_case("c", "c-transmission-pair-te1xte2x-amam-000", 7)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["te_1x", "te_2x"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def _stiffening_reading(result) -> bool:
    return any(r.get("reading") == "progressive_spring" for r in result["equivalent_readings"])


@pytest.mark.parametrize("index", [0, 1])
def test_a_stiffening_housing_spring_is_not_read_as_backlash(index):
    """Suite C's cubic housing spring (k1·θ + k3·θ³ = T, its low-torque stiffness 0.3–0.6 of
    its secant at T0) fits a tanh backlash only with the width at 0.25–0.3·T0: a clearance
    still closing at half the largest torque, against the catalog's lost motion at ±3 % load
    (FD table 314-1). Weighed against a spring that stiffens, it is the housing spring (with
    its knee torque), and the backlash is printed as the other reading. Both cases were
    named backlash before."""
    case = named_case("c", f"c-torsion-single-housingcompliance-cubic-00{index}", 7)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["housing_compliance"]
    assert _stiffening_reading(result)
    params = result["steps"][0]["params"]
    assert params["K_h_at_T0"]["value"] > params["K_h"]["value"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_a_backlash_named_alone_is_weighed_against_a_stiffening_spring_at_any_width():
    """Suite C's cubic housing spring in the test sample (seed 11, 1 per cell) fits a tanh
    backlash of width 0.12·T0, under the 0.2·T0 past which a backlash beside another effect
    is weighed against a spring that stiffens; it was named backlash. A backlash named
    alone is weighed at any width: here the spring fits better (the backlash's ΔBIC over it
    −20), while suite C's sharp tanh single keeps its backlash by ΔBIC 671 and suite B's
    (below) gets no spring reading."""
    case, result = case_run("c", "c-torsion-single-housingcompliance-cubic-000")
    assert result["missing_effects"] == ["housing_compliance"]
    assert _stiffening_reading(result)
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_a_stiffening_spring_behind_a_sharp_backlash_is_named_second():
    """Suite C's tanh backlash + cubic housing pair (seed 11): a stiffening spring adds
    ΔBIC ≈ 80–140 over the backlash and passes every gate, so it is named with its knee
    torque (a linear spring beside the backlash is weighed against it when that passes by
    its shape only); it was named backlash alone before."""
    case = named_case("c", "c-torsion-pair-backlashhousingcompliance-tanhcubic-000", 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["backlash", "housing_compliance"]
    assert "T_k" in result["steps"][1]["params"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_a_sharp_backlash_gets_no_stiffening_spring():
    """Suite B's tanh backlash (width 0.5–3 % of T0) is taken up inside the catalog's
    lost-motion load: named alone, no spring reading, the housing spring stays linear."""
    _, result = case_run("b", "b-torsion-single-backlash-tanh-000")
    assert result["missing_effects"] == ["backlash"]
    assert not _stiffening_reading(result)
    assert "T_k" not in result["steps"][0]["params"]


def test_a_spring_whose_knee_goes_to_its_floor_stays_a_backlash():
    """Suite B's Dahl loop + tanh dead zone (seed 11, 1 per cell; the dead zone 86 % closed
    at 3 % of T0): beside the loop the backlash's width went past 0.2·T0 and the pair was
    read as a loop + stiffening spring, with the spring's knee at its floor 0.1·T0, as
    steep as the spring may stiffen (1.19σ). A knee at its floor is a clearance's step:
    the backlash stays, both are named, within 1.2σ, with no spring reading."""
    case, result = case_run("b", "b-torsion-pair-hysteresis+backlash-dahl-000")
    assert set(result["missing_effects"]) == {"hysteresis", "backlash"}
    assert not _stiffening_reading(result)
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_a_low_load_factor_is_not_named_for_the_viscosity_law_s_shape():
    """Suite E's Andrade–Palmgren temperature single (seed 11, 2 per cell): Reynolds'
    exponential names the temperature dependence and leaves the curvature of Andrade's law,
    which a low-load factor took as a second effect. Against the temperature law with its
    best viscosity law the factor adds too little: the temperature dependence alone."""
    case = named_case("e", "e-efficiency-single-temperature_dependence-andrade-palmgren-091",
                      11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["temperature_dependence"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_a_loop_through_the_gear_beside_a_spring_of_its_own_keeps_the_pair():
    """Suite E's Jiles–Atherton loop with a tapered-bearing housing (seed 11, 2 per cell):
    with the loop at constant width the free spring adds nothing over one slip element in
    series (ΔBIC −5.6), but with the loop narrowing where the gear stiffens (its width × the
    catalog curve's local compliance) the pair beats the series element by ΔBIC 84: the
    spring is the housing's own and both are named."""
    case = named_case("e", "e-torsion-pair-hysteresis+housing_compliance-jiles-atherton-"
                           "tapered-preload-025", 11)
    result = bench.reconcile_case(case)
    assert set(result["missing_effects"]) == {"hysteresis", "housing_compliance"}
    assert not _series_reading(result)
    assert result["rmse_after"] <= 1.2 * case.noise_rms


@pytest.mark.parametrize("suite,name,named", [
    # Roelands viscosity, churning loss ∝ (ν·n)^a at every temperature: the efficiency at
    # 20 °C falls with speed; without the speed nuisance the grid-ordered residual read as
    # noise 2.8× and 5× too large (τ 21 and 11) and nothing was named
    ("f", "f-efficiency-single-temperature_dependence-roelands-churning-mult-112",
     ["temperature_dependence"]),
    ("f", "f-efficiency-single-temperature_dependence-roelands-churning-mult-113",
     ["temperature_dependence"]),
    # Andrade–Palmgren single: the speed that the law leaves was taken by a low-load second
    ("e", "e-efficiency-single-temperature_dependence-andrade-palmgren-090",
     ["temperature_dependence"]),
])
def test_an_efficiency_level_that_changes_with_speed_is_the_catalog_s_nuisance(suite, name,
                                                                               named):
    """The catalog's efficiency curves are given per input speed (seed 000 p.023): a level
    that changes with speed belongs to the baseline, so a temperature law is named for the
    temperature and a low-load factor for the load (seed 11, 2 per cell)."""
    case = named_case(suite, name, 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == named
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    assert any(n["name"] == "efficiency_speed" for n in result["nuisances"])


@pytest.mark.parametrize("suite,name", [
    # Valanis endochronic loop: the housing spring added ΔBIC 149 beside the constant-width
    # loop, −100 … 0 beside the loop through the gear's compliance
    ("f", "f-torsion-single-hysteresis-valanis-endochronic-012"),
    # Coleman–Hodgdon (Duhem) loop, its width × the local compliance: ΔBIC 606 and 35
    ("e", "e-torsion-single-hysteresis-coleman-hodgdon-007"),
])
def test_a_spring_that_stands_in_for_the_loop_s_narrowing_is_not_named(suite, name):
    """A hysteresis single (seed 11, 2 per cell) whose loop narrows where the gear stiffens:
    beside a loop of constant width a linear housing spring took part of that narrowing and
    was named second; it adds too little beside the loop through the gear's compliance, so
    only the hysteresis is named (suites E and F: wrong second names 7 → 0 at seeds 7 and
    11; at seed 13, kept out of the choice, C 3 → 2, E 2 → 0, F 4 → 1)."""
    case = named_case(suite, name, 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["hysteresis"]
    assert any("the loop's own narrowing" in note for note in result["notes"])


def test_a_temperature_that_rose_with_test_time_gives_the_drift_reading_too():
    """Suite F's Reynolds temperature single (seed 7, 2 per cell) ran its temperatures in test
    order (correlation with time 0.97): the temperature law and a drift of the rig with
    time fit it alike (ΔBIC 96.6 against 96.1 with a linear + quadratic drift; with the
    drift as a steady drift plus a first-order warm-up, the fits' stopping tolerance decides
    which is the larger, 1e-5 naming the law and 1e-4 the drift). Whichever is named, the
    report gives the other as its reading: the data cannot tell them apart."""
    case = named_case("f", "f-efficiency-single-temperature_dependence-reynolds-mult-117", 7)
    result = bench.reconcile_case(case)
    named = result["missing_effects"] + [m["effect"] for m in result["measurement_effects"]]
    assert named in (["temperature_dependence"], ["thermal_drift"])
    assert any("temperature_dependence" in r.get("effects", [])
               and r.get("measurement") == "thermal_drift"
               for r in result["equivalent_readings"])


@pytest.mark.parametrize("name", [
    # Everett-function Preisach loops about the catalog curve: named with a housing spring
    # second at 2.0 and 2.8× the noise before
    "g-torsion-single-hysteresis-everett-preisach-triangular-000",
    "g-torsion-single-hysteresis-everett-preisach-triangular-001",
    # a Krasnosel'skii–Pokrovskii loop: named with a backlash second before
    "g-torsion-single-hysteresis-kp-triangular-001",
])
def test_a_loop_about_the_catalog_curve_gets_no_second_name(name):
    """Suite G draws its loops about the catalog curve (the loop's centre line taken out: the
    catalog's curve is the mean of loading and unloading). A loop with its own backbone then
    needs a spring or a play to undo that backbone; the loop about the curve does not
    (seed 11, 2 per cell). The loop's final form (Bouc–Wen or, where BIC prefers them, a
    Preisach relay sum or a sum of friction elements) is drawn about the curve, and the
    notes say so."""
    case = named_case("g", name, 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["hysteresis"]
    assert any("a loop about the catalog curve" in note
               or (note.startswith("hysteresis: a ") and "about the catalog curve" in note)
               for note in result["notes"])


@pytest.mark.parametrize("name", ["i-torsion-clean-clean-ar1-000",
                                  "i-torsion-clean-clean-ar1-001"])
def test_a_curve_through_the_printed_theta_values_is_clean(name):
    """Suite I draws the catalog curve through the printed θ1, θ2 (as seed 000 p.020's worked
    example does), not T1/K1 and on (seed 11, 2 per cell). Against the T/K curve alone these
    clean records were named housing_compliance; the printed reading is a nuisance of the
    catalog, fitted and reported as such."""
    case = named_case("i", name, 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == []
    printed = {n["name"]: n["value"] for n in result["nuisances"]}["printed_reading"]
    assert printed > 0.5


def test_the_effect_that_explains_most_alone_is_named_first():
    """A pair is reported with the effect that alone explains the most (ΔBIC against the
    baseline) first, whatever way the search reached it. Suite I's back-driven play beside a
    bolt-circle spring (seed 7) is reached through a named play read again as a stiffening
    spring, which kept the play's place: the spring came first, with ΔBIC 0 alone (it
    explains nothing without the loop), and the loop alone gains ΔBIC 23."""
    from hdcad.catalog import load_catalog
    from hdcad.models import resolve_gear
    from hdcad.reconcile import reconcile, validate_data

    case = named_case("i", "i-torsion-pair-backlash-housing-compliance-backdrive-held-play-"
                           "huth-bolt-circle-001", 7)
    catalog = load_catalog()
    result = reconcile(case.kind, validate_data(case.kind, case.columns),
                       resolve_gear(case.model, catalog)[0], catalog)
    alone = {row["effect"]: row["delta_bic"] for row in result.candidates[-1]
             if "+" not in row["effect"]}
    gains = [alone[effect] for effect in result.missing_effects]
    assert len(gains) == 2 and gains == sorted(gains, reverse=True)
    assert result.steps[0].criterion_gain == pytest.approx(gains[0])
