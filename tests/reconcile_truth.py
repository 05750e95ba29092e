"""Truth simulator for the `hdcad reconcile` proof tests: measured data with hidden effects.

Written independently of ``hdcad.reconcile`` (nothing is imported from it): every hidden
effect has its own formulation here, so the library passes only if its effect forms fit
physics they were not written from.

- torsion: twist = ∫ compliance dT along the catalog curve (numerical integration, not the
  segment formula) + a Masing-rule hysteresis loop on a Ramberg–Osgood backbone (the
  library uses Bouc–Wen) + a smoothed dead zone (backlash) solved numerically + a series
  housing spring.
- transmission: output = input/R + offset + TE harmonics of the wave-generator angle.
- efficiency: η = η0 · Ke(α, n) · (viscous-loss temperature factor), α = T/Tr. Ke comes from
  a Palmgren-type loss split, a speed-dependent no-load drag plus a load-dependent
  Coulomb-like loss ∝ T^(1+y) (the library: one fixed no-load loss, α/(α + c)); the viscous
  loss follows an ISO VG68-like oil's Vogel viscosity ln ν = A + B/(t + C) (the library: an
  exponential).
- vibration: J·θ'' + c·θ' + K·θ = K·e(φ(t)) integrated with ``solve_ivp`` (DOP853) over a
  linear run-up of the input speed from standstill.

Every case is reproducible from ``(kind, model, effects, seed)``. A hidden effect's
parameters are drawn from physically plausible ranges tied to catalog figures. Its size
k = RMS(contribution) / noise RMS is uniform in [1, 10]; the contribution counted is the
part the baseline's fitted constant (twist offset, output offset, η0) cannot absorb, i.e.
its mean is removed except in vibration. The noise RMS is set from the drawn effect
(σ = RMS/k; with two effects, from the smaller one), except where ``NOISE_CAP`` bounds it.
With no hidden effect, σ is drawn the same way from an effect that is then not applied, so
the noise levels of both groups match. Noise is white + AR(1), scaled to RMS σ exactly.

References
----------
Seed 000 p.020: torque-twist curve K1/K2/K3, T1/T2, θ1/θ2; loading ±T0 with the input
locked; hysteresis loss (B−B′, mostly internal friction, almost none at very small torque);
backlash (Oldham-coupling clearance, measured at the output, input locked); "the twist of
the component alone; output shaft etc. not included" (→ housing compliance).
Seed 000 p.021: transmission error θer = θ2 − θ1/R, mainly two cycles per WG revolution;
f = (1/2π)·√(K/J); resonance at N = f/2·60.
Seed 000 p.023: η = Ke·ηR, α = T/Tr, Ke(0.58) = 0.93 (CSF, graph 023-1, catalog table
``ke_curve``); efficiency depends on load, speed and temperature; example lubricant 20 °C.
Seed 003 tables 051-1/059-1 (``gh_performance``, accuracy), 052-1/060-1 (``gh_stiffness``),
p.052/060 (``gh_hysteresis``), 052-2/060-2 (``gh_backlash``), 050-1/058-1 (rated torque).
Seed 001 table 314-1 (FD spring constant), 310-1 (FD rated torque).
Masing, G. (1926) "Eigenspannungen und Verfestigung beim Messing", Proc. 2nd Int. Congr.
Appl. Mech., Zürich; Ramberg, W. & Osgood, W. R. (1943) "Description of stress-strain curves
by three parameters", NACA TN 902; Jennings, P. C. (1964) "Periodic response of a general
yielding structure", J. Eng. Mech. Div. 90(EM2) (extended Masing rule).
Palmgren, A. (1959) "Ball and roller bearing engineering", 3rd ed. (friction torque
M = M0 + M1: M0 ∝ (ν·n)^(2/3) without load, M1 = f1·P·dm with f1 ∝ (P/C0)^y).
Vogel, H. (1921) Phys. Z. 22, 645 (ln ν = A + B/(t + C)); Andrade, E. N. da C. (1930)
Nature 125, 309; ISO 3448 (viscosity grade VG68: 61.2-74.8 mm²/s at 40 °C).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from scipy.integrate import cumulative_trapezoid, solve_ivp
from scipy.signal import lfilter

from hdcad.catalog import Catalog, load_catalog
from hdcad.models import GearModel, resolve

KINDS = ("torsion", "transmission", "efficiency", "vibration")
# Effects the truth can hide per kind (names as in the issue). "te_3x" is truth-only: a
# harmonic no library candidate explains, for the "unexplained" check.
TRUTH_EFFECTS = {
    "torsion": ("hysteresis", "backlash", "housing_compliance"),
    "transmission": ("te_1x", "te_2x", "te_3x"),
    "efficiency": ("low_load_efficiency", "temperature_dependence"),
    "vibration": ("te_1x", "te_2x"),
}
# Effects used to set the noise level of a "none" case (truth-only te_3x excluded).
NOISE_REFERENCE = {kind: tuple(e for e in names if e != "te_3x")
                   for kind, names in TRUTH_EFFECTS.items()}

K_RANGE = (1.0, 10.0)             # effect RMS / noise RMS, from the issue
# Largest plausible noise RMS per kind [unit of the measured column]. Efficiency is bounded
# to 0-100 %: a 1×-noise Ke effect (RMS up to ~10 % points) would otherwise need ~10 %
# noise. Above the cap the noise is capped and the effect scaled down to k × cap (its shape
# kept; Ke(0.58) then lies closer to 1, still a plausible gear).
NOISE_CAP = {"efficiency": 2.0}
AR1_COEF_RANGE = (0.0, 0.8)       # coloured-noise AR(1) coefficient, from the task brief

# --- torsion design choices -----------------------------------------------------------
T0_FRACTION = (0.5, 1.0)          # T0 / rated torque (task brief; T0 ≤ rated torque)
CYCLES = (2, 4)                   # full ±T0 cycles per record (task brief)
TORSION_ROWS = (2000, 4000)
# The curve is built from the defining data T1, T2, K1, K2, K3 (seed 000 p.020); the
# printed θ1, θ2 are their rounded results and are not used.
TORQUE_GRID = 4001                # points of the compliance integration grid, 0…|T|max
HYSTERESIS_SCALE = (0.5, 1.5)     # × catalog hysteresis loss ("about", seed 003 p.052/060)
# Masing loop on a Ramberg–Osgood backbone (the formulation the generator uses):
# |T|/T_y = u·(1 + α_RO·u^(r−1)), u = hysteretic twist / its scale.
RO_YIELD_TORQUE = (0.05, 0.3)     # T_y / rated torque: where the internal friction slips
RO_ALPHA = (0.5, 2.0)             # Ramberg–Osgood yield offset α_RO (1 is the usual choice)
RO_EXPONENT = (1.5, 4.0)          # Ramberg–Osgood exponent r (≥ 1; large r ≈ Coulomb slip)
BACKLASH_SCALE = (0.3, 1.0)       # × catalog maximum backlash (052-2/060-2 are maxima)
BACKLASH_SMOOTH = (0.005, 0.02)   # torque that half-closes the play / T0
BACKLASH_EPS = 0.1                # dead-zone rounding angle / half play
HOUSING_SHARE = (0.05, 0.5)       # housing twist / catalog twist at T0 (extra series spring)
OFFSET_SHARE = 0.02               # |twist zero offset| ≤ this × catalog twist at T0

# --- transmission design choices ------------------------------------------------------
REVOLUTIONS = (3, 10)             # WG revolutions per record (task brief)
TRANSMISSION_ROWS = (2000, 4000)
# TE amplitude / catalog accuracy (051-1/059-1 give the maximum error, taken as the
# peak-to-peak band, so a single harmonic's amplitude stays below half of it).
TE_AMPLITUDE = {1: (0.05, 0.3), 2: (0.1, 0.5), 3: (0.05, 0.3)}
OUTPUT_OFFSET_RAD = 1e-3          # |constant output-angle offset| bound (encoder zero)

# --- efficiency design choices --------------------------------------------------------
SPEED_RANGE_RPM = (500.0, 3500.0)
LOAD_RANGE = (0.1, 1.2)           # α = T/Tr
TEMPERATURE_RANGE_C = (0.0, 40.0)
GRID_SPEEDS, GRID_LOADS, GRID_TEMPERATURES = (4, 7), (8, 12), (3, 5)
ETA0_RANGE_PCT = (60.0, 85.0)     # efficiency at rated torque and T_REF (task brief)
KE_AT_058 = (0.90, 0.96)          # Ke(0.58) around the catalog point 0.93 (ke_curve, 023-1)
KE_ALPHA_POINT = 0.58             # α of the catalog point (seed 000 p.023 example)
T_REF_C = 20.0                    # lubricant temperature of the seed 000 p.023 example
VISCOUS_SHARE = (0.3, 0.7)        # share of the loss at T_REF that scales with viscosity
# Loss split of the low-load truth (Palmgren's bearing friction M = M0 + M1): a no-load drag
# torque M0 ∝ n^m (M0 ∝ (ν·n)^(2/3) in Palmgren) and a load-dependent Coulomb-like torque
# M1 = f1·P·dm with f1 ∝ (P/C0)^y, i.e. a loss ∝ T^(1+y).
KE_REF_SPEED_RPM = 1000.0         # input speed of the catalog Ke example (seed 000 p.023)
DRAG_SPEED_EXPONENT = (0.3, 0.8)  # m: drag torque ∝ n^m (Palmgren 2/3; churning 0.3-1)
LOAD_LOSS_EXPONENT = (0.0, 0.5)   # y: Coulomb-like loss ∝ T^(1+y) (Palmgren f1 ∝ (P/C0)^y)
DRAG_SHARE_LIMITS = (0.02, 0.95)  # no-load drag / total loss at rated torque and 1000 r/min
# Vogel viscosity of an ISO VG68-like base oil: ln ν = A + B/(t + C), ν in mm²/s, t in °C.
VG_NU40 = (61.2, 74.8)            # ν at 40 °C: the VG68 band (ISO 3448: 68 ± 10 %)
VG_NU100 = (8.0, 9.5)             # ν at 100 °C: mineral VG68 oils with VI ≈ 85-120
VOGEL_C = (80.0, 110.0)           # °C: Vogel's temperature offset C of mineral oils
VISCOUS_EXPONENT = (0.5, 1.0)     # viscous loss ∝ ν^p (Palmgren drag p = 2/3; Petroff p = 1)

# --- vibration design choices ---------------------------------------------------------
RESONANCE_2X_RPM = (150.0, 600.0)  # input speed of the te_2x resonance (sets J)
RUNUP_TOP = 1.4                   # top speed / te_1x resonance speed: passes both resonances
SAMPLES_PER_PERIOD = 20           # samples per period of the fastest excitation (2× at top)
VIBRATION_ROWS = (5000, 10000)
DAMPING_RATIO = (0.02, 0.1)       # task brief: light damping
ODE_RTOL = 1e-8                   # DOP853: error ~1e-7 of the response, ≪ noise (≥ 0.1×)


def rms(x) -> float:
    """Root mean square of an array."""
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x)))


def coloured_noise(n: int, sigma: float, rng: np.random.Generator) -> tuple[np.ndarray, dict]:
    """White + AR(1) noise scaled to sample RMS ``sigma`` exactly, with its description.

    A random share of the power is AR(1) with a random coefficient in ``AR1_COEF_RANGE``
    (coloured: neighbouring rows correlate, as drift and vibration do on a rig).
    """
    phi = rng.uniform(*AR1_COEF_RANGE)
    share = rng.uniform(0.0, 1.0)
    drive = rng.standard_normal(n)
    # AR(1) x[i] = φ·x[i−1] + w[i], started in its stationary distribution.
    ar, _ = lfilter([1.0], [1.0, -phi], drive[1:],
                    zi=[phi * drive[0] / math.sqrt(1.0 - phi * phi)])
    ar = np.concatenate([[drive[0] / math.sqrt(1.0 - phi * phi)], ar])
    white = rng.standard_normal(n)
    noise = math.sqrt(1.0 - share) * white / rms(white) + math.sqrt(share) * ar / rms(ar)
    noise *= sigma / rms(noise)
    return noise, {"ar1_coefficient": phi, "coloured_share": share}


# ======================================================================================
# catalog figures
# ======================================================================================

@lru_cache(maxsize=None)
def default_catalog() -> Catalog:
    return load_catalog()


def _value(model: GearModel, name: str) -> float | None:
    datum = model.get(name)
    return float(datum) if datum is not None else None


def rated_torque(model: GearModel) -> float:
    """Rated torque Tr [N·m]: GH table 050-1/058-1; FD table 310-1 at 1450 r/min."""
    if model.is_fd:
        return float(dict(model.fd_torque_by_speed)[1450.0])
    return float(model.get("rated_torque_Nm"))


def _gh_row(catalog: Catalog, table: str, model: GearModel, **keys) -> dict | None:
    """Row of a GH table for the model's series; tables split by ratio group honoured."""
    for row in reversed(catalog.rows(table, series=model.series, **keys)):
        if "ratio" in row and row["ratio"] != model.ratio:
            continue
        low, high = row.get("ratio_min"), row.get("ratio_max")
        if low is not None and (model.ratio < low or (high is not None and model.ratio > high)):
            continue
        return row
    return None


def catalog_figures(model: GearModel, catalog: Catalog) -> dict:
    """Catalog hysteresis loss, max backlash and accuracy [rad] (None when not in the seeds).

    References: seed 003 p.052/060 (hysteresis), tables 052-2/060-2 (backlash),
    051-1/059-1 (transmission accuracy).
    """
    if model.is_fd:
        return {"hysteresis_rad": None, "backlash_rad": None, "accuracy_rad": None}
    hyst = _gh_row(catalog, "gh_hysteresis", model)
    back = _gh_row(catalog, "gh_backlash", model, size=model.size)
    perf = _gh_row(catalog, "gh_performance", model, size=model.size)
    return {"hysteresis_rad": hyst and hyst["hysteresis_rad"],
            "backlash_rad": back and back["backlash_rad"],
            "accuracy_rad": perf and perf["accuracy_rad"]}


# Catalog figure a hidden effect's plausible range needs (None: needs none).
NEEDS = {"hysteresis": "hysteresis_rad", "backlash": "backlash_rad", "te_1x": "accuracy_rad",
         "te_2x": "accuracy_rad", "te_3x": "accuracy_rad"}


def available_effects(kind: str, figures: dict) -> tuple[str, ...]:
    """Reference effects whose catalog figures this model has (for a case's noise level)."""
    return tuple(e for e in NOISE_REFERENCE[kind]
                 if NEEDS.get(e) is None or figures.get(NEEDS[e]) is not None)


def low_torque_stiffness(model: GearModel) -> float:
    """K [N·m/rad] of the vibration convention: GH K1 (052-1/060-1) or FD 314-1 spring."""
    name = "spring_constant_Nm_per_rad" if model.is_fd else "K1_Nm_per_rad"
    return float(model.get(name))


# ======================================================================================
# torsion
# ======================================================================================

def compliance_knots(model: GearModel) -> tuple[np.ndarray, np.ndarray]:
    """(torque breakpoints [N·m], compliance on each interval [rad/(N·m)]) for T ≥ 0.

    FD: one spring (table 314-1). GH: slopes 1/K1, 1/K2, 1/K3 (052-1/060-1) changing at T1
    and T2.
    """
    if model.is_fd:
        return np.array([0.0, math.inf]), np.array([1.0 / low_torque_stiffness(model)])
    t1, t2 = _value(model, "T1_Nm"), _value(model, "T2_Nm")
    k1, k2, k3 = (_value(model, f"K{i}_Nm_per_rad") for i in (1, 2, 3))
    return np.array([0.0, t1, t2, math.inf]), np.array([1 / k1, 1 / k2, 1 / k3])


def catalog_twist(torque, model: GearModel) -> np.ndarray:
    """Twist [rad] of the catalog curve at torque [N·m]: ∫₀^|T| c(τ) dτ · sign(T).

    The compliance c(τ) of ``compliance_knots`` is integrated numerically (cumulative
    trapezoid on a fine grid), independently of the closed-form segment formula.
    """
    torque = np.asarray(torque, dtype=float)
    knots, compliance = compliance_knots(model)
    top = max(float(np.max(np.abs(torque))), 1e-9) * 1.001
    grid = np.unique(np.concatenate([np.linspace(0.0, top, TORQUE_GRID),
                                     knots[np.isfinite(knots) & (knots < top)]]))
    # Value on each interval; at a knot take the interval that starts there.
    index = np.clip(np.searchsorted(knots, grid, side="right") - 1, 0, len(compliance) - 1)
    # Duplicate knots so the trapezoid integrates a step exactly.
    tau = np.repeat(grid, 2)[1:]
    c = np.repeat(compliance[index], 2)[:-1]
    theta = np.concatenate([[0.0], cumulative_trapezoid(c, tau)])[::2]
    return np.sign(torque) * np.interp(np.abs(torque), grid, theta)


def torque_path(t0: float, cycles: int, rows: int) -> np.ndarray:
    """Quasi-static triangle torque [N·m]: 0 → +T0 → −T0 → … (``cycles`` times) → +T0 → 0.

    Sampled evenly along the path (constant loading rate), as on the rig of seed 000 p.020.
    """
    turns = [0.0, t0] + [-t0, t0] * cycles + [0.0]
    length = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(turns)))])
    return np.interp(np.linspace(0.0, length[-1], rows), length, turns)


def ramberg_osgood_backbone(torque, t_y: float, alpha_ro: float, r: float) -> np.ndarray:
    """Backbone u(T) of the truth's hysteresis, |T|/T_y = u·(1 + α·u^(r−1)) (Ramberg & Osgood
    1943, NACA TN 902): a power-law slip that never saturates, unlike the library's Bouc–Wen.

    Odd in T. Written as the slip u of the internal friction
    against the torque that drives it: linear (u = T/T_y) well below T_y, softening above
    (u ∝ T^(1/r)). Solved by bisection (the right-hand side is monotone in u ≥ 0).
    """
    torque = np.asarray(torque, dtype=float)
    x = np.abs(torque) / t_y
    lo, hi = np.zeros_like(x), x.copy()           # u ≤ x since α·u^r ≥ 0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        above = mid * (1.0 + alpha_ro * mid ** (r - 1.0)) > x
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    return np.sign(torque) * 0.5 * (lo + hi)


def masing_state(torque, t_y: float, alpha_ro: float, r: float) -> np.ndarray:
    """Hysteretic slip u by Masing's rule on the Ramberg–Osgood backbone (Masing 1926;
    Jennings 1964): a rate-free memory-rule loop, not the library's Bouc–Wen differential law.

    Virgin loading follows the backbone B(T); after a reversal at (T_r, u_r) the branch is
    u = u_r + 2·B((T − T_r)/2) (Masing 1926: the backbone doubled in both axes); a branch
    that passes the largest |T| reached before rejoins the backbone (Jennings 1964, the
    extended Masing rule). Independent of Bouc–Wen: a rate-free, memory-rule model.
    """
    torque = np.asarray(torque, dtype=float)
    step = np.diff(torque)
    sign = np.sign(step)
    for i in range(1, len(sign)):
        if sign[i] == 0:
            sign[i] = sign[i - 1]
    u = np.zeros_like(torque)
    if len(torque) < 2:
        return u
    start, virgin, reached = 0, True, 0.0
    while start < len(step):
        stop = start
        while stop + 1 < len(step) and sign[stop + 1] == sign[start]:
            stop += 1
        leg = torque[start:stop + 2]
        t_r, u_r = leg[0], u[start]
        branch = ramberg_osgood_backbone(leg, t_y, alpha_ro, r) if virgin else \
            u_r + 2.0 * ramberg_osgood_backbone(0.5 * (leg - t_r), t_y, alpha_ro, r)
        beyond = np.abs(leg) > reached
        branch = np.where(beyond & (np.sign(leg) == sign[start]),
                          ramberg_osgood_backbone(leg, t_y, alpha_ro, r), branch)
        u[start:stop + 2] = branch
        reached = max(reached, float(np.max(np.abs(leg))))
        virgin = False
        start = stop + 1
    return u


def masing_loss(t0: float, t_y: float, alpha_ro: float, r: float) -> float:
    """Loop width at zero torque (B − B′, seed 000 p.020) of steady ±T0 cycles of −u.

    Closed form of Masing's rule: unloading from +T0 leaves u = B(T0) − 2·B(T0/2) at T = 0,
    so the width is 2·(2·B(T0/2) − B(T0)); it vanishes as T0/T_y → 0 (linear backbone).
    """
    b = ramberg_osgood_backbone(np.array([0.5 * t0, t0]), t_y, alpha_ro, r)
    return float(2.0 * (2.0 * b[0] - b[1]))


def smoothed_dead_zone_twist(torque, width_rad: float, t_half: float) -> np.ndarray:
    """Lost-motion twist [rad] of a play of total ``width_rad`` behind a softplus dead zone.

    The play element transmits T = Kp·ε·[sp((δ−c)/ε) − sp((−δ−c)/ε)] for a relative angle δ
    (c = width/2, ε = ``BACKLASH_EPS``·c, sp = softplus); Kp is set so that T = ``t_half``
    at δ = c. δ(T) is found by bisection (T is monotone in δ); the contact compliance T/Kp
    is removed so the element adds only the play: ±c once the play has closed.
    """
    torque = np.asarray(torque, dtype=float)
    c = 0.5 * width_rad
    eps = BACKLASH_EPS * c
    k_p = t_half / (eps * (math.log(2.0) - np.logaddexp(0.0, -2.0 * c / eps)))

    def transmitted(delta):
        return k_p * eps * (np.logaddexp(0.0, (delta - c) / eps)
                            - np.logaddexp(0.0, (-delta - c) / eps))

    span = c + np.abs(torque) / k_p + 50.0 * eps
    lo, hi = -span, span.copy()
    for _ in range(80):            # bisection to ≪ 1e-12 rad
        mid = 0.5 * (lo + hi)
        above = transmitted(mid) > torque
        hi = np.where(above, mid, hi)
        lo = np.where(above, lo, mid)
    return 0.5 * (lo + hi) - torque / k_p


def _torsion_effect(name: str, torque, model, figures, t0, rng) -> tuple[np.ndarray, dict]:
    """One hidden torsion effect: (twist contribution [rad], parameters)."""
    tr = rated_torque(model)
    if name == "hysteresis":
        loss = figures["hysteresis_rad"] * rng.uniform(*HYSTERESIS_SCALE)
        t_y = tr * rng.uniform(*RO_YIELD_TORQUE)
        alpha_ro, r = rng.uniform(*RO_ALPHA), rng.uniform(*RO_EXPONENT)
        amplitude = loss / masing_loss(tr, t_y, alpha_ro, r)
        params = {"loss_at_rated_rad": loss, "amplitude_rad": amplitude, "t_yield_Nm": t_y,
                  "ro_alpha": alpha_ro, "ro_exponent": r}
        # Internal friction slips by u (Masing loop): the twist lags the torque, −amplitude·u,
        # so unloading leaves a positive twist at T = 0 (B, seed 000 p.020).
        return -amplitude * masing_state(torque, t_y, alpha_ro, r), params
    if name == "backlash":
        width = figures["backlash_rad"] * rng.uniform(*BACKLASH_SCALE)
        t_half = t0 * rng.uniform(*BACKLASH_SMOOTH)
        return (smoothed_dead_zone_twist(torque, width, t_half),
                {"width_rad": width, "t_half_Nm": t_half})
    if name == "housing_compliance":
        share = rng.uniform(*HOUSING_SHARE)
        k_h = t0 / (share * float(catalog_twist(t0, model)))
        return torque / k_h, {"k_housing_Nm_per_rad": k_h, "share_at_T0": share}
    raise ValueError(f"torsion has no truth effect {name!r}")


def torsion_case(model: GearModel, effects, rng: np.random.Generator, catalog: Catalog,
                 rows: int | None = None) -> tuple[dict, dict]:
    """Torque-twist loading record (seed 000 p.020) with hidden ``effects``."""
    figures = catalog_figures(model, catalog)
    t0 = rated_torque(model) * rng.uniform(*T0_FRACTION)
    rows = rows or int(rng.integers(*TORSION_ROWS, endpoint=True))
    torque = torque_path(t0, int(rng.integers(*CYCLES, endpoint=True)), rows)
    base = catalog_twist(torque, model)
    offset = OFFSET_SHARE * float(catalog_twist(t0, model)) * rng.uniform(-1.0, 1.0)

    def make(name):
        return _torsion_effect(name, torque, model, figures, t0, rng)

    signal, truth = _hide(effects, make, "torsion", rng, len(torque), model, figures=figures)
    twist = base + offset + signal["total"] + signal["noise"]
    truth["params"]["offset_rad"] = offset
    truth["t0_Nm"] = t0
    return {"torque_Nm": torque, "twist_rad": twist}, truth


# ======================================================================================
# transmission
# ======================================================================================

def te_harmonic(wg_angle, order: int, amplitude: float, phase: float) -> np.ndarray:
    """Transmission error at the output [rad]: a·sin(order·φ + p), φ the WG angle [rad].

    Order 2 is the wave generator's ellipse (seed 000 p.021: two cycles per WG revolution);
    order 1 an eccentricity (once per revolution).
    """
    return amplitude * np.sin(order * np.asarray(wg_angle) + phase)


_TE_ORDER = {"te_1x": 1, "te_2x": 2, "te_3x": 3}


def _te_params(name: str, figures: dict, rng: np.random.Generator) -> dict:
    order = _TE_ORDER[name]
    accuracy = figures["accuracy_rad"]
    if accuracy is None:
        raise ValueError("not evaluated: transmission accuracy missing from the catalog")
    return {"order": order, "amplitude_rad": accuracy * rng.uniform(*TE_AMPLITUDE[order]),
            "phase_rad": rng.uniform(0.0, 2.0 * math.pi)}


def transmission_case(model: GearModel, effects, rng: np.random.Generator, catalog: Catalog,
                      rows: int | None = None) -> tuple[dict, dict]:
    """No-load constant-speed record: output = input/R + offset + TE (seed 000 p.021)."""
    figures = catalog_figures(model, catalog)
    rows = rows or int(rng.integers(*TRANSMISSION_ROWS, endpoint=True))
    revolutions = rng.uniform(*REVOLUTIONS)
    start = rng.uniform(0.0, 2.0 * math.pi)
    phi = start + np.linspace(0.0, 2.0 * math.pi * revolutions, rows)
    offset = rng.uniform(-OUTPUT_OFFSET_RAD, OUTPUT_OFFSET_RAD)

    def make(name):
        p = _te_params(name, figures, rng)
        return te_harmonic(phi, p["order"], p["amplitude_rad"], p["phase_rad"]), p

    signal, truth = _hide(effects, make, "transmission", rng, rows, model, figures=figures)
    output = phi / model.ratio + offset + signal["total"] + signal["noise"]
    truth["params"]["offset_rad"] = offset
    return {"input_angle_rad": phi, "output_angle_rad": output}, truth


# ======================================================================================
# efficiency
# ======================================================================================

def palmgren_load_factor(alpha, speed_rpm, ke_point: float, eta0: float, drag_exponent: float,
                         load_exponent: float) -> tuple[np.ndarray, dict]:
    """Ke(α, n) = η(α, n)/η(1, n) with Palmgren's (1959) loss split, a speed-dependent drag
    plus a Coulomb-like loss ∝ T^(1+y): the library has one speed-free no-load loss instead.

    Palmgren (1959, "Ball and roller bearing engineering") splits friction into a no-load
    torque M0 ∝ (ν·n)^(2/3) and a load torque M1 ∝ P^(1+y); per rated output power the loss
    is d(n) + μ·α^(1+y), d(n) = d1·(n/1000 r/min)^m, so η = α/(α + d(n) + μ·α^(1+y)). With
    d1 + μ = 1/η0 − 1, d1 is solved so that Ke(0.58) = ``ke_point`` at 1000 r/min, the
    catalog example's speed (seed 000 p.023, ke_curve 023-1); Ke = 1 for α ≥ 1 (note under
    graph 023-1). Warmer or faster: the drag share and so the low-load drop grow with n.
    """
    total, a = 1.0 / eta0 - 1.0, KE_ALPHA_POINT
    p = a ** (1.0 + load_exponent)
    drag = (a * (1.0 + total) / ke_point - a - total * p) / (1.0 - p)
    drag = float(np.clip(drag, DRAG_SHARE_LIMITS[0] * total, DRAG_SHARE_LIMITS[1] * total))
    mu = total - drag
    alpha = np.asarray(alpha, dtype=float)
    d = drag * (np.asarray(speed_rpm, dtype=float) / KE_REF_SPEED_RPM) ** drag_exponent

    def eta(x):
        return x / (x + d + mu * x ** (1.0 + load_exponent))

    ke = np.where(alpha >= 1.0, 1.0, eta(np.minimum(alpha, 1.0)) / eta(1.0))
    ke_ref = a * (1.0 + total) / (a + drag + mu * p)
    return ke, {"drag_share_at_1000rpm": drag / total, "coulomb_loss": mu,
                "ke_at_0.58_1000rpm": ke_ref}


def vogel_viscosity(temp_c, nu40: float, nu100: float, c: float) -> np.ndarray:
    """Kinematic viscosity [mm²/s] by Vogel's law ln ν = A + B/(t + C) through ν(40 °C),
    ν(100 °C) (Vogel 1921, Phys. Z. 22; the Andrade form with a temperature offset C)."""
    b = math.log(nu40 / nu100) / (1.0 / (40.0 + c) - 1.0 / (100.0 + c))
    a = math.log(nu40) - b / (40.0 + c)
    return np.exp(a + b / (np.asarray(temp_c, dtype=float) + c))


def vogel_temperature_factor(temp_c, eta0: float, viscous_share: float, nu40: float,
                             nu100: float, c: float, exponent: float) -> np.ndarray:
    """η(t)/η0 with the viscous loss ∝ ν^p and Vogel's (1921) ν(t) of a VG68-like oil: steeper
    and curved against the library's exponential viscosity (Reynolds).

    Loss ratio 1/η − 1 = (1/η0 − 1)·[1 + w·((ν/ν(20 °C))^p − 1)]: churning and drag losses
    follow the oil's viscosity (Palmgren p = 2/3), which falls steeply and non-exponentially
    with temperature (seed 000 p.023: temperature is a factor; example at 20 °C).
    """
    ratio = vogel_viscosity(temp_c, nu40, nu100, c) / float(vogel_viscosity(T_REF_C, nu40,
                                                                           nu100, c))
    loss = (1.0 / eta0 - 1.0) * (1.0 + viscous_share * (ratio ** exponent - 1.0))
    return 1.0 / (1.0 + loss) / eta0


def _efficiency_grid(rng: np.random.Generator, rows: int | None) -> tuple[np.ndarray, ...]:
    speeds = np.linspace(*SPEED_RANGE_RPM, int(rng.integers(*GRID_SPEEDS, endpoint=True)))
    loads = np.linspace(*LOAD_RANGE, int(rng.integers(*GRID_LOADS, endpoint=True)))
    temps = np.linspace(*TEMPERATURE_RANGE_C, int(rng.integers(*GRID_TEMPERATURES,
                                                                endpoint=True)))
    # Temperature outermost (the rig soaks at each temperature), then speed, then load.
    tt, ss, aa = (g.ravel() for g in np.meshgrid(temps, speeds, loads, indexing="ij"))
    if rows:                        # repeated sweeps for long files
        reps = -(-rows // len(tt))
        tt, ss, aa = (np.tile(g, reps)[:rows] for g in (tt, ss, aa))
    return ss, aa, tt


def efficiency_case(model: GearModel, effects, rng: np.random.Generator, catalog: Catalog,
                    rows: int | None = None) -> tuple[dict, dict]:
    """Efficiency map over speed, load and temperature (seed 000 p.023)."""
    tr = rated_torque(model)
    speed, alpha, temp = _efficiency_grid(rng, rows)
    eta0 = rng.uniform(*ETA0_RANGE_PCT) / 100.0

    def make(name):
        if name == "low_load_efficiency":
            p = {"ke_at_0.58": rng.uniform(*KE_AT_058),
                 "drag_speed_exponent": rng.uniform(*DRAG_SPEED_EXPONENT),
                 "load_loss_exponent": rng.uniform(*LOAD_LOSS_EXPONENT)}
            ke, info = palmgren_load_factor(alpha, speed, p["ke_at_0.58"], eta0,
                                            p["drag_speed_exponent"], p["load_loss_exponent"])
            p.update(info)
            return 100.0 * eta0 * (ke - 1.0), p
        if name == "temperature_dependence":
            p = {"viscous_share": rng.uniform(*VISCOUS_SHARE), "nu40_mm2s": rng.uniform(*VG_NU40),
                 "nu100_mm2s": rng.uniform(*VG_NU100), "vogel_C": rng.uniform(*VOGEL_C),
                 "viscous_exponent": rng.uniform(*VISCOUS_EXPONENT)}
            factor = vogel_temperature_factor(temp, eta0, p["viscous_share"], p["nu40_mm2s"],
                                              p["nu100_mm2s"], p["vogel_C"],
                                              p["viscous_exponent"])
            return 100.0 * eta0 * (factor - 1.0), p
        raise ValueError(f"efficiency has no truth effect {name!r}")

    signal, truth = _hide(effects, make, "efficiency", rng, len(speed), model,
                          combine=lambda parts: _combine_efficiency(parts, eta0))
    eff = 100.0 * eta0 + signal["total"] + signal["noise"]
    truth["params"]["eta0_pct"] = 100.0 * eta0
    return {"input_speed_rpm": speed, "load_torque_Nm": alpha * tr, "temperature_C": temp,
            "efficiency_pct": eff}, truth


def _combine_efficiency(parts: list[np.ndarray], eta0: float) -> np.ndarray:
    """Effects multiply η: η0·Π(1 + part/(100·η0)) − η0, in %."""
    factor = np.ones_like(parts[0]) if parts else 1.0
    for part in parts:
        factor = factor * (1.0 + part / (100.0 * eta0))
    return 100.0 * eta0 * (factor - 1.0)


# ======================================================================================
# vibration
# ======================================================================================

def runup_angle(t, top_rpm: float, duration: float, start: float) -> np.ndarray:
    """WG angle φ(t) [rad] of a linear run-up 0 → ``top_rpm`` over ``duration`` [s]."""
    t = np.asarray(t, dtype=float)
    return start + 2.0 * math.pi / 60.0 * 0.5 * top_rpm / duration * t * t


def joint_response(t, phi_of_t, harmonics, stiffness: float, inertia: float,
                   damping_ratio: float) -> np.ndarray:
    """θ(t) [rad] of J·θ'' + c·θ' + K·θ = K·e(φ(t)), c = 2ζ√(KJ), from static rest.

    ``harmonics``: (order, amplitude, phase) of e. Integrated with ``solve_ivp`` (DOP853,
    rtol ``ODE_RTOL``) — not a modal or frequency-domain formula. Initial state: the load
    at rest in static equilibrium, θ(0) = e(φ(0)), θ'(0) = 0 (the run-up starts at 0 r/min).
    """
    omega2 = stiffness / inertia
    two_zeta_omega = 2.0 * damping_ratio * math.sqrt(omega2)

    def error(time):
        phi = phi_of_t(time)
        return sum(a * math.sin(k * phi + p) for k, a, p in harmonics)

    def rate(time, y):
        return [y[1], omega2 * (error(time) - y[0]) - two_zeta_omega * y[1]]

    scale = max(a for _, a, _ in harmonics)
    sol = solve_ivp(rate, (t[0], t[-1]), [error(t[0]), 0.0], method="DOP853", t_eval=t,
                    rtol=ODE_RTOL, atol=ODE_RTOL * scale * 1e-2)
    if not sol.success:
        raise RuntimeError(sol.message)
    return sol.y[0]


def vibration_case(model: GearModel, effects, rng: np.random.Generator, catalog: Catalog,
                   rows: int | None = None) -> tuple[dict, dict]:
    """Run-up record of the output vibration (seed 000 p.021); truth has the load inertia."""
    figures = catalog_figures(model, catalog)
    k = low_torque_stiffness(model)
    n_2x = rng.uniform(*RESONANCE_2X_RPM)
    f_n = n_2x * 2.0 / 60.0                    # seed 000 formula 021-2: N = f/2·60
    inertia = k / (2.0 * math.pi * f_n) ** 2    # formula 021-3: f = √(K/J)/2π
    zeta = rng.uniform(*DAMPING_RATIO)
    top = RUNUP_TOP * f_n * 60.0               # te_1x resonance at f·60, passed with margin
    fs = SAMPLES_PER_PERIOD * 2.0 * top / 60.0
    rows = rows or int(rng.integers(*VIBRATION_ROWS, endpoint=True))
    duration = rows / fs
    t = np.arange(rows) / fs
    start = rng.uniform(0.0, 2.0 * math.pi)

    accel = float(runup_angle(1.0, top, duration, 0.0))   # φ = start + accel·t²

    def phi_of_t(time):            # scalar form for the ODE right-hand side (speed)
        return start + accel * time * time

    def make(name):
        p = _te_params(name, figures, rng)
        harmonic = [(p["order"], p["amplitude_rad"], p["phase_rad"])]
        return joint_response(t, phi_of_t, harmonic, k, inertia, zeta), p

    signal, truth = _hide(effects, make, "vibration", rng, rows, model, figures=figures)
    truth.update(load_inertia_kgm2=inertia, damping_ratio=zeta, stiffness_Nm_per_rad=k,
                 resonance_2x_rpm=n_2x, resonance_1x_rpm=2.0 * n_2x, top_rpm=top)
    speed = top * t / duration
    # The joint is linear: the response to several harmonics is the sum of the responses.
    return {"time_s": t, "input_speed_rpm": speed,
            "output_vibration_rad": signal["total"] + signal["noise"]}, truth


# ======================================================================================
# shared: hide effects, set noise
# ======================================================================================

def _detectable(part: np.ndarray, kind: str) -> np.ndarray:
    """The part of a contribution the baseline cannot absorb: all but vibration fit a
    constant (twist offset, output offset, η0), so the mean is removed there."""
    return part if kind == "vibration" else part - np.mean(part)


def _hide(effects, make, kind: str, rng: np.random.Generator, n: int, model: GearModel,
          combine=None, figures: dict | None = None) -> tuple[dict, dict]:
    """Build the hidden effects and the noise; σ = min(effect RMS)/k, k ~ U(``K_RANGE``).

    Effect RMS is that of ``_detectable``. With no effect, a reference effect is drawn (not
    applied) to set σ, so the noise of the "none" cases has the same distribution as that
    of the effect cases.
    """
    effects = tuple(effects)
    k = rng.uniform(*K_RANGE)
    parts, params = [], {}
    for name in effects:
        part, p = make(name)
        parts.append(part)
        params[name] = p
    sizes = {name: rms(_detectable(p, kind)) for name, p in zip(effects, parts)}
    if effects:
        reference = min(sizes.values())
    else:
        names = available_effects(kind, figures or {})
        name = names[int(rng.integers(len(names)))]
        reference = rms(_detectable(make(name)[0], kind))
    sigma = reference / k
    cap = NOISE_CAP.get(kind, math.inf)
    if sigma > cap:
        scale = cap / sigma
        parts = [p * scale for p in parts]
        sizes = {name: size * scale for name, size in sizes.items()}
        for name in effects:
            params[name]["scale"] = scale
        sigma = cap
    noise, noise_info = coloured_noise(n, sigma, rng)
    total = combine(parts) if combine is not None else sum(parts, np.zeros(n))
    truth = {"kind": kind, "model": model.code, "effects": list(effects), "params": params,
             "k": k, "noise_rms": sigma, "noise": noise_info, "effect_rms": sizes}
    return {"total": np.zeros(n) + total, "noise": noise}, truth


# Models of the proof cases, with the catalog data each kind needs (stiffness 052-1/060-1,
# hysteresis, backlash 052-2/060-2, accuracy 051-1/059-1, rated torque 050-1/058-1).
# Torsion uses the size-32 GH rows, whose printed θ1/θ2 agree best with T/K (see
# ``compliance_knots``); the FD unit (one spring constant, table 314-1, no hysteresis,
# backlash or accuracy figures) joins where it has the data.
GH_TORSION_MODELS = ("CSF-32-100-GH", "CSG-32-100-GH")
GH_MODELS = ("CSF-32-100-GH", "CSG-20-80-GH")
FD_MODEL = "FD-32-100-0"
FD_SCENARIOS = {"torsion": ((), ("housing_compliance",))}
# Hidden-effect scenarios of the proof: each single effect, none, and the pairs.
SINGLE_SCENARIOS = [(kind, (effect,)) for kind in KINDS for effect in NOISE_REFERENCE[kind]]
COMBO_SCENARIOS = [("torsion", ("hysteresis", "backlash")), ("transmission", ("te_1x", "te_2x"))]


def proof_model(kind: str, effects: tuple[str, ...], seed: int) -> str:
    """Model of a proof case: the FD unit every third seed where it has the data, else GH."""
    if tuple(effects) in FD_SCENARIOS.get(kind, ()) and seed % 3 == 2:
        return FD_MODEL
    models = GH_TORSION_MODELS if kind == "torsion" else GH_MODELS
    return models[seed % len(models)]


_GENERATORS = {"torsion": torsion_case, "transmission": transmission_case,
               "efficiency": efficiency_case, "vibration": vibration_case}


def make_case(kind: str, model_code: str, effects=(), seed: int = 0,
              rows: int | None = None, catalog: Catalog | None = None) -> tuple[dict, dict]:
    """(data in the CSV column names, truth) for one reproducible case.

    ``truth``: kind, model, effects (hidden names), params per effect, k, noise_rms [unit of
    the measured column], noise (AR(1) description), effect_rms; vibration adds
    load_inertia_kgm2 and the resonance speeds.
    """
    catalog = catalog or default_catalog()
    model = resolve(model_code, catalog)
    unknown = [e for e in effects if e not in TRUTH_EFFECTS[kind]]
    if unknown:
        raise ValueError(f"{kind} truth has no effect {unknown[0]!r}")
    rng = np.random.default_rng([KINDS.index(kind), seed, *map(_effect_id, effects)])
    data, truth = _GENERATORS[kind](model, effects, rng, catalog, rows)
    truth["seed"] = seed
    return data, truth


def _effect_id(name: str) -> int:
    """Stable small integer per effect name for the seed sequence."""
    names = sorted({e for v in TRUTH_EFFECTS.values() for e in v})
    return names.index(name) + 1
