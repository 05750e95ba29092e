"""The named model's final form (:mod:`hdcad.reconcile.refine`): the viscosity law and the
temperature law's speed term, checked against the formulas they come from and on truth
suites written without reading hdcad/reconcile (``truths/``)."""

from __future__ import annotations

import re

import numpy as np
import pytest
from truth_runs import bench, case_run, named_case

from hdcad.reconcile import efficiency_laws as laws


def test_viscosity_laws_are_andrade_and_vogel_with_their_slope_at_the_reference():
    """ν ∝ exp(B/(t + C)): the ratio to t_ref with slope b = B/(t_ref + C)² is the law
    itself (Andrade 1930 with C = 273.15; Vogel 1921 with Cameron's C = 95 °C), and C → ∞
    is Reynolds' exponential."""
    t = np.array([0.0, 20.0, 45.0, 80.0])
    for C in (273.15, 95.0):
        B = 4000.0
        law = np.exp(B * (1 / (t + C) - 1 / (20.0 + C)))
        b = B / (20.0 + C) ** 2
        assert laws.viscosity_ratio(t, b, 20.0, C) == pytest.approx(law, rel=1e-12)
    assert laws.viscosity_ratio(t, 0.03, 20.0) == pytest.approx(np.exp(-0.03 * (t - 20.0)))


def test_speed_loss_moves_the_efficiency_at_the_reference_temperature_only_with_speed():
    speed = np.array([500.0, 1000.0, 2000.0])
    t = np.full(3, laws.REFERENCE_TEMPERATURE_C)
    plain = laws.temperature_factor(t, 0.2, 0.03, laws.REFERENCE_TEMPERATURE_C, speed, s=0.5)
    assert plain == pytest.approx(1.0)
    grown = laws.temperature_factor(t, 0.2, 0.03, laws.REFERENCE_TEMPERATURE_C, speed, s=0.5,
                                  speed_loss=0.1)
    assert grown[1] == pytest.approx(1.0)            # n_ref: the reference point
    assert grown[0] > 1.0 > grown[2]                 # less loss slower, more faster


@pytest.mark.parametrize("name", [
    # Stribeck–Hersey friction over the film parameter Λ ∝ (ν·n)^0.7, referred to 40 °C and
    # 2000 r/min
    "e-efficiency-single-temperature_dependence-stribeck-hersey-046",
    # Andrade viscosity, loss ∝ (ν·n)^(2/3) referred to the same point, with a clamped
    # hyperbolic low-load factor
    "e-efficiency-pair-low_load_efficiency+temperature_dependence-hyperbolic-clamped-"
    "andrade-palmgren-047",
])
def test_a_law_referred_to_one_point_is_followed_to_the_noise(name):
    """Suite E puts the viscous loss's reference at one temperature and one speed, so its
    efficiency at hdcad's t_ref still changes with speed; with the speed followed (the
    baseline's efficiency level per speed, and the law's own speed term where BIC asks for
    it) the fit leaves ≤ 1.2× the suite's noise (seed 7, with neither: 3.35× and 2.32× the
    noise on the suite's two Andrade cases; now 0.99× and 0.97×)."""
    case, result = case_run("e", name)
    assert set(case.gear_effects) <= set(result["missing_effects"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    assert any(n["name"] == "efficiency_speed" for n in result["nuisances"])
    assert any(note.startswith("viscosity law:") for note in result["notes"])


@pytest.mark.parametrize("suite,name,keeps_viscosity", [
    # an EP additive's film that activates over a few kelvin (suite L; 2.73σ left at its
    # held-out score with the viscosity laws alone)
    ("l", "l-efficiency-single-temp-ep-000", False),
    # Andrade viscous drag: a viscosity law, no band
    ("b", "b-efficiency-single-temperature_dependence-viscous-000", True),
])
def test_a_loss_that_steps_over_a_band_of_temperature_is_followed(suite, name,
                                                                  keeps_viscosity):
    """A loss that changes over a band of temperature takes the band's form in place of the
    viscosity law when BIC prefers it, and a viscous law keeps its viscosity law."""
    case, result = case_run(suite, name)
    assert result["missing_effects"] == ["temperature_dependence"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    banded = any("band of temperature" in note for note in result["notes"])
    assert banded is not keeps_viscosity


def test_a_low_load_curve_flat_at_rated_torque_takes_the_flat_shape():
    """Suite B's Ke power curve, Ke = 1 − a·(1 − α)^p with p 1.2–2.5, reaches rated torque
    with no slope and stays finite at no load; the load-independent loss's shape left
    1.85σ on this pair (seed 11, 1 per cell; 0.99σ now), 1.64 and 3.23σ on the two at 2 per cell
    (1.00 and 1.01σ with the flat shape)."""
    case, result = case_run("b", "b-efficiency-pair-low_load_efficiency+"
                            "temperature_dependence-kepower-viscous-000")
    assert set(result["missing_effects"]) == {"low_load_efficiency", "temperature_dependence"}
    assert any(note.startswith("low-load factor: Ke = 1 − c/(1 + c)") for note in result["notes"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_an_outlier_hidden_by_the_effects_is_left_out_of_the_named_model():
    """Suite C's drag-torque low-load single (seed 11, 2 per cell) holds one gross outlier,
    9.8× its noise. On the baseline's residual the efficiency drop, in the grid's random run
    order, is as rough as noise to the neighbours and hides it; on the named model's
    residual it stands out and is left out (before: RMSE 1.65× the noise, 0.99× without
    that one row)."""
    case = named_case("c", "c-efficiency-single-lowloadefficiency-dragtorque-000", 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["low_load_efficiency"]
    assert result["outliers"] == 1
    assert any("left out of the named model's fit" in note for note in result["notes"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_a_drag_that_grows_with_viscosity_lowers_the_low_load_efficiency_of_a_cold_gear():
    """c_n × g^k: k = 0 is the drag independent of temperature; in a cold gear (g > 1) the
    no-load loss is larger, so Ke falls further; at α ≥ 1 Ke stays 1."""
    alpha = np.array([0.1, 0.5, 1.0])
    plain = laws.low_load_factor(alpha, 0.05, 1.0)
    assert laws.low_load_factor(alpha, 0.05, 1.0, viscosity=np.full(3, 3.0), k=0.0) == \
        pytest.approx(plain)
    cold = laws.low_load_factor(alpha, 0.05, 1.0, viscosity=np.full(3, 3.0), k=2 / 3)
    warm = laws.low_load_factor(alpha, 0.05, 1.0, viscosity=np.full(3, 0.5), k=2 / 3)
    assert cold[0] < plain[0] < warm[0] and cold[2] == warm[2] == 1.0
    # Palmgren's no-load torque ∝ ν^(2/3): c_n scales by 3^(2/3) in oil three times as thick
    c = 0.05 * 3.0 ** (2 / 3)
    assert cold[0] == pytest.approx(0.1 * (1 + c) / (0.1 + c))


@pytest.mark.parametrize("suite,seed,name", [
    # Palmgren's no-load torque ∝ (ν·n)^(2/3) with Roelands viscosity: 4.86× the noise left
    # with the two effects multiplied independently
    ("f", 7, "f-efficiency-pair-low_load_efficiency+temperature_dependence-palmgren-coupled-119"),
    # a drag torque with Vogel viscosity: 1.65× the noise before
    ("d", 11, "d-efficiency-pair-low_load_efficiency+temperature_dependence-drag-vogel-"
              "coupled-000"),
])
def test_a_low_load_drag_coupled_to_the_viscosity_is_followed_to_the_noise(suite, seed, name):
    """Suites D and F make the low-load drag a viscous loss (it grows as the oil thickens),
    so low-load and temperature effects do not multiply independently; with the drag × g^k
    (k chosen by BIC) the pair leaves ≤ 1.2× the noise (2 per cell)."""
    case = named_case(suite, name, seed)
    result = bench.reconcile_case(case)
    assert set(result["missing_effects"]) == set(case.gear_effects)
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    assert any("its drag grows with the oil's viscosity" in n for n in result["notes"])


def test_a_play_held_by_friction_is_crossed_past_its_holding_torque():
    """Backlash 0.2 mrad held by friction until the load passes ±6 N·m in the new direction
    (Karnopp's stuck side), on CSF-32-100-GH's catalog curve with noise 2 µrad: the backlash is
    named, the holding torque found within 10 % and the residual left at the noise."""
    from hdcad.catalog import load_catalog
    from hdcad.models import resolve
    from hdcad.reconcile import reconcile
    from hdcad.reconcile.baseline import catalog_twist, stiffness_curve
    catalog = load_catalog()
    model = resolve("CSF-32-100-GH", catalog)
    knots = [0.0, 137.0, -137.0, 137.0, -137.0, 0.0]
    torque = np.interp(np.linspace(0, 5, 1500), np.arange(6), knots)
    direction = np.sign(np.gradient(torque))
    sigma = 2e-6
    twist = (catalog_twist(stiffness_curve(model)[0], torque, 5.0)
             + 1e-4 * np.tanh((torque - 6.0 * direction) / 1.5)
             + sigma * np.random.default_rng(4).standard_normal(len(torque)))
    result = reconcile("torsion", {"torque_Nm": torque, "twist_rad": twist}, model, catalog)
    assert result.missing_effects == ["backlash"]
    note = next(n for n in result.notes if "held by friction" in n)
    held = float(note.split("passes ")[1].split(" N·m")[0])
    assert held == pytest.approx(6.0, rel=0.1)
    assert result.rmse_after == pytest.approx(sigma, rel=0.1)


def test_a_held_play_starts_where_the_last_handling_left_it():
    """The same held play (0.2 mrad, ±6 N·m), but the record starts with it at its centre,
    where friction keeps it until the load first passes +6 N·m (the first branch's form
    puts it at the unloading flank, 50 µrad = 25× the noise away): its start position is
    fitted, found within 10 µrad of the centre (5× the noise over the ~13 rows before the
    hold is passed), and the residual is left at the noise."""
    from hdcad.catalog import load_catalog
    from hdcad.models import resolve
    from hdcad.reconcile import reconcile
    from hdcad.reconcile.baseline import catalog_twist, stiffness_curve
    catalog = load_catalog()
    model = resolve("CSF-32-100-GH", catalog)
    knots = [0.0, 137.0, -137.0, 137.0, -137.0, 0.0]
    torque = np.interp(np.linspace(0, 5, 1500), np.arange(6), knots)
    direction = np.sign(np.gradient(torque))
    play = 1e-4 * np.tanh((torque - 6.0 * direction) / 1.5)
    play[:np.argmax(np.abs(torque) > 6.0)] = 0.0          # centred until first passed
    sigma = 2e-6
    twist = (catalog_twist(stiffness_curve(model)[0], torque, 5.0) + play
             + sigma * np.random.default_rng(4).standard_normal(len(torque)))
    result = reconcile("torsion", {"torque_Nm": torque, "twist_rad": twist}, model, catalog)
    assert result.missing_effects == ["backlash"]
    start = result.steps[0].params["start_position"]
    assert abs(start["value"]) < 1e-5 and start["unit"] == "rad"
    assert any("the record starts with the play at" in n for n in result.notes)
    assert "T − s·T_h − T_c in place of T" in result.steps[0].form    # the form as fitted
    assert "start position" in result.steps[0].form
    assert result.rmse_after == pytest.approx(sigma, rel=0.1)


@pytest.mark.parametrize("suite,seed,name,left", [
    # friction-held play: 2.16× the noise left by a play crossed at zero torque, now 1.02×
    ("e", 7, "e-torsion-single-backlash-friction-play-012", 1.2),
    # Karnopp stiction play, breakaway 1 N·m: 1.18× → 1.04×
    ("f", 11, "f-torsion-single-backlash-karnopp-stiction-play-023", 1.2),
    # breakaway 21.4 N·m, read as held to 7.3 N·m: 1.44× → 1.23× (the stuck play's release
    # is not the smooth crossing of this form)
    ("f", 11, "f-torsion-single-backlash-karnopp-stiction-play-022", 1.3),
])
def test_a_play_held_by_friction_in_the_truth_suites_is_followed_closer(suite, seed, name,
                                                                        left):
    """Suites E and F hold the play at one side by friction until the load passes a
    breakaway torque; with the holding torque fitted once backlash is named (kept by BIC) the
    single leaves the noise or close to it (2 per cell)."""
    case = named_case(suite, name, seed)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["backlash"]
    assert result["rmse_after"] <= left * case.noise_rms
    assert any("held by friction" in n for n in result["notes"])


@pytest.mark.parametrize("name,named", [
    ("k-torsion-single-backlash-gravity-biased-oldham-000", ["backlash"]),
    # beside a housing spring inside the stiffness scale's spread (named by its shape)
    ("k-torsion-pair-backlash-housing-compliance-gravity-biased-oldham-tolerance-ring-000",
     ["backlash", "housing_compliance"]),
])
def test_a_play_crossed_off_zero_torque_is_followed_to_the_noise(name, named):
    """Suite K's Oldham slider on a horizontal axis: its weight preloads one flank, so the
    clearance is crossed at ±(2–6 %)·T0, not at zero torque (seed 11, 1 per cell). A play
    crossed at zero left 1.92× and 1.51× the noise; with the crossing torque fitted once
    backlash is named (kept by BIC), 1.01× and 1.03× (1.00× once the pair's spring is
    named by its shape)."""
    case, result = case_run("k", name)
    assert result["missing_effects"] == named
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    assert any("not at zero torque" in n for n in result["notes"])


def _play_record(lost_motion, sigma=2e-6, seed=5, width=1.5, exponent=1.0):
    """CSF-32-100-GH's catalog curve cycled ±137 N·m eight times over 2400 rows, plus a play
    whose lost motion [rad] is ``lost_motion(u)`` along the record (u from −1 to 1), taken up
    as sign(T)·tanh(|T/width|^exponent) over ±``width`` N·m, and white noise ``sigma``."""
    from hdcad.catalog import load_catalog
    from hdcad.models import resolve
    from hdcad.reconcile.baseline import catalog_twist, stiffness_curve
    catalog = load_catalog()
    model = resolve("CSF-32-100-GH", catalog)
    knots = [0.0] + [137.0, -137.0] * 8 + [0.0]
    torque = np.interp(np.linspace(0, len(knots) - 1, 2400), np.arange(len(knots)), knots)
    u = np.linspace(-1.0, 1.0, len(torque))
    twist = (catalog_twist(stiffness_curve(model)[0], torque, 5.0)
             + 0.5 * lost_motion(u) * np.sign(torque) * np.tanh(np.abs(torque / width) ** exponent)
             + sigma * np.random.default_rng(seed).standard_normal(len(torque)))
    return {"torque_Nm": torque, "twist_rad": twist}, model, catalog


def _lost_motion_along(result, form):
    """(start, end) [rad] of the play's lost motion from its note, whose form names
    ``form`` ("Legendre order", "one step")."""
    note = next(n for n in result.notes if n.startswith("backlash: the lost motion"))
    assert form in note, note
    found = re.search(r"from ([-\d.e]+) rad at its start to ([-\d.e]+) rad", note)
    return float(found[1]), float(found[2])


@pytest.mark.parametrize("lost_motion,form", [
    (lambda u: 1.3e-4 + 0.3e-4 * u, "Legendre order"),              # worn over the test
    (lambda u: np.where(u < 0.0, 1.0e-4, 1.6e-4), "one step"),      # locked elsewhere
], ids=["worn", "relocked"])
def test_a_play_that_changes_along_the_record_is_followed(lost_motion, form):
    """A clearance that grows from 0.10 to 0.16 mrad over the test (wear, warmth) or steps
    between its halves (the input locked at another angle): backlash is named, its lost
    motion read at the record's ends within 10 % in the right form and the residual left at
    the noise (a lost motion constant along the record leaves 4.33× and 7.50× the noise
    here; with the drift and the step 1.00× both)."""
    from hdcad.reconcile import reconcile
    sigma = 2e-6
    result = reconcile("torsion", *_play_record(lost_motion, sigma))
    assert result.missing_effects == ["backlash"]
    assert _lost_motion_along(result, form) == pytest.approx((1.0e-4, 1.6e-4), rel=0.1)
    assert result.rmse_after <= 1.15 * sigma


def test_a_constant_play_is_not_given_a_drift():
    """The same record with the lost motion 0.13 mrad throughout: no drift and no step."""
    from hdcad.reconcile import reconcile
    result = reconcile("torsion", *_play_record(lambda u: 1.3e-4 + 0.0 * u))
    assert result.missing_effects == ["backlash"]
    assert not any(n.startswith("backlash: the lost motion") for n in result.notes)
    assert "engagement_exponent" not in result.steps[0].params      # taken up as a tanh


@pytest.mark.parametrize("exponent", [0.6, 2.5])
def test_a_play_taken_up_more_or_less_smoothly_gets_its_engagement_exponent(exponent):
    """A 0.13 mrad play taken up over ±3 N·m as tanh(|T/3|^p): p = 2.5 waits, then closes
    steeply (a slider held centred), p = 0.6 starts at once and closes slowly. Backlash
    alone is named, its exponent read within 10 %, its lost motion within 5 % and the
    residual left at the noise. The search takes a play up as a tanh; at p = 2.5 the misfit
    that leaves is taken by a linear housing spring beside it, which beside the play in its
    final form no longer earns its place and is dropped. Before the exponent: at p = 2.5 the
    play and the spring named, the lost motion 6 % high, 1.19× the noise left; at p = 0.6
    1.11× left. (At ±6 N·m a take-up with p = 0.6 is still closing at 10 % of the largest
    torque and a spring beside it keeps its place by its shape.)"""
    from hdcad.reconcile import reconcile
    sigma = 2e-6
    result = reconcile("torsion", *_play_record(lambda u: 1.3e-4 + 0.0 * u, sigma, width=3.0,
                                                exponent=exponent))
    assert result.missing_effects == ["backlash"]
    params = result.steps[0].params
    assert params["engagement_exponent"]["value"] == pytest.approx(exponent, rel=0.1)
    assert params["engagement_exponent"]["unit"] == "-"
    assert params["lost_motion"]["value"] == pytest.approx(1.3e-4, rel=0.05)
    assert "tanh(|T/T_w|^p)" in result.steps[0].form
    assert result.rmse_after <= 1.1 * sigma
    # rows the tanh missed before the exponent (13 at p = 2.5) were set aside as gross
    # outliers; the final form fits them, so they count in the RMSE again: no outlier left
    assert result.outliers == 0


@pytest.mark.parametrize("suite,name", [
    # a play taken up linearly across its gap torque: read as a clearance between 0.110 and
    # 0.125 mrad with Legendre terms of order 3
    ("e", "e-torsion-single-backlash-linear-gap-014"),
    # a play held by back-drive friction beside a Mindlin–Deresiewicz loop: its first
    # engagement read as a step at 2 % of the record, then as order 6
    ("i", "i-torsion-pair-hysteresis-backlash-mindlin-deresiewicz-backdrive-held-play-000"),
])
def test_a_play_constant_along_the_truth_suites_records_keeps_its_lost_motion(suite, name):
    """Plays whose clearance does not change over the test (seed 7, 2 per cell) keep one
    lost motion: the drift is at most a parabola and a step is looked for in the middle
    80 % of the record, where the play is crossed on either side of it."""
    result = bench.reconcile_case(named_case(suite, name, 7))
    assert "backlash" in result["missing_effects"]
    assert not any(n.startswith("backlash: the lost motion") for n in result["notes"])


@pytest.mark.parametrize("suite,name", [
    # wear per reversal: 1.69× → 1.04×
    ("k", "k-torsion-single-backlash-wear-grown-000"),
    # beside an Iwan loop: 1.32× → 0.99×
    ("k", "k-torsion-pair-hysteresis-backlash-iwan-powerlaw-wear-grown-000"),
    # two lock angles: 1.89× → 1.08×
    ("l", "l-torsion-single-backlash-twolock-000"),
])
def test_a_play_that_changes_along_the_truth_suites_records_is_followed(suite, name):
    """Suite K's clearance grows with every reversal and suite L's is seen through an input
    locked at two angles in turn (seed 11, 1 per cell). With a lost motion constant along
    the record they left the noise × the first number above; with its drift or step they
    come within 1.2×."""
    case, result = case_run(suite, name)
    assert "backlash" in result["missing_effects"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    assert any(n.startswith("backlash: the lost motion") for n in result["notes"])
