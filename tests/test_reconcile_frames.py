"""The member a transmission error turns with in a run-up (:mod:`hdcad.reconcile.frames`).

The reference is a general-purpose ODE integrator (scipy's DOP853 at tight tolerances) on the
load joint J·θ'' + c·θ' + K·(θ − e) = 0, K the CSG-20-50-GH row of table 052-1 (K1 13 000
N·m/rad), excited by a 1× error carried by the flexspline, which the wave generator passes
1 + 1/R times per revolution with the circular spline fixed (seed 000 p.010, figure 010-1 ①),
or by the same error on the fixed circular spline (exactly once per revolution). Two
end-to-end cases come from truth suite J (written without reading hdcad/reconcile), whose
flexspline errors turn at 1 − 1/R.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from truth_runs import case_run

from hdcad.catalog import load_catalog
from hdcad.models import resolve_gear
from hdcad.reconcile import frames, reconcile, validate_data

MODEL, RATIO, K1 = "CSG-20-50-GH", 50.0, 13000.0
FN_HZ, ZETA = 10.0, 0.04  # the 1× resonance at 600 r/min
J = K1 / (2 * math.pi * FN_HZ) ** 2
C = 2 * ZETA * math.sqrt(K1 * J)
AMPLITUDE, NOISE = 2.0e-5, 1.0e-5  # error and noise [rad]; the peak twist stays below T1/K1


def _wg_angle(t, seconds: float):
    """WG angle [rad] of a run-up 300 → 900 r/min over ``seconds`` (≈ 300 revolutions)."""
    return 2 * math.pi / 60.0 * (300.0 * t + 300.0 * t * t / seconds)


def _run_up(rate: float, seconds: float = 30.0, rows: int = 6000) -> dict:
    """The vibration record of an error sin(rate·φ + 0.7) with white noise (seed 3)."""
    t = np.linspace(0.0, seconds, rows)

    def rhs(time, state):
        e = AMPLITUDE * math.sin(rate * _wg_angle(time, seconds) + 0.7)
        return [state[1], -(C * state[1] + K1 * (state[0] - e)) / J]

    sol = solve_ivp(rhs, (0.0, seconds), [0.0, 0.0], method="DOP853", t_eval=t,
                    rtol=1e-9, atol=1e-14, max_step=2e-3)
    noise = np.random.default_rng(3).normal(0.0, NOISE, rows)
    return {"time_s": t, "input_speed_rpm": 300.0 + 600.0 * t / seconds,
            "output_vibration_rad": sol.y[0] + noise}


@pytest.fixture(scope="module")
def gear():
    catalog = load_catalog()
    return resolve_gear(MODEL, catalog)[0], catalog


def _reconciled(gear, data) -> dict:
    model, catalog = gear
    return reconcile("vibration", validate_data("vibration", data), model, catalog,
                     load_inertia_kgm2=J).as_dict()


def _te_1x(result) -> dict:
    return next(s["params"] for s in result["steps"] if s["effect"] == "te_1x")


def test_an_error_on_the_flexspline_is_named_at_its_own_rate(gear):
    result = _reconciled(gear, _run_up(1 + 1 / RATIO))
    assert result["missing_effects"] == ["te_1x"]
    assert _te_1x(result)["cycles_per_wg_revolution"]["value"] == pytest.approx(1 + 1 / RATIO)
    assert any("output member" in note for note in result["notes"])
    assert result["rmse_after"] <= 1.2 * NOISE


def test_in_the_fixed_frame_alone_the_same_record_is_left_far_above_the_noise(gear,
                                                                               monkeypatch):
    """The control: without the output member's frame the fit cannot follow the slide."""
    monkeypatch.setattr(frames, "frames", lambda ratio: (0.0,))
    result = _reconciled(gear, _run_up(1 + 1 / RATIO))
    assert result["rmse_after"] > 1.5 * NOISE


def test_an_error_on_the_fixed_circular_spline_stays_in_its_frame(gear):
    result = _reconciled(gear, _run_up(1.0))
    assert result["missing_effects"] == ["te_1x"]
    assert "cycles_per_wg_revolution" not in _te_1x(result)
    assert not any("output member" in note for note in result["notes"])
    assert result["rmse_after"] <= 1.2 * NOISE


@pytest.mark.parametrize("name, note", [
    # a 1× error fixed to the flexspline: before the frames nothing was named
    ("j-vibration-single-te_1x-fsframe-quadsweep-000", "output member"),
    # a 2× ellipse error of both splines: before the second frame 1.48σ was left
    ("j-vibration-single-te_2x-twoframe-viscous-000", "a share turning at"),
])
def test_truth_suite_j_errors_carried_by_the_output_member_are_named_and_fitted(name, note):
    """Truth suite J (seed 11; its flexspline errors turn at 1 − 1/R per input revolution,
    within 1/R² of the circular spline's frame as output): named, fitted to the noise, and
    the frame said in the notes."""
    case, result = case_run("j", name)
    assert result["missing_effects"] == list(case.gear_effects)
    assert result["rmse_after"] <= 1.2 * case.noise_rms
    assert any(note in n for n in result["notes"])
