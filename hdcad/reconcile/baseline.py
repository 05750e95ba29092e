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

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from ..catalog import Catalog
from ..checks.run import stiffness_curve
from ..checks.stiffness import StiffnessCurve
from ..errors import InputError
from ..models import GearModel
from .effects import Parameter
from .rig import TORQUE_GAIN_KEY, TORQUE_OFFSET_KEY, block_position

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
    curve: StiffnessCurve | None = None
    spring: StiffnessCurve | None = None  # vibration: the joint's catalog curve
    # torsion: the free columns by corner width and rows, the last few (a fit moves the width
    # in one of its directions at a time, on the same rows)
    _kept: dict = field(default_factory=dict, repr=False, compare=False)

    def free_columns(self, theta: dict[str, float], rows=slice(None)) -> np.ndarray:
        """The free columns on ``rows`` with the nuisance shape ``theta`` (torsion: the catalog
        curve with corner width ``catalog.corner_width``, read at the true torque when the
        torque channel's gain ``sensor_gain.torque_gain`` or its zero offset
        ``torque_offset.T_off`` is fitted; the array is kept for
        the next call, so it is read only)."""
        if self.curve is None:
            return self.free[rows]
        torque = self.inputs["torque_Nm"]
        width = float(theta.get("catalog.corner_width", 0.0))
        gain = float(theta.get(TORQUE_GAIN_KEY, 0.0))
        zero = float(theta.get(TORQUE_OFFSET_KEY, 0.0))
        every = isinstance(rows, slice) and rows == slice(None)
        key = (width, gain, zero, None if every else id(rows))
        kept = self._kept.get(key)  # the same torque and rows objects, not merely their ids
        if kept is None or kept[0] is not torque or not (every or kept[1] is rows):
            if len(self._kept) >= _WIDTHS_KEPT:
                del self._kept[next(iter(self._kept))]
            kept = (torque, rows, _torsion_columns(self.curve,
                                                   (torque[rows] - zero) / (1.0 + gain), width))
            self._kept[key] = kept
        return kept[2]


_WIDTHS_KEPT = 8


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


def catalog_twist(curve: StiffnessCurve, torque_Nm: np.ndarray, width_Nm: float
                  ) -> np.ndarray:
    """Catalog twist θ [rad] at torque T [N·m] from the defining data K1, K2, K3, T1, T2.

    The compliance steps from 1/K1 to 1/K2 at T1 and to 1/K3 at T2 (seed 000 p.020); a real
    curve has no corners, so each step is a logistic of width w [N·m], integrated in closed
    form with softplus: θ = t/K1 + (1/K2 − 1/K1)·w·[sp((t − T1)/w) − sp(−T1/w)] + (1/K3 −
    1/K2)·w·[sp((t − T2)/w) − sp(−T2/w)], t = |T|, odd in T. w → 0 is the three-segment
    curve. The printed θ1, θ2 are rounded results of these data and are not used. Where T2/K3
    are missing the K2 segment continues; where T1/K2 are, K1 does.
    """
    t = np.abs(np.asarray(torque_Nm, dtype=float))
    theta = t / curve.K1
    w = max(float(width_Nm), 1e-9)
    for corner, jump in _steps(curve):
        theta = theta + jump * w * (np.logaddexp(0.0, (t - corner) / w)
                                    - np.logaddexp(0.0, -corner / w))
    return np.sign(torque_Nm) * theta


def catalog_compliance(curve: StiffnessCurve, torque_Nm: np.ndarray, width_Nm: float
                       ) -> np.ndarray:
    """dθ/dT [rad/(N·m)] of :func:`catalog_twist`: 1/K1, stepping to 1/K2 at T1 and to 1/K3
    at T2 by logistics of width w (even in T)."""
    t = np.abs(np.asarray(torque_Nm, dtype=float))
    out = np.full_like(t, 1.0 / curve.K1)
    w = max(float(width_Nm), 1e-9)
    for corner, jump in _steps(curve):
        out = out + jump * 0.5 * (1.0 + np.tanh((t - corner) / (2.0 * w)))
    return out


def _steps(curve: StiffnessCurve) -> list[tuple[float, float]]:
    """(corner torque [N·m], compliance step [rad/(N·m)]) of the curve's segments."""
    steps = []
    if curve.T1 is not None and not math.isinf(curve.T1) and curve.K2 is not None:
        steps.append((curve.T1, 1.0 / curve.K2 - 1.0 / curve.K1))
        if curve.T2 is not None and curve.K3 is not None:
            steps.append((curve.T2, 1.0 / curve.K3 - 1.0 / curve.K2))
    return steps


def _curve_notes(curve: StiffnessCurve) -> list[str]:
    if curve.T1 is None or math.isinf(curve.T1) or curve.K2 is None:
        return ["T1/K2 missing from the catalog: K1 used over the whole range"]
    if curve.T2 is None or curve.K3 is None:
        return ["T2/K3 missing from the catalog: the K2 segment is extended above T1"]
    return []


# Nonlinear nuisance parameters of each kind's baseline, fitted in every model.
NUISANCE = {"torsion": (Parameter(
    "corner_width", "N·m", "torque width over which the compliance changes at T1 and T2",
    0.01, 1.0, "T1"),)}

# Largest gain error of the output angle channel read as the sensor's (transmission): the
# ratio is exact, so a slope error is the channel's; a unit error (degrees, ×57.3) is found
# before the fit, and a slope of the output nowhere near 1/R is not a gain error (an input
# angle read with its own error, e.g. an eccentric input encoder, must not trade the input
# for the record's time).
ANGLE_GAIN_LIMIT = 0.2

# Input speed at which the efficiency level η0 is given [r/min] (the speed nuisance's zero).
SPEED_REFERENCE_RPM = 1000.0

# The seeds call the stiffness table's values averages (seed 000 p.020) and state no spread;
# ±10 % is assumed for the scatter of a real gear about them (printed with the result).
STIFFNESS_SPREAD = 0.10
# the compliance scale of a gear within that spread (stiffness 1 ± spread)
COMPLIANCE_SCALE_BOUNDS = (1.0 / (1.0 + STIFFNESS_SPREAD), 1.0 / (1.0 - STIFFNESS_SPREAD))


def torsion(data: dict, model: GearModel, catalog: Catalog) -> Baseline:
    """Twist [rad] = s·θ_catalog(T; w) + offset.

    The catalog's scatter is fitted, not treated as a missing effect: the compliance scale s
    (1/s is the stiffness relative to the catalog) and the corner width w (a nonlinear
    nuisance the fit adds, :data:`NUISANCE`) are free in every model.
    """
    curve, source = _curve(model, "torsion")
    torque = data["torque_Nm"]
    figures = catalog_figures(model, catalog)
    figures["K1_Nm_per_rad"] = (curve.K1, source)
    figures["T1_Nm"] = (curve.T1 if curve.T1 and not math.isinf(curve.T1) else
                        float(np.max(np.abs(torque))), source)
    notes = _curve_notes(curve) + [
        f"catalog stiffness scatter: ±{STIFFNESS_SPREAD:.0%} assumed (seed 000 p.020 gives "
        "average values and no spread); a twist sensor's gain reads the same (a torque "
        "channel's gain moves the curve's corners and is looked for as the rig's)"]
    n = len(torque)
    free = _torsion_columns(curve, torque, 0.0)
    names, units = ("compliance_scale", "offset"), ("-", "rad")
    if free.shape[1] > 2:
        names, units = names + ("printed_reading",), units + ("-",)
        notes.append(_printed_note(curve))
    inputs = {"torque_Nm": torque, "measured_rad": data["twist_rad"]}
    if "time_s" in data:  # the logger's time, for a loop that follows the loading rate
        inputs["time_s"] = data["time_s"]
    base = Baseline("torsion", data["twist_rad"], np.zeros(n), free, names, units, "rad",
                    figures, notes, inputs, curve)
    return base


def _torsion_columns(curve: StiffnessCurve, torque: np.ndarray, width: float) -> np.ndarray:
    """The catalog twist, a constant and, where the tables print θ1/θ2, the printed
    reading's departure from the defining data (:func:`printed_departure`)."""
    columns = [catalog_twist(curve, torque, width), np.ones(len(torque))]
    if _departures(curve):
        columns.append(printed_departure(curve, torque, width))
    return np.column_stack(columns)


@functools.lru_cache(maxsize=64)
def _departures(curve: StiffnessCurve) -> tuple[tuple[float, float], ...]:
    """(T1 or T2 [N·m], printed θ less the T/K data's θ there [rad]) where θ is printed
    (kept per curve: the fits ask for them at every step of the corner width)."""
    out = []
    for (corner, _), printed in zip(_steps(curve), (curve.theta1, curve.theta2)):
        if printed is None:
            break
        out.append((corner, printed - float(catalog_twist(curve, np.array([corner]), 0.0)[0])))
    return tuple(out)


def printed_departure(curve: StiffnessCurve, torque_Nm: np.ndarray, width_Nm: float
                      ) -> np.ndarray:
    """The printed reading of the curve less the defining data's [rad]: θ = θ1 + (T − T1)/K2
    above T1 with the printed θ1 (as seed 000 p.020's worked example reads it), not
    T1/K1, and likewise θ2; steps at T1 and T2 (logistics of width w, as the compliance
    steps of :func:`catalog_compliance`), odd in T."""
    t = np.abs(np.asarray(torque_Nm, dtype=float))
    w = max(float(width_Nm), 1e-9)
    out, below = np.zeros_like(t), 0.0
    for corner, departure in _departures(curve):
        out = out + (departure - below) * 0.5 * (1.0 + np.tanh((t - corner) / (2.0 * w)))
        below = departure
    return np.sign(torque_Nm) * out


def _printed_note(curve: StiffnessCurve) -> str:
    words = " and ".join(f"θ{i} {abs(d):.3g} rad {'above' if d > 0 else 'below'}"
                         for i, (_, d) in enumerate(_departures(curve), start=1))
    return (f"the tables print {words} the T/K data's values: the curve is fitted anywhere "
            "between the T/K data "
            "(printed_reading 0) and the printed values (1), a nuisance (seed 000 p.020's "
            "worked example reads the printed θ1)")


def transmission(data: dict, model: GearModel, catalog: Catalog) -> Baseline:
    """Output angle [rad] = input angle / R + offset (formula 021-1; R fixed by the code)."""
    phi = data["input_angle_rad"]
    figures = catalog_figures(model, catalog)
    figures["ratio"] = (float(model.ratio), "model code")
    notes = ["output turns in the same direction as the input (sign convention of the data)",
             "the ratio is exact (tooth counts): a slope error of the output angle is the "
             "angle sensor's gain"]
    free = np.column_stack([phi / model.ratio, np.ones(len(phi))])
    return Baseline("transmission", data["output_angle_rad"], phi / model.ratio, free,
                    ("scale_error", "offset"), ("-", "rad"), "rad", figures, notes,
                    {"wg_angle_rad": phi, "output_angle_rad": phi / model.ratio,
                     "measured_rad": data["output_angle_rad"]})


def efficiency(data: dict, model: GearModel, catalog: Catalog) -> Baseline:
    """Efficiency [%] = η0 + η_n·ln(n/1000 r/min), fitted to the data: the rated-torque
    efficiency and how it changes with input speed.

    Both are nuisances: the catalog's efficiency curves (one per input speed, seed 000
    p.023) are lost, and they fall with speed, so a level that changes with speed is the
    catalog's own behaviour, not a missing effect (a temperature law must be named for the
    temperature, not for the speeds). η_n is left out when the test runs at one speed.
    """
    tr, source = rated_torque(model)
    torque, speed = data["load_torque_Nm"], data["input_speed_rpm"]
    figures = {"rated_torque_Nm": (tr, source)}
    eta_r = model.get("efficiency_rated_pct")
    if eta_r is not None:
        figures["efficiency_rated_pct"] = (float(eta_r), eta_r.source)
    notes = [f"α = T/Tr with Tr = {tr:g} N·m ({source})"]
    free, names, units = _offset(len(torque)), ("eta0",), ("%",)
    if np.ptp(speed) > 0 and np.all(speed > 0):
        free = np.column_stack([free, np.log(speed / SPEED_REFERENCE_RPM)])
        names, units = names + ("eta_speed",), units + ("%/ln(n/1000 r/min)",)
    return Baseline("efficiency", data["efficiency_pct"], np.zeros_like(torque),
                    free, names, units, "%", figures, notes,
                    {"alpha": torque / tr, "temperature_C": data["temperature_C"],
                     "input_speed_rpm": data["input_speed_rpm"], "load_torque_Nm": torque})


def vibration(data: dict, model: GearModel, catalog: Catalog,
              load_inertia_kgm2: float | None) -> Baseline:
    """Load vibration [rad] with no excitation: zero, plus a zero offset.

    The gear's spring K (catalog K1 while the twist stays below T1/K1) and the load inertia J
    define the resonance f_n = √(K/J)/2π (formula 021-3) the transmission error effects
    excite; a resonance that twists the gear past T1/K1 runs on the catalog's three-segment
    curve instead (``spring``, :mod:`.joint`).
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
    figures["ratio"] = (float(model.ratio), "model code")
    fn = math.sqrt(curve.K1 / load_inertia_kgm2) / (2 * math.pi)
    notes = [f"f_n = √(K1/J)/2π = {fn:.4g} Hz; te_2x resonance at {fn * 30:.4g} r/min, "
             f"te_1x at {fn * 60:.4g} r/min (seed 000 p.021)"]
    return Baseline("vibration", data["output_vibration_rad"], np.zeros_like(t),
                    _offset(len(t)), ("offset",), ("rad",), "rad", figures, notes,
                    {"time_s": t, "input_speed_rpm": speed, "wg_angle_rad": wg,
                     "K_Nm_per_rad": np.array(curve.K1), "J_kgm2": np.array(load_inertia_kgm2)},
                    spring=curve)


def build(kind: str, data: dict, model: GearModel, catalog: Catalog,
          load_inertia_kgm2: float | None = None) -> Baseline:
    """The :class:`Baseline` of ``kind`` for ``model``; rows are taken in time order
    (``record_position`` runs from −1 at the first row to 1 at the last)."""
    if kind == "vibration":
        base = vibration(data, model, catalog, load_inertia_kgm2)
        base.inputs["output_angle_rad"] = base.inputs["wg_angle_rad"] / model.ratio
    else:
        base = {"torsion": torsion, "transmission": transmission,
                "efficiency": efficiency}[kind](data, model, catalog)
    base.inputs["record_position"] = np.linspace(-1.0, 1.0, len(base.y))
    blocks = block_position(np.asarray(data["temperature_C"])) if kind == "efficiency" else None
    if blocks is not None:  # oven blocks: a drift may restart at each
        base.inputs["block_position"] = blocks
    return base


def catalog_curve(model: GearModel):
    """θ(T) [rad] of the model's catalog curve (sharp corners), for the unit check."""
    curve, _ = _curve(model, "torsion")
    return lambda torque: catalog_twist(curve, torque, 0.0)
