"""Parameters of the named effects with their units, as the final model has them."""

from __future__ import annotations

import math

import numpy as np

from . import creep, duhem, plays, spring_forms
from . import efficiency_laws as laws
from . import effects as fx
from .effects import key_of
from .fitting import Fit, Problem
from .model_columns import drift_labels, parameters_of, stribeck_takes
from .harmonics import TE_LABELS, frames_of, legendre, te_order_of
from .stribeck import hersey_params


def linear_of(fit: Fit, effect: str) -> dict[str, float]:
    """The linear amplitudes of ``effect`` in ``fit``, by name."""
    return {name: float(v) for (e, name), v in zip(fit.labels, fit.beta) if e == effect}


def play_along_record(problem: Problem, fit: Fit, points: int = 201
                      ) -> tuple[float, float, float, float]:
    """(start, end, least, largest) of a play's lost motion [rad] along the record, from its
    Legendre terms or its step in ``fit`` (:func:`.refine.refine_play_drift`)."""
    b = linear_of(fit, "backlash")
    u = np.linspace(-1.0, 1.0, points)
    along = np.polynomial.legendre.legval(
        u, [b["lost_motion"]] + [b[k] for k in drift_labels(problem.play_drift)])
    if problem.play_step is not None:
        along = along + b["lost_motion_step"] * (u >= problem.play_step)
    return float(along[0]), float(along[-1]), float(along.min()), float(along.max())


def _te(b: dict[str, float], th: dict[str, float]) -> dict[str, tuple[float, str]]:
    out = {"amplitude": (math.hypot(b["sin"], b["cos"]), "rad"),
           "phase": (math.atan2(b["cos"], b["sin"]), "rad")}
    if "sin_u1" in b:  # slowly varying amplitude: the largest over the record
        u = np.linspace(-1, 1, 201)
        polys = legendre(u, sum(1 for k in b if k.startswith("sin_u")))
        s = b["sin"] + sum(b[f"sin_u{k}"] * polys[k] for k in range(1, len(polys)))
        c = b["cos"] + sum(b[f"cos_u{k}"] * polys[k] for k in range(1, len(polys)))
        out["amplitude_max"] = (float(np.max(np.hypot(s, c))), "rad")
    for key in b:  # sidebands of a periodic modulation
        if key.startswith("sin_sb"):
            rest = key[4:]
            out[f"{rest}_amplitude"] = (math.hypot(b[key], b["cos_" + rest]), "rad")
    for key in b:  # overtones of the error's harmonic series
        if key.startswith("sin_") and key.endswith("x"):
            k = key[4:-1]
            out[f"amplitude_{k}x"] = (math.hypot(b[key], b[f"cos_{k}x"]), "rad")
    if "locked_2x" in b:  # the 2× overtone locked to the 1× error's phase
        out["amplitude_2x"] = (abs(b["locked_2x"]), "rad")
    for shared in ("damping_ratio", "stiffness_scale"):
        if shared in th:
            out[shared] = (th[shared], "-")
    return out


def _frames(problem: Problem, b: dict[str, float], order: int) -> dict[str, tuple[float, str]]:
    """The error's cycles per WG revolution, k·(1 + δ) in its frame δ, and the share of a
    second frame when there is one (``Problem.te_frames``)."""
    frame, second = frames_of(problem, order)
    if not (frame or second is not None):
        return {}
    out = {"cycles_per_wg_revolution": (order * (1 + frame), "-")}
    if second is not None:
        out["second_frame_cycles_per_wg_revolution"] = (order * (1 + second), "-")
        out["second_frame_amplitude"] = (math.hypot(b["sin_second"], b["cos_second"]), "rad")
    return out


PREISACH_FORM = ("θ = θ_catalog(T) + z_sat·f(T history)  (Preisach relay sum: "
                 "f = −E(α0, β0) + 2·Σ[E(M_k, m_k−1) − E(M_k, m_k)] over the alternating "
                 "dominant extrema of the torque, E the Everett function of lognormal slip "
                 "torques × normally spread relay centres; Mayergoyz 1991)")


PLAYS_FORM = ("θ = θ_catalog(T) − Σ a_k·s_k(T history)/r_k, a_k ≥ 0  (friction elements "
              "with slip torques r_k: stop operators, s_k = T − p_k with the play p_k kept "
              "within r_k of T; Iwan 1966)")
FLANK_FORM = ("θ = θ_catalog(T) − Σ a_k·s_k(T history)/(r_k + μ·T0), a_k ≥ 0  (friction "
              "elements whose slip torques grow with the torque carried: s_k = T − p_k with "
              "the play p_k kept within r_k + μ·|T| of T; flank friction, Tuttle & Seering "
              "1996)")
DUHEM_FORM = ("θ = θ_catalog(T) + z_sat·w(T history), dw/d|u| = λ·(−d·h − w), h = (A/T0)^p, "
              "u = T/T0, d the branch's direction, A half the last branch's excursion  (a "
              "Duhem loop whose height follows the last excursion; Dhaouadi, Ghorbel & "
              "Gandhi 2003)")
SERIES_PLAYS_FORM = ("θ = θ_catalog(T) + Σ a_k·p_k(T history)/r_k, a_k ≥ 0  (friction "
                     "elements in series with the gear: play operators p_k kept within the "
                     "slip torque r_k of T, each adding its slip past r_k; Prandtl–Ishlinskii, "
                     "Brokate & Sprekels 1996)")


def _plays(problem: Problem, b: dict[str, float]) -> dict[str, tuple[float, str]]:
    """A sum of friction elements: its saturation, loss at zero torque and each element in
    use (slip torque and weight)."""
    t0 = problem.scales["T0"]
    r = plays.thresholds(t0)
    # in series, the elements that slip below plays.SERIES_MIN_SHARE·T0 have no column
    a = np.array([b.get(f"a_{k}", 0.0) for k in range(len(r))])
    mu = problem.plays_load_share
    out = {"z_sat": (float(a.sum()), "rad"), "T0": (t0, "N·m"),
           "loss_at_T0": (plays.loss_at_zero(a, r, t0, mu), "rad")}
    if mu:  # each slip torque grows by μ·|T|
        out["load_share"] = (mu, "-")
    if problem.hysteresis_series:  # the compliance it adds once every element slips
        out["slip_compliance"] = (float(np.sum(a / r)), "rad/(N·m)")
    for k in np.flatnonzero(a):
        out[f"slip_torque_{k}"] = (float(r[k]), "N·m")
        out[f"weight_{k}"] = (float(a[k]), "rad")
    return out


HERSEY_FORM = ("η = (η0 + η_n·ln(n/n_ref) − d_b·exp(−H/H_b) − d_f·√H − d_v·H)·(the other "
               "named factor, if one is kept), H = ν(t)/ν(20 °C)·(n/1000 r/min)/α^r  (a "
               "Stribeck curve in Hersey's number; Stribeck 1902, Hersey 1914, Petroff "
               "1883)")
CREEP_FORM = ("θ = θ_catalog(T) + Σ c_k·(T_τk − T), c_k ≥ 0  (creep elements: standard "
              "linear solids, T_τk the torque through a first-order lag of relaxation time "
              "τ_k; Zener 1948)")


def _creep(problem: Problem, b: dict[str, float]) -> dict[str, tuple[float, str]]:
    """Creep elements: each one in use (relaxation time, delayed compliance) and the loop's
    width at zero torque they make over the record."""
    torque, t0 = problem.base.inputs["torque_Nm"], problem.scales["T0"]
    time = problem.base.inputs.get("time_s")
    tau, unit = creep.record_taus(len(torque), time)
    w = np.array([b.get(f"creep_{k}", 0.0) for k in range(len(tau))])
    out = {"creep_loss_at_zero_torque": (creep.loss_at_zero(w, tau, torque, t0, time), "rad")}
    for k in np.flatnonzero(w):
        out[f"relaxation_time_{k}"] = (float(tau[k]), unit)
        out[f"delayed_compliance_{k}"] = (float(w[k] / t0), "rad/(N·m)")
    return out


def effect_form(problem: Problem, effect: str) -> str:
    """The formula of the effect as the final model has it (the catalog of effects gives
    the form it is named with)."""
    if effect == "hysteresis" and problem.hysteresis_creep == "alone":
        return CREEP_FORM
    if effect == "hysteresis" and problem.hysteresis_creep:
        return f"{_loop_form(problem)}; beside it {CREEP_FORM}"
    if stribeck_takes(problem, effect):
        return HERSEY_FORM
    if effect == "housing_compliance" and math.isfinite(problem.housing_opening):
        return (f"{fx.EFFECTS[effect].form}; a joint that opens: + c_o·sign(T)·max(|T| − T_o, 0),"
                " c_o ≥ 0 (its compliance grows past T_o; VDI 2230 opening limit)")
    if effect == "backlash" and (problem.play_hold or problem.play_bias or problem.play_shape):
        return (f"{fx.EFFECTS[effect].form}"
                + ("; T − s·T_h − T_c in place of T (s = +1 loading, −1 unloading: held by "
                   "friction until the load passes T_h; crossed at T_c)"
                   if problem.play_hold or problem.play_bias else "")
                + ("; before the load first passes ±T_h the play's own start position"
                   if problem.play_start else "")
                + (f"; taken up as sign(T)·tanh(|T/T_w|^p), p = "
                   f"{math.exp(problem.play_shape):.2f}" if problem.play_shape else ""))
    if effect == "te_1x" and problem.te_locked_2x is not None:
        p, shift = problem.te_locked_2x
        return (f"{fx.EFFECTS[effect].form}; + b(u)·sin(2·φ + q), q = "
                f"{(2 * p + shift) % (2 * math.pi):.3f} rad: the 1× error's own 2× overtone, "
                "its phase locked to the 1×'s p (q = 2p + π/2 for a function of the 1×'s "
                "value, 2p for one of the member's angle; b along the record as a; in a "
                "vibration test a function of the value acts on the 1×'s response)")
    return _loop_form(problem) if effect == "hysteresis" else fx.EFFECTS[effect].form


def _loop_form(problem: Problem) -> str:
    """The formula of the friction loop as the final model has it."""
    if problem.hysteresis_duhem is not None:
        return DUHEM_FORM
    if problem.hysteresis_plays:
        return (SERIES_PLAYS_FORM if problem.hysteresis_series
                else FLANK_FORM if problem.plays_load_share else PLAYS_FORM)
    if problem.hysteresis_preisach is not None:
        return PREISACH_FORM
    return fx.EFFECTS["hysteresis"].form


def effect_params(problem: Problem, fit: Fit, effect: str) -> dict[str, dict]:
    """The gear effect's parameters with units (amplitudes, shapes and derived figures)."""
    b = linear_of(fit, effect)
    th = {p.name: fit.theta[key_of(effect, p.name)]
          for p in parameters_of(effect, problem.kind)}
    out: dict[str, tuple[float, str]] = {}
    if effect == "hysteresis" and problem.hysteresis_creep == "alone":
        out = {"T0": (problem.scales["T0"], "N·m")}
    elif effect == "hysteresis" and problem.hysteresis_plays:
        out = _plays(problem, b)
    elif effect == "hysteresis" and problem.hysteresis_duhem is not None:
        rate, power = problem.hysteresis_duhem
        out = {"z_sat": (b["z_sat"], "rad"), "relaxation_rate": (rate, "1/T0"),
               "height_power": (power, "-"), "T0": (problem.scales["T0"], "N·m"),
               "loss_at_T0": (duhem.loss_at_zero(b["z_sat"], rate, power), "rad")}
    elif effect == "hysteresis" and problem.hysteresis_preisach is not None:
        w, spread, c = problem.hysteresis_preisach
        out = {"z_sat": (b["z_sat"], "rad"), "slip_torque_median": (w, "N·m"),
               "slip_torque_log_spread": (spread, "-"), "centre_spread": (c, "N·m"),
               "T0": (problem.scales["T0"], "N·m"),
               "loss_at_T0": (b["z_sat"] * problem.preisach_plane.loss(w, spread, c), "rad")}
    elif effect == "hysteresis":
        t0 = problem.scales["T0"]
        out = {"z_sat": (b["z_sat"], "rad"), "T_s": (th["T_s"], "N·m"), "rho": (th["rho"], "-"),
               "n": (th["n"], "-"), "z0": (th["z0"], "-"),
               "first_scale": (th["first_scale"], "-"),
               "loss_at_T0": (fx.hysteresis_loss(b["z_sat"], th["T_s"], th["rho"], th["n"], t0),
                              "rad"),
               "T0": (t0, "N·m")}
        # the compliance of the loop read as a slip element in series (z_sat·(T/T_s − z))
        out["slip_compliance"] = (b["z_sat"] / th["T_s"], "rad/(N·m)")
    elif effect == "backlash":
        out = {"lost_motion": (b["lost_motion"], "rad"), "T_w": (th["T_w"], "N·m")}
        if problem.play_shape:  # the take-up's engagement exponent, where it is not tanh's
            out["engagement_exponent"] = (math.exp(problem.play_shape), "-")
        if problem.play_start:  # where the record found it, before the load passed T_h
            out["start_position"] = (b["start_position"], "rad")
        if problem.play_drift or problem.play_step is not None:  # where it starts and ends
            start, end, _, _ = play_along_record(problem, fit)
            out.update({"lost_motion_at_start": (start, "rad"),
                        "lost_motion_at_end": (end, "rad")})
        if problem.play_step is not None:  # 0 at the record's first row, 1 at its last
            out["step_at_share_of_record"] = ((1.0 + problem.play_step) / 2.0, "-")
    elif effect == "housing_compliance":
        c = b["compliance"]
        out = {"K_h": (1.0 / c if c > 0 else math.inf, "N·m/rad"), "compliance": (c, "rad/(N·m)")}
        knee = problem.housing_knee
        if math.isfinite(knee) and c > 0:  # a spring that stiffens: K_h is its value at T = 0
            u = float(spring_forms.progressive_twist(np.array(problem.scales["T0"]), knee)) / knee
            out.update({"T_k": (knee, "N·m"), "K_h_at_T0": ((1 + 3 * u * u) / c, "N·m/rad")})
        if math.isfinite(problem.housing_opening):  # past T_o the opened joint is softer
            opened = c + b.get("opening_compliance", 0.0)
            out.update({"T_o": (problem.housing_opening, "N·m"),
                        "K_h_opened": (1.0 / opened if opened > 0 else math.inf, "N·m/rad")})
    elif effect in ("te_1x", "te_2x"):
        out = {**_te(b, fit.theta), **_frames(problem, b, te_order_of(effect))}
        if te_order_of(effect) in problem.te_sidebands:
            out["modulation_period"] = (1.0 / problem.te_sidebands[te_order_of(effect)][0],
                                        "WG revolutions")
    elif stribeck_takes(problem, effect):
        out = hersey_params(problem, fit, effect)
    elif effect == "low_load_efficiency":
        out = {"c": (th["c"], "-"), "q": (th["q"], "-"), "s": (th["s"], "-"),
               "Ke_at_alpha_0.58_1000rpm": (
                   float(laws.low_load_factor(np.array(0.58), th["c"], th["q"],
                                             flat=problem.low_load_flat)), "-")}
    elif effect == "temperature_dependence":
        out = {"a": (th["a"], "-"), "b": (th["b"], "1/K"), "s": (th["s"], "-"),
               "boundary": (th["boundary"], "-"),
               "t_ref": (laws.REFERENCE_TEMPERATURE_C, "°C")}
    if effect == "hysteresis" and problem.hysteresis_creep:
        out.update(_creep(problem, b))
    return {k: {"value": float(v), "unit": u} for k, (v, u) in out.items()}


__all__ = ["effect_form", "effect_params", "linear_of", "play_along_record", "TE_LABELS"]
