"""Measurement effects that read about the same over one record.

An output encoder mounted off-centre errs once per output revolution; a test that turns the
output through a fraction of a revolution at a steady speed sees an arc of that sine, which
a slow drift with test time follows as well (and a drift is, at that speed, a ramp in the
output angle: its sensor's gain). The search names the one that fits best; this module
says which of the others the data cannot refuse, so a reviewer checks the rig for each.

A rival reads the same when, with its columns added to the named model's design, the named
effect's own columns no longer earn their place (ΔBIC ≤ ``BIC_MIN`` or less than
``EXPLAINED_MIN`` noise variances, :func:`.rig_entries.significant`).

References
----------
Seed 000 p.021 (transmission error measured as the output angle against the input angle).
"""

from __future__ import annotations

import numpy as np

from . import rig
from .fitting import Fit, Problem
from .model_columns import _inputs_on
from .rig_entries import significant
from .rig import WARM_UP_TAU

# The drifts a rival reading is drawn with: warm-ups over the fitted range of time constants
# (WARM_UP_TAU), each beside its straight line; the drift reads the same if one of them does.
RIVAL_TAUS = tuple(np.geomspace(WARM_UP_TAU[0], WARM_UP_TAU[1], 5))

# The measurement effects that may read as one another over an arc of the output.
ALIKE = ("thermal_drift", "encoder_eccentricity")


def _rival_columns(problem: Problem, name: str) -> list[np.ndarray]:
    """The designs a rival may take on the fit rows (a drift's for each time constant)."""
    inputs = _inputs_on(problem, False)
    taus = RIVAL_TAUS if name == "thermal_drift" else (None,)
    return [rig.columns(name, problem.kind, inputs, problem.step_position, {"tau": t})[1]
            for t in taus]


def rivals(problem: Problem, fit: Fit, effect: str, sigma: float, tau: float) -> list[str]:
    """The measurement effects of ``ALIKE`` besides ``effect`` (named in ``fit``) that read
    about the same on this record."""
    if (effect not in ALIKE or fit.columns is None
            or "output_angle_rad" not in problem.base.inputs):
        return []
    own = [i for i, (e, _) in enumerate(fit.labels) if e == effect]
    out = []
    for rival in ALIKE:
        if rival == effect or rival in fit.effects:
            continue
        if any(not significant(problem, np.column_stack([fit.columns, c]), own, sigma, tau)
               for c in _rival_columns(problem, rival)):
            out.append(rival)
    return out


def mark(problem: Problem, entry: dict, alike: list[str]) -> dict:
    """``entry`` with the rivals that read the same (``reads_as``) and a sentence saying so."""
    if not alike:
        return entry
    turned = np.degrees(float(np.ptp(problem.base.inputs["output_angle_rad"][problem.rows])))
    words = {"thermal_drift": "a slow drift with test time",
             "encoder_eccentricity": "an output encoder mounted off-centre (once per output "
                                     "revolution)"}
    text = " or ".join(words[a] for a in alike)
    reading = entry.get("reading") or ", ".join(  # the values, where no sentence gives them
        f"{k} = {v['value']:.4g} {v['unit']}" for k, v in entry["params"].items())
    sentence = f"over the {turned:.0f}° of output this test turns, {text} reads about the same"
    return {**entry, "reads_as": list(alike), "reading": f"{reading}; {sentence}"}
