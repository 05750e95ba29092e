"""Loops that widen with the torque or the amplitude (:mod:`hdcad.reconcile.widening_loops`).

Friction whose slip torque grows with the torque carried: the friction elements of
:mod:`hdcad.reconcile.plays` with thresholds r_k + μ·|T|. The vectorised stop operators are
checked against a play operator written row by row from its definition (the play p kept
within r + μ·|T| of T, moving only when it must: Brokate & Sprekels 1996, ch. 2, with an
input-dependent threshold), and the centre lines and the loss at zero torque against the
steady loop that operator draws.

A Duhem loop whose height follows the last excursion (:mod:`hdcad.reconcile.duhem`): its
per-branch closed form against the differential law integrated row by row, its loss at zero
torque against the steady loop.

The reconcile cases come from suites written by helpers from the contract only: H's
flank-friction play whose threshold is r0 + μ|T| (Tuttle & Seering 1996), F's rate-independent
Duhem loop of amplitude-dependent height (after Dhaouadi, Ghorbel & Gandhi 2003), which the
loops of fixed form left at 1.25–3.44σ; and D's friction loops of fixed slip torques, which
must keep them.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from truth_runs import bench, named_case

from hdcad.reconcile import duhem, plays
from hdcad.reconcile.params import DUHEM_FORM, FLANK_FORM


def _play_by_rows(torque: np.ndarray, r: float, mu: float) -> np.ndarray:
    """s = T − p of one play operator, row by row from rest (p starts at the first torque)."""
    p, out = torque[0], np.empty(len(torque))
    for i, t in enumerate(torque):
        slip = r + mu * abs(t)
        p = min(max(p, t - slip), t + slip)
        out[i] = t - p
    return out


def _history() -> tuple[np.ndarray, tuple[np.ndarray, int]]:
    """A torque history of straight legs between turning points (minor loops inside the
    major one) and its branches (turning-point rows, first direction)."""
    turns = [0.0, 100.0, -100.0, 40.0, -20.0, 100.0, -60.0, 100.0, -100.0]
    legs = [np.linspace(a, b, 60)[:-1] for a, b in zip(turns[:-1], turns[1:])]
    torque = np.concatenate(legs + [np.array([turns[-1]])])
    starts = np.array([59 * i for i in range(len(turns) - 1)])
    return torque, (starts, 1)


@pytest.mark.parametrize("mu", [0.0, 0.1, 0.45])
def test_the_stop_states_are_the_play_operator_s_row_by_row(mu):
    """Each element's state s/R (R = r + μ·T0) is the row-by-row play operator's s over R
    along a history with minor loops, to rounding; μ = 0 is the fixed slip torque."""
    torque, branches = _history()
    r = np.array([3.0, 15.0, 40.0, 80.0])
    states = plays.stop_states(torque, r, branches, mu, 100.0)
    for k, rk in enumerate(r):
        expected = _play_by_rows(torque, rk, mu) / (rk + mu * 100.0)
        assert np.allclose(states[:, k], expected, atol=1e-12)


@pytest.mark.parametrize("mu", [0.0, 0.2, 0.6])
def test_the_centre_line_and_loss_are_the_steady_loop_s(mu):
    """After a first cycle the loop between ±T0 is steady: its centre line (mean of the
    loading and unloading branches at the same torque) and its width at zero torque are
    the closed forms' (``centre_lines``, ``loss_at_zero``)."""
    T0, r = 100.0, np.array([2.0, 10.0, 30.0, 95.0])  # the last never slips once μ > 0.05
    up = np.linspace(-T0, T0, 401)
    torque = np.concatenate([np.linspace(0, T0, 201), up[::-1][1:], up[1:]])
    states = plays.stop_states(torque, r, (np.array([0, 200, 600]), 1), mu, T0)
    loading, unloading = states[600:], states[200:601][::-1]  # both at torque `up`
    centre = plays.centre_lines(up, r, T0, mu)
    assert np.allclose(centre, 0.5 * (loading + unloading), atol=1e-12)
    zero = 200  # row of T = 0 on `up`
    width = (loading[zero] - unloading[zero]) @ np.ones(4)  # s leads on loading
    assert plays.loss_at_zero(np.ones(4), r, T0, mu) == pytest.approx(width, rel=1e-12)


@pytest.mark.parametrize("name, named", [
    ("h-torsion-single-hysteresis-flank-001", ["hysteresis"]),
    ("h-torsion-single-hysteresis-flank-002", ["hysteresis", "housing_compliance"])])
def test_a_loop_that_widens_with_the_torque_takes_load_dependent_slip(name, named):
    """Suite H's flank-friction plays (seed 7, 2 per cell): with slip torques fixed the
    loop left 1.25σ and 1.56σ; with the load share the residual is within the issue's
    1.2σ, and the report gives the share and its formula. The second case's spring is a
    wrong second name, as before: the selection, before any loop form is refined, reads the
    loop's widening as a spring beside a loop of fixed slip torques."""
    case = named_case("h", name, 7)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == named
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    step = next(s for s in result["steps"] if s["effect"] == "hysteresis")
    assert step["form"].startswith(FLANK_FORM)
    assert 0.0 < step["params"]["load_share"]["value"] < 1.0
    assert any("slip torques grow with the torque carried" in n for n in result["notes"])


@pytest.mark.parametrize("name", ["d-torsion-single-hysteresis-gpi-play-000",
                                  "d-torsion-single-hysteresis-lugre-000"])
def test_friction_of_fixed_slip_torques_keeps_them(name):
    """Suite D's generalised play and LuGre loops (seed 7), fitted as friction elements of
    fixed slip torques: a load share does not pay for itself there."""
    result = bench.reconcile_case(named_case("d", name, 7))
    step = next(s for s in result["steps"] if s["effect"] == "hysteresis")
    assert "load_share" not in step["params"]
    assert "slip torques r_k" in step["form"] and "μ" not in step["form"]


def _duhem_by_rows(torque: np.ndarray, T0: float, rate: float, power: float) -> np.ndarray:
    """dw/d|u| = λ·(−d·h − w), u = T/T0, integrated exactly over each row's step (the target
    is constant between reversals); h = (half the excursion between the last two turning
    points)^p, 0 before the first reversal."""
    u = torque / T0
    w, out, d, h, turns = 0.0, np.zeros(len(u)), 0.0, 0.0, [u[0]]
    for i in range(1, len(u)):
        step = u[i] - u[i - 1]
        new = 1.0 if step > 0 else -1.0
        if d and new != d:  # a reversal at the row before
            turns.append(u[i - 1])
            h = (0.5 * abs(turns[-1] - turns[-2])) ** power
        d = new
        w = -d * h + (w + d * h) * np.exp(-rate * abs(step))
        out[i] = w
    return out


@pytest.mark.parametrize("rate, power", [(0.4, 1.0), (2.5, 1.6), (12.0, 0.7)])
def test_the_duhem_state_is_the_law_integrated_row_by_row(rate, power):
    """Along a history with minor loops the per-branch closed form is the law integrated
    row by row, to rounding."""
    torque, branches = _history()
    w = duhem.states(torque, branches, 100.0, rate, power)
    assert np.allclose(w, _duhem_by_rows(torque, 100.0, rate, power), atol=1e-12)


@pytest.mark.parametrize("rate", [0.3, 2.0, 9.0])
def test_the_duhem_loss_is_the_steady_loop_s_width(rate):
    """Between ±T0 the loop settles (its branches' start is the last branch's end): its
    width at zero torque after 40 cycles is ``loss_at_zero``'s (at λ = 0.3 a branch keeps
    e^(−0.6) of its start: 40 cycles settle it to 1e-20)."""
    T0 = 50.0
    leg = np.linspace(-T0, T0, 201)
    cycles = [np.linspace(0, T0, 101)] + [leg[::-1][1:], leg[1:]] * 40
    torque = np.concatenate(cycles)
    starts = np.array([0] + [100 + 200 * k for k in range(80)])
    w = duhem.states(torque, (starts, 1), T0, rate, 1.3)
    loading, unloading = w[-201:], w[-401:-200][::-1]
    width = unloading[100] - loading[100]  # at T = 0; loading lags below
    assert duhem.loss_at_zero(1.0, rate, 1.3) == pytest.approx(width, rel=1e-9)


@pytest.mark.parametrize("name", ["f-torsion-single-hysteresis-duhem-ampdep-016",
                                  "f-torsion-single-hysteresis-duhem-ampdep-017"])
def test_a_loop_whose_height_follows_the_amplitude_is_a_duhem_loop(name):
    """Suite F's amplitude-dependent Duhem loops (seed 7, 2 per cell): the loops of fixed
    form left 3.44σ and 2.92σ; as a Duhem loop the residual is within 1.2σ, the name is
    unchanged, and the height exponent is within 0.2 of the truth's (1.77 and 1.45, printed
    in its formulation; fitted 1.64 and 1.41: the amplitudes tested pin it loosely)."""
    case = named_case("f", name, 7)
    result = bench.reconcile_case(case)
    assert result["missing_effects"] == ["hysteresis"]
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    step = next(s for s in result["steps"] if s["effect"] == "hysteresis")
    assert step["form"] == DUHEM_FORM
    truth = float(re.search(r" p=([0-9.]+)", case.formulation).group(1))
    assert abs(step["params"]["height_power"]["value"] - truth) <= 0.2
