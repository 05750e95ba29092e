"""The library of physical effects a catalog model may be missing.

Each effect is a frozen :class:`Effect`: its name (the JSON name), a physical description
citing the seed page, the parametric form, its parameters with units and bounds, and the
measurement kinds it applies to. The forms are plain functions below; the workflow turns them
into design-matrix columns (:func:`columns`): parameters that enter linearly (amplitudes) are
solved by linear least squares, the others (shapes, widths, damping) by
``scipy.optimize.least_squares``.

Bounds are written as multiples of a *scale*: a catalog figure where the catalog has one
(hysteresis loss, backlash, accuracy: tables 052/060, 052-2/060-2, 051-1/059-1; FD lost motion
314-1) or a range of the data (the largest torque T0 of a torsion test). Where the catalog
lacks the figure, the workflow substitutes a data-based scale and says so.

References
----------
Seed 000 p.020: torque-twist curve; hysteresis loss (B−B′ after loading to rated torque and
back to zero; caused by internal friction, so almost none at very small torque); backlash
(the clearance of the wave generator's Oldham coupling; the tooth mesh has none); the twist
of the component alone excludes output shafts and housing.
Seed 000 p.021: angular transmission error θer = θ2 − θ1/R, mainly two cycles per WG
revolution; it appears as torsional vibration of the load and resonates when 2·f_input = f_n,
f_n = (1/2π)·√(K/J).
Seed 000 p.023: efficiency depends on ratio, input speed, load torque, temperature and
lubrication; below rated torque η = Ke·ηR, α = T/Tr, Ke = 1 for α ≥ 1 (graph 023-1; one point
survives: α = 0.58 → Ke = 0.93).
Bouc, R. (1971); Wen, Y.-K. (1976) "Method for random vibration of hysteretic systems",
J. Eng. Mech. 102(2): the hysteresis form below is their first-order (n = 1) model.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

# Torque reversals smaller than this fraction of the torque range are noise, not a new
# loading branch (design choice: a quasi-static rig's torque signal is smooth; 2 % ignores
# measurement ripple while any real reversal of the cycle is far larger).
TURN_FRACTION = 0.02


@dataclass(frozen=True)
class Parameter:
    """One effect parameter: bounds are ``lower·scale … upper·scale`` in ``unit``."""

    name: str
    unit: str
    description: str
    lower: float
    upper: float
    scale: str = "1"       # context key: a catalog figure or a data range ('1' = absolute)
    linear: bool = False   # solved by linear least squares (an amplitude)
    start: float | None = None  # fixed start of the shape fit (not grid-searched)


@dataclass(frozen=True)
class Effect:
    """A physical effect the catalog model may miss."""

    name: str
    description: str
    form: str
    parameters: tuple[Parameter, ...]
    kinds: tuple[str, ...]

    @property
    def nonlinear(self) -> tuple[Parameter, ...]:
        return tuple(p for p in self.parameters if not p.linear)


# Shared nonlinear parameters: one value per model, whichever effect brings them.
SHARED = ("damping_ratio", "stiffness_scale")


def key_of(effect: str, param: str) -> str:
    """The name of an effect's parameter in a fit's ``theta``."""
    return param if param in SHARED else f"{effect}.{param}"


# --------------------------------------------------------------------------- forms
def turning_points(x: np.ndarray, threshold: float) -> tuple[np.ndarray, int]:
    """Indices where a quasi-static signal reverses by more than ``threshold``.

    Returns (branch start indices, direction of the first branch ±1). A branch starts at the
    extreme sample of the reversal.
    """
    values = x.tolist()
    start, direction, ext_i = [0], 0, 0
    first = 0
    for i in range(1, len(values)):
        v = values[i]
        if direction == 0:
            if abs(v - values[0]) >= threshold:
                direction = first = 1 if v > values[0] else -1
                ext_i = i
        elif (v - values[ext_i]) * direction > 0:
            ext_i = i
        elif (values[ext_i] - v) * direction >= threshold:
            start.append(ext_i)
            direction, ext_i = -direction, i
    return np.asarray(start), first or 1


@functools.lru_cache(maxsize=64)
def _bouc_wen_table(rho: float, n: float) -> tuple[np.ndarray, np.ndarray]:
    """(G, w): G(w) = ∫₀^w dw'/f(w') of the normalised Bouc–Wen branch, increasing in w.

    f(w) = 1 − wⁿ for w ≥ 0 (towards saturation) and 1 + ρ·|w|ⁿ for w < 0. The positive side
    is tabulated in s = −ln(1 − w), where the integrand e^(−s)/f stays finite (→ 1/n). Kept
    for the last shapes (a fit's steps in the loop's torque scale reuse the table; read
    only).
    """
    w_neg = np.linspace(-1.0, 0.0, 401)
    g_neg = _cumtrapz(1.0 / (1.0 + rho * np.abs(w_neg[::-1]) ** n), w_neg[::-1])
    s = np.linspace(0.0, 30.0, 1501)
    w_pos = -np.expm1(-s)
    # 1 − wⁿ with w = 1 − e^(−s), written to stay accurate as w → 1
    f_pos = -np.expm1(n * np.log1p(-np.exp(-s[1:])))
    integrand = np.concatenate([[1.0], np.exp(-s[1:]) / f_pos])
    g_pos = _cumtrapz(integrand, s)
    return (np.concatenate([g_neg[::-1][:-1], g_pos]),
            np.concatenate([w_neg[:-1], w_pos]))


def _cumtrapz(y: np.ndarray, x: np.ndarray) -> np.ndarray:
    return np.concatenate([[0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(x))])


def _bouc_wen_branch(v: np.ndarray, w0: float, table) -> np.ndarray:
    """Normalised state w along one branch from w0; v ≥ 0 torque travelled / T_s.

    dw/dv = f(w) is autonomous, so w(v) = G⁻¹(G(w0) + v).
    """
    g, w = table
    return np.interp(np.interp(w0, w, g) + v, g, w)


def hysteresis_state(torque_Nm: np.ndarray, T_s: float, rho: float, n: float = 1.0,
                     branches: tuple[np.ndarray, int] | None = None,
                     z_start: float = 0.0, first_scale: float = 1.0) -> np.ndarray:
    """Hysteretic twist z [rad per rad of z_sat] along a torque history T [N·m].

    Bouc–Wen model written as a function of torque, normalised so that z saturates at ±1:
    dz/dT = (1/T_s)·[1 − |z|ⁿ·(β·sgn(dT·z) + γ)], β + γ = 1, ρ = β − γ. z rises towards
    +1 on loading and falls towards −1 on unloading over a torque scale T_s; n sets how
    sharply it saturates; ρ = 1, n = 1 is Dahl's friction model (a Masing loop with an
    exponential backbone), ρ = 0 unloads linearly until z changes sign. Starts from
    z = ``z_start`` (0: virgin state; a gear with a loading history before the record starts
    anywhere in −1…1). The first branch runs over the torque scale ``first_scale``·T_s: 1 is
    plain Bouc–Wen, 0.5 makes Dahl's model obey Masing's rule (the virgin curve is the loop
    branch halved in both axes; Masing 1926). Friction makes the twist lag the torque (smaller on loading than on
    unloading, so the loop absorbs energy and a positive twist B remains after unloading from
    +T, seed 000 p.020): the twist contribution is −z_sat·z. Each loading branch (between
    turning points) is solved exactly by quadrature of the autonomous branch equation.
    """
    if branches is None:
        branches = turning_points(torque_Nm, TURN_FRACTION * np.ptp(torque_Nm))
    table = _bouc_wen_table(rho, n)
    starts, direction = branches
    z = np.empty_like(torque_Nm, dtype=float)
    bounds = list(starts) + [len(torque_Nm)]
    z0 = float(np.clip(z_start, -1.0, 1.0))
    scale = T_s * first_scale
    for s, e in zip(bounds[:-1], bounds[1:]):
        seg = torque_Nm[s:e + 1] if e < len(torque_Nm) else torque_Nm[s:e]
        travel = direction * (seg - seg[0])
        v = np.maximum.accumulate(np.maximum(travel, 0.0)) / scale
        scale = T_s
        w = _bouc_wen_branch(v, direction * z0, table)
        z[s:e] = direction * w[:e - s]
        z0 = direction * w[-1]
        direction = -direction
    return z


def _steady_start(T_s: float, rho: float, n: float, T0: float, table) -> float:
    """z at −T0 of steady cycles between ±T0 (the loop closes on itself)."""
    w0 = -1.0
    v = np.array([2.0 * T0 / T_s])
    for _ in range(500):
        w = _bouc_wen_branch(v, w0, table)
        if abs(-w[-1] - w0) < 1e-12:
            break
        w0 = -float(w[-1])
    return w0


def loop_centre(torque_Nm: np.ndarray, T_s: float, rho: float, n: float, T0: float
                ) -> np.ndarray:
    """Centre line of the steady major loop between ±T0 [N·m], in units of z, at T.

    Half the sum of the loading branch z↑(T) and the unloading one z↓(T) = −z↑(−T): the
    backbone a Bouc–Wen loop adds to the twist besides its width. A gear whose catalog curve
    is the centre of its own loop (the average of loading and unloading) has the loop
    z − centre about that curve.
    """
    table = _bouc_wen_table(rho, n)
    w0 = _steady_start(T_s, rho, n, T0, table)
    t = np.clip(np.asarray(torque_Nm, dtype=float), -T0, T0)
    grid = np.linspace(-T0, T0, 401)
    up = _bouc_wen_branch((grid + T0) / T_s, w0, table)
    return 0.5 * (np.interp(t, grid, up) - np.interp(-t, grid, up))


def hysteresis_loss(z_sat_rad: float, T_s: float, rho: float, n: float, T0: float) -> float:
    """Loop width at zero torque B − B′ [rad] of steady cycles between ±T0 [N·m].

    B is the twist left at zero torque after unloading from +T0, B′ after unloading from −T0,
    for the twist θ_catalog(T) − z_sat·z; positive for a friction loop. The catalog's
    hysteresis loss (seed 000 p.020) is this width for T0 = rated torque.
    """
    table = _bouc_wen_table(rho, n)
    w0 = _steady_start(T_s, rho, n, T0, table)
    return 2.0 * z_sat_rad * float(_bouc_wen_branch(np.array([T0 / T_s]), w0, table)[0])


def backlash_twist(torque_Nm: np.ndarray, lost_motion_rad: float, width_Nm: float,
                   exponent: float = 1.0) -> np.ndarray:
    """Lost motion around zero torque [rad]: (b/2)·sign(T)·tanh(|T/T_w|^p).

    A clearance b lets the output move b with (almost) no torque; seen as twist against
    torque it is a step of height b at T = 0, smoothed over a torque width T_w (the contact
    closes gradually). The engagement exponent p [-] (1 while effects are named, fitted
    once backlash is: :func:`hdcad.reconcile.refine.refine_play`) is the take-up's
    smoothness: p > 1,
    the play barely moves until the torque nears T_w and then closes steeply (a slider held
    centred, lugs that touch together); p < 1, it starts at once and closes ever more
    slowly (contact spreading over lugs or along a line); p = 1 is the plain tanh. Odd and
    single-valued in T: unlike hysteresis, it does not depend on the direction of loading.
    A play held by friction is crossed only once the load passes the holding torque T_h in
    the new direction: T − d·T_h (d = +1 loading, −1 unloading; fitted once backlash is
    named, :func:`hdcad.reconcile.refine.refine_play`).

    References: Karnopp, D. (1985) "Computer simulation of stick-slip friction in mechanical
    dynamic systems", J. Dyn. Syst. Meas. Control 107: 100-103 (the stuck side held until
    the force passes the breakaway level). Nordin, M., Gutman, P.-O. (2002) "Controlling
    mechanical systems with backlash — a survey", Automatica 38(10): 1633-1649 (dead-zone
    forms, sharp and smoothed).
    """
    x = np.asarray(torque_Nm, dtype=float) / width_Nm
    if exponent == 1.0:
        return 0.5 * lost_motion_rad * np.tanh(x)
    return 0.5 * lost_motion_rad * np.sign(x) * np.tanh(np.abs(x) ** exponent)


def before_first_hold(torque_Nm: np.ndarray, hold_Nm: float) -> np.ndarray:
    """True on the rows before the torque first passes ±T_h [N·m], in record order: a play
    that friction holds stays where the last handling left it until then (anywhere within
    its clearance), so its twist there is a position of its own, not a flank's."""
    passed = np.abs(np.asarray(torque_Nm, dtype=float)) > hold_Nm
    first = int(np.argmax(passed)) if passed.any() else len(passed)
    return np.arange(len(passed)) < first


def branch_direction(n: int, branches: tuple[np.ndarray, int]) -> np.ndarray:
    """+1 on the rows of loading branches, −1 on unloading ones (``branches`` as from
    :func:`turning_points`: branch start indices and the first branch's direction)."""
    starts, first = branches
    out = np.empty(n)
    bounds = list(starts) + [n]
    for k, (s, e) in enumerate(zip(bounds[:-1], bounds[1:])):
        out[s:e] = first * (-1) ** k
    return out


def harmonic_error(wg_angle_rad: np.ndarray, order: int, amplitude_rad: float,
                   phase_rad: float) -> np.ndarray:
    """Transmission error at the output [rad]: a·sin(k·φ + p), k cycles per WG revolution."""
    return amplitude_rad * np.sin(order * wg_angle_rad + phase_rad)


# --------------------------------------------------------------------------- library
_TE_FORM = ("e(φ) = a·sin({k}·φ + p), φ = WG (input) angle; transmission: output = "
            "input/R + e; vibration: J·θ'' + c·θ' + K·θ = K·e(t), c = 2ζ√(KJ), on the "
            "catalog's three-segment curve T(θ − e) where the twist passes T1/K1, or the "
            "steady state θ = K*·e/(K* − Jω²), K* = K·(1 + 2iζ), with structural damping")


def _te(order: int, what: str) -> Effect:
    return Effect(
        name=f"te_{order}x",
        description=(f"Angular transmission error {order} time(s) per wave-generator revolution "
                     f"({what}); seed 000 p.021 (formula 021-1 θer = θ2 − θ1/R; the error "
                     "appears as torsional vibration of the load and resonates at N = "
                     f"f_n·60/{order})."),
        form=_TE_FORM.format(k=order),
        parameters=(
            Parameter("amplitude", "rad", "amplitude a of the output error", 0.0, 20.0,
                      "accuracy_rad", linear=True),
            Parameter("phase", "rad", "phase p at φ = 0", -math.pi, math.pi, linear=True),
            Parameter("damping_ratio", "-", "damping ratio ζ of the joint (vibration only)",
                      0.002, 0.5),
            Parameter("stiffness_scale", "-", "joint stiffness / catalog K1 (vibration only; "
                      "the catalog's scatter, refitted with the resonance)", 0.5, 2.0,
                      start=1.0),
        ),
        kinds=("transmission", "vibration"))


EFFECTS: dict[str, Effect] = {e.name: e for e in (
    Effect(
        name="hysteresis",
        description=("Hysteresis loss: after loading to rated torque and back to zero the "
                     "twist does not return to zero (B−B′); internal friction makes the twist "
                     "depend on the loading direction, a loop (seed 000 p.020; figures seed "
                     "003 p.052/p.060)."),
        form=("θ = θ_catalog(T) − z_sat·z(T history; T_s, ρ, n, z0, first_scale)  "
              "(Bouc–Wen in torque: friction in parallel with the gear); with a series "
              "spring of compliance z_sat/T_s it reads as a slip element in series, "
              "θ_catalog(T) + z_sat·(T/T_s − z) (Iwan, Preisach)"),
        parameters=(
            Parameter("z_sat", "rad", "saturation of the hysteretic twist", 0.0, 20.0,
                      "hysteresis_rad", linear=True),
            Parameter("T_s", "N·m", "torque over which the loop saturates", 0.01, 5.0, "T0"),
            Parameter("rho", "-", "branch shape (1 = Dahl/Masing, 0 = linear unloading)",
                      -0.9, 5.0),
            Parameter("n", "-", "sharpness of the saturation", 0.5, 4.0),
            Parameter("z0", "-", "hysteretic state at the first sample (0 = virgin; the "
                      "loading history before the record is unknown)", -1.0, 1.0, start=0.0),
            Parameter("first_scale", "-", "torque scale of the first loading branch / T_s "
                      "(1 = Bouc–Wen; Masing's rule halves it from the virgin state)", 0.2, 2.0,
                      start=1.0),
        ),
        kinds=("torsion",)),
    Effect(
        name="backlash",
        description=("Lost motion around zero torque: the clearance of the wave generator's "
                     "Oldham coupling (the tooth mesh has none), measured at the output with "
                     "the input locked (seed 000 p.020; table 052-2/060-2; FD 314-1)."),
        form=("θ = θ_catalog(T) + (b/2)·tanh(T/T_w); once named, its engagement exponent p "
              "(sign(T)·tanh(|T/T_w|^p)) and b may change along the "
              "record u: b0 + b1·P1(u) + b2·P2(u) or a step b0 + d·[u ≥ u_s]"),
        parameters=(
            Parameter("lost_motion", "rad", "lost motion b", 0.0, 20.0, "backlash_rad",
                      linear=True),
            Parameter("T_w", "N·m", "torque width of the transition", 0.002, 0.3, "T0"),
        ),
        kinds=("torsion",)),
    Effect(
        name="housing_compliance",
        description=("An extra spring in series (housing, shafts, fixture): the catalog twist "
                     "is of the component alone and excludes output shafts (seed 000 p.020), so "
                     "the measured twist is larger than the catalog stiffness gives."),
        form=("θ = θ_catalog(T) + T/K_h; a spring that stiffens: θ = θ_catalog(T) + "
              "T_k·u/K_h, u + u³ = T/T_k (K_h its stiffness at T = 0)"),
        parameters=(
            Parameter("compliance", "rad/(N·m)", "1/K_h", 0.0, 10.0, "1/K1", linear=True),
        ),
        kinds=("torsion",)),
    _te(1, "eccentricity of the wave generator or the output"),
    _te(2, "the wave generator's ellipse: the main component"),
    Effect(
        name="low_load_efficiency",
        description=("Efficiency falls when the load torque is below rated: η = Ke·ηR, "
                     "α = T/Tr, Ke = 1 for α ≥ 1 (seed 000 p.023, graph 023-1: α = 0.58 → "
                     "Ke = 0.93)."),
        form=("η = Ke(α, n)·η0, Ke = (α(1 + c_n)/(α + c_n))^q for α < 1, 1 above; "
              "c_n = c·(n/1000 r/min)^s; once named, Ke = 1 − c_n/(1 + c_n)·(1 − α)^q "
              "(flat at rated torque) where that fits better"),
        parameters=(
            Parameter("c", "-", "load-independent loss as a fraction of rated power at "
                      "1000 r/min input speed", 1e-4, 3.0),
            Parameter("q", "-", "shape exponent", 0.2, 5.0),
            Parameter("s", "-", "speed exponent of the no-load loss (0: independent of "
                      "speed; drag and churning torques rise about as n^0.3…n^1)", 0.0, 1.5),
        ),
        kinds=("efficiency",)),
    Effect(
        name="temperature_dependence",
        description=("Efficiency changes with the lubricant temperature through the "
                     "viscosity of the grease or oil (seed 000 p.023 lists temperature among "
                     "the factors; its example is at 20 °C lubricant temperature)."),
        form=("η = η0·Ke(α)/(1 + a·(g − 1)·v + c·(1/g − 1)/v), g = ν(t)/ν(20 °C) = "
              "exp(−b·Δt/(1 + Δt/(20 °C + C))), Δt = t − 20 °C, C of the viscosity law "
              "(Reynolds ∞, Andrade 273.15 °C, Vogel–Cameron 95 °C), v = (n/1000 r/min)^s"),
        parameters=(
            Parameter("a", "-", "viscous loss / input power at 20 °C and 1000 r/min "
                      "(negative: efficiency falls as the gear warms)", -0.5, 0.9),
            Parameter("b", "1/K", "temperature coefficient of the viscosity", 0.002, 0.2),
            Parameter("s", "-", "speed exponent of the viscous share (0: the same at every "
                      "speed; viscous drag goes with viscosity × speed)", 0.0, 1.5,
                      start=0.0),
            Parameter("boundary", "-", "boundary-friction loss share at 20 °C and 1000 r/min "
                      "that grows as the film thins (Stribeck: efficiency peaks at a middle "
                      "temperature; 0: a monotone law)", 0.0, 0.5, start=0.0),
        ),
        kinds=("efficiency",)),
)}

EFFECT_NAMES = ("hysteresis", "backlash", "housing_compliance", "te_1x", "te_2x",
                "low_load_efficiency", "temperature_dependence")


def applicable(kind: str) -> tuple[str, ...]:
    """Names of the effects that apply to ``kind``, in library order."""
    return tuple(n for n, e in EFFECTS.items() if kind in e.kinds)


def nonlinear_parameters(name: str, kind: str) -> tuple[Parameter, ...]:
    """The effect's parameters fitted by nonlinear least squares for this kind."""
    params = EFFECTS[name].nonlinear
    if name.startswith("te_") and kind != "vibration":
        return ()
    return params
