"""The forms a named effect takes once it is named: a hysteresis loop as a Preisach relay sum
(:mod:`hdcad.reconcile.preisach`, :mod:`hdcad.reconcile.loops`) and a transmission error with
the overtones of its harmonic series (:func:`hdcad.reconcile.te_forms.refine_te_overtones`).

The Preisach model is checked against a brute-force simulation of the relays it stands for
(a Monte Carlo sample of the density, each relay switched sample by sample: a different
computation from the Everett-function sum), and against the properties Mayergoyz (1991,
ch. 1) proves for every Preisach model: return-point memory and wiping out. The reconcile
cases come from suite G (``truths/truth_g.py``), written by a helper from the contract only
(Everett-function Preisach and Krasnosel'skii–Pokrovskii loops; an ellipse series with a 4×
overtone) and suite M (``truths/truth_m.py``: a run-up driven by a triangular 1× error).
"""

from __future__ import annotations

import numpy as np
import pytest
from truth_runs import bench, named_case

from hdcad.reconcile import preisach

T0 = 100.0
DENSITY = (30.0, 0.5, 10.0)   # median slip torque [N·m], log-spread, centre spread [N·m]


def _history(*turns, points=60):
    """A piecewise-linear torque history through ``turns`` (×T0), ``points`` per unit."""
    out = [np.array([0.0])]
    for a, b in zip((0.0,) + turns[:-1], turns):
        n = max(2, int(abs(b - a) * points))
        out.append(np.linspace(a, b, n + 1)[1:])
    return np.concatenate(out) * T0


def _relays_by_brute_force(torque, n=40_000, seed=0):
    """Mean relay output along ``torque``: relays drawn from the density, demagnetised
    (centred below zero up), each switched up at α and down at β, sample by sample."""
    rng = np.random.default_rng(seed)
    w = DENSITY[0] * np.exp(DENSITY[1] * rng.standard_normal(n))
    c = DENSITY[2] * rng.standard_normal(n)
    alpha, beta = c + w, c - w
    state = np.where(c < 0, 1.0, -1.0)
    out = []
    for u in torque:
        state[u >= alpha] = 1.0
        state[u <= beta] = -1.0
        out.append(state.mean())
    return np.array(out)


def test_the_everett_sum_is_the_mean_of_the_relays_it_stands_for():
    """Monte Carlo with 40 000 relays: standard error of the mean ≤ 1/√40000 = 0.005, so
    0.02 is four standard errors."""
    torque = _history(1.0, -1.0, 0.4, -0.2, 0.7, -1.0, 1.0)
    plane = preisach.PreisachPlane(torque, T0)
    z = plane.loop(torque, slice(None), *DENSITY, centred=False)
    assert -z == pytest.approx(_relays_by_brute_force(torque), abs=0.02)


def test_the_memory_terms_are_exact_for_a_finite_set_of_relays():
    """The Everett terms (the memory followed run by run, a noisy torque's short runs one
    sample at a time) against 300 relays switched sample by sample from the same
    demagnetised state: for a finite set E(α, β) is the weight of the relays inside the
    triangle, so the sum must agree to rounding. The history has long runs, plateaus, and
    a dither of one- and two-sample runs."""
    rng = np.random.default_rng(3)
    a, b = rng.uniform(-1.5 * T0, 1.5 * T0, (2, 300))
    alpha, beta, weight = np.maximum(a, b), np.minimum(a, b), rng.uniform(0.5, 1.5, 300)
    dither = 0.4 * T0 + rng.normal(0.0, 0.02 * T0, 200)
    torque = np.concatenate([_history(1.0, -0.6, 0.3), np.full(5, 0.3 * T0), dither,
                             _history(-1.2, 0.9, points=7), np.repeat(dither[:40], 2)])
    top = preisach.LIMIT * T0
    prehistory = [(-1) ** k * top * preisach.DECAY ** k for k in range(1, 200)
                  if top * preisach.DECAY ** k > preisach.DEMAG_END * T0] + [0.0]
    state, relays = -np.ones(300), []
    for u in np.concatenate([prehistory, torque]):
        state[u >= alpha] = 1.0
        state[u <= beta] = -1.0
        relays.append(weight @ state)
    rows, alphas, betas, coefs = preisach.everett_terms(torque, T0)
    inside = (betas[:, None] <= beta) & (alpha <= alphas[:, None])
    output = np.bincount(rows, coefs * (inside @ weight), len(torque)) - weight.sum()
    assert output == pytest.approx(relays[len(prehistory):], abs=1e-9)


def test_a_minor_loop_returns_to_its_turning_point_and_is_wiped_out_by_a_larger_one():
    """Return-point memory: after 0.2 → 0.6 → 0.2 the output is back where it left 0.2;
    wiping out: once the torque passes the earlier maximum, the output is that of the
    history without the minor loop."""
    with_loop = _history(1.0, 0.2, 0.6, 0.2, -1.0, 1.0)
    without = _history(1.0, 0.2, -1.0, 1.0)
    z_with = preisach.PreisachPlane(with_loop, T0).loop(with_loop, slice(None), *DENSITY,
                                                        centred=False)
    z_without = preisach.PreisachPlane(without, T0).loop(without, slice(None), *DENSITY,
                                                         centred=False)
    # 0.2·T0 is passed on the first loading, reached twice as a turning point, passed on
    # the last loading
    at_02 = np.flatnonzero(np.isclose(with_loop, 0.2 * T0))[1:3]
    assert with_loop[at_02[0] - 1] > with_loop[at_02[0]] < with_loop[at_02[0] + 1]
    assert z_with[at_02[0]] == pytest.approx(z_with[at_02[1]], abs=1e-12)
    assert z_with[-1] == pytest.approx(z_without[-1], abs=1e-12)


def test_the_loss_is_the_loop_width_at_zero_torque_and_the_centred_loop_has_no_backbone():
    torque = _history(1.0, -1.0, 1.0, -1.0, points=400)
    plane = preisach.PreisachPlane(torque, T0)
    f = -plane.loop(torque, slice(None), *DENSITY, centred=False)
    zeros = np.flatnonzero(np.isclose(torque, 0.0))
    b_up, b_down = f[zeros[-2]], f[zeros[-1]]   # loading from −T0, then unloading from +T0
    assert plane.loss(*DENSITY) == pytest.approx(b_down - b_up, rel=1e-3)
    # about its centre line the steady loop's branches are mirror images: at every torque
    # the loading and unloading states sum to zero (the centre line is on a 200-point grid)
    centred = plane.loop(torque, slice(None), *DENSITY, centred=True)
    turns = [int(np.argmax(torque)), 1200, 2000]          # +T0, −T0, +T0 (400 per T0)
    assert torque[turns[1]] == -T0 and torque[turns[2]] == T0
    loading = slice(turns[1], turns[2] + 1)
    unloading = slice(turns[2], None)
    for t in (-0.5 * T0, 0.0, 0.5 * T0):
        up = np.interp(t, torque[loading], centred[loading])
        down = np.interp(t, torque[unloading][::-1], centred[unloading][::-1])
        assert up + down == pytest.approx(0.0, abs=1e-3 * plane.loss(*DENSITY))


@pytest.mark.parametrize("name,before", [
    ("g-torsion-single-hysteresis-everett-preisach-triangular-001", 1.68),
    ("g-torsion-single-hysteresis-kp-triangular-001", 1.68),
])
def test_a_preisach_loop_is_followed_to_the_noise(name, before):
    """Suite G's Everett-function and Krasnosel'skii–Pokrovskii loops (seed 11, 2 per cell):
    the Bouc–Wen loop, in its best form, left ``before`` × the noise (1.68σ both); the
    Preisach relay sum brings them within 1.2σ, the issue's bar."""
    case = named_case("g", name, 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["hysteresis"]
    assert any("Preisach relay sum" in note for note in result["notes"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms < before * case.noise_rms


def test_a_multi_amplitude_loop_that_bouc_wen_cannot_follow_is_named_as_a_preisach_loop():
    """Suite G's Everett loop over a staircase of amplitudes (seed 11): the Bouc–Wen loop,
    without return-point memory, left a residual that read as noise correlated over 32 rows
    (σ 2.5× too large) and nothing was named. When nothing passes, the Preisach loop is tried
    with the noise estimated beside it: it passes the gates and follows the data to the
    noise; the report gives its formula."""
    case = named_case("g", "g-torsion-single-hysteresis-everett-preisach-staircase-001", 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["hysteresis"]
    assert "Preisach" in result["steps"][0]["form"]
    assert "slip_torque_median" in result["steps"][0]["params"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_an_ellipse_series_keeps_its_4x_overtone_under_the_2x_error():
    """Suite G's ellipse series: a 2× error with a 4× overtone of 10–25 % (seed 11). The
    4× was reported as unexplained structure, leaving 2.10σ; kept as te_2x's overtone the
    residual is at the noise and nothing is left unexplained at 4×."""
    case = named_case("g", "g-transmission-single-te-2x-ellipse-series-coarse-001", 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["te_2x"]
    assert any("overtones" in note and "4×" in note for note in result["notes"])
    assert not any("4 cycle(s)" in u for u in result["unexplained"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms


def test_a_run_up_keeps_the_overtone_of_a_triangular_1x_error():
    """Suite M's vibration run-up driven by a triangular 1× error (odd harmonics, the 3× at
    1/9 of the 1×; seed 11). Its 3× excites the resonance at a third of the 1×'s speed:
    without the overtone the residual was 1.26σ; kept as te_1x's overtone, passed through
    the joint like the error itself, it is at the noise (1.01σ, bar 1.2σ as the issue's)."""
    case = named_case("m", "m-vibration-single-te1x-etd-cycloidal-triangle-001", 11)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["te_1x"]
    assert any("overtones" in note and "3×" in note for note in result["notes"])
    assert result["rmse_after"] <= 1.2 * case.noise_rms
