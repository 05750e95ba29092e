"""What a transmission residual still holds, at any order (:func:`hdcad.reconcile.regions.ripples`).

References: a hand-written record (output = input/R + a 2× error + a ripple at a
non-integer order + white noise) whose ripple order and size are known; truth suite H's
ball-pass ripple (a WG bearing's, order q = n_b/2·(1 − d/D·cos α)) and the clean cases of
every suite (written without reading hdcad/reconcile; the session's shared sample,
``truth_runs``).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from truth_runs import SUITES, suite_runs

from hdcad.catalog import load_catalog
from hdcad.models import resolve
from hdcad.reconcile import reconcile

NOISE, TE2 = 2e-6, 3e-5


def _reconciled(ripple: float, order: float = 7.3, seed: int = 0):
    """CSF-32-100-GH, 12 WG revolutions at 128 samples each, a 2× error of 3e-5 rad and a
    ripple of amplitude ``ripple`` at ``order`` cycles per WG revolution."""
    catalog = load_catalog()
    rng = np.random.default_rng(seed)
    phi = np.arange(12 * 128) * 2 * math.pi / 128
    out = (phi / 100 + TE2 * np.sin(2 * phi + 0.4) + ripple * np.sin(order * phi + 1.1)
           + NOISE * rng.standard_normal(phi.size))
    return reconcile("transmission", {"input_angle_rad": phi, "output_angle_rad": out},
                     resolve("CSF-32-100-GH", catalog), catalog)


def _orders(result) -> list[float]:
    return [float(m.group(1)) for u in result.unexplained
            if (m := re.match(r"residual at ([\d.]+) cycles per WG", u))]


def test_a_ripple_between_the_harmonics_is_reported_at_its_order():
    """A ripple of 0.7× the noise's amplitude at 7.3 cycles per WG revolution: its order
    within 0.005 (the record resolves 1/12 of an order; the fit's error at this size is
    ~σ/(A·√N)/revolutions), its RMS within 10 %, and the text says it is not the WG's."""
    result = _reconciled(0.7 * NOISE)
    assert result.missing_effects == ["te_2x"]
    [order] = _orders(result)
    assert order == pytest.approx(7.3, abs=0.005)
    text = next(u for u in result.unexplained if "cycles per WG" in u)
    rms = float(re.search(r"RMS ([\d.e-]+) rad", text).group(1))
    assert rms == pytest.approx(0.7 * NOISE / math.sqrt(2), rel=0.1)
    assert "not a harmonic of the WG" in text


@pytest.mark.parametrize("seed", range(4))
def test_white_noise_leaves_no_ripple(seed):
    """The control: the 2× error and white noise only, four noise draws."""
    assert _orders(_reconciled(0.0, seed=seed)) == []


def test_the_ball_pass_ripple_of_suite_h_is_found_at_its_order():
    """Suite H's elliptic WG with a ball-pass ripple (order 5–12.4): the residual's ripple
    at the order the suite drew, within 0.02 (the records span 4–8 WG revolutions)."""
    path = next(p for p in SUITES if p.stem == "truth_h")
    cases, results = suite_runs(path)
    found = 0
    for case, result in zip(cases, results):
        drawn = re.search(r"ball-pass ripple \(order ([\d.]+)", case.formulation)
        if case.kind != "transmission" or not drawn:
            continue
        orders = [float(m.group(1)) for u in result["unexplained"]
                  if (m := re.match(r"residual at ([\d.]+) cycles per WG", u))]
        assert orders and orders[0] == pytest.approx(float(drawn.group(1)), abs=0.02)
        found += 1
    assert found == 2


def test_no_ripple_is_reported_on_clean_transmission_data():
    """Every suite's clean transmission cases and separable decoys named right leave no
    ripple (a white or correlated noise's periodogram peak stays below the look-elsewhere
    threshold)."""
    for path in SUITES:
        cases, results = suite_runs(path)
        for case, result in zip(cases, results):
            if case.kind == "transmission" and case.category == "clean":
                assert not any("cycles per WG" in u for u in result["unexplained"]), case.name
