"""The catalog model of each measurement kind: what the data should be if nothing is missing.

A :class:`Baseline` holds the measured quantity, the part of the prediction fixed by the
catalog (twist from K1/K2/K3, output = input/R, zero vibration), the baseline's own free
parameters (a zero offset or a constant efficiency) and the catalog figures that bound the
candidate effects. The free parameters are the same for every candidate effect so that the
candidates are compared like with like: refitting the catalog stiffness would let a softer K
hide a housing compliance or a low-torque softening.

References
----------
Seed 000 p.020: three-segment torque-twist curve K1/K2/K3, T1/T2; hysteresis loss and backlash.
Seed 000 p.021 (formula 021-1): θer = θ2 − θ1/R; (021-3) f = (1/2π)·√(K/J).
Seed 000 p.023: η = Ke·ηR, α = T/Tr.
Seed 003 p.051/052, p.059/060: accuracy, hysteresis loss, backlash of the gear heads.
Seed 001 p.314 (table 314-1): FD lost motion and spring constant.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..catalog import Catalog
from ..checks.run import stiffness_curve
from ..checks.stiffness import StiffnessCurve
from ..errors import InputError
from ..models import GearModel

# FD ratings depend on speed; the rated torque used for α = T/Tr is the 1450 r/min row
# (table 310-1), the speed hdcad's catalog listing shows for FD models.
FD_RATED_SPEED_RPM = 1450.0

MEASURED = {"torsion": ("twist_rad", "rad"), "transmission": ("output_angle_rad", "rad"),
            "efficiency": ("efficiency_pct", "%"),
            "vibration": ("output_vibration_rad", "rad")}


@dataclass
class Baseline:
    """Catalog prediction of one data set.

    ``fixed`` [unit of the measured column] is the catalog part of the prediction;
    ``free`` (n × p) the columns of the baseline's free linear parameters (names and units in
    ``free_names``/``free_units``); ``figures`` catalog values (with sources) that bound the
    effects; ``notes`` assumptions made for this model.
    """

    kind: str
    y: np.ndarray
    fixed: np.ndarray
    free: np.ndarray
    free_names: tuple[str, ...]
    free_units: tuple[str, ...]
    unit: str
    figures: dict[str, tuple[float, str]] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    inputs: dict[str, np.ndarray] = field(default_factory=dict)


def twist_of(curve: StiffnessCurve, torque_Nm: np.ndarray) -> tuple[np.ndarray, list[str]]:
    """Catalog twist θ [rad] at each torque T [N·m] (sign follows T), vectorised.

    Slopes 1/K1, 1/K2, 1/K3 on the three segments, through the printed θ1 and θ2 where the
    catalog prints them. The printed θ differ from T1/K1 and θ1 + (T2 − T1)/K2 by their
    rounding (CSG-20-80-GH: θ2 printed 1.13×10⁻³ rad, 1.16×10⁻³ from K2), so the segment
    formulas of seed 000 p.020 step at T1 and T2; a measured curve is continuous, so the step
    is spread over a short share (BRIDGE_FRACTIONS) of the segment below each break. Where T2 or K3
    is missing the K2 segment is extended beyond T1; where K2 is missing K1 is; the notes say
    so.
    """
    t = np.abs(np.asarray(torque_Nm, dtype=float))
    knots, twists, notes = _knots(curve, float(t.max()) if t.size else 0.0)
    return np.sign(torque_Nm) * np.interp(t, knots, twists), notes


# Shares of a segment, just below T1 and T2, over which the difference between the printed θ
# and the segment slopes may be spread; the smallest that keeps the compliance positive on
# both bridges is used (design choice, shared with the proof tests' truth simulator: keeps
# the catalog slopes over ≥ 90 % of each segment; any width gives a continuous curve through
# the printed points).
BRIDGE_FRACTIONS = (0.02, 0.05, 0.10)


def _knots(curve: StiffnessCurve, t_max: float) -> tuple[list[float], list[float], list[str]]:
    """Torque and twist at the corners of the continuous piecewise-linear catalog curve."""
    top = max(t_max, 1e-12) * 1.001
    if curve.T1 is None or math.isinf(curve.T1) or curve.K2 is None:
        notes = [] if curve.T1 is None or math.isinf(curve.T1) or top <= curve.T1 else \
            ["K2 missing from the catalog: K1 used above T1"]
        return [0.0, top], [0.0, top / curve.K1], notes
    t1, notes = curve.T1, []
    theta1 = curve.theta1 if curve.theta1 is not None else t1 / curve.K1
    full = curve.T2 is not None and curve.K3 is not None
    t2 = curve.T2 if full else None
    theta2 = (curve.theta2 if curve.theta2 is not None else theta1 + (t2 - t1) / curve.K2) \
        if full else None
    for share in BRIDGE_FRACTIONS:
        below1 = (1 - share) * t1
        below2 = t2 - share * (t2 - t1) if full else None
        ok = theta1 > below1 / curve.K1 and (not full or
                                              theta2 > theta1 + (below2 - t1) / curve.K2)
        if ok:
            break
    else:
        notes.append("printed θ1/θ2 cannot be joined with positive compliance: the segment "
                     "slopes are used as printed")
    knots = [0.0, below1, t1]
    twists = [0.0, below1 / curve.K1, theta1]
    if full:
        knots += [below2, t2]
        twists += [theta1 + (below2 - t1) / curve.K2, theta2]
        last, slope = (t2, theta2), curve.K3
    else:
        last, slope = (t1, theta1), curve.K2
        if top > t1:
            notes.append("T2/K3 missing from the catalog: the K2 segment is extended above T1")
    knots.append(max(top, last[0] + 1.0))
    twists.append(last[1] + (knots[-1] - last[0]) / slope)
    return knots, twists, notes


def _curve(model: GearModel, kind: str) -> tuple[StiffnessCurve, str]:
    curve, source = stiffness_curve(model)
    if curve is None or curve.K1 is None:
        raise InputError("--model", f"model {model.code} has no stiffness data for {kind}")
    return curve, source


def catalog_figures(model: GearModel, catalog: Catalog) -> dict[str, tuple[float, str]]:
    """Catalog hysteresis loss, backlash (lost motion) and accuracy [rad] with their sources.

    Only the figures the catalog holds for this model are returned.
    """
    figures: dict[str, tuple[float, str]] = {}
    if model.is_fd:
        lost = model.get("lost_motion_rad")
        if lost is not None:
            figures["backlash_rad"] = (float(lost), lost.source)
        return figures
    series = model.series if model.family == "GH" else f"{model.series}-GH"
    for row in catalog.rows("gh_hysteresis", series=series):
        high = row.get("ratio_max")
        if row["ratio_min"] <= model.ratio and (high is None or model.ratio <= high):
            figures["hysteresis_rad"] = (float(row["hysteresis_rad"]),
                                         catalog.table("gh_hysteresis").row_source(row))
    if model.family == "GH":
        row = catalog.find("gh_backlash", series=model.series, size=model.size,
                           ratio=model.ratio)
        if row is not None:
            figures["backlash_rad"] = (float(row["backlash_rad"]),
                                       catalog.table("gh_backlash").row_source(row))
        rows = [r for r in catalog.rows("gh_performance", series=model.series,
                                        size=model.size, ratio=model.ratio)
                if r.get("accuracy_rad") is not None]
        if rows:  # the largest over the input codes of the size (051-1/059-1)
            figures["accuracy_rad"] = (max(float(r["accuracy_rad"]) for r in rows),
                                       catalog.table("gh_performance").row_source(rows[0]))
    return figures


def rated_torque(model: GearModel) -> tuple[float, str]:
    """Rated torque Tr [N·m] and its source; InputError when the catalog has none."""
    if model.is_fd:
        datum = dict(model.fd_torque_by_speed).get(FD_RATED_SPEED_RPM)
    else:
        datum = model.get("rated_torque_Nm")
    if datum is None:
        raise InputError("--model", f"model {model.code} has no rated torque for efficiency")
    return float(datum), datum.source


def _offset(n: int) -> np.ndarray:
    return np.ones((n, 1))


def torsion(data: dict, model: GearModel, catalog: Catalog) -> Baseline:
    """Twist [rad] = catalog curve(T) + zero offset (the only free parameter)."""
    curve, source = _curve(model, "torsion")
    torque = data["torque_Nm"]
    fixed, notes = twist_of(curve, torque)
    figures = catalog_figures(model, catalog)
    figures["K1_Nm_per_rad"] = (curve.K1, source)
    return Baseline("torsion", data["twist_rad"], fixed, _offset(len(torque)), ("offset",),
                    ("rad",), "rad", figures, notes, {"torque_Nm": torque})


def transmission(data: dict, model: GearModel, catalog: Catalog) -> Baseline:
    """Output angle [rad] = input angle / R + offset (formula 021-1; R fixed by the code)."""
    phi = data["input_angle_rad"]
    figures = catalog_figures(model, catalog)
    figures["ratio"] = (float(model.ratio), "model code")
    notes = ["output turns in the same direction as the input (sign convention of the data)"]
    return Baseline("transmission", data["output_angle_rad"], phi / model.ratio,
                    _offset(len(phi)), ("offset",), ("rad",), "rad", figures, notes,
                    {"wg_angle_rad": phi})


def efficiency(data: dict, model: GearModel, catalog: Catalog) -> Baseline:
    """Efficiency [%] = η0, a constant fitted to the data (the rated-torque efficiency)."""
    tr, source = rated_torque(model)
    torque = data["load_torque_Nm"]
    figures = {"rated_torque_Nm": (tr, source)}
    eta_r = model.get("efficiency_rated_pct")
    if eta_r is not None:
        figures["efficiency_rated_pct"] = (float(eta_r), eta_r.source)
    notes = [f"α = T/Tr with Tr = {tr:g} N·m ({source})"]
    return Baseline("efficiency", data["efficiency_pct"], np.zeros_like(torque),
                    _offset(len(torque)), ("eta0",), ("%",), "%", figures, notes,
                    {"alpha": torque / tr, "temperature_C": data["temperature_C"],
                     "input_speed_rpm": data["input_speed_rpm"], "load_torque_Nm": torque})


def vibration(data: dict, model: GearModel, catalog: Catalog,
              load_inertia_kgm2: float | None) -> Baseline:
    """Load vibration [rad] with no excitation: zero, plus a zero offset.

    The gear's spring K (catalog K1: the load is an inertia only, so the torque stays low) and
    the load inertia J define the resonance f_n = √(K/J)/2π (formula 021-3) the transmission
    error effects excite.
    """
    if load_inertia_kgm2 is None:
        raise InputError("--load-inertia", "vibration needs the load inertia [kg·m²]")
    if not load_inertia_kgm2 > 0:
        raise InputError("--load-inertia", f"{load_inertia_kgm2} must be > 0 kg·m²")
    curve, source = _curve(model, "vibration")
    t, speed = data["time_s"], data["input_speed_rpm"]
    omega = 2 * math.pi * speed / 60.0
    wg = np.concatenate([[0.0], np.cumsum(0.5 * (omega[1:] + omega[:-1]) * np.diff(t))])
    figures = catalog_figures(model, catalog)
    figures["K1_Nm_per_rad"] = (curve.K1, source)
    figures["J_kgm2"] = (float(load_inertia_kgm2), "--load-inertia")
    fn = math.sqrt(curve.K1 / load_inertia_kgm2) / (2 * math.pi)
    notes = [f"f_n = √(K1/J)/2π = {fn:.4g} Hz; te_2x resonance at {fn * 30:.4g} r/min, "
             f"te_1x at {fn * 60:.4g} r/min (seed 000 p.021)"]
    return Baseline("vibration", data["output_vibration_rad"], np.zeros_like(t),
                    _offset(len(t)), ("offset",), ("rad",), "rad", figures, notes,
                    {"time_s": t, "input_speed_rpm": speed, "wg_angle_rad": wg,
                     "K_Nm_per_rad": np.array(curve.K1), "J_kgm2": np.array(load_inertia_kgm2)})


def build(kind: str, data: dict, model: GearModel, catalog: Catalog,
          load_inertia_kgm2: float | None = None) -> Baseline:
    """The :class:`Baseline` of ``kind`` for ``model``."""
    if kind == "vibration":
        return vibration(data, model, catalog, load_inertia_kgm2)
    return {"torsion": torsion, "transmission": transmission,
            "efficiency": efficiency}[kind](data, model, catalog)
