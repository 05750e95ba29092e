"""Truth suite C: synthetic "measured" strain-wave-gear data with known hidden effects.

Written from the contract (/work/truths/CONTRACT.md), the catalog tables and the physics
literature only; numpy + scipy, nothing from hdcad.  Formulations deliberately differ from the
obvious ones:
  torsion      hysteresis: a Dahl (exponent 1-2) or Bouc-Wen (n = 1, 2, 3) friction element in
               parallel with a spring, driven by torque (twist lags, dissipative), or a
               Preisach weighted relay sum (demagnetised start);
               backlash: smooth dead zone, tanh in torque or softplus gap spring inverted;
               housing compliance: series spring, linear or cubic-stiffening.
  transmission TE at 1x / 2x WG revolution, amplitude- or phase-modulated harmonic; samples are
               triggered at equal steps of the measured input angle (encoder-triggered TE rig).
  efficiency   low-load loss as a constant drag torque (Ke = a(1+c)/(a+c)) or exponential Ke;
               temperature: multiplicative exp(-(T-T0)/Tc) viscous loss, or additive loss in
               percentage points that scales with speed^0.6.
  vibration    slow run-up; TE as displacement excitation of the gear spring with the load
               inertia; viscous damping (time-domain filter) or structural damping (complex
               stiffness K(1+i eta), quasi-stationary response).
Effect sizes: every hidden effect has RMS = k * noise_rms, k ~ U[4, 12] (pairs: each effect;
`snr` is the smallest k).  noise_rms is the RMS of the white / AR(1) part; gross outliers
(0.5 % of rows, 8-15 x noise_rms) come on top and are listed in `info`.
"""
from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import optimize, signal

SUITE = "c"
DEG = 180.0 / math.pi
T_REF_C = 25.0  # reference lubricant temperature of the temperature laws (003: surface 25 C)


@dataclass
class TruthCase:
    name: str
    kind: str
    model: str
    columns: dict
    load_inertia_kgm2: float | None
    gear_effects: tuple
    measurement_effects: tuple
    nuisance: dict
    category: str
    equivalent_effects: tuple = ()
    noise_rms: float = 0.0
    formulation: str = ""
    snr: float = 0.0
    info: dict = field(default_factory=dict)  # extra: noise type, AR phi, outliers, k per effect

    def write_csv(self, path) -> None:
        names = list(self.columns)
        cols = [np.asarray(self.columns[c], dtype=float).tolist() for c in names]
        with open(path, "w", encoding="utf-8") as f:
            f.write(",".join(names) + "\n")
            for row in zip(*cols):
                f.write(",".join(repr(v) for v in row) + "\n")


# ----------------------------------------------------------------------------- catalog
def _read(p):
    with open(p, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def _in_range(r, R):
    return int(r["ratio_min"]) <= R and (r["ratio_max"] == "" or R <= int(r["ratio_max"]))


def _load_models(catalog_dir):
    d = Path(catalog_dir)
    rat = _read(d / "gh_ratings_050-1_058-1.csv")
    stf = _read(d / "gh_stiffness_052-1_060-1.csv")
    hys = _read(d / "gh_hysteresis_052_060.csv")
    bls = _read(d / "gh_backlash_052-2_060-2.csv")
    prf = _read(d / "gh_performance_051-1_059-1.csv")
    models = []
    for r in rat:
        ser, size, R = r["series"], int(r["size"]), int(r["ratio"])
        st = [x for x in stf if x["series"] == ser and int(x["size"]) == size and _in_range(x, R)]
        hy = [x for x in hys if x["series"] == ser and _in_range(x, R)]
        bl = [x for x in bls if x["series"] == ser and int(x["size"]) == size and int(x["ratio"]) == R]
        if not (st and hy and bl):
            continue
        acc = [float(x["accuracy_rad"]) for x in prf if x["series"] == ser and int(x["size"]) == size
               and int(x["ratio"]) == R and x["accuracy_rad"]]
        s = st[0]
        models.append(dict(
            code=f"{ser.split('-')[0]}-{size}-{R}-GH", R=R, Tr=float(r["rated_torque_2000_Nm"]),
            nmax=float(r["avg_input_speed_max_rpm"]),
            T1=float(s["T1_Nm"]), T2=float(s["T2_Nm"]), K1=float(s["K1_Nm_per_rad"]),
            K2=float(s["K2_Nm_per_rad"]), K3=float(s["K3_Nm_per_rad"]),
            hyst=float(hy[0]["hysteresis_rad"]), bl=float(bl[0]["backlash_rad"]),
            acc=acc[0] if acc else 2.9e-4))  # 1 arc-min where the table leaves it blank
    return models


def _twist3(T, m, s=1.0):
    """Catalog three-segment curve (theta1 = T1/K1, theta2 = theta1 + (T2-T1)/K2), odd in T."""
    a = np.abs(T)
    th1 = m["T1"] / m["K1"]
    th2 = th1 + (m["T2"] - m["T1"]) / m["K2"]
    th = np.where(a <= m["T1"], a / m["K1"],
                  np.where(a <= m["T2"], th1 + (a - m["T1"]) / m["K2"], th2 + (a - m["T2"]) / m["K3"]))
    return np.sign(T) * th / s


# ----------------------------------------------------------------------------- helpers
def _rms(x):
    return float(np.sqrt(np.mean(np.square(x))))


def _fit(parts, ks, sigma=None, anchor=False):
    """Scale each part to RMS k_i*sigma.  Without sigma, sigma is the geometric mean of
    rms_i/k_i (or rms_0/k_0 with anchor: the first part keeps its size), so a single effect
    keeps its physical size and a pair is rescaled evenly."""
    r = [_rms(p) for p in parts]
    if sigma is None and anchor:
        sigma = r[0] / ks[0]
    if sigma is None:
        sigma = float(np.exp(np.mean([np.log(ri / k) for ri, k in zip(r, ks)])))
    return [p * (k * sigma / ri) for p, k, ri in zip(parts, ks, r)], sigma


def _noise(rng, n, sigma, phi, outliers):
    w = rng.standard_normal(n)
    if phi > 0:
        w[0] /= math.sqrt(1.0 - phi * phi)  # stationary start
        w = signal.lfilter([1.0], [1.0, -phi], w)
    e = w * (sigma / _rms(w))
    n_out = 0
    if outliers:
        n_out = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, n_out, replace=False)
        e[idx] += rng.choice([-1.0, 1.0], n_out) * rng.uniform(8, 15, n_out) * sigma
    return e, n_out


def _drift(rng, t):
    return 1.0 - np.exp(-(t - t[0]) / (rng.uniform(0.3, 1.5) * (t[-1] - t[0])))


def _step(rng, t):
    ts = t[0] + rng.uniform(0.3, 0.7) * (t[-1] - t[0])
    return np.where(t > ts, 1.0, 0.0) * rng.choice([-1.0, 1.0])


# ----------------------------------------------------------------------------- hysteresis
def _path(knots, step):
    Ts, legs = [np.array([float(knots[0])])], [np.array([0])]
    for i, (a, b) in enumerate(zip(knots[:-1], knots[1:])):
        n = max(24, int(math.ceil(abs(b - a) / step)))
        Ts.append(np.linspace(a, b, n + 1)[1:])
        legs.append(np.full(n, i))
    return np.concatenate(Ts), np.concatenate(legs)


def _friction_twist(x, law, fc, sub=8):
    """Torque-driven twist of a hysteretic friction element in parallel with a spring:
    u = d + fc*g (torque / T0 = spring twist d + friction torque), dg/dd = law(g, sgn dd),
    |g| <= 1.  Returns the twist beyond the linear spring, d - u = -fc*g (lags the torque,
    dissipative; small cycles stay elastic because the friction element is stiff there)."""
    z = np.zeros_like(x)
    g = 0.0
    for i in range(1, len(x)):
        du = (x[i] - x[i - 1]) / sub
        if du != 0.0:
            sg = 1.0 if du > 0 else -1.0
            for _ in range(sub):
                dg = law(g, sg)
                g = min(1.0, max(-1.0, g + dg * du / (1.0 + fc * dg)))
        z[i] = -fc * g
    return z


def _dahl(x, rho, expo, fc):
    """Dahl friction dF/dd = sigma |1 - F/Fc sgn|^i (normalised: g = F/Fc, rho = sigma/k/fc)."""
    return _friction_twist(x, lambda g, s: rho * abs(1.0 - g * s) ** expo, fc)


def _boucwen(x, n, rho, beta, fc):
    """Bouc-Wen friction dg/dd = rho [1 - (beta sgn(dd g) + gamma)|g|^n], beta + gamma = 1."""
    gamma = 1.0 - beta
    return _friction_twist(x, lambda g, s: rho * (1.0 - (beta * (1.0 if s * g >= 0 else -1.0) + gamma) * abs(g) ** n), fc)


def _preisach(x, p, sm, M=40):
    """Weighted sum of relays (up at x >= alpha, down at x <= beta); weights vanish for
    narrow relays (small loops ~ no loss) and concentrate near alpha + beta = 0."""
    g = np.linspace(-1.05, 1.05, M)
    A, B = np.meshgrid(g, g, indexing="ij")
    k = A > B
    a, b = A[k], B[k]
    w = np.exp(-((a + b) / 2) ** 2 / (2 * sm * sm)) * ((a - b) / 2) ** p
    w /= w.sum()
    st = np.where(a + b < 0, 1.0, -1.0)  # demagnetised state
    out = np.empty_like(x)
    for i, xi in enumerate(x):
        st[a <= xi] = 1.0
        st[b >= xi] = -1.0
        out[i] = w @ st
    return out - out[0]


def _zero_width(z, x, leg):
    """Loop width at zero torque between the T0 -> -T0 and the -T0 -> T0 legs (B - B')."""
    d, u = leg == 4, leg == 5
    return float(np.interp(0.0, x[d][::-1], z[d][::-1]) - np.interp(0.0, x[u], z[u]))


def _softplus_deadzone(T, delta, eps, Kc):
    """Gap spring T = Kc[sp(th - delta) - sp(-th - delta)], sp = eps log(1 + e^(u/eps)); inverted."""
    tmax = delta + 1.2 * np.max(np.abs(T)) / Kc + 10 * eps
    th = np.linspace(-tmax, tmax, 40001)
    Tg = Kc * eps * (np.logaddexp(0, (th - delta) / eps) - np.logaddexp(0, (-th - delta) / eps))
    return np.interp(T, Tg, th)


def _cubic_spring(T, k1, k3):
    """Root of k1 th + k3 th^3 = T (Newton from the upper bound, monotone convergence)."""
    a = np.abs(T)
    th = np.minimum(a / k1, np.cbrt(a / k3))
    for _ in range(40):
        th = th - (k1 * th + k3 * th ** 3 - a) / (k1 + 3 * k3 * th ** 2)
    return np.sign(T) * th


def _torsion_effect(rng, e, f, T, leg, T0, m, s):
    x = T / T0
    if e == "hysteresis":
        H, rho, fc = m["hyst"] * rng.uniform(0.6, 1.6), rng.uniform(3, 12), rng.uniform(0.05, 0.2)
        expo, beta, p, sm = rng.uniform(1, 2), rng.uniform(0.6, 0.9), rng.uniform(1, 3), rng.uniform(0.2, 0.5)
        dT = np.diff(T)
        nz = dT != 0
        bslope = (np.diff(_twist3(T, m, s))[nz] / dT[nz])
        for _ in range(12):
            if f == "dahl":
                z = _dahl(x, rho, expo, fc)
            elif f == "preisach":
                z = _preisach(x, p, sm)
            else:
                z = _boucwen(x, int(f[-1]), rho, beta, fc)
            c = H / _zero_width(z, x, leg)
            zs = np.diff(z)[nz] / dT[nz]  # keep the total twist monotone: base + c*zs >= 0.1 base
            neg = zs < 0
            cmax = np.min(0.9 * bslope[neg] / -zs[neg]) if neg.any() else np.inf
            if c <= cmax or fc >= 0.9:
                break
            fc = min(0.9, fc * 1.25)  # a larger friction torque carries the catalog's loss
        return z * min(c, cmax)
    if e == "backlash":
        b = m["bl"] * rng.uniform(1, 4)
        if f == "tanh":
            return 0.5 * b * np.tanh(T / (T0 * rng.uniform(0.005, 0.03)))
        return _softplus_deadzone(T, 0.5 * b, 0.5 * b * rng.uniform(0.1, 0.25), s * m["K1"] * rng.uniform(10, 30))
    Kh = s * m["K3"] * rng.uniform(2, 6)  # housing_compliance
    if f == "linear":
        return T / Kh
    k1 = Kh * rng.uniform(0.3, 0.6)
    th0 = T0 / Kh
    return _cubic_spring(T, k1, (T0 - k1 * th0) / th0 ** 3)


# ----------------------------------------------------------------------------- kinds
def _torsion(rng, m, cat, gear, meas, form, ks):
    T0 = m["Tr"] * rng.uniform(1.0, 1.4)
    a = T0 * rng.uniform(0.08, 0.15)
    T, leg = _path([0, a, -a, 0, T0, -T0, T0, 0], T0 / 150)
    t = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(T)))]) / T0 * rng.uniform(20, 60)
    s = rng.uniform(0.9, 1.1)
    nuis, params, equiv, snr, conv = {"stiffness_scale": s}, {}, (), None, None
    base = _twist3(T, m, s)
    Tcol = T.copy()
    sig_ref = m["hyst"] * rng.uniform(0.03, 0.1)
    y = base
    if cat in ("single", "pair"):
        parts = [_torsion_effect(rng, e, f, T, leg, T0, m, s) for e, f in zip(gear, form.split(" + "))]
        parts, sigma = _fit(parts, ks, anchor=True)  # hysteresis (first) keeps its checked size
        y = base + sum(parts)
    elif cat == "clean":
        sigma = sig_ref
    elif form == "stiffness-scale":
        s2 = 1.0 + rng.choice([-1.0, 1.0]) * rng.uniform(0.02, 0.08)
        nuis = {"stiffness_scale": s2}
        y = _twist3(T, m, s2)
        sigma = _rms(y - _twist3(T, m)) / ks[0]
    elif form == "softer gear":
        s2 = rng.uniform(0.55, 0.8)
        nuis, equiv = {"stiffness_scale": s2}, ("housing_compliance",)
        y = _twist3(T, m, s2)
        sigma = _rms(y - _twist3(T, m)) / ks[0]
    elif form == "input-lock spring":  # compliant WG lock, K_in * R^2 at the output
        Kout = s * m["K3"] * rng.uniform(2, 6)
        nuis["input_lock_stiffness_Nm_per_rad"] = Kout / m["R"] ** 2
        equiv = ("housing_compliance",)
        d = T / Kout
        y, sigma = base + d, _rms(d) / ks[0]
    elif form == "input-lock play":  # clearance in the WG lock, delta_in / R at the output
        din = rng.uniform(0.5e-3, 3e-3)
        nuis["input_lock_play_rad"] = din
        equiv = ("backlash",)
        d = 0.5 * din / m["R"] * np.tanh(T / (T0 * rng.uniform(0.005, 0.03)))
        y, sigma = base + d, _rms(d) / ks[0]
    elif meas[0] == "sensor_gain":
        g = 1.0 + rng.choice([-1.0, 1.0]) * rng.uniform(0.03, 0.1)
        params["torque_gain"] = g
        Tcol = g * T
        sigma = _rms(base - _twist3(Tcol, m, s)) / ks[0]
    elif meas[0] in ("thermal_drift", "angle_offset"):
        shape = _drift(rng, t) if meas[0] == "thermal_drift" else _step(rng, t)
        (d,), sigma = _fit([shape], ks, sig_ref)
        y = base + d
    else:  # wrong_units
        sigma = sig_ref
        if form == "deg for rad":
            conv = ("twist_rad", DEG)
            snr = _rms(base) * (DEG - 1) / (sigma * DEG)
        else:
            conv = ("torque_Nm", 1e-3)
            snr = _rms(base - _twist3(T * 1e-3, m, s)) / sigma
    cols = {"torque_Nm": Tcol, "twist_rad": y, "time_s": t}
    return cols, "twist_rad", sigma, nuis, params, equiv, snr, conv, None


def _transmission(rng, m, cat, gear, meas, form, ks):
    R, spr = m["R"], 128
    n = int(rng.uniform(8, 24) * spr)
    thm = rng.uniform(0, 2 * math.pi) + 2 * math.pi * np.arange(n) / spr  # measured input angle
    th = thm.copy()
    off = rng.uniform(-math.pi, math.pi)
    rev = (thm - thm[0]) / (2 * math.pi)
    nuis, params, equiv, snr, conv = {"offset_rad": off}, {}, (), None, None
    sig_ref = m["acc"] * rng.uniform(0.02, 0.08)
    extra = 0.0

    def te(k):
        a0, psi, Pm, pm = m["acc"] * rng.uniform(0.15, 0.5), rng.uniform(0, 2 * math.pi), rng.uniform(3, 8), rng.uniform(0, 2 * math.pi)
        mod = np.sin(2 * math.pi * rev / Pm + pm)
        if form == "AM":
            return a0 * (1 + rng.uniform(0.2, 0.6) * mod) * np.sin(k * th + psi)
        return a0 * np.sin(k * th + psi + rng.uniform(0.3, 1.2) * mod)

    if cat in ("single", "pair"):
        parts, sigma = _fit([te(1 if e == "te_1x" else 2) for e in gear], ks)
        extra = sum(parts)
    elif cat == "clean":
        sigma = sig_ref
    elif cat == "decoy_equivalent":  # input-encoder error at k per input rev: th + e sin(k th + psi) = thm
        k = 1 if "1x" in form else 2
        e_in, psi = R * math.sqrt(2) * ks[0] * sig_ref, rng.uniform(0, 2 * math.pi)
        for _ in range(30):
            th = th - (th + e_in * np.sin(k * th + psi) - thm) / (1 + e_in * k * np.cos(k * th + psi))
        nuis.update({"input_encoder_error_rad": e_in, "input_encoder_order": float(k)})
        equiv = ("te_1x",) if k == 1 else ("te_2x",)
        sigma = _rms((th - thm) / R) / ks[0]
    elif meas[0] == "wrong_units":
        sigma, conv = sig_ref, ("output_angle_rad", DEG)
        snr = _rms(th / R + off) * (DEG - 1) / (sigma * DEG)
    else:
        shape = {"sensor_gain": (th - th[0]) / R, "angle_offset": _step(rng, rev),
                 "encoder_eccentricity": np.sin(th / R + rng.uniform(0, 2 * math.pi)),
                 "thermal_drift": _drift(rng, rev)}[meas[0]]
        (extra,), sigma = _fit([shape], ks, sig_ref)
        if meas[0] == "sensor_gain":
            params["output_gain"] = 1.0 + ks[0] * sig_ref / _rms(shape)
    cols = {"input_angle_rad": thm, "output_angle_rad": th / R + off + extra}
    return cols, "output_angle_rad", sigma, nuis, params, equiv, snr, conv, None


def _efficiency(rng, m, cat, gear, meas, form, ks):
    sp = [v for v in (250, 500, 1000, 1500, 2000, 2500, 3000, 3500) if v <= m["nmax"]]
    speeds = np.sort(rng.choice(sp, int(rng.integers(3, 5)), replace=False))
    alphas = np.linspace(rng.uniform(0.08, 0.15), rng.uniform(1.0, 1.15), int(rng.integers(6, 10)))
    temps = np.sort(np.r_[rng.choice([-10.0, 0.0, 10.0]), rng.choice([20.0, 30.0, 40.0, 50.0, 60.0], int(rng.integers(2, 4)), replace=False)])
    N, A, TC = (v.ravel() for v in np.meshgrid(speeds, alphas, temps, indexing="ij"))
    order = rng.permutation(len(N))  # random run order; time_s is an extra column
    N, A, TC = N[order].astype(float), A[order], TC[order]
    t = np.arange(len(N)) * rng.uniform(60, 180)
    eta0 = rng.uniform(60, 78)
    nuis, params, equiv, snr, conv = {"efficiency_level_pct": eta0}, {}, (), None, None
    sig_ref = rng.uniform(0.3, 1.5)
    y = np.full(len(N), eta0)

    def ke(f, K58):
        if f == "drag-torque":  # constant no-load drag torque: Ke = a(1+c)/(a+c), Ke(0.58) = K58
            c = 0.58 * (1 - K58) / (K58 - 0.58)
            return np.where(A < 1, A * (1 + c) / (A + c), 1.0)
        a = 0.3 + 0.2 * (K58 - 0.58) / 0.42
        d = (1 - K58) / (math.exp(-0.58 / a) - math.exp(-1 / a))
        return np.where(A < 1, 1 - d * (np.exp(-A / a) - math.exp(-1 / a)), 1.0)

    def lowload(f, target=None):  # physical Ke(0.58) ~ 0.88-0.96 (graph 023-1: 0.93), or solved for an RMS
        K58 = rng.uniform(0.88, 0.96) if target is None else optimize.brentq(
            lambda K: _rms(eta0 * (ke(f, K) - 1)) - target, 0.62, 0.99999)
        params["Ke_at_0.58"] = float(K58)
        return eta0 * (ke(f, K58) - 1)

    def temp(f):  # viscous loss ~ exp(-(T - T0)/Tc); F = 0 at T0; physical peak change 4-12 points
        F = np.exp(-(TC - T_REF_C) / rng.uniform(15, 40)) - 1
        shape = -eta0 * F if f == "multiplicative" else -(N / 1000.0) ** 0.6 * F
        return shape * (rng.uniform(4, 12) / np.max(np.abs(shape)))

    if cat in ("single", "pair"):
        forms = form.split(" + ")
        dev = [lowload(f) if e == "low_load_efficiency" else temp(f) for e, f in zip(gear, forms)]
        scaled, sigma = _fit(dev, ks)
        if gear[0] == "low_load_efficiency" and len(dev) == 2:  # keep the exact Ke law at the new size
            scaled[0] = lowload(forms[0], ks[0] * sigma)
        if len(dev) == 1:
            y = eta0 + scaled[0]
        elif forms[1] == "multiplicative":
            y = eta0 * (1 + scaled[0] / eta0) * (1 + scaled[1] / eta0)
        else:
            y = eta0 + scaled[0] + scaled[1]
    elif cat == "clean":
        sigma = sig_ref
    elif form == "torque-sensor tempco":  # torque-sensor gain 1 + gamma (T - T0)
        gamma = rng.choice([-1.0, 1.0]) * rng.uniform(1e-3, 4e-3)
        d = eta0 * gamma * (TC - T_REF_C)
        nuis["torque_sensor_tempco_per_C"] = float(gamma)
        y, equiv, sigma = eta0 + d, ("temperature_dependence",), _rms(d) / ks[0]
    elif form == "rig drag torque":  # rig bearing/seal drag counted as input torque
        c = rng.uniform(0.04, 0.2)
        nuis["rig_drag_torque_Nm"] = c * m["Tr"] / (m["R"] * eta0 / 100)
        y, equiv = eta0 * A / (A + c), ("low_load_efficiency",)
        sigma = _rms(y - eta0) / ks[0]
    elif meas[0] == "wrong_units":
        sigma, conv = sig_ref, ("efficiency_pct", 0.01)
        snr = _rms(y) * 0.99 / (sigma * 0.01)
    else:
        shape = np.ones(len(N)) if meas[0] == "sensor_gain" else t / t[-1]
        (d,), sigma = _fit([shape * rng.choice([-1.0, 1.0])], ks, sig_ref)
        if meas[0] == "sensor_gain":
            params["torque_gain"] = 1 + float(d[0]) / eta0
        y = y + d
    cols = {"input_speed_rpm": N, "load_torque_Nm": A * m["Tr"], "temperature_C": TC, "efficiency_pct": y, "time_s": t}
    return cols, "efficiency_pct", sigma, nuis, params, equiv, snr, conv, None


def _vibration(rng, m, cat, gear, meas, form, ks):
    s = rng.uniform(0.9, 1.1)
    Ks = m["K1"] * s
    J = m["K1"] / (2 * math.pi * rng.uniform(6, 25)) ** 2
    fn = math.sqrt(Ks / J) / (2 * math.pi)
    Nlo, Nhi, D = 30 * fn * rng.uniform(0.4, 0.6), 60 * fn * rng.uniform(1.3, 1.5), rng.uniform(15, 30)
    fs = max(0.4 * Nhi, 100.0)  # >= 12 samples per cycle of the 2x excitation at the top speed
    t = np.arange(int(D * fs)) / fs
    N = Nlo + (Nhi - Nlo) * t / D
    phi = 2 * math.pi / 60 * (Nlo * t + (Nhi - Nlo) * t ** 2 / (2 * D)) + rng.uniform(0, 2 * math.pi)
    nuis, params, equiv, snr = {"stiffness_scale": s}, {}, (), None
    structural = "structural" in form
    if structural:
        eta = rng.uniform(0.04, 0.16)
        nuis["loss_factor"] = eta
    elif "viscous" in form:
        zeta = rng.uniform(0.02, 0.08)
        nuis["damping_ratio"] = zeta
    sig_ref = m["acc"] * rng.uniform(0.01, 0.05)

    def resp(k, force=False):
        """Load angle for a unit excitation at k x input: TE displaces the gear spring end
        (force=False) or a motor torque ripple acts through the ratio (force=True)."""
        arg = k * phi + rng.uniform(0, 2 * math.pi)
        if structural:
            w = k * 2 * math.pi * N / 60
            Kc = Ks * (1 + 1j * eta)
            H = (Ks if force else Kc) / (Kc - J * w * w)
            return np.abs(H) * np.sin(arg + np.angle(H))
        c = 2 * zeta * math.sqrt(Ks * J)
        b, a, _ = signal.cont2discrete(([Ks] if force else [c, Ks], [J, c, Ks]), 1 / fs, method="bilinear")
        b = np.ravel(b)
        u = np.sin(arg)
        return signal.lfilter(b, a, u, zi=signal.lfilter_zi(b, a) * u[0])[0]

    y = np.zeros_like(t)
    if cat in ("single", "pair"):
        parts = [m["acc"] * rng.uniform(0.1, 0.4) * resp(1 if e == "te_1x" else 2) for e in gear]
        parts, sigma = _fit(parts, ks)
        y = sum(parts)
    elif cat == "clean":
        sigma = sig_ref
    elif cat == "decoy_equivalent":
        k = 1 if "1x" in form else 2
        amp = m["acc"] * rng.uniform(0.1, 0.4)  # quasi-static output angle of the ripple torque
        y = amp * resp(k, force=True)
        sigma = _rms(y) / ks[0]
        nuis.update({"motor_ripple_order": float(k), "motor_ripple_Nm": amp * Ks / m["R"]})
        equiv = ("te_1x",) if k == 1 else ("te_2x",)
    else:
        shape = {"thermal_drift": _drift(rng, t), "angle_offset": _step(rng, t),
                 "encoder_eccentricity": np.sin(phi / m["R"] + rng.uniform(0, 2 * math.pi))}[meas[0]]
        (y,), sigma = _fit([shape], ks, sig_ref)
    cols = {"time_s": t, "input_speed_rpm": N, "output_vibration_rad": y}
    return cols, "output_vibration_rad", sigma, nuis, params, equiv, snr, None, J


# ----------------------------------------------------------------------------- cells
NOISES = ("white", "ar1", "white+outliers", "ar1+outliers")
_SEP = {
    "torsion": [(("sensor_gain",), "torque gain"), (("thermal_drift",), "exponential drift"),
                (("angle_offset",), "step"), (("wrong_units",), "deg for rad"),
                (("wrong_units",), "kNm for Nm"), ((), "stiffness-scale")],
    "transmission": [(("sensor_gain",), "output gain"), (("angle_offset",), "step"),
                     (("encoder_eccentricity",), "1x output"), (("thermal_drift",), "exponential drift"),
                     (("wrong_units",), "deg for rad")],
    "efficiency": [(("sensor_gain",), "torque gain"), (("wrong_units",), "fraction for percent"),
                   (("thermal_drift",), "linear drift in time")],
    "vibration": [(("thermal_drift",), "exponential drift"), (("angle_offset",), "step"),
                  (("encoder_eccentricity",), "1x output")],
}
_EQ = {"torsion": ["softer gear", "input-lock spring", "input-lock play"],
       "transmission": ["input-encoder 1x", "input-encoder 2x"],
       "efficiency": ["torque-sensor tempco", "rig drag torque"],
       "vibration": ["motor ripple 1x viscous", "motor ripple 2x structural"]}
_GEAR = {
    "torsion": [(("hysteresis",), f) for f in ("dahl", "preisach", "bouc-wen n=1", "bouc-wen n=2", "bouc-wen n=3")]
    + [(("backlash",), "tanh"), (("backlash",), "softplus"),
       (("housing_compliance",), "linear"), (("housing_compliance",), "cubic")],
    "transmission": [((e,), f) for e in ("te_1x", "te_2x") for f in ("AM", "PM")],
    "efficiency": [(("low_load_efficiency",), "drag-torque"), (("low_load_efficiency",), "exponential"),
                   (("temperature_dependence",), "multiplicative"), (("temperature_dependence",), "additive")],
    "vibration": [((e,), f) for e in ("te_1x", "te_2x") for f in ("viscous", "structural")],
}
_PAIR = {
    "torsion": [(("hysteresis", "backlash"), "dahl + tanh"), (("hysteresis", "backlash"), "bouc-wen n=2 + softplus"),
                (("hysteresis", "housing_compliance"), "preisach + linear"),
                (("hysteresis", "housing_compliance"), "bouc-wen n=3 + cubic"),
                (("backlash", "housing_compliance"), "tanh + cubic"), (("backlash", "housing_compliance"), "softplus + linear")],
    "transmission": [(("te_1x", "te_2x"), "AM + AM"), (("te_1x", "te_2x"), "PM + PM")],
    "efficiency": [(("low_load_efficiency", "temperature_dependence"), "drag-torque + multiplicative"),
                   (("low_load_efficiency", "temperature_dependence"), "exponential + additive")],
    "vibration": [(("te_1x", "te_2x"), "viscous + viscous"), (("te_1x", "te_2x"), "structural + structural")],
}
KINDS = ("torsion", "transmission", "efficiency", "vibration")
CELLS = []  # (kind, category, gear_effects, measurement_effects, formulation)
for _k in KINDS:
    CELLS += [(_k, "clean", (), (), f) for f in NOISES]
    CELLS += [(_k, "single", g, (), f) for g, f in _GEAR[_k]]
    CELLS += [(_k, "pair", g, (), f) for g, f in _PAIR[_k]]
    CELLS += [(_k, "decoy_separable", (), me, f) for me, f in _SEP[_k]]
    CELLS += [(_k, "decoy_equivalent", (), (), f) for f in _EQ[_k]]
_GEN = {"torsion": _torsion, "transmission": _transmission, "efficiency": _efficiency, "vibration": _vibration}


def _slug(s):
    return re.sub(r"[^a-z0-9]+", "", s.lower().replace("+", "_")) or "none"


def _make(rng, m, cell, idx):
    kind, cat, gear, meas, form = cell
    n_eff = max(1, len(gear))
    ks = rng.uniform(4, 12, n_eff)
    cols, mcol, sigma, nuis, params, equiv, snr, conv, J = _GEN[kind](rng, m, cat, gear, meas, form, ks)
    if cat == "clean":
        phi = rng.uniform(0.3, 0.8) if form.startswith("ar1") else 0.0
        outl = form.endswith("outliers")
    else:
        phi = rng.uniform(0.3, 0.8) if rng.random() < 0.5 else 0.0
        outl = bool(rng.random() < 0.2)
    e, n_out = _noise(rng, len(cols[mcol]), sigma, phi, outl)
    cols = {k: np.asarray(v, dtype=float).copy() for k, v in cols.items()}
    cols[mcol] = cols[mcol] + e
    noise_rms = sigma
    if conv:
        cols[conv[0]] = cols[conv[0]] * conv[1]
        if conv[0] == mcol:
            noise_rms = sigma * conv[1]
        params["unit_factor"] = conv[1]
    k_used = snr is None and cat != "clean"
    if snr is None:
        snr = float(np.min(ks)) if k_used else 0.0
    eff_slug = "_".join(gear) or "_".join(meas) or ("nuisance" if cat == "decoy_separable" else "equiv" if cat == "decoy_equivalent" else "none")
    name = f"c-{kind}-{cat.replace('_', '')}-{_slug(eff_slug)}-{_slug(form)}-{idx:03d}"
    info = {"noise": "ar1" if phi > 0 else "white", "ar1_phi": float(phi), "outliers": int(n_out),
            "k": [float(k) for k in ks] if k_used else [], "params": {k: float(v) for k, v in params.items()}}
    return TruthCase(name=name, kind=kind, model=m["code"], columns=cols,
                     load_inertia_kgm2=float(J) if J is not None else None,
                     gear_effects=tuple(gear), measurement_effects=tuple(meas), nuisance={k: float(v) for k, v in nuis.items()},
                     category=cat, equivalent_effects=tuple(equiv), noise_rms=float(noise_rms),
                     formulation=form, snr=float(snr), info=info)


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list:
    rng = np.random.default_rng(seed)
    models = _load_models(catalog_dir)
    cases = []
    for cell in CELLS:
        for i in range(per_cell):
            m = models[int(rng.integers(len(models)))]
            cases.append(_make(rng, m, cell, i))
    return cases
