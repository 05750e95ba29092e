"""Truth suite B: synthetic "measured" strain-wave-gear test data with known hidden effects.

Written from the contract (../CONTRACT.md), the catalog tables (catalog/*.csv) and the
literature only; it imports nothing from hdcad and never read hdcad's reconcile code.

Every case = catalog baseline (x nuisance within the catalog's spread)
             + hidden gear effect(s)  (category single / pair)
             + hidden rig / measurement-chain effect or out-of-spread nuisance (decoys)
             + noise (white or AR(1); some clean cases with 0.5 % gross outliers).

Effect sizes: every hidden effect has RMS = k * noise_rms with k drawn in [4, 12] (for pairs each
effect separately in [4, 12] *and* the combined RMS in [4, 12]).  Exception: ``wrong_units``
(a gross unit factor, x57.3 or x1e-3 or x0.01) cannot be sized that way without noise larger
than the signal itself; its noise is an ordinary noise level and ``snr`` records the (huge)
actual ratio.

Formulations and sources are given in the docstring of each generator function below; see also
README.md.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp
from scipy.signal import lfilter

SUITE = "b"

RAD2DEG = 57.29577951308232


# --------------------------------------------------------------------------------------------
# the case record (exactly the contract's fields; private extras are set as plain attributes)
# --------------------------------------------------------------------------------------------
@dataclass
class TruthCase:
    name: str
    kind: str
    model: str
    columns: dict[str, np.ndarray]
    load_inertia_kgm2: float | None
    gear_effects: tuple[str, ...]
    measurement_effects: tuple[str, ...]
    nuisance: dict[str, float]
    category: str
    equivalent_effects: tuple[str, ...] = ()
    noise_rms: float = 0.0
    formulation: str = ""
    snr: float = 0.0

    def write_csv(self, path) -> None:
        path = Path(path)
        names = list(self.columns)
        cols = [np.asarray(self.columns[n], dtype=float) for n in names]
        n = len(cols[0])
        with path.open("w", newline="") as fh:
            fh.write(",".join(names) + "\n")
            for i in range(n):
                fh.write(",".join(repr(float(c[i])) for c in cols) + "\n")


# --------------------------------------------------------------------------------------------
# catalog access (read-only CSV tables)
# --------------------------------------------------------------------------------------------
MODELS = (  # 10 gear heads across all sizes, both series, ratio 50 .. 160
    "CSF-14-50-GH", "CSG-14-100-GH", "CSF-20-80-GH", "CSG-20-160-GH", "CSF-32-100-GH",
    "CSG-32-50-GH", "CSF-45-120-GH", "CSG-45-80-GH", "CSF-65-160-GH", "CSG-65-100-GH",
)


def _f(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return None


def _rows(catalog_dir, name):
    with open(Path(catalog_dir) / name, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _ratio_ok(row, ratio):
    lo = _f(row.get("ratio_min"))
    hi = _f(row.get("ratio_max"))
    return (lo is None or ratio >= lo) and (hi is None or ratio <= hi)


def load_model(catalog_dir, model: str) -> dict:
    """Catalog data of one gear head ``CSF|CSG-<size>-<ratio>-GH``."""
    cup, size, ratio, _ = model.split("-")
    series, size, ratio = cup + "-GH", int(size), int(ratio)
    st = [r for r in _rows(catalog_dir, "gh_stiffness_052-1_060-1.csv")
          if r["series"] == series and int(r["size"]) == size and _ratio_ok(r, ratio)]
    if not st:
        raise KeyError(f"no stiffness row for {model}")
    s = st[0]
    rt = [r for r in _rows(catalog_dir, "gh_ratings_050-1_058-1.csv")
          if r["series"] == series and int(r["size"]) == size and int(r["ratio"]) == ratio][0]
    bl = [r for r in _rows(catalog_dir, "gh_backlash_052-2_060-2.csv")
          if r["series"] == series and int(r["size"]) == size and int(r["ratio"]) == ratio]
    hy = [r for r in _rows(catalog_dir, "gh_hysteresis_052_060.csv")
          if r["series"] == series and _ratio_ok(r, ratio)]
    perf = [r for r in _rows(catalog_dir, "gh_performance_051-1_059-1.csv")
            if r["series"] == series and int(r["size"]) == size]
    acc = None
    for r in perf:  # same ratio first, then any ratio of that size
        if _f(r.get("ratio")) == ratio and _f(r.get("accuracy_arcmin")):
            acc = _f(r["accuracy_arcmin"]) * math.pi / 180 / 60
            break
    if acc is None:
        for r in perf:
            if _f(r.get("accuracy_arcmin")):
                acc = _f(r["accuracy_arcmin"]) * math.pi / 180 / 60
                break
    if acc is None:
        acc = 1.0 * math.pi / 180 / 60  # 1 arc-min: the value printed for sizes 20..65
    return dict(
        model=model, series=series, size=size, ratio=ratio,
        T1=float(s["T1_Nm"]), T2=float(s["T2_Nm"]),
        K1=float(s["K1_Nm_per_rad"]), K2=float(s["K2_Nm_per_rad"]), K3=float(s["K3_Nm_per_rad"]),
        rated=float(rt["rated_torque_2000_Nm"]), peak=float(rt["peak_torque_Nm"]),
        max_speed=float(rt["max_input_speed_rpm"]),
        backlash=float(bl[0]["backlash_rad"]) if bl else 3e-5,
        hysteresis=float(hy[0]["hysteresis_rad"]) if hy else 2.9e-4,
        accuracy=acc,
    )


# --------------------------------------------------------------------------------------------
# noise
# --------------------------------------------------------------------------------------------
def _rms(x):
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def make_noise(rng, n, sigma, kind):
    """White Gaussian or AR(1) (phi in [0.3, 0.8]) noise, rescaled to RMS exactly ``sigma``.

    ``kind='outliers'``: white noise plus 0.5 % of rows hit by gross errors of 8..15 sigma
    (random sign).  Returns (noise, outlier_mask, description).
    Source for the AR(1) disturbance model: Box, Jenkins, Reinsel & Ljung, *Time Series Analysis:
    Forecasting and Control*, 5th ed., Wiley 2015, ch. 3.
    """
    w = rng.standard_normal(n)
    desc = "white"
    if kind == "ar1":
        phi = float(rng.uniform(0.3, 0.8))
        w = lfilter([1.0], [1.0, -phi], w)
        desc = f"AR(1) phi={phi:.3f}"
    mask = np.zeros(n, dtype=bool)
    if kind == "outliers":
        m = max(1, int(round(0.005 * n)))
        mask[rng.choice(n, size=m, replace=False)] = True
    w = w - w[~mask].mean()
    w *= sigma / _rms(w[~mask])  # RMS over the ordinary rows is exactly sigma
    if kind == "outliers":  # outlier rows carry a gross error instead of the ordinary noise
        w[mask] = rng.uniform(8, 15, m) * sigma * rng.choice([-1.0, 1.0], m)
        desc = f"white + {m} outliers (0.5 %) at 8-15 sigma"
    out = 0.0
    return w + out, mask, desc


def _pick_k(rng, rms_list, max_tries=200):
    """Noise RMS such that each effect has k_i = rms_i / sigma in [4, 12] and the combined k too.

    ``rms_list`` holds the RMS of each component and the last element the combined RMS.
    Returns sigma or None when infeasible."""
    comps, comb = rms_list[:-1], rms_list[-1]
    lo = max(max(comps) / 12.0, comb / 12.0)
    hi = min(min(comps) / 4.0, comb / 4.0)
    if lo > hi:
        return None
    return float(rng.uniform(lo, hi))


# --------------------------------------------------------------------------------------------
# TORSION
# --------------------------------------------------------------------------------------------
def twist_three_segment(T, m, scale=1.0):
    """Catalog three-segment torque-twist curve, odd in T (seed 000 p.020, formula 020):
    theta = T/K1 (|T|<=T1); theta1 + (T-T1)/K2 (<=T2); theta2 + (T-T2)/K3 beyond.
    All three spring constants are multiplied by the stiffness-scale nuisance ``scale``.
    Source: Harmonic Drive LLC / HDS catalog "Engineering Data", *Torsional stiffness*
    (the seed text, page 020)."""
    a = np.abs(T)
    K1, K2, K3 = m["K1"] * scale, m["K2"] * scale, m["K3"] * scale
    th1 = m["T1"] / K1
    th2 = th1 + (m["T2"] - m["T1"]) / K2
    th = np.where(a <= m["T1"], a / K1,
                  np.where(a <= m["T2"], th1 + (a - m["T1"]) / K2, th2 + (a - m["T2"]) / K3))
    return np.sign(T) * th


def _softplus(x, w):
    return w * np.logaddexp(0.0, x / w)


def twist_softplus(T, m, scale=1.0, width=None):
    """Smooth (softplus-blended) version of the three-segment curve: the compliance steps
    1/K1 -> 1/K2 -> 1/K3 at T1, T2 are blended with softplus(x) = w ln(1 + e^(x/w)),
        theta(|T|) = |T|/K1 + (1/K2-1/K1) sp(|T|-T1) + (1/K3-1/K2) sp(|T|-T2) - (same at 0),
    odd in T; it tends to the catalog polyline as w -> 0.  Smooth HD stiffness curves of this
    kind (a continuously stiffening spring instead of a polyline) are used by Taghirad &
    Belanger, "Modeling and parameter identification of harmonic drive systems", ASME J. Dyn.
    Syst. Meas. Control 120(4):439-444, 1998 (cubic stiffness) and Tuttle & Seering, "A nonlinear
    model of a harmonic drive gear transmission", IEEE Trans. Robot. Autom. 12(3):368-374, 1996;
    the softplus blend is Dugas et al.'s smooth ReLU ("Incorporating second-order functional
    knowledge for better option pricing", NIPS 2000)."""
    w = width if width is not None else 0.1 * m["T1"]
    a = np.abs(T)
    K1, K2, K3 = m["K1"] * scale, m["K2"] * scale, m["K3"] * scale
    c2, c3 = 1 / K2 - 1 / K1, 1 / K3 - 1 / K2

    def f(x):
        return x / K1 + c2 * _softplus(x - m["T1"], w) + c3 * _softplus(x - m["T2"], w)
    return np.sign(T) * (f(a) - f(np.zeros_like(a)))


def torque_history(rng, m, n):
    """Quasi-static torsion test (seed 000 p.020, figure 020-1): input side locked, output torque
    0 -> +T0 -> -T0 -> +T0 ... (triangle in test time, 2-3 full cycles, ends at 0).
    T0 = rated torque x U(1.0, 1.5), not above the peak torque."""
    T0 = min(m["rated"] * float(rng.uniform(1.0, 1.5)), m["peak"])
    cycles = int(rng.integers(2, 4))
    # path in units of T0: 0,1,-1,1,-1,...,0
    knots = [0.0, 1.0] + [(-1.0 if i % 2 == 0 else 1.0) for i in range(2 * cycles - 1)] + [0.0]
    seg = np.abs(np.diff(knots))
    s = np.concatenate([[0], np.cumsum(seg)])
    u = np.linspace(0, s[-1], n)
    return T0 * np.interp(u, s, knots), T0


def _hyst_state(drive, law, n_exp, rate, beta):
    """Integrate a rate-independent hysteresis state z (|z|<=1) driven by ``drive`` (twist).

    bouc-wen: dz/dx = rate [1 - (beta sgn(dx z) + (1-beta)) |z|^n]
        Bouc, "Forced vibration of mechanical systems with hysteresis", Proc. 4th Conf. on
        Nonlinear Oscillations, Prague 1967; Wen, "Method for random vibration of hysteretic
        systems", J. Eng. Mech. Div. ASCE 102(2):249-263, 1976.
    dahl:     dz/dx = rate (1 - z sgn(dx))          (Dahl exponent i = 1)
        Dahl, "A solid friction model", Aerospace Corp. TOR-0158(3107-18)-1, 1968;
        Dahl, "Solid friction damping of mechanical vibrations", AIAA J. 14(12), 1976.
    Explicit sub-stepping (20 per sample)."""
    z = 0.0
    out = np.empty_like(drive)
    out[0] = 0.0
    sub = 20
    for i in range(1, len(drive)):
        dx = (drive[i] - drive[i - 1]) / sub
        for _ in range(sub):
            if law == "dahl":
                dz = rate * (1.0 - z * np.sign(dx)) * dx
            else:
                a = abs(z) ** n_exp
                dz = rate * (1.0 - (beta * np.sign(dx * z) + (1.0 - beta)) * a) * dx
            z = min(1.0, max(-1.0, z + dz))
        out[i] = z
    return out


def effect_hysteresis(rng, T, T0, m, base_fn, law, n_exp=1):
    """Hysteresis (internal friction) in the torque-twist curve, seed 000 p.020: a loop
    0-A-B-A'-B'-A, residual twist B-B' at zero torque after loading to rated torque, almost none
    at very small torque.  Physical reading (HD hysteresis as a friction torque in parallel with
    the flexspline spring: Seyfferth, Maghzal & Angeles, "Nonlinear modeling and parameter
    identification of harmonic drive robotic transmissions", ICRA 1995; Tjahjowidodo, Al-Bender &
    Van Brussel, "Nonlinear modelling and identification of torsional behaviour in harmonic
    drives", ISMA 2006): T = T_spring(theta) + Th z  =>  to first order in Th
        theta = theta_cat(T) - Th z / K_local(T),
    z the Bouc-Wen (n = 1, 2, 3) or Dahl state driven by the twist.  The part of the loop term
    collinear with the catalog curve (a pure stiffness-scale change, a nuisance) is projected
    out, so the hidden effect is the loop itself.  Loop width at zero torque (B-B') is scaled to
    the catalog hysteresis loss (table 052/060) x U(0.4, 1.3)."""
    th_cat = base_fn(T)
    span = float(np.max(np.abs(th_cat)))
    rate = 1.0 / (span * float(rng.uniform(0.15, 0.45)))
    beta = float(rng.uniform(0.55, 0.9))
    z = _hyst_state(th_cat, law, n_exp, rate, beta)
    dT = 1e-4 * T0
    K_loc = 2 * dT / (base_fn(T + dT) - base_fn(T - dT))
    e = -z / K_loc
    e = e - (np.dot(e, th_cat) / np.dot(th_cat, th_cat)) * th_cat
    # width at zero torque on the last cycle: difference between branches near T = 0
    near0 = np.abs(T) < 0.05 * T0
    width = float(np.ptp(e[near0])) if near0.sum() > 2 else float(np.ptp(e))
    target = m["hysteresis"] * float(rng.uniform(0.4, 1.3))
    return e * (target / width)


def effect_backlash(rng, T, T0, m):
    """Backlash (Oldham-coupling clearance of the wave generator, seed 000 p.020): a dead zone of
    width b at torque reversal, theta_bl = (b/2) tanh(T/T_eps) (smooth edge, T_eps = 0.5-3 % of
    T0).  Dead-zone/backlash as an angle play: Nordin & Gutman, "Controlling mechanical systems
    with backlash - a survey", Automatica 38(10):1633-1649, 2002 (smooth tanh approximation of
    the dead zone, section 2).  b = catalog backlash (table 052-2/060-2) x U(0.7, 3)."""
    b = m["backlash"] * float(rng.uniform(0.7, 3.0))
    eps = T0 * float(rng.uniform(0.005, 0.03))
    return 0.5 * b * np.tanh(T / eps)


def effect_housing(rng, T, T0, base_fn):
    """Housing / output-shaft compliance: an extra series spring, theta_h = T / Kh, with
    1/Kh = c * theta_gear(T0)/T0, c in [0.05, 0.25] (5-25 % extra compliance).  Springs in series
    add compliances (seed 000 p.020 note: the catalog twist excludes output-shaft twist);
    cf. Rivin, *Stiffness and Damping in Mechanical Design*, Marcel Dekker 1999, ch. 1."""
    c = float(rng.uniform(0.05, 0.25))
    return T * c * float(base_fn(np.array([T0]))[0]) / T0


def gen_torsion(rng, m, cell, idx):
    cat, effects, form = cell["category"], cell["effects"], cell["form"]
    n = int(rng.integers(500, 3001))
    T, T0 = torque_history(rng, m, n)
    basef = cell.get("base") or ("softplus" if rng.random() < 0.5 else "three-segment")
    wsp = float(rng.uniform(0.05, 0.2)) * m["T1"]
    nuis = {}
    in_spread = float(rng.uniform(0.9, 1.1))

    def base_fn_s(s):
        if basef == "softplus":
            return lambda x: twist_softplus(x, m, s, wsp)
        return lambda x: twist_three_segment(x, m, s)

    scale = in_spread
    dec = cell.get("decoy")
    if dec == "stiff_in":
        scale = float(rng.choice([-1, 1]) * rng.uniform(0.05, 0.1) + 1.0)
    elif dec == "stiff_out_stiffer":
        scale = float(rng.uniform(1.11, 1.16))
    elif dec == "stiff_out_softer":
        scale = float(rng.uniform(0.70, 0.86))
    nuis["stiffness_scale"] = scale
    if basef == "softplus":
        nuis["softplus_width_Nm"] = wsp
    base_fn = base_fn_s(scale)
    signal = base_fn(T)
    baseline = signal.copy()
    parts = {}
    if dec in ("stiff_in", "stiff_out_stiffer", "stiff_out_softer"):
        # nuisance decoy: the reference is the catalog curve itself (scale 1)
        baseline = base_fn_s(1.0)(T)
        parts["stiffness_scale"] = signal - baseline
        signal = baseline.copy()

    for eff in effects:
        if eff == "hysteresis":
            law, ne = cell["hyst"]
            parts[eff] = effect_hysteresis(rng, T, T0, m, base_fn, law, ne)
        elif eff == "backlash":
            parts[eff] = effect_backlash(rng, T, T0, m)
        elif eff == "housing_compliance":
            parts[eff] = effect_housing(rng, T, T0, base_fn)
    th_span = float(np.max(np.abs(signal)))
    tnorm = np.linspace(0, 1, n)
    meas = {}
    if dec == "sensor_gain":
        g = float(rng.choice([rng.uniform(0.93, 0.97), rng.uniform(1.03, 1.07)]))
        nuis["twist_sensor_gain"] = g
        meas["sensor_gain"] = (g - 1.0) * signal
    elif dec == "offset_const":
        off = float(rng.choice([-1, 1]) * rng.uniform(0.02, 0.1) * th_span)
        meas["angle_offset"] = np.full(n, off)
    elif dec == "offset_step":
        off = float(rng.choice([-1, 1]) * rng.uniform(0.02, 0.1) * th_span)
        ts = float(rng.uniform(0.3, 0.7))
        meas["angle_offset"] = np.where(tnorm >= ts, off, 0.0)
    elif dec == "drift_lin":
        d = float(rng.choice([-1, 1]) * rng.uniform(0.02, 0.1) * th_span)
        meas["thermal_drift"] = d * tnorm
    elif dec == "drift_exp":
        d = float(rng.choice([-1, 1]) * rng.uniform(0.02, 0.1) * th_span)
        tau = float(rng.uniform(0.2, 0.6))
        meas["thermal_drift"] = d * (1 - np.exp(-tnorm / tau)) / (1 - np.exp(-1 / tau))
    return _finish(rng, cell, idx, m, n, baseline, signal, parts, meas,
                   lambda y: {"torque_Nm": T, "twist_rad": y},
                   clean_sigma=th_span * float(np.exp(rng.uniform(np.log(5e-4), np.log(1e-2)))),
                   nuis=nuis, extra_form=f"baseline {basef}", J=None,
                   units=cell.get("units"), T=T)


# --------------------------------------------------------------------------------------------
# TRANSMISSION
# --------------------------------------------------------------------------------------------
def te_harmonic(rng, k, th_in, t, amp, form):
    """Angular transmission error at k cycles per wave-generator revolution (seed 000 p.021:
    theta_er = theta2 - theta1/R; the 2-per-rev component dominates), an additive harmonic
        e_k(t) = A(t) sin(k theta_in + phi(t))
    with a slowly drifting amplitude (AM: A = a (1 + m sin(2 pi t/Tm + psi)), m in [0.2, 0.6])
    or phase (PM: phi = phi0 + dphi sin(2 pi t/Tm + psi), dphi in [0.5, 1.5] rad), Tm = 0.8-1.6 x
    test time.  Sources: Ghorbel, Gandhi & Alpeter, "On the kinematic error in harmonic drive
    gears", ASME J. Mech. Des. 123(1):90-97, 2001 (kinematic error as harmonics of WG rotation,
    with modulation over the flexspline/output rotation); Tuttle & Seering 1996 (see above)."""
    ttot = t[-1]
    Tm = ttot * float(rng.uniform(0.8, 1.6))
    psi = float(rng.uniform(0, 2 * np.pi))
    phi0 = float(rng.uniform(0, 2 * np.pi))
    slow = np.sin(2 * np.pi * t / Tm + psi)
    if form == "AM":
        mm = float(rng.uniform(0.2, 0.6))
        return amp * (1 + mm * slow) * np.sin(k * th_in + phi0)
    if form == "PM":
        dphi = float(rng.uniform(0.5, 1.5))
        return amp * np.sin(k * th_in + phi0 + dphi * slow)
    return amp * np.sin(k * th_in + phi0)


def encoder_ecc(rng, angle):
    """Encoder eccentricity: a once-per-revolution error of the measured angle,
    d_phi = 2 e / D sin(angle + phi) (graduation eccentric by e on a disc of diameter D;
    HEIDENHAIN, "Angle Encoders with Integral Bearing" brochure, section "Mounting accuracy /
    eccentricity": d_phi = +-412 e/D arc-sec with e in um, D in mm).  e = 2-15 um, D = 40-120 mm."""
    e_um = float(rng.uniform(2, 15))
    D = float(rng.uniform(40, 120))
    amp = 412.0 * e_um / D / 3600 * np.pi / 180
    return amp * np.sin(angle + float(rng.uniform(0, 2 * np.pi)))


def gen_transmission(rng, m, cell, idx):
    R = m["ratio"]
    n_rev = R * float(rng.uniform(1.05, 1.3))  # > 1 OUTPUT revolution
    spr_max = int(min(40, 3000 // n_rev))
    spr_min = int(max(12, math.ceil(400 / n_rev)))
    spr = int(rng.integers(spr_min, spr_max + 1))
    n = int(n_rev * spr)
    speed_rpm = float(rng.uniform(10, 60))  # slow, constant input speed
    omega = speed_rpm * 2 * np.pi / 60
    th_in = np.arange(n) * (2 * np.pi / spr)
    t = th_in / omega
    off = float(rng.uniform(-0.5, 0.5))
    nuis = {"output_offset_rad": off}
    parts = {}
    acc = m["accuracy"]
    for eff in cell["effects"]:
        k = 1 if eff == "te_1x" else 2
        amp = acc * float(rng.uniform(0.1, 0.5))
        parts[eff] = te_harmonic(rng, k, th_in, t, amp, cell["form"])
    dec = cell.get("decoy")
    meas = {}
    tn = t / t[-1]
    th_in_meas = th_in
    if dec == "ecc_out":
        meas["encoder_eccentricity"] = encoder_ecc(rng, th_in / R)
    elif dec == "ecc_in":
        # eccentric / misaligned INPUT (motor-side) encoder: the recorded input angle is
        # theta_in + d sin(theta_in + phi); the output is untouched, so the output against the
        # recorded input carries -d/R sin(...) at 1 per input rev: data-equivalent to te_1x.
        # Amplitude d = R * accuracy * U(0.1, 0.5) (a coarse motor encoder, 0.1-2 deg).
        d = R * acc * float(rng.uniform(0.1, 0.5)) * np.sin(th_in + float(rng.uniform(0, 2 * np.pi)))
        th_in_meas = th_in + d
        meas["encoder_eccentricity"] = -d / R
    elif dec == "offset_step":
        s = float(rng.choice([-1, 1]) * acc * rng.uniform(0.1, 0.5))
        meas["angle_offset"] = np.where(tn >= rng.uniform(0.3, 0.7), s, 0.0)
    elif dec == "drift_lin":
        meas["thermal_drift"] = float(rng.choice([-1, 1]) * acc * rng.uniform(0.1, 0.5)) * tn
    elif dec == "drift_exp":
        tau = float(rng.uniform(0.2, 0.6))
        d = float(rng.choice([-1, 1]) * acc * rng.uniform(0.1, 0.5))
        meas["thermal_drift"] = d * (1 - np.exp(-tn / tau)) / (1 - np.exp(-1 / tau))
    # the catalog baseline is a function of the RECORDED input angle
    baseline = th_in_meas / R + off

    def cols(y):
        return {"input_angle_rad": th_in_meas, "output_angle_rad": y}
    return _finish(rng, cell, idx, m, n, baseline, baseline.copy(), parts, meas, cols,
                   clean_sigma=acc * float(np.exp(rng.uniform(np.log(0.005), np.log(0.05)))),
                   nuis=nuis, extra_form=f"{spr} samples/rev, {n_rev:.1f} input revs",
                   J=None, units=cell.get("units"))


# --------------------------------------------------------------------------------------------
# EFFICIENCY
# --------------------------------------------------------------------------------------------
ETA_REF = 78.0  # % : eta_R of the worked example CSF-20-80 (seed 000 p.023)


def ke_curve(alpha, form, ke058):
    """Efficiency correction factor Ke(alpha), alpha = T/T_rated (seed 000 p.023, graph 023-1:
    eta = Ke eta_R, Ke = 1 for alpha >= 1, the one surviving point alpha = 0.58 -> Ke = 0.93).
    'ke-power': Ke = 1 - a (1-alpha)^p, p in [1.2, 2.5];  'ke-exp': Ke = 1 - a (e^{-(alpha)/s} -
    e^{-1/s}), s in [0.2, 0.5]; a chosen so Ke(0.58) = ke058 (0.88..0.96 around the catalog 0.93).
    The falling shape at low load follows from a load-independent (no-load running) loss torque
    added to a load-proportional mesh loss: eta = eta_m T/(T + T_0) (cf. the HD catalogs'
    efficiency-correction graphs; Kiyosawa et al., "Performance of a strain wave gearing using a
    new tooth profile", Proc. ASME Power Transmission and Gearing Conf., 1989)."""
    alpha = np.asarray(alpha, dtype=float)
    a_c = np.minimum(alpha, 1.0)
    if form[0] == "ke-power":
        p = form[1]
        a = (1 - ke058) / (0.42 ** p)
        return 1 - a * (1 - a_c) ** p
    s = form[1]
    g = lambda x: np.exp(-x / s) - np.exp(-1 / s)  # noqa: E731
    a = (1 - ke058) / g(0.58)
    return 1 - a * g(a_c)


def viscous_loss(temp_C, B_K, nu_ratio_exp=2 / 3, T_ref=40.0):
    """Viscous-drag loss shape: churning/drag torque ~ (nu n)^(2/3) (Palmgren's load-independent
    friction moment M0 = 1e-7 f0 (nu n)^(2/3) dm^3; Harris & Kotzalas, *Rolling Bearing Analysis*,
    5th ed., CRC 2007, ch. 9), viscosity from the Andrade/Arrhenius law
    nu(T) = nu_ref exp(B (1/T - 1/T_ref)) (Andrade, Nature 125:309, 1930), B = 2500-4500 K.
    Returns (nu/nu_ref)^(2/3): rises as the lubricant gets colder."""
    TK = np.asarray(temp_C, dtype=float) + 273.15
    return np.exp(B_K * (1 / TK - 1 / (T_ref + 273.15))) ** nu_ratio_exp


def gen_efficiency(rng, m, cell, idx):
    Tr = m["rated"]
    speeds_all = [500, 1000, 1500, 2000, 2500, 3000, 3500]
    speeds_all = [s for s in speeds_all if s <= m["max_speed"]]
    ns = int(rng.integers(4, min(6, len(speeds_all)) + 1))
    speeds = sorted(rng.choice(speeds_all, ns, replace=False).tolist())
    nl = int(rng.integers(8, 13))
    alphas = np.linspace(float(rng.uniform(0.05, 0.15)), float(rng.uniform(1.0, 1.2)), nl)
    temps = [0.0, 10.0, 20.0, 30.0, 40.0, 50.0][: int(rng.integers(4, 7))]
    grid = [(s, a, tc) for tc in temps for s in speeds for a in alphas]
    reps = max(1, int(math.ceil(450 / len(grid))))
    reps = int(rng.integers(reps, reps + 2))
    while len(grid) * reps > 3000:
        reps -= 1
    rows = [g for g in grid for _ in range(reps)]
    dec = cell.get("decoy")
    ordered = dec == "drift_equiv" or (dec != "drift_sep" and rng.random() < 0.5)
    nrow = len(rows)
    if ordered:  # warm-up test: temperature blocks in ascending order, random order inside
        order = []
        for tc in temps:
            blk = [i for i, r in enumerate(rows) if r[2] == tc]
            order += rng.permutation(blk).tolist()
    else:
        order = rng.permutation(nrow).tolist()
    rows = [rows[i] for i in order]
    spd = np.array([r[0] for r in rows], dtype=float)
    alp = np.array([r[1] for r in rows], dtype=float)
    tmp = np.array([r[2] for r in rows], dtype=float)
    load = alp * Tr
    level = float(rng.uniform(ETA_REF * 0.9, ETA_REF * 1.1))
    if dec == "level":
        level = float(rng.choice([rng.uniform(55, 68), rng.uniform(88, 93)]))
    nuis = {"efficiency_level_pct": level}
    baseline = np.full(nrow, ETA_REF if dec == "level" else level)
    signal = np.full(nrow, level)
    parts = {}
    if dec == "level":
        parts["efficiency_level"] = signal - baseline
        signal = baseline.copy()
    for eff in cell["effects"]:
        if eff == "low_load_efficiency":
            ke058 = float(rng.uniform(0.88, 0.96))
            if cell["form"].startswith("ke-power") or cell["form"] == "pair":
                form = ("ke-power", float(rng.uniform(1.2, 2.5)))
            else:
                form = ("ke-exp", float(rng.uniform(0.2, 0.5)))
            parts[eff] = level * (ke_curve(alp, form, ke058) - 1.0)
        elif eff == "temperature_dependence":
            B = float(rng.uniform(2500, 4500))
            c = float(rng.uniform(0.8, 3.0))  # percentage points of loss at 40 C
            loss = c * viscous_loss(tmp, B)
            parts[eff] = -(loss - loss.mean())  # additive; its mean is absorbed by the level
    meas = {}
    if dec == "sensor_gain":
        g = float(rng.choice([rng.uniform(0.93, 0.97), rng.uniform(1.03, 1.07)]))
        nuis["torque_sensor_gain"] = g
        meas["sensor_gain"] = (g - 1.0) * signal
    elif dec in ("drift_sep", "drift_equiv"):
        # test time: 1 unit per row plus (ordered test) a long soak before each temperature block
        tt = np.arange(nrow, dtype=float)
        if ordered:
            blk = np.searchsorted(np.array(temps), tmp)
            tt = tt + blk * 20.0 * nrow
        tn = (tt - tt.min()) / (tt.max() - tt.min())
        tau = float(rng.uniform(0.25, 0.6))
        d = float(rng.uniform(1.0, 4.0))  # pp, reading rises as the rig warms up
        dr = d * (1 - np.exp(-tn / tau)) / (1 - np.exp(-1 / tau))
        meas["thermal_drift"] = dr - dr.mean()  # constant part = level nuisance
    return _finish(rng, cell, idx, m, nrow, baseline, signal, parts, meas,
                   lambda y: {"input_speed_rpm": spd, "load_torque_Nm": load,
                              "temperature_C": tmp, "efficiency_pct": y},
                   clean_sigma=float(rng.uniform(0.2, 1.0)), nuis=nuis,
                   extra_form=("temperature-ordered" if ordered else "random order"),
                   J=None, units=cell.get("units"))


# --------------------------------------------------------------------------------------------
# VIBRATION
# --------------------------------------------------------------------------------------------
def vib_response(t, th_fn, w_fn, k, phi, wn, zeta):
    """1-DOF load inertia J on the gear spring K (wn^2 = K/J), base-excited by the transmission
    error e = sin(k theta_in + phi) (unit amplitude; the ODE is linear):
        x'' = -wn^2 (x - e) - 2 zeta wn (x' - e'),   x = output angle about its mean rotation.
    Seed 000 p.021 (f = sqrt(K/J)/2pi; TE excites resonance when k f_in = f_n); model as in
    Tuttle & Seering 1996 and Thomson & Dahleh, *Theory of Vibration with Applications*, 5th ed.,
    Prentice Hall 1998, ch. 3 (base excitation).  Starts on the quasi-steady-state solution.
    Integrated with scipy.integrate.solve_ivp (RK45, rtol 1e-8)."""
    def exc(tt):
        th = k * th_fn(tt) + phi
        return np.sin(th), k * w_fn(tt) * np.cos(th)

    def rhs(tt, y):
        e, de = exc(tt)
        return [y[1], -wn * wn * (y[0] - e) - 2 * zeta * wn * (y[1] - de)]
    w0 = k * w_fn(t[0])
    H = (wn * wn + 2j * zeta * wn * w0) / (wn * wn - w0 * w0 + 2j * zeta * wn * w0)
    ph = k * th_fn(t[0]) + phi
    z0 = H * np.exp(1j * (ph - np.pi / 2))  # sin = Re(e^{i(ph - pi/2)})
    y0 = [z0.real, (1j * w0 * z0).real]
    fmax = max(k * w_fn(t[-1]), wn) / (2 * np.pi)
    sol = solve_ivp(rhs, (t[0], t[-1]), y0, t_eval=t, method="RK45", rtol=1e-8, atol=1e-10,
                    max_step=1.0 / (25 * fmax))
    return sol.y[0]


def gen_vibration(rng, m, cell, idx):
    scale = float(rng.uniform(0.9, 1.1))
    K = m["K1"] * scale
    fn = float(rng.uniform(8, 25))
    wn = 2 * np.pi * fn
    J = K / wn ** 2
    zeta = float(rng.uniform(0.02, 0.1))
    f_lo = fn * float(rng.uniform(0.3, 0.4))
    f_hi = fn * float(rng.uniform(1.3, 1.5))
    fs = 8.0 * fn
    n = int(rng.integers(1200, 3001))
    D = n / fs
    t = np.arange(n) / fs
    r = (f_hi - f_lo) / D  # Hz/s run-up of the input (WG) speed

    def th_fn(tt):
        return 2 * np.pi * (f_lo * tt + 0.5 * r * tt * tt)

    def w_fn(tt):
        return 2 * np.pi * (f_lo + r * tt)
    speed_rpm = 60 * (f_lo + r * t)
    nuis = {"stiffness_scale": scale, "damping_ratio": zeta}
    baseline = np.zeros(n)
    parts = {}
    acc = m["accuracy"]
    for eff in cell["effects"]:
        k = 1 if eff == "te_1x" else 2
        amp = acc * float(rng.uniform(0.05, 0.3))
        parts[eff] = amp * vib_response(t, th_fn, w_fn, k, float(rng.uniform(0, 2 * np.pi)),
                                        wn, zeta)
    dec = cell.get("decoy")
    meas = {}
    tn = t / t[-1]
    lvl = acc * 0.05
    if dec == "offset_step":
        s = float(rng.choice([-1, 1]) * lvl * rng.uniform(0.5, 2))
        meas["angle_offset"] = np.where(tn >= rng.uniform(0.3, 0.7), s, 0.0)
    elif dec == "drift_lin":
        meas["thermal_drift"] = float(rng.choice([-1, 1]) * lvl * rng.uniform(0.5, 2)) * tn
    elif dec == "drift_exp":
        tau = float(rng.uniform(0.2, 0.6))
        d = float(rng.choice([-1, 1]) * lvl * rng.uniform(0.5, 2))
        meas["thermal_drift"] = d * (1 - np.exp(-tn / tau)) / (1 - np.exp(-1 / tau))
    elif dec == "ecc_out":
        meas["encoder_eccentricity"] = encoder_ecc(rng, th_fn(t) / m["ratio"])
    return _finish(rng, cell, idx, m, n, baseline, baseline.copy(), parts, meas,
                   lambda y: {"time_s": t, "input_speed_rpm": speed_rpm,
                              "output_vibration_rad": y},
                   clean_sigma=acc * float(np.exp(rng.uniform(np.log(0.002), np.log(0.02)))),
                   nuis=nuis, extra_form=f"f_n={fn:.2f} Hz, zeta={zeta:.3f}", J=J,
                   units=cell.get("units"))


# --------------------------------------------------------------------------------------------
# assembling a case
# --------------------------------------------------------------------------------------------
UNIT_FACTOR = {"deg": RAD2DEG, "kNm": 1e-3, "fraction": 1e-2}


def _finish(rng, cell, idx, m, n, baseline, signal, parts, meas, make_cols, clean_sigma, nuis,
            extra_form, J, units=None, T=None):
    cat = cell["category"]
    names = list(parts) + list(meas)
    comps = [parts[k] for k in parts] + [meas[k] for k in meas]
    # noise kind
    if cat == "clean":
        nkind = cell["noise"]
    else:
        nkind = "white" if rng.random() < 0.5 else "ar1"
    if comps and units is None:
        total = np.sum(comps, axis=0)
        rl = [_rms(c) for c in comps] + [_rms(total)]
        sigma = _pick_k(rng, rl)
        tries = 0
        while sigma is None and tries < 50:  # shrink the larger component(s) until feasible
            big = int(np.argmax(rl[:-1]))
            comps[big] = comps[big] * 0.8
            total = np.sum(comps, axis=0)
            rl = [_rms(c) for c in comps] + [_rms(total)]
            sigma = _pick_k(rng, rl)
            tries += 1
        if sigma is None:
            raise RuntimeError("infeasible effect sizes")
        for nm, c in zip(names, comps):
            if nm in parts:
                parts[nm] = c
            else:
                meas[nm] = c
    else:
        total = np.sum(comps, axis=0) if comps else np.zeros(n)
        sigma = clean_sigma
    noise, omask, ndesc = make_noise(rng, n, sigma, nkind)
    gear_total = np.sum([parts[k] for k in parts], axis=0) if parts else np.zeros(n)
    meas_total = np.sum([meas[k] for k in meas], axis=0) if meas else np.zeros(n)
    noiseless = signal + gear_total + meas_total
    y = noiseless + noise
    hidden = total
    cols = make_cols(y)
    noise_rms = sigma
    uf = 1.0
    if units is not None:
        uf = UNIT_FACTOR[units]
        if units == "kNm":
            key = "torque_Nm" if "torque_Nm" in cols else "load_torque_Nm"
            cols[key] = cols[key] * uf
            hidden = None
        else:
            key = [k for k in cols if k in ("twist_rad", "output_angle_rad",
                                             "efficiency_pct")][0]
            cols[key] = cols[key] * uf
            noise_rms = sigma * uf
            hidden = noiseless * uf - baseline
    if units is not None:
        if units == "kNm":
            kcol = "torque_Nm" if "torque_Nm" in cols else "load_torque_Nm"
            orig = make_cols(y)[kcol]
            # no noise on that channel: compare with the measured channel's relative noise level
            rel = sigma / max(_rms(noiseless), 1e-300)
            snr = _rms(cols[kcol] - orig) / (rel * _rms(orig))
        else:
            snr = _rms(hidden) / noise_rms
        meas_names = ("wrong_units",)
    else:
        snr = _rms(hidden) / sigma if comps else 0.0
        meas_names = tuple(meas)
    gear = tuple(cell["effects"])
    form = cell["form_desc"] + "; " + extra_form + "; noise " + ndesc
    case = TruthCase(
        name=f"b-{cell['kind']}-{cat}-{cell['tag']}-{idx:03d}",
        kind=cell["kind"], model=m["model"],
        columns={k: np.asarray(v, dtype=float) for k, v in cols.items()},
        load_inertia_kgm2=J, gear_effects=gear, measurement_effects=meas_names,
        nuisance={k: float(v) for k, v in nuis.items()}, category=cat,
        equivalent_effects=tuple(cell.get("equiv", ())), noise_rms=float(noise_rms),
        formulation=form, snr=float(snr))
    # private extras for the self-test (not dataclass fields)
    case._baseline = np.asarray(baseline) * (
        uf if units in ("deg", "fraction") else 1.0)
    case._parts = {k: np.asarray(v) for k, v in {**parts, **meas}.items()}
    case._noise = noise * (uf if units in ("deg", "fraction") else 1.0)
    case._outliers = omask
    case._sigma_si = sigma
    case._units = units
    return case


# --------------------------------------------------------------------------------------------
# the cell table
# --------------------------------------------------------------------------------------------
def _cells():
    C = []

    def add(kind, category, effects, tag, form_desc, **kw):
        C.append(dict(kind=kind, category=category, effects=tuple(effects), tag=tag,
                      form_desc=form_desc, **kw))
    for kind in ("torsion", "transmission", "efficiency", "vibration"):
        for nz in ("white", "ar1", "outliers"):
            add(kind, "clean", (), f"none-{nz}", "catalog baseline", noise=nz, form="")
    # torsion
    for law, ne, tg, fd in (("bw", 1, "boucwen1", "bouc-wen n=1"), ("bw", 2, "boucwen2",
                            "bouc-wen n=2"), ("bw", 3, "boucwen3", "bouc-wen n=3"),
                            ("dahl", 1, "dahl", "dahl")):
        add("torsion", "single", ("hysteresis",), f"hysteresis-{tg}", fd, hyst=(law, ne), form=fd)
    add("torsion", "single", ("backlash",), "backlash-tanh", "dead zone tanh edge", form="")
    add("torsion", "single", ("housing_compliance",), "housing_compliance-series",
        "series spring", form="")
    add("torsion", "pair", ("hysteresis", "backlash"), "hysteresis+backlash-boucwen2",
        "bouc-wen n=2 + dead zone tanh edge", hyst=("bw", 2), form="")
    add("torsion", "pair", ("hysteresis", "backlash"), "hysteresis+backlash-dahl",
        "dahl + dead zone tanh edge", hyst=("dahl", 1), form="")
    add("torsion", "pair", ("hysteresis", "housing_compliance"),
        "hysteresis+housing_compliance-boucwen1", "bouc-wen n=1 + series spring",
        hyst=("bw", 1), form="")
    add("torsion", "pair", ("backlash", "housing_compliance"),
        "backlash+housing_compliance-tanh", "dead zone tanh edge + series spring", form="")
    for dec, tg, fd, units in (
            ("sensor_gain", "sensor_gain-twist", "twist-sensor gain error", None),
            ("offset_const", "angle_offset-constant", "constant twist offset", None),
            ("offset_step", "angle_offset-stepped", "stepped twist offset", None),
            ("drift_lin", "thermal_drift-linear", "thermal drift linear in test time", None),
            ("drift_exp", "thermal_drift-exponential", "thermal drift exponential in test time",
             None),
            (None, "wrong_units-degrees", "twist in degrees (x57.2958)", "deg"),
            (None, "wrong_units-kNm", "torque in kN.m (x1e-3)", "kNm"),
            ("stiff_in", "stiffness_scale-inspread", "stiffness scale 5-10 % off catalog", None),
            ("stiff_out_stiffer", "stiffness_scale-stiffer",
             "stiffness scale 1.11-1.16 (just outside, stiffer)", None)):
        add("torsion", "decoy_separable", (), tg, fd, decoy=dec, units=units, form="")
    add("torsion", "decoy_equivalent", (), "stiffness_scale-softer",
        "gear softer than catalog, scale 0.70-0.86", decoy="stiff_out_softer",
        equiv=("housing_compliance",), form="")
    # transmission
    for eff in ("te_1x", "te_2x"):
        for fm in ("AM", "PM"):
            add("transmission", "single", (eff,), f"{eff}-{fm}", f"additive harmonic {fm}",
                form=fm)
    for fm in ("AM", "PM"):
        add("transmission", "pair", ("te_1x", "te_2x"), f"te_1x+te_2x-{fm}",
            f"additive harmonics {fm}", form=fm)
    for dec, tg, fd, units in (
            ("ecc_out", "encoder_eccentricity-output", "output encoder eccentricity, 1/output rev",
             None),
            ("offset_step", "angle_offset-stepped", "stepped output-angle offset", None),
            ("drift_lin", "thermal_drift-linear", "thermal drift linear in test time", None),
            ("drift_exp", "thermal_drift-exponential", "thermal drift exponential in test time",
             None),
            (None, "wrong_units-degrees", "output angle in degrees (x57.2958)", "deg")):
        add("transmission", "decoy_separable", (), tg, fd, decoy=dec, units=units, form="")
    add("transmission", "decoy_equivalent", (), "encoder_eccentricity-input",
        "INPUT encoder eccentricity, 1/input rev (reads as te_1x)", decoy="ecc_in",
        equiv=("te_1x",), form="")
    # efficiency
    add("efficiency", "single", ("low_load_efficiency",), "low_load_efficiency-kepower",
        "Ke power curve (multiplicative)", form="ke-power")
    add("efficiency", "single", ("low_load_efficiency",), "low_load_efficiency-keexp",
        "Ke exponential curve (multiplicative)", form="ke-exp")
    add("efficiency", "single", ("temperature_dependence",), "temperature_dependence-viscous",
        "viscous drag, Andrade viscosity (additive)", form="viscous")
    add("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"),
        "low_load_efficiency+temperature_dependence-kepower-viscous",
        "Ke power curve + viscous drag", form="pair")
    for dec, tg, fd, units in (
            ("sensor_gain", "sensor_gain-torque", "torque-sensor gain error", None),
            (None, "wrong_units-fraction", "efficiency as a fraction (x0.01)", "fraction"),
            (None, "wrong_units-kNm", "load torque in kN.m (x1e-3)", "kNm"),
            ("drift_sep", "thermal_drift-randomorder",
             "thermal drift with test time, random test order", None),
            ("level", "efficiency_level-outside", "efficiency level far from 78 %", None)):
        add("efficiency", "decoy_separable", (), tg, fd, decoy=dec, units=units, form="")
    add("efficiency", "decoy_equivalent", (), "thermal_drift-warmup",
        "thermal drift in a cold-to-warm ordered test (reads as temperature dependence)",
        decoy="drift_equiv", equiv=("temperature_dependence",), form="")
    # vibration
    add("vibration", "single", ("te_1x",), "te_1x-additive", "TE 1x excitation", form="")
    add("vibration", "single", ("te_2x",), "te_2x-additive", "TE 2x excitation", form="")
    add("vibration", "pair", ("te_1x", "te_2x"), "te_1x+te_2x-additive",
        "TE 1x + 2x excitation", form="")
    for dec, tg, fd in (("offset_step", "angle_offset-stepped", "stepped angle offset"),
                        ("drift_lin", "thermal_drift-linear", "thermal drift linear"),
                        ("drift_exp", "thermal_drift-exponential", "thermal drift exponential"),
                        ("ecc_out", "encoder_eccentricity-output",
                         "output encoder eccentricity, 1/output rev")):
        add("vibration", "decoy_separable", (), tg, fd, decoy=dec, form="")
    return C


_GEN = {"torsion": gen_torsion, "transmission": gen_transmission,
        "efficiency": gen_efficiency, "vibration": gen_vibration}


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    """All cells x ``per_cell`` cases, drawn with numpy.random.default_rng(seed)."""
    rng = np.random.default_rng(seed)
    models = {mc: load_model(catalog_dir, mc) for mc in MODELS}
    out = []
    for cell in _cells():
        for i in range(per_cell):
            m = models[MODELS[int(rng.integers(len(MODELS)))]]
            out.append(_GEN[cell["kind"]](rng, m, cell, i))
    return out


if __name__ == "__main__":  # pragma: no cover
    import sys
    from collections import Counter
    cd = sys.argv[1] if len(sys.argv) > 1 else "/work/main/catalog"
    cs = generate_cases(int(sys.argv[2]) if len(sys.argv) > 2 else 0, cd)
    print(len(cs))
    for (k, c), v in sorted(Counter((c.kind, c.category) for c in cs).items()):
        print(f"{k:13s} {c:17s} {v}")
