"""A torsion loop's turning points against the catalog curve.

The catalog gives the total twist of a gear loaded forward and reverse as twice the twist
its curve gives for the torque plus the backlash (seed 000 p.020, the worked example of
CSF-25-100-2A-GR: 負荷を正逆に加えたときの総ねじれ量は上記で求めた値の2倍にバックラッシ量をプラスした値).
The curve passes through the loop's turning points, so the gear's compliance seen there is
what the catalog's stiffness and its spread bound. A loop whose slip adds to the gear's
twist (friction elements in series, one slip element) carries a compliance of its own and
moves its turning points off the curve. Where such a loop is named alone, the report says
where its turning points lie: beyond the spread, the gear with that loop twists more than
the catalog allows, which a spring in series reads the same as. The naming does not use it:
over the truth suites the loops that carry such a compliance are as often a writer's
hysteresis alone as a loop beside a spring (``truths/README.md``, session 27).

References
----------
Harmonic Drive Systems, engineering data "剛性について", figures 020-1 and 020-2 and the
twist example (seed 000, p.020).
"""

from __future__ import annotations

import numpy as np

from .baseline import COMPLIANCE_SCALE_BOUNDS
from .fitting import Fit, Problem

# rows within this share of the record's largest and smallest torque are its turning points
TURNING_SHARE = 0.97
# each flank's largest torque at least this share of the other's: a record loaded one way
# (a dip below zero is no turning point) measures one flank only
TWO_SIDED_SHARE = 0.5


def tip_scale(problem: Problem, fit: Fit) -> float | None:
    """The gear's compliance scale seen at the loop's outermost turning points [-].

    The fitted compliance scale s plus the loop's twist between the rows at the largest and
    the smallest torque (mean over the rows within ``TURNING_SHARE`` of each) over the
    catalog curve's twist between them: s for a loop about the curve, more for one whose
    slip adds to the twist. None without a compliance scale, without turning points on both
    flanks (each flank's largest torque ``TWO_SIDED_SHARE`` of the other's or more), or
    where the curve or the scale there is not positive."""
    labels = fit.labels
    if ("baseline", "compliance_scale") not in labels:
        return None
    torque = np.asarray(problem.base.inputs["torque_Nm"])[problem.rows]
    top, bottom = float(torque.max()), float(-torque.min())
    if min(top, bottom) < TWO_SIDED_SHARE * max(top, bottom) or min(top, bottom) <= 0.0:
        return None
    upper, lower = torque >= TURNING_SHARE * top, torque <= -TURNING_SHARE * bottom
    i = labels.index(("baseline", "compliance_scale"))
    loop = [k for k, (effect, _) in enumerate(labels) if effect == "hysteresis"]
    twist = fit.columns[:, loop] @ fit.beta[loop]
    curve = fit.columns[upper, i].mean() - fit.columns[lower, i].mean()
    if not curve > 0.0:
        return None
    scale = float(fit.beta[i] + (twist[upper].mean() - twist[lower].mean()) / curve)
    return scale if scale > 0.0 else None


def text(scale: float) -> str:
    """What the turning points of a loop in series at compliance scale ``scale`` say,
    against the catalog curve and its spread."""
    softer = 1.0 - 1.0 / scale
    where = (f"{softer:.1%} softer than the catalog curve" if softer >= 0.0005 else
             f"{-softer:.1%} stiffer than the catalog curve" if softer <= -0.0005 else
             "on the catalog curve")
    lo, hi = COMPLIANCE_SCALE_BOUNDS
    said = (f"the loop in series puts its turning points {where}, which should pass through "
            "them (the total twist forward and reverse is twice the curve's plus the "
            "backlash, seed 000 p.020): ")
    if lo <= scale <= hi:
        return said + "within the stiffness's assumed spread"
    said += "beyond the stiffness's assumed spread, so the gear with this loop twists "
    if scale > hi:
        return said + ("more than the catalog allows; a spring in series (housing, shafts) "
                       "of the loop's own compliance reads the same")
    return said + "less than the catalog allows; check the twist sensor's gain"
