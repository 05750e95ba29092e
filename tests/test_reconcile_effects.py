"""Properties of the reconcile effect library, noise estimator and baseline.

Each test checks a physical property stated in the seeds or a closed-form result of the
model's own physics (Dahl's friction model, the linear joint's frequency response), not a
copy of the implementation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from hdcad.checks.run import stiffness_curve
from hdcad.checks.stiffness import natural_frequency, resonant_input_speed
from hdcad.models import resolve
from hdcad.reconcile import EFFECT_NAMES, EFFECTS, KINDS
from hdcad.reconcile import efficiency_laws as laws
from hdcad.reconcile import effects as fx
from hdcad.reconcile import joint, spring_forms
from hdcad.reconcile.baseline import catalog_twist
from hdcad.reconcile.noise import correlation_time, noise_model, noise_rms


def triangle(t0: float, cycles: int, rows: int) -> np.ndarray:
    """Quasi-static torque 0 → +T0 → −T0 … → 0 [N·m], evenly sampled along the path."""
    turns = [0.0, t0] + [-t0, t0] * cycles + [0.0]
    length = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(turns)))])
    return np.interp(np.linspace(0.0, length[-1], rows), length, turns)


def zero_crossing_width(torque: np.ndarray, twist: np.ndarray) -> float:
    """B − B′ of the last full cycle: twist at T = 0 after unloading from +T0 minus after
    unloading from −T0, by linear interpolation between samples."""
    down, up = [], []
    for i in range(len(torque) - 1):
        a, b = torque[i], torque[i + 1]
        if a > 0 >= b:
            down.append(twist[i] + (twist[i + 1] - twist[i]) * a / (a - b))
        elif a < 0 <= b:
            up.append(twist[i] + (twist[i + 1] - twist[i]) * a / (a - b))
    return down[-1] - up[-1]


# --------------------------------------------------------------------------- library
def test_library_has_the_issue_effects_with_sources_units_bounds_and_kinds():
    assert set(EFFECT_NAMES) <= set(EFFECTS)
    for name in EFFECT_NAMES:
        effect = EFFECTS[name]
        assert "seed 000 p.02" in effect.description, name   # pages 020/021/023
        assert effect.form and effect.kinds and set(effect.kinds) <= set(KINDS)
        for p in effect.parameters:
            assert p.unit and p.lower < p.upper, (name, p.name)
    # the kinds the issue names for each effect
    assert fx.applicable("torsion") == ("hysteresis", "backlash", "housing_compliance")
    assert set(fx.applicable("transmission")) == {"te_1x", "te_2x"}
    assert set(fx.applicable("vibration")) == {"te_1x", "te_2x"}
    assert set(fx.applicable("efficiency")) == {"low_load_efficiency", "temperature_dependence"}


# --------------------------------------------------------------------------- hysteresis
@pytest.mark.parametrize("t_s", [10.0, 30.0, 80.0])
def test_dahl_loop_width_matches_the_closed_form(t_s):
    """ρ = 1, n = 1 is Dahl's model dz/dT = (1 − z·sgn(dT))/T_s. Its steady ±T0 loop has the
    end state z_e = tanh(a), a = T0/T_s, and at T = 0 on the rising branch
    z = 1 − (1 + tanh a)·e^(−a); B − B′ = 2·z_sat·that (solved by hand from the ODE)."""
    t0, z_sat = 100.0, 2.9e-4             # gh_hysteresis CSF-GH ratio ≥ 80: 2.9×10⁻⁴ rad
    a = t0 / t_s
    expected = 2 * z_sat * (1 - (1 + math.tanh(a)) * math.exp(-a))
    assert fx.hysteresis_loss(z_sat, t_s, 1.0, 1.0, t0) == pytest.approx(expected, rel=1e-4)


@pytest.mark.parametrize("rho,n", [(0.0, 1.0), (0.6, 2.0), (1.0, 1.5)])
def test_stated_loss_equals_the_width_of_the_simulated_loop(rho, n):
    """The loss reported for a fit is the zero-torque width of the loop the form draws."""
    t0, t_s, z_sat = 120.0, 20.0, 1.5e-4
    torque = triangle(t0, 3, 12001)
    twist = -z_sat * fx.hysteresis_state(torque, t_s, rho, n)
    width = zero_crossing_width(torque, twist)
    assert width == pytest.approx(fx.hysteresis_loss(z_sat, t_s, rho, n, t0), rel=2e-3)


def test_hysteresis_loop_absorbs_energy_and_leaves_positive_twist_after_loading():
    """Seed 000 p.020: after loading to +T and back to zero a positive twist B remains; a
    friction loop dissipates energy: ∮T·dθ > 0 over a cycle."""
    torque = triangle(100.0, 2, 8001)
    twist = -1e-4 * fx.hysteresis_state(torque, 15.0, 0.7, 1.5)
    assert zero_crossing_width(torque, twist) > 0
    cycle = slice(len(torque) // 2 - 2000, len(torque) // 2 + 2000)  # one full cycle
    work = np.sum(0.5 * (torque[cycle][1:] + torque[cycle][:-1]) * np.diff(twist[cycle]))
    assert work > 0


def test_dahl_with_halved_first_branch_obeys_masing_rule():
    """Masing (1926): the first loading from the virgin state is the backbone and every later
    branch is the backbone doubled. For Dahl (ρ = n = 1) a branch from −1 is
    1 − 2·e^(−ΔT/T_s), so the backbone is 1 − e^(−2T/T_s): ``first_scale`` = 0.5."""
    t0, t_s = 100.0, 25.0
    torque = triangle(t0, 1, 4001)
    z = fx.hysteresis_state(torque, t_s, 1.0, 1.0, first_scale=0.5)
    first = slice(0, int(np.argmax(torque)) + 1)
    np.testing.assert_allclose(z[first], 1.0 - np.exp(-2.0 * torque[first] / t_s),
                               atol=2e-3)


def test_hysteresis_start_state_is_the_loading_history():
    """A gear already loaded to saturation (z0 = 1) twists no further hysteretically while
    loading on; from z0 = −1 it has the whole rising branch ahead."""
    torque = np.linspace(0.0, 50.0, 501)
    assert np.allclose(fx.hysteresis_state(torque, 10.0, 1.0, 1.0, z_start=1.0), 1.0)
    rising = fx.hysteresis_state(torque, 10.0, 1.0, 1.0, z_start=-1.0)
    assert rising[0] == -1.0 and np.all(np.diff(rising) >= 0) and rising[-1] > 0.9


def test_hysteresis_is_small_for_small_torque():
    """Seed 000 p.020: hysteresis loss is almost nil at very small torque."""
    big = fx.hysteresis_loss(1.0, 20.0, 0.5, 1.5, 100.0)
    small = fx.hysteresis_loss(1.0, 20.0, 0.5, 1.5, 1.0)
    assert small < 0.1 * big


# --------------------------------------------------------------------------- backlash etc.
def test_backlash_lost_motion_equals_its_parameter_and_is_direction_free():
    b, t_w = 4.4e-5, 0.5                  # gh_backlash CSF-GH 32/100: 4.4×10⁻⁵ rad
    far = fx.backlash_twist(np.array([-100.0, 100.0]), b, t_w)
    assert far[1] - far[0] == pytest.approx(b, rel=1e-9)
    t = np.linspace(-5, 5, 101)
    theta = fx.backlash_twist(t, b, t_w)
    np.testing.assert_allclose(theta, -theta[::-1])          # odd: no loading direction
    assert fx.backlash_twist(np.array([0.0]), b, t_w)[0] == 0.0
    assert np.all(np.diff(theta) > 0)


@pytest.mark.parametrize("p", [0.5, 1.0, 3.0])
def test_a_play_s_engagement_exponent_keeps_its_lost_motion_and_its_width(p):
    """(b/2)·sign(T)·tanh(|T/T_w|^p): odd, rising, the whole lost motion b far out and
    tanh(1)·b/2 at T = T_w whatever p; p = 1 is the plain tanh; p > 1 is flatter than it
    inside T_w and steeper past it, p < 1 the reverse."""
    b, t_w = 4.4e-5, 0.5
    t = np.linspace(-5, 5, 101)
    theta = fx.backlash_twist(t, b, t_w, p)
    np.testing.assert_allclose(theta, -theta[::-1])
    assert np.all(np.diff(theta) >= 0) and np.all(np.diff(theta[np.abs(t) <= 2 * t_w]) > 0)
    far = fx.backlash_twist(np.array([-100.0, 100.0]), b, t_w, p)
    assert far[1] - far[0] == pytest.approx(b, rel=1e-9)
    assert fx.backlash_twist(np.array([t_w]), b, t_w, p)[0] == pytest.approx(
        0.5 * b * np.tanh(1.0), rel=1e-12)
    plain = fx.backlash_twist(np.array([0.5 * t_w]), b, t_w)[0]
    inside = fx.backlash_twist(np.array([0.5 * t_w]), b, t_w, p)[0]
    assert (inside < plain) if p > 1 else (inside > plain) if p < 1 else inside == plain


def test_housing_compliance_is_a_spring_in_series():
    """An extra spring K_h in series with the gear's spring K: 1/K_total = 1/K + 1/K_h."""
    k, k_h = 148300.0, 5.0e5                # FD-32 spring constant (table 314-1)
    t = np.linspace(-150, 150, 7)
    total = t / k + spring_forms.compliance_twist(t, k_h)
    np.testing.assert_allclose(total, t / (1 / (1 / k + 1 / k_h)), rtol=1e-12)


def test_stiffening_spring_solves_its_cubic_and_is_linear_without_a_knee():
    """θ = (1/k)·T_k·u with u + u³ = T/T_k (Cardano): the cubic's residual is at rounding
    level, the low-torque compliance is 1/k, the secant stiffness at T = 10·T_k is
    (1 + u²)·k = 5·k (u³ + u = 10 → u = 2), and T_k = ∞ is the linear spring."""
    torque = np.linspace(-50.0, 50.0, 401)
    knee = 5.0
    u = spring_forms.progressive_twist(torque, knee) / knee
    assert np.max(np.abs(u + u ** 3 - torque / knee)) < 1e-12
    assert spring_forms.progressive_twist(np.array([1e-4]), knee)[0] == pytest.approx(1e-4, rel=1e-6)
    assert 50.0 / spring_forms.progressive_twist(np.array([50.0]), knee)[0] == pytest.approx(5.0)
    assert np.array_equal(spring_forms.progressive_twist(torque, math.inf), torque)


def test_te_2x_has_period_pi_and_te_1x_period_two_pi():
    """Seed 000 p.021: the main error component repeats twice per WG revolution."""
    phi = np.linspace(0, 4 * math.pi, 1001)
    two = fx.harmonic_error(phi, 2, 1e-4, 0.3)
    np.testing.assert_allclose(fx.harmonic_error(phi + math.pi, 2, 1e-4, 0.3), two, atol=1e-15)
    one = fx.harmonic_error(phi, 1, 1e-4, 0.3)
    assert np.max(np.abs(fx.harmonic_error(phi + math.pi, 1, 1e-4, 0.3) - one)) > 1e-4
    np.testing.assert_allclose(fx.harmonic_error(phi + 2 * math.pi, 1, 1e-4, 0.3), one,
                               atol=1e-15)


# --------------------------------------------------------------------------- vibration
@pytest.mark.parametrize("ratio_to_fn", [0.3, 0.9, 1.0, 1.5])
def test_joint_steady_amplitude_is_the_sdof_frequency_response(ratio_to_fn):
    """|θ/e| = 1/√((1 − r²)² + (2ζr)²) for J·θ'' + c·θ' + Kθ = K·e (textbook SDOF)."""
    k, j, zeta = 67000.0, 5.0, 0.05           # K1 of CSF-32-100-GH (table 060-1)
    fn = math.sqrt(k / j) / (2 * math.pi)
    f = ratio_to_fn * fn
    t = np.arange(0, 60 / (zeta * fn), 1 / (40 * max(f, fn)))   # ≫ decay time 1/(ζ·ω)
    theta = joint.joint_response(t, np.sin(2 * math.pi * f * t), k, j, zeta)
    tail = theta[len(t) * 3 // 4:]
    amplitude = 0.5 * (tail.max() - tail.min())
    r = ratio_to_fn
    assert amplitude == pytest.approx(1 / math.hypot(1 - r * r, 2 * zeta * r), rel=0.01)


def test_joint_starts_in_static_equilibrium_and_both_solvers_agree():
    k, j, zeta = 67000.0, 5.0, 0.05
    t = np.linspace(0, 2.0, 4001)
    e = 1e-4 * np.sin(2 * math.pi * 3.0 * t + 1.0)
    even = joint.joint_response(t, e, k, j, zeta)
    assert even[0] == pytest.approx(e[0], rel=1e-9)
    uneven_t = t.copy()
    uneven_t[1:-1] += 1e-5 * np.sin(np.arange(1, len(t) - 1))  # forces the lsim path
    uneven = joint.joint_response(uneven_t, e, k, j, zeta)
    assert np.max(np.abs(uneven - even)) < 0.01 * np.max(np.abs(even))


def test_te_2x_resonates_at_the_seed_input_speed():
    """Seed 000 p.021: f = 15 Hz resonates at N = 15/2·60 = 450 r/min input speed."""
    k = 67000.0
    j = k / (2 * math.pi * 15.0) ** 2
    assert resonant_input_speed(natural_frequency(k, j)) == pytest.approx(450.0)
    speeds = np.arange(350.0, 551.0, 10.0)
    amplitudes = []
    for n in speeds:
        t = np.arange(0, 4.0, 1e-3)
        phi = 2 * math.pi * n / 60 * t
        theta = joint.joint_response(t, fx.harmonic_error(phi, 2, 1.0, 0.0), k, j, 0.05)
        amplitudes.append(np.max(np.abs(theta[len(t) // 2:])))
    assert speeds[int(np.argmax(amplitudes))] == pytest.approx(450.0, abs=10.0)


# --------------------------------------------------------------------------- efficiency
def test_low_load_factor_meets_the_catalog_point_and_rule():
    """Graph 023-1: Ke(0.58) = 0.93 (CSF-20-80 example); Ke = 1 at and above rated torque.
    With q = 1, c solves 0.58·(1 + c)/(0.58 + c) = 0.93 → c = 0.58·0.07/0.35."""
    c = 0.58 * 0.07 / 0.35
    ke = laws.low_load_factor(np.array([0.1, 0.3, 0.58, 1.0, 1.3]), c, 1.0)
    assert ke[2] == pytest.approx(0.93, abs=1e-12)
    assert ke[3] == 1.0 and ke[4] == 1.0
    assert np.all(np.diff(ke[:4]) > 0)


def test_low_load_drop_grows_with_speed_and_keeps_the_catalog_point_at_1000_rpm():
    """The no-load running torque rises with input speed (seed 000 p.023: efficiency
    depends on speed): with s > 0, Ke(0.58) is the catalog 0.93 at the example's 1000 r/min,
    lower above it and higher below; s = 0 is the speed-free curve; Ke = 1 at rated."""
    c = 0.58 * 0.07 / 0.35
    alpha = np.full(4, 0.58)
    speed = np.array([500.0, 1000.0, 3000.0, 3000.0])
    ke = laws.low_load_factor(alpha, c, 1.0, speed, 0.7)
    assert ke[1] == pytest.approx(0.93, abs=1e-12)
    assert ke[0] > ke[1] > ke[2]
    assert laws.low_load_factor(alpha, c, 1.0, speed, 0.0)[3] == pytest.approx(0.93, abs=1e-12)
    assert laws.low_load_factor(np.array([1.0]), c, 1.0, np.array([3000.0]), 0.7)[0] == 1.0


def test_temperature_factor_is_one_at_reference_and_rises_with_warm_grease():
    t = np.array([0.0, 20.0, 40.0, 1e4])
    f = laws.temperature_factor(t, 0.2, 0.03, 20.0)
    assert f[1] == 1.0
    assert f[0] < f[1] < f[2]
    assert f[3] == pytest.approx(1 / (1 - 0.2))   # viscous loss gone entirely


def test_the_flat_low_load_shape_meets_rated_torque_without_slope():
    """Ke = 1 − c/(1 + c)·(1 − α)^q: 1 from rated torque up, 1 − c/(1 + c) at no load, no
    slope at α = 1 for q > 1 (the hyperbolic shape has slope q·c/(1 + c) there and falls to
    0 at no load)."""
    alpha = np.array([0.0, 0.5, 1.0 - 1e-6, 1.0, 2.0])
    ke = laws.low_load_factor(alpha, 0.25, 2.0, flat=True)
    assert ke[0] == pytest.approx(1 - 0.25 / 1.25)
    assert ke[1] == pytest.approx(1 - 0.2 * 0.25)
    assert (ke[3], ke[4]) == (1.0, 1.0)
    assert (ke[3] - ke[2]) / 1e-6 == pytest.approx(0.0, abs=1e-5)
    hyperbolic = laws.low_load_factor(alpha, 0.25, 2.0)
    assert hyperbolic[0] == 0.0
    assert (hyperbolic[3] - hyperbolic[2]) / 1e-6 == pytest.approx(2.0 * 0.25 / 1.25, rel=1e-4)


def test_a_band_law_steps_over_its_band_and_is_reynolds_when_wide():
    """ln g changes by 4·b·w across the band, with slope −b at its centre, is flat well
    outside it, and tends to Reynolds' exp(−b·Δt) as the band widens (σ(x) ≈ ½ + x/4)."""
    t = np.array([-40.0, 0.0, 20.0, 30.0, 40.0, 120.0])
    g = laws.band_ratio(t, 0.05, 20.0, (30.0, 3.0))
    assert g[2] == 1.0
    assert np.log(g[0] / g[-1]) == pytest.approx(4 * 0.05 * 3.0, rel=1e-6)
    h = 1e-4
    slope = np.log(laws.band_ratio(np.array([30.0 + h, 30.0 - h]), 0.05, 20.0, (30.0, 3.0)))
    assert (slope[0] - slope[1]) / (2 * h) == pytest.approx(-0.05, rel=1e-6)
    wide = laws.band_ratio(t, 0.05, 20.0, (30.0, 1e6))
    assert wide == pytest.approx(laws.viscosity_ratio(t, 0.05, 20.0), rel=1e-6)


# --------------------------------------------------------------------------- noise
def test_noise_estimate_ignores_a_smooth_signal_and_sees_coloured_noise():
    rng = np.random.default_rng(1)
    n, sigma = 4000, 1.0
    signal = 50 * np.sin(np.linspace(0, 6 * math.pi, n))          # 50× the noise
    white = sigma * rng.standard_normal(n)
    assert noise_rms(signal + white) == pytest.approx(sigma, rel=0.06)
    ar = np.empty(n)                                              # AR(1), φ = 0.8
    ar[0] = rng.standard_normal()
    for i in range(1, n):
        ar[i] = 0.8 * ar[i - 1] + rng.standard_normal()
    ar *= sigma / ar.std()
    assert noise_rms(signal + ar) == pytest.approx(sigma, rel=0.12)
    # AR(1): τ = (1 + φ)/(1 − φ) = 9 samples
    assert correlation_time(ar) == pytest.approx(9.0, rel=0.35)


def test_a_short_series_does_not_read_more_noise_than_it_holds():
    """72 samples of AR(1) noise (φ = 0.71, τ = 5.9: an efficiency grid in time order) leave
    only lags 1, 2, 4 to the fit, and φ loose: unchecked, a third of the draws read φ > 0.9
    and σ up to 2.6× the truth (p90), which took an efficiency effect's evidence from 72
    rows down to N/τ ≈ 2. The noise cannot hold more variance than the series: p90 of σ
    ≤ 1.2× and at most 5 % of the draws with φ > 0.9 (200 draws, fixed seed)."""
    rng = np.random.default_rng(1)
    phi_true, n = 0.71, 72
    sigmas, phis = [], []
    for _ in range(200):
        e = np.empty(n)
        e[0] = rng.standard_normal()
        for i in range(1, n):
            e[i] = phi_true * e[i - 1] + math.sqrt(1 - phi_true ** 2) * rng.standard_normal()
        sigma, phi = noise_model(e)
        sigmas.append(sigma)
        phis.append(phi)
    assert np.percentile(sigmas, 90) <= 1.2
    assert np.mean(np.array(phis) > 0.9) <= 0.05
    assert 0.5 <= np.median(phis) / phi_true <= 1.1


# --------------------------------------------------------------------------- baseline
def test_baseline_twist_reproduces_the_seed_example_from_the_defining_data():
    """Seed 000 p.020, CSF-25-100: 2.9 N·m → 9.4×10⁻⁵ rad, 39 N·m → 9.4×10⁻⁴ rad. The seed
    adds (T − T1)/K2 to the printed θ1 (two digits); from T1/K1 the defining data give
    9.52×10⁻⁴ rad, 1.2 % above: 1.5 % tolerance. The GH curve from T1, T2, K1, K2, K3 meets the printed θ1, θ2
    of table 060-1 to their rounding (3 digits: 2 %)."""
    from hdcad.catalog import load_catalog
    catalog = load_catalog()
    curve, _ = stiffness_curve(resolve("CSF-25-100-2A-GR", catalog))
    theta = catalog_twist(curve, np.array([2.9, 39.0, -39.0]), 0.0)
    np.testing.assert_allclose(theta, [9.4e-5, 9.4e-4, -9.4e-4], rtol=0.015)
    model = resolve("CSF-32-100-GH", catalog)
    curve, _ = stiffness_curve(model)
    theta = catalog_twist(curve, np.array([29.0, 108.0]), 0.0)
    np.testing.assert_allclose(theta, [0.00044, 0.00116], rtol=0.02)


def test_corner_width_smooths_the_curve_without_moving_it_far():
    """w → 0 is the three-segment curve; a width of T1 keeps the twist odd, increasing and
    within the compliance change × w of the sharp curve (softplus bound w·ln 2 per corner)."""
    from hdcad.catalog import load_catalog
    curve, _ = stiffness_curve(resolve("CSF-32-100-GH", load_catalog()))
    torque = np.linspace(-150.0, 150.0, 3001)
    sharp = catalog_twist(curve, torque, 0.0)
    smooth = catalog_twist(curve, torque, curve.T1)
    np.testing.assert_allclose(catalog_twist(curve, torque, 1e-6), sharp, atol=1e-12)
    assert np.all(np.diff(smooth) > 0) and np.allclose(smooth, -smooth[::-1])
    jumps = abs(1 / curve.K2 - 1 / curve.K1) + abs(1 / curve.K3 - 1 / curve.K2)
    assert np.max(np.abs(smooth - sharp)) <= jumps * curve.T1 * math.log(2) * 2


def test_the_printed_reading_is_the_seed_example_s_arithmetic():
    """Seed 000 p.020, CSF-25-100 at 39 N·m: the worked example adds (T − T1)/K2 to the
    printed θ1 and gets 9.4×10⁻⁴ rad (two digits: ±0.5 %). The T/K curve plus the printed
    reading's departure (:func:`printed_departure`, the nuisance the baseline fits between
    0 and 1) is that arithmetic exactly; below T1 the two readings agree."""
    from hdcad.catalog import load_catalog
    from hdcad.reconcile.baseline import printed_departure
    curve, _ = stiffness_curve(resolve("CSF-25-100-2A-GR", load_catalog()))
    torque = np.array([2.9, 39.0, -39.0])
    printed = catalog_twist(curve, torque, 0.0) + printed_departure(curve, torque, 0.0)
    by_hand = curve.theta1 + (39.0 - curve.T1) / curve.K2
    np.testing.assert_allclose(printed[1:], [by_hand, -by_hand], rtol=1e-9)
    assert printed[1] == pytest.approx(9.4e-4, rel=0.0055)
    assert printed[0] == catalog_twist(curve, torque, 0.0)[0]


@pytest.mark.parametrize("seed", range(6))
def test_bounded_solve_matches_bvls_on_the_full_rows(seed):
    """``fitting.solve`` folds the rows into the columns' triangular factor before the bounded
    solver: the solution must be BVLS's on the n × p system (scipy's ``lsq_linear``), with
    near-collinear columns (a catalog curve and its printed reading) and bounds active."""
    from scipy.optimize import lsq_linear

    from hdcad.reconcile.bounded import solve
    rng = np.random.default_rng(seed)
    t = np.linspace(-1.0, 1.0, 2000)
    X = np.column_stack([t + 0.1 * t ** 3, np.ones_like(t), t + 0.12 * t ** 3,
                         np.tanh(t / 0.05), rng.standard_normal(len(t)) * 1e-3])
    y = X @ rng.normal(0.0, 1.0, X.shape[1]) + 0.01 * rng.standard_normal(len(t))
    lower = np.array([0.9, -np.inf, 0.0, 0.0, -np.inf])
    upper = np.array([1.1, np.inf, 1.1, np.inf, np.inf])
    norm = np.sqrt(np.mean(X * X, axis=0))
    expected = lsq_linear(X / norm, y, bounds=(lower * norm, upper * norm),
                          method="bvls").x / norm
    found = solve(X, y, lower, upper)
    assert np.sum((X @ found - y) ** 2) == pytest.approx(np.sum((X @ expected - y) ** 2),
                                                         rel=1e-9)
    np.testing.assert_allclose(found, expected, rtol=1e-6, atol=1e-9)


def test_the_catalog_columns_kept_by_corner_width_are_the_ones_computed():
    """The torsion baseline keeps its free columns by corner width (a fit moves one width
    at a time); what it returns, on every row or a subset, after more widths than it keeps,
    is what the curve gives."""
    from hdcad.catalog import load_catalog
    from hdcad.reconcile import baseline as bl
    catalog = load_catalog()
    torque = triangle(400.0, 2, 1200)
    base = bl.build("torsion", {"torque_Nm": torque, "twist_rad": np.zeros_like(torque)},
                    resolve("CSF-32-100-GH", catalog), catalog)
    rows = np.arange(0, len(torque), 7)
    for width in [0.0, 2.0, 5.0] + [float(w) for w in range(10, 10 + bl._WIDTHS_KEPT)] + [2.0]:
        got = base.free_columns({"catalog.corner_width": width}, rows)
        np.testing.assert_array_equal(got, bl._torsion_columns(base.curve, torque[rows], width))
