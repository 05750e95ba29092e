"""Friction whose slip torque grows with the torque carried (:mod:`hdcad.reconcile.flank_friction`):
the friction elements of :mod:`hdcad.reconcile.plays` with thresholds r_k + μ·|T|.

The vectorised stop operators are checked against a play operator written row by row from
its definition (the play p kept within r + μ·|T| of T, moving only when it must: Brokate &
Sprekels 1996, ch. 2, with an input-dependent threshold), and the centre lines and the loss
at zero torque against the steady loop that operator draws. The reconcile cases come from
suite H (``truths/truth_h.py``, written by a helper from the contract only): a flank-friction
play whose threshold is r0 + μ|T| (Tuttle & Seering 1996), which a loop of fixed slip
torques follows only to 1.25–1.56σ; and suite D's friction loops of fixed slip torques,
which must keep them.
"""

from __future__ import annotations

import numpy as np
import pytest
from truth_runs import bench, named_case

from hdcad.reconcile import plays
from hdcad.reconcile.params import FLANK_FORM


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
    T0, r = 100.0, np.array([2.0, 10.0, 30.0])
    up = np.linspace(-T0, T0, 401)
    torque = np.concatenate([np.linspace(0, T0, 201), up[::-1][1:], up[1:]])
    states = plays.stop_states(torque, r, (np.array([0, 200, 600]), 1), mu, T0)
    loading, unloading = states[600:], states[200:601][::-1]  # both at torque `up`
    centre = plays.centre_lines(up, r, T0, mu)
    assert np.allclose(centre, 0.5 * (loading + unloading), atol=1e-12)
    zero = 200  # row of T = 0 on `up`
    width = (loading[zero] - unloading[zero]) @ np.ones(3)  # s leads on loading
    assert plays.loss_at_zero(np.ones(3), r, T0, mu) == pytest.approx(width, rel=1e-12)


@pytest.mark.parametrize("name", ["h-torsion-single-hysteresis-flank-001",
                                  "h-torsion-single-hysteresis-flank-002"])
def test_a_loop_that_widens_with_the_torque_takes_load_dependent_slip(name):
    """Suite H's flank-friction plays (seed 7, 2 per cell): with slip torques fixed the
    loop left 1.25σ and 1.56σ; with the load share the residual is within the issue's
    1.2σ, the hysteresis is still named first, and the report gives the share and its
    formula."""
    case = named_case("h", name, 7)
    result = bench.reconcile_case(case)
    assert result["missing_effects"][0] == "hysteresis"
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
