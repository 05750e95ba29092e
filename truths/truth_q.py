"""Truth suite Q for `hdcad reconcile` -- synthetic strain-wave-gear test data with known hidden effects.

Written from the contract, the catalog tables and the physics literature only (numpy + scipy).
Every formulation below is cited in a comment next to its code; NOTES_q.md explains them.

Visibility rule used throughout (see _visible / _resid): after the catalog nuisances (stiffness
scale bounded to +-10 %, free offsets, free efficiency level, free linear term in input angle)
have taken what they can by (bounded) least squares, the hidden effect's remaining RMS must be
>= 3 x noise_rms (single), >= 2.5 x each pair member alone and >= 2 x given a simple basis of the
other member; otherwise the draw is repeated.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import signal, special
from scipy.optimize import lsq_linear

SUITE = "q"
_DEG = 180.0 / math.pi


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

    def write_csv(self, path) -> None:
        keys = list(self.columns)
        cols = [np.asarray(self.columns[k], dtype=float) for k in keys]
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(keys)
            for row in zip(*cols):
                w.writerow([repr(float(v)) for v in row])


# --------------------------------------------------------------------------------------------
# catalog
# --------------------------------------------------------------------------------------------
def _read(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _f(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return None


class _Catalog:
    def __init__(self, d):
        d = Path(d)
        self.stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
        self.rat = _read(d / "gh_ratings_050-1_058-1.csv")
        self.bl = _read(d / "gh_backlash_052-2_060-2.csv")
        self.hy = _read(d / "gh_hysteresis_052_060.csv")
        self.perf = _read(d / "gh_performance_051-1_059-1.csv")
        self.models = []
        for r in self.rat:
            ser, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
            st = self._stiff(ser, size, ratio)
            if st is None:
                continue
            acc = [(_f(p["accuracy_rad"])) for p in self.perf
                   if p["series"] == ser and int(p["size"]) == size and int(p["ratio"]) == ratio]
            acc = [a for a in acc if a]
            bl = [_f(b["backlash_rad"]) for b in self.bl
                  if b["series"] == ser and int(b["size"]) == size and int(b["ratio"]) == ratio]
            hy = None
            for h in self.hy:
                lo, hi = _f(h["ratio_min"]), _f(h["ratio_max"])
                if h["series"] == ser and ratio >= lo and (hi is None or ratio <= hi):
                    hy = _f(h["hysteresis_rad"])
            self.models.append(dict(
                code=f"{ser.split('-')[0]}-{size}-{ratio}-GH", series=ser, size=size, ratio=ratio,
                T1=st[0], T2=st[1], K1=st[2], K2=st[3], K3=st[4],
                rated=_f(r["rated_torque_2000_Nm"]), vmax_avg=_f(r["avg_input_speed_max_rpm"]),
                vmax=_f(r["max_input_speed_rpm"]), acc=(min(acc) if acc else None),
                backlash=(bl[0] if bl else None), hyst=hy))
        self.tx_models = [m for m in self.models if m["acc"]]

    def _stiff(self, ser, size, ratio):
        for s in self.stiff:
            if s["series"] != ser or int(s["size"]) != size:
                continue
            lo, hi = _f(s["ratio_min"]), _f(s["ratio_max"])
            if ratio >= lo and (hi is None or ratio <= hi):
                return tuple(_f(s[k]) for k in ("T1_Nm", "T2_Nm", "K1_Nm_per_rad", "K2_Nm_per_rad",
                                                "K3_Nm_per_rad"))
        return None


def _theta_cat(T, m):
    """Catalog three-segment curve, continuous (theta1 = T1/K1, theta2 = theta1 + (T2-T1)/K2), odd."""
    a = np.abs(T)
    t1 = m["T1"] / m["K1"]
    t2 = t1 + (m["T2"] - m["T1"]) / m["K2"]
    th = np.where(a <= m["T1"], a / m["K1"],
                  np.where(a <= m["T2"], t1 + (a - m["T1"]) / m["K2"], t2 + (a - m["T2"]) / m["K3"]))
    return np.sign(T) * th


# --------------------------------------------------------------------------------------------
# noise processes
# --------------------------------------------------------------------------------------------
def _unit_noise(rng, n, kind):
    if kind == "white":
        return rng.standard_normal(n), "white"
    if kind == "ar1":
        # AR(1), phi in [0.3, 0.8], stationary start (Box & Jenkins, Time Series Analysis, ch. 3)
        phi = rng.uniform(0.3, 0.8)
        w = rng.standard_normal(n)
        w[0] /= math.sqrt(1 - phi * phi)
        return signal.lfilter([math.sqrt(1 - phi * phi)], [1.0, -phi], w), f"ar1 phi={phi:.2f}"
    if kind == "tukey":
        # Tukey's contaminated normal (1-eps) N(0,1) + eps N(0,c^2) (Tukey 1960; Huber, Robust
        # Statistics, 1981), scaled to unit variance; eps 2-8 %, c 2.5-4
        eps, c = rng.uniform(0.02, 0.08), rng.uniform(2.5, 4.0)
        z = rng.standard_normal(n) * np.where(rng.random(n) < eps, c, 1.0)
        return z / math.sqrt(1 - eps + eps * c * c), f"tukey eps={eps:.2f}"
    if kind == "sech":
        # hyperbolic-secant distribution (Talacko 1956): X = (2/pi) ln tan(pi U / 2), unit variance
        u = rng.uniform(1e-9, 1 - 1e-9, n)
        return (2 / math.pi) * np.log(np.tan(math.pi * u / 2)), "sech"
    raise ValueError(kind)


def _noise(rng, n, sigma, kind, outliers):
    z, desc = _unit_noise(rng, n, kind)
    z = z / max(np.sqrt(np.mean(z * z)), 1e-300)
    e = sigma * z
    rms = float(np.sqrt(np.mean(e * e)))  # RMS of the noise process (outliers excluded)
    if outliers:
        k = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, k, replace=False)
        e = e.copy()
        e[idx] += rng.choice([-1, 1], k) * rng.uniform(8, 15, k) * sigma
        desc += "+outliers"
    return e, rms, desc


def _pick_noise(rng, allow_outliers=True):
    kind = ["white", "ar1", "tukey", "sech"][int(rng.integers(4))]
    return kind, bool(allow_outliers and rng.random() < 0.3)


# --------------------------------------------------------------------------------------------
# least-squares visibility machinery
# --------------------------------------------------------------------------------------------
def _resid(y, cols, lb, ub):
    """RMS of y minus its best bounded least-squares fit on the columns."""
    if not cols:
        return float(np.sqrt(np.mean(y * y)))
    A = np.column_stack(cols)
    sc = np.sqrt(np.mean(A * A, axis=0)) + 1e-300
    As = A / sc
    r = lsq_linear(As, y, bounds=(np.asarray(lb) * sc, np.asarray(ub) * sc), method="bvls")
    res = y - As @ r.x
    return float(np.sqrt(np.mean(res * res)))


INF = np.inf


def _rms(x):
    return float(np.sqrt(np.mean(np.asarray(x) ** 2)))


# --------------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------------
def _kumaraswamy_scale(rng, half=0.09):
    # stiffness scale: Kumaraswamy(2, 2.5) density on 1 +- half (Kumaraswamy 1980) -- a bounded
    # lot-to-lot scatter inside the catalog's +-10 % (the table values are averages, seed 000 p.020)
    u = rng.random()
    x = (1 - (1 - u) ** (1 / 2.5)) ** 0.5
    return 1 - half + 2 * half * x


def _hyperbolic_drift(t, d, tau):
    # warm-up drift of Michaelis-Menten (rectangular hyperbola) form d t/(t+tau), the response
    # of a sensor whose thermal time constant grows with time (empirical "hyperbolic" creep
    # law used for strain-gauge/transducer zero drift, cf. Hoffmann, Applying the Wheatstone
    # Bridge Circuit, HBM 1986)
    return d * t / (t + tau)


# --------------------------------------------------------------------------------------------
# TORSION
# --------------------------------------------------------------------------------------------
def _torsion_protocol(rng, T0):
    """0 -> +T0 -> -T0 -> +T0 (the 0-A-B-A'-B'-A loop of seed 000 p.020)."""
    form = "uniform" if rng.random() < 0.5 else "arcsine"
    legs = [(0.0, T0), (T0, -T0), (-T0, T0)]
    Ts, ds = [], []
    for a, b in legs:
        n = int(rng.integers(110, 190)) * (1 if a == 0 else 2)
        u = np.linspace(0, 1, n, endpoint=False)[1:] if Ts else np.linspace(0, 1, n, endpoint=False)
        if form == "arcsine":
            # Chebyshev-Lobatto spacing per leg: dense near reversals (servo slowing at the turns)
            u = 0.5 - 0.5 * np.cos(np.pi * u)
        u = u + rng.normal(0, 0.15 / n, u.size)
        Ts.append(a + (b - a) * np.clip(u, 0, 1))
        ds.append(np.full(u.size, np.sign(b - a)))
    T = np.concatenate(Ts + [np.array([T0])])
    d = np.concatenate(ds + [np.array([1.0])])
    return T, d, form


def _hyst_richard_abbott(rng, T, d, T0, m):
    """Masing branches on a Richard-Abbott backbone.
    Richard & Abbott (1975), 'Versatile elastic-plastic stress-strain formula', J. Eng. Mech.
    Div. ASCE 101(EM4): F(x) = (k0-kp) x / (1 + |(k0-kp) x / F0|^n)^(1/n) + kp x; Masing (1926)
    rule: branch from reversal (Tr, xr): x = xr + 2 g((T - Tr)/2) with g = F^-1."""
    n = rng.uniform(1.0, 4.0)
    F0 = rng.uniform(0.2, 0.6) * T0
    kp_ratio = rng.uniform(0.08, 0.35)
    k0 = 1.0
    xs = np.linspace(0, 50 * T0 / k0, 4000)
    Fs = (k0 - kp_ratio) * xs / (1 + np.abs((k0 - kp_ratio) * xs / F0) ** n) ** (1 / n) + kp_ratio * xs

    def g(t):
        return np.sign(t) * np.interp(np.abs(t), Fs, xs)

    x = np.empty_like(T)
    Tr, xr, dr = 0.0, 0.0, None
    first = True
    for i in range(T.size):
        if dr is not None and d[i] != dr:
            Tr, xr = T[i - 1], x[i - 1]
            first = False
        dr = d[i]
        x[i] = g(T[i]) if first else xr + 2 * g((T[i] - Tr) / 2)
    # loss at zero torque after loading to +T0 set to the catalog's hysteresis loss x U(0.6, 1.6)
    H = (m["hyst"] or 3e-4) * rng.uniform(0.6, 1.6)
    w = 2 * g(T0) - 4 * g(T0 / 2)
    x = x * H / max(abs(w), 1e-300)
    return x, f"richard-abbott masing n={n:.1f}"


def _hyst_ozdemir(rng, T, d, T0, m):
    """Rate-independent power-law flow slider with linear kinematic hardening, torque driven.
    Ozdemir (1976), 'Nonlinear transient dynamic analysis of yielding structures', PhD UC
    Berkeley; Graesser & Cozzarelli (1991), J. Eng. Mech. 117(11): plastic twist z with
    dz/dT = (1/Kp) |(T-beta)/Ty|^n  when dT (T - beta) > 0, back torque beta = Kb z."""
    n = rng.uniform(1.5, 5.0)
    Ty = rng.uniform(0.25, 0.7) * T0
    Kb = rng.uniform(0.3, 1.5)          # in units where Kp = 1 (rescaled below)
    z = np.zeros_like(T)
    zi = 0.0
    for i in range(1, T.size):
        dT = T[i] - T[i - 1]
        sub = 6
        h = dT / sub
        Tc = T[i - 1]
        for _ in range(sub):
            Tc += h
            over = Tc - Kb * zi
            if h * over > 0:
                zi += h * min(abs(over / Ty) ** n, 50.0)
        z[i] = zi
    # loss at zero after loading to +T0 (descending leg crossing T=0)
    desc = np.where((d < 0))[0]
    i0 = desc[np.argmin(np.abs(T[desc]))]
    asc = np.where((d > 0) & (np.arange(T.size) > desc[-1]))[0]
    i1 = asc[np.argmin(np.abs(T[asc]))]
    w = abs(z[i0] - z[i1])
    H = (m["hyst"] or 3e-4) * rng.uniform(0.6, 1.6)
    return z * H / max(w, 1e-300), f"ozdemir/graesser-cozzarelli n={n:.1f}"


def _detrend_T(x, T):
    A = np.column_stack([T, np.ones_like(T)])
    c, *_ = np.linalg.lstsq(A, x, rcond=None)
    return x - A @ c


def _backlash_gamma(rng, T, T0, m):
    """Multi-lug Oldham engagement: the play b is taken up as the lugs of the WG Oldham coupling
    touch one after another, their engagement torques Gamma(k, Tc)-distributed (a gamma model of
    clearance scatter, cf. Johnson & Kotz, Continuous Univariate Distributions, ch. 17):
    theta_b = (b/2) sgn(T) P(k, |T|/Tc) (regularised lower incomplete gamma)."""
    b = (m["backlash"] or 5e-5) * rng.uniform(1.5, 4.0)
    k = rng.uniform(1.5, 4.0)
    Tc = rng.uniform(0.008, 0.04) * T0 / k
    return 0.5 * b * np.sign(T) * special.gammainc(k, np.abs(T) / Tc), f"gamma-cdf k={k:.1f}"


def _backlash_langevin(rng, T, T0, m):
    """Langevin take-up theta_b = (b/2) L(T/Tc), L(x) = coth x - 1/x (Langevin 1905's orientation
    function, here the statistical alignment of a centring Oldham slider with distributed contact
    points; slow 1 - Tc/T saturation = residual softening just past the reversal)."""
    b = (m["backlash"] or 5e-5) * rng.uniform(1.5, 4.0)
    Tc = rng.uniform(0.003, 0.012) * T0
    x = T / Tc
    with np.errstate(divide="ignore", invalid="ignore"):
        L = np.where(np.abs(x) < 1e-4, x / 3, 1 / np.tanh(x) - 1 / x)
    return 0.5 * b * L, f"langevin Tc/T0={Tc / T0:.3f}"


_G_STEEL, _E_STEEL = 79.3e9, 206e9


def _housing_cone(rng, T, T0, m):
    """Output shaft as a tapered (conical) solid shaft, Roark's Formulas for Stress and Strain
    (Young & Budynas, 7th ed., Table 10.1 case 10): theta = 2 T L (r1^2 + r1 r2 + r2^2) /
    (3 pi G r1^3 r2^3). Radii from the gear size, length chosen so that the added compliance is
    18-55 % of the gear's 1/K1 (a long adaptor shaft)."""
    r1 = m["size"] * 1e-3 * rng.uniform(0.25, 0.45)
    r2 = r1 * rng.uniform(0.55, 0.85)
    f = rng.uniform(0.18, 0.55)
    c_per_L = 2 * (r1 ** 2 + r1 * r2 + r2 ** 2) / (3 * math.pi * _G_STEEL * r1 ** 3 * r2 ** 3)
    L = f / m["K1"] / c_per_L
    return T * c_per_L * L, f"roark conical shaft L={L * 1e3:.0f}mm"


def _housing_pins(rng, T, T0, m):
    """Output flange connected by n dowel pins acting as clamped-guided Timoshenko beams
    (Timoshenko & Gere, Mechanics of Materials, shear coefficient kappa = 0.9 for a circular
    section): pin lateral compliance l^3/(12 E I) + l/(kappa G A); torsional compliance
    1/(n k_pin rb^2). Pin length chosen for 18-55 % of the gear's 1/K1."""
    npin = int(rng.choice([4, 6, 8]))
    rb = m["size"] * 1e-3 * rng.uniform(0.9, 1.4)
    dp = m["size"] * 1e-3 * rng.uniform(0.12, 0.22)
    I, A = math.pi * dp ** 4 / 64, math.pi * dp ** 2 / 4
    f = rng.uniform(0.18, 0.55)
    target = f / m["K1"] * npin * rb ** 2     # pin lateral compliance needed
    ls = np.linspace(1e-4, 1.0, 20000)
    comp = ls ** 3 / (12 * _E_STEEL * I) + ls / (0.9 * _G_STEEL * A)
    l = float(np.interp(target, comp, ls))
    c = (l ** 3 / (12 * _E_STEEL * I) + l / (0.9 * _G_STEEL * A)) / (npin * rb ** 2)
    return T * c, f"timoshenko dowel-pin joint n={npin}"


_TORSION_EFFECTS = {
    "hysteresis": [("richardabbott", _hyst_richard_abbott), ("ozdemir", _hyst_ozdemir)],
    "backlash": [("gammacdf", _backlash_gamma), ("langevin", _backlash_langevin)],
    "housing_compliance": [("conicalshaft", _housing_cone), ("dowelpins", _housing_pins)],
}


def _torsion_bases(T, d, T0):
    """Simple bases of the gear effects (with physical sign: >= 0)."""
    u = T / T0
    return {
        "hysteresis": [-d * (1 - u ** 2), -d * (1 - np.abs(u))],
        "backlash": [np.tanh(T / (0.01 * T0)), np.tanh(T / (0.04 * T0))],
        "housing_compliance": [T],
    }


def _torsion_nuis(T, m):
    th = _theta_cat(T, m)
    return [th, np.ones_like(T)], [1 / 1.1, -INF], [1 / 0.9, INF]


def _eff_call(fn, rng, T, d, T0, m):
    if fn in (_hyst_richard_abbott, _hyst_ozdemir):
        x, desc = fn(rng, T, d, T0, m)
        return _detrend_T(x, T), desc      # loops drawn about the catalog curve
    return fn(rng, T, T0, m)


def _gen_torsion(rng, cat, category, effects, forms, decoy=None):
    for _attempt in range(60):
        m = cat.models[int(rng.integers(len(cat.models)))]
        T0 = m["rated"] * rng.uniform(0.85, 1.2)
        T, d, proto = _torsion_protocol(rng, T0)
        s = _kumaraswamy_scale(rng)
        off = rng.uniform(-2e-4, 2e-4)
        base = _theta_cat(T, m) / s + off
        nuis = {"stiffness_scale": s, "twist_offset_rad": off, "T0_Nm": T0}
        nk, outl = _pick_noise(rng)
        cols, lb, ub = _torsion_nuis(T, m)
        bases = _torsion_bases(T, d, T0)
        contribs, descs = [], []
        for eff, form in zip(effects, forms):
            fn = dict(_TORSION_EFFECTS[eff])[form]
            c, ds = _eff_call(fn, rng, T, d, T0, m)
            contribs.append(c)
            descs.append(ds)
        meas, equiv = (), ()
        y = base.copy()
        Tmeas = T.copy()
        if category in ("clean",):
            sigma = rng.uniform(2e-6, 1e-5)
        elif contribs:
            sigma, contribs, ok = _scale_effects(rng, contribs)
            if not ok:
                continue
            if not _visible(base, contribs, cols, lb, ub, sigma,
                            [bases[e] for e in effects], effects):
                continue
            for c in contribs:
                y = y + c
        else:  # decoys
            r = _torsion_decoy(rng, decoy, T, d, T0, m, s, off)
            if r is None:
                continue
            y, Tmeas, meas, equiv, ds, nuis_extra = r
            nuis.update(nuis_extra)
            descs.append(ds)
            abs_sig = rng.uniform(2e-6, 1e-5)
            sigma, ok, equiv2 = _decoy_sigma(rng, y, base, cols, lb, ub, bases, meas, equiv,
                                             abs_sig, decoy != "wrong_units")
            if decoy == "wrong_units":
                # a 57.3x softer gear is outside any physical reading: separable by its size
                sigma, equiv2 = abs_sig, ()
            if not ok or (category == "decoy_separable" and equiv2):
                continue
            equiv = equiv2
        e, nrms, nd = _noise(rng, T.size, sigma, nk, outl)
        if decoy == "wrong_units":
            e = e * _DEG
            nrms *= _DEG
        y = y + e
        eff_sum = sum(contribs) if contribs else (y - e - base)
        snr = _rms(eff_sum) / nrms if category != "clean" else 0.0
        cat_out = category
        if category in ("decoy_separable", "decoy_equivalent"):
            cat_out = "decoy_equivalent" if equiv else "decoy_separable"
        return dict(kind="torsion", model=m["code"], columns={"torque_Nm": Tmeas, "twist_rad": y},
                    gear_effects=tuple(effects), measurement_effects=meas, nuisance=nuis,
                    category=cat_out, equivalent_effects=equiv, noise_rms=nrms,
                    formulation="; ".join([f"protocol {proto}"] + descs + [f"noise {nd}"]), snr=snr,
                    load_inertia_kgm2=None)
    raise RuntimeError("torsion draw failed")


def _torsion_decoy(rng, decoy, T, d, T0, m, s, off):
    th = _theta_cat(T, m) / s + off
    n = T.size
    t = np.cumsum(np.abs(np.diff(T, prepend=T[0]))) / T0 * rng.uniform(20, 60)  # test time, s
    if decoy == "sensor_gain":
        # twist-channel gain below 1 (autocollimator arm length entered too long): the gear
        # reads STIFFER than the spread, which no added compliance can explain
        g = rng.uniform(0.65, 0.78)
        return th * g, T, ("sensor_gain",), (), f"twist gain {g:.3f}", {"twist_gain": g}
    if decoy == "angle_offset":
        i = int(rng.integers(n // 5, 4 * n // 5))
        st = rng.choice([-1, 1]) * rng.uniform(1.0, 3.0) * (m["hyst"] or 3e-4)
        return th + st * (np.arange(n) >= i), T, ("angle_offset",), (), "re-zero step", {}
    if decoy == "thermal_drift":
        dd = rng.choice([-1, 1]) * rng.uniform(0.5, 2.0) * (m["hyst"] or 3e-4)
        tau = rng.uniform(0.1, 0.6) * t[-1]
        return th + _hyperbolic_drift(t, dd, tau), T, ("thermal_drift",), (), \
            "hyperbolic warm-up drift", {}
    if decoy == "wrong_units":
        return th * _DEG, T, ("wrong_units",), (), "twist in degrees", {}
    if decoy == "stiffness_in_spread":
        return th, T, (), (), "stiffness scale only", {}
    if decoy == "servo_lock":
        # input held by a servo position loop instead of a mechanical lock: input deflection
        # T/(R Kservo) appears at the output divided by R -> series compliance 1/(R^2 Kservo)
        # (reflected-stiffness law, e.g. Ellis, Control System Design Guide, ch. 16)
        f = rng.uniform(0.2, 0.5)
        Ks = m["K1"] / (f * m["ratio"] ** 2)
        return th + T / (m["ratio"] ** 2 * Ks), T, (), ("housing_compliance",), \
            f"servo-held input Kservo={Ks:.3g}", {}
    if decoy == "ballscrew_play":
        # twist computed from the loading actuator's linear scale; the ball-screw nut changes
        # flank when the actuator force reverses (force ~ torque) -> a take-up at T = 0,
        # smoothed by the preload ramp (Altintas, Manufacturing Automation, ch. 5 ball screws)
        c = (m["backlash"] or 5e-5) * rng.uniform(2, 4)
        w = rng.uniform(0.005, 0.02) * T0
        return th + 0.5 * c * special.erf(T / w), T, (), ("backlash",), "ball-screw nut play", {}
    if decoy == "indicator_play":
        # dial indicator / rack-pinion reading with lost motion w: a play operator on the twist
        # (Krasnosel'skii & Pokrovskii 1989) -> constant-width loop = Coulomb-like hysteresis
        w = (m["hyst"] or 3e-4) * rng.uniform(0.6, 1.4)
        out = np.empty(n)
        p = th[0]
        for i in range(n):
            p = min(max(p, th[i] - w / 2), th[i] + w / 2)
            out[i] = p
        return out, T, (), ("hysteresis",), "indicator lost motion (play operator)", {}
    raise ValueError(decoy)


def _scale_effects(rng, contribs):
    """k in [4, 12] for the first effect sets sigma; the others keep their physical size when their
    k lands in [4, 12], else they are rescaled to the nearest end (a change of amplitude parameter)."""
    k0 = rng.uniform(4, 12)
    r0 = _rms(contribs[0])
    if r0 <= 0:
        return 0, contribs, False
    sigma = r0 / k0
    out = [contribs[0]]
    for c in contribs[1:]:
        kk = _rms(c) / sigma
        kt = min(max(kk, 4.0), 12.0)
        if kk <= 0 or kt / kk > 4 or kk / kt > 4:
            return sigma, contribs, False
        out.append(c * kt / kk)
    return sigma, out, True


def _visible(base, contribs, cols, lb, ub, sigma, basis_list, effects):
    if len(contribs) == 1:
        return _resid(base + contribs[0], cols, lb, ub) >= 3 * sigma
    for i, c in enumerate(contribs):
        if _resid(base + c, cols, lb, ub) < 2.5 * sigma:
            return False
        other = [b for j, bl in enumerate(basis_list) if j != i for b in bl]
        tot = base + sum(contribs)
        if _resid(tot - 0.0, cols + other, list(lb) + [0.0] * len(other),
                  list(ub) + [INF] * len(other)) < 2 * sigma:
            return False
    return True


def _decoy_sigma(rng, y, base, cols, lb, ub, bases, meas, equiv, abs_sigma, need_visible=True):
    """Noise for a decoy: k in [4, 12] of the decoy's contribution left after the nuisances; a
    decoy the nuisances absorb (stiffness in spread, level, small gains) gets the realistic absolute
    noise abs_sigma. Separability test: the decoy is separable when no single gear-effect basis
    (physical sign) brings the residual under 2 sigma. Returns (sigma, ok, explaining effects)."""
    r0 = _resid(y, cols, lb, ub)
    if not meas and not equiv:
        return abs_sigma, True, ()
    if r0 < 3 * abs_sigma:
        # absorbed by the nuisances: acceptable only for nuisance-like decoys (gains, units)
        return abs_sigma, not need_visible, tuple(equiv)
    sigma = r0 / rng.uniform(4, 12)
    if equiv:
        return sigma, True, tuple(equiv)
    expl = []
    for e, bl in bases.items():
        r = _resid(y, cols + bl, list(lb) + [0.0] * len(bl), list(ub) + [INF] * len(bl))
        if r < 2 * sigma:
            expl.append(e)
    return sigma, True, tuple(expl)


# --------------------------------------------------------------------------------------------
# TE waveforms (transmission and vibration)
# --------------------------------------------------------------------------------------------
def _te_cubic(rng, x, amp, k=1):
    """1x: runout of the WG sensed through a stiffening (cubic) tooth-contact law,
    e = a (cos u + beta cos^3 u) -- Chebyshev: cos^3 u = (3 cos u + cos 3u)/4, odd harmonics only
    (no 2x content); cf. Duffing-type contact nonlinearity, Kahraman & Singh (1990) JSV 142."""
    beta = rng.uniform(0.2, 0.8)
    u = k * x + rng.uniform(0, 2 * np.pi)
    e = np.cos(u) + beta * np.cos(u) ** 3
    return amp * e / np.sqrt(np.mean(e * e)) / math.sqrt(2) * 1.0, f"cubic-runout beta={beta:.2f}"


def _te_poisson(rng, x, amp, k=1):
    """Odd-harmonic Poisson-kernel waveform: sum over odd m of rho^(m-1) cos(m u) =
    Re[e^{iu} / (1 - rho^2 e^{2iu})] (Poisson kernel, e.g. Zygmund, Trigonometric Series ch. III),
    a geometrically decaying odd-harmonic spectrum; at 1x (u = x) or 2x (u = 2x)."""
    rho = rng.uniform(0.3, 0.6)
    u = k * x + rng.uniform(0, 2 * np.pi)
    z = np.exp(1j * u)
    e = np.real(z / (1 - rho * rho * z * z))
    return amp * e / np.sqrt(np.mean(e * e)) / math.sqrt(2), f"poisson-kernel rho={rho:.2f}"


def _te_superellipse(rng, x, amp, k=2):
    """2x: Lame superellipse wave-generator cam |X/a|^p + |Y/b|^p = 1 (Gielis 2003 superformula
    family); the radius r(phi) = (|cos phi/a|^p + |sin phi/b|^p)^(-1/p) has period pi, so the
    TE it produces has only even input harmonics (2x dominant, a 4x from p != 2)."""
    p = rng.uniform(1.8, 2.6)
    ba = rng.uniform(0.90, 0.97)
    u = x + rng.uniform(0, np.pi)
    r = (np.abs(np.cos(u)) ** p + np.abs(np.sin(u) / ba) ** p) ** (-1 / p)
    e = r - r.mean()
    return amp * e / np.sqrt(np.mean(e * e)) / math.sqrt(2), f"superellipse p={p:.2f}"


_TE_FORMS = {
    "te_1x": [("cubicrunout", _te_cubic, 1), ("poisson", _te_poisson, 1)],
    "te_2x": [("superellipse", _te_superellipse, 2), ("poisson", _te_poisson, 2)],
}


# --------------------------------------------------------------------------------------------
# TRANSMISSION
# --------------------------------------------------------------------------------------------
def _gen_transmission(rng, cat, category, effects, forms, decoy=None):
    for _attempt in range(60):
        m = cat.tx_models[int(rng.integers(len(cat.tx_models)))]
        R = m["ratio"]
        nrev = rng.uniform(3, 8)
        spr = int(rng.integers(180, 540))
        if decoy == "encoder_eccentricity":
            # the eccentricity needs most of an output revolution to be told from a ratio slope
            nrev, spr = R * rng.uniform(0.6, 1.0), int(rng.integers(24, 40))
        N = int(nrev * spr)
        if rng.random() < 0.5:
            proto = "encoder-triggered"
            x = np.linspace(0, 2 * np.pi * nrev, N) + rng.uniform(0, 2 * np.pi)
        else:
            # time-sampled with a motor speed ripple at a non-integer order (inverter ripple)
            proto = "time-sampled with speed ripple"
            t = np.linspace(0, 1, N)
            order = rng.uniform(0.3, 0.7)
            x = 2 * np.pi * nrev * t + 0.02 * np.sin(2 * np.pi * order * nrev * t) \
                + rng.uniform(0, 2 * np.pi)
        off = rng.uniform(-0.01, 0.01)
        base = x / R + off
        nuis = {"output_offset_rad": off}
        cols, lb, ub = [np.ones(N), x], [-INF, -INF], [INF, INF]
        bases = {"te_1x": [np.cos(x), np.sin(x)], "te_2x": [np.cos(2 * x), np.sin(2 * x)]}
        nk, outl = _pick_noise(rng)
        contribs, descs, meas, equiv = [], [], (), ()
        for eff, form in zip(effects, forms):
            _, fn, k = [f for f in _TE_FORMS[eff] if f[0] == form][0]
            amp = m["acc"] * rng.uniform(0.15, 0.45)
            c, ds = fn(rng, x, amp, k)
            contribs.append(c)
            descs.append(ds)
        y = base.copy()
        free = lambda bl: ([-INF] * len(bl), [INF] * len(bl))
        if category == "clean":
            sigma = m["acc"] * rng.uniform(0.01, 0.04)
        elif contribs:
            sigma, contribs, ok = _scale_effects(rng, contribs)
            if not ok:
                continue
            if not _visible_free(base, contribs, cols, lb, ub, sigma,
                                 [bases[e] for e in effects]):
                continue
            y = y + sum(contribs)
        else:
            th = base
            acc = m["acc"]
            if decoy == "encoder_eccentricity":
                # once per OUTPUT revolution (eccentric output disc, Heidenhain 'Angle encoders' brochure:
                # error = e/r sin(theta_out + phi))
                ea = acc * rng.uniform(0.3, 1.0)
                y = th + ea * np.sin(x / R + rng.uniform(0, 2 * np.pi))
                meas, ds = ("encoder_eccentricity",), "output-disc eccentricity"
            elif decoy == "angle_offset":
                i = int(rng.integers(N // 5, 4 * N // 5))
                y = th + rng.choice([-1, 1]) * acc * rng.uniform(0.5, 1.5) * (np.arange(N) >= i)
                meas, ds = ("angle_offset",), "index re-latch step"
            elif decoy == "thermal_drift":
                tt = np.linspace(0, 1, N)
                y = th + _hyperbolic_drift(tt, rng.choice([-1, 1]) * acc * rng.uniform(0.5, 2),
                                           rng.uniform(0.05, 0.5))
                meas, ds = ("thermal_drift",), "hyperbolic warm-up drift"
            elif decoy == "wrong_units":
                y = th * _DEG
                meas, ds = ("wrong_units",), "output angle in degrees"
            elif decoy == "seal_drag_1x":
                # WG-side lip seal on a run-out journal: drag ripple Td(1 + cos x) winds the input
                # shaft between motor encoder and WG -> the encoder's angle leads the WG by
                # Td cos(x)/Ks (1x input-angle error, output sees -err/R) -- equivalent to te_1x
                a = acc * rng.uniform(0.2, 0.45)
                y = th + a * np.cos(x + rng.uniform(0, 2 * np.pi))
                equiv, ds = ("te_1x",), "seal-runout drag ripple winding the input shaft"
            elif decoy == "split_clamp_2x":
                # two-screw split clamp ovalises the input encoder hub: 2x reading error
                a = acc * rng.uniform(0.2, 0.45)
                y = th + a * np.cos(2 * x + rng.uniform(0, 2 * np.pi))
                equiv, ds = ("te_2x",), "ovalised input-encoder hub (two-screw clamp)"
            descs.append(ds)
            sigma, ok, equiv = _decoy_sigma(rng, y, base, cols, lb, ub,
                                            {k: v for k, v in bases.items()}, meas, equiv,
                                            m["acc"] * rng.uniform(0.01, 0.04),
                                            decoy != "wrong_units")
            if decoy in ("wrong_units",):
                sigma = m["acc"] * rng.uniform(0.01, 0.04) * _DEG
            if not ok:
                continue
            if decoy not in ("seal_drag_1x", "split_clamp_2x"):
                # free-sign TE bases must not explain the decoy
                bad = [e for e, bl in bases.items()
                       if _resid(y, cols + bl, lb + free(bl)[0], ub + free(bl)[1]) < 2 * sigma
                       and _resid(y, cols, lb, ub) >= 3 * sigma]
                if bad:
                    continue
        e, nrms, nd = _noise(rng, N, sigma, nk, outl)
        y = y + e
        eff_sum = sum(contribs) if contribs else (y - e - base)
        snr = _rms(eff_sum - (eff_sum.mean() if decoy else 0)) / nrms if category != "clean" else 0.0
        cat_out = category
        if category.startswith("decoy"):
            cat_out = "decoy_equivalent" if equiv else "decoy_separable"
        return dict(kind="transmission", model=m["code"],
                    columns={"input_angle_rad": x, "output_angle_rad": y},
                    gear_effects=tuple(effects), measurement_effects=meas, nuisance=nuis,
                    category=cat_out, equivalent_effects=tuple(equiv), noise_rms=nrms,
                    formulation="; ".join([f"protocol {proto}"] + descs + [f"noise {nd}"]),
                    snr=snr, load_inertia_kgm2=None)
    raise RuntimeError("transmission draw failed")


def _visible_free(base, contribs, cols, lb, ub, sigma, basis_list):
    if len(contribs) == 1:
        return _resid(base + contribs[0], cols, lb, ub) >= 3 * sigma
    for i, c in enumerate(contribs):
        if _resid(base + c, cols, lb, ub) < 2.5 * sigma:
            return False
        other = [b for j, bl in enumerate(basis_list) if j != i for b in bl]
        if _resid(base + sum(contribs), cols + other, list(lb) + [-INF] * len(other),
                  list(ub) + [INF] * len(other)) < 2 * sigma:
            return False
    return True


# --------------------------------------------------------------------------------------------
# EFFICIENCY
# --------------------------------------------------------------------------------------------
def _ke_gompertz(rng, a):
    """Ke from a Gompertz tooth-engagement law: the share of teeth in load-carrying contact grows
    with torque (in strain wave gears ~30 % of the teeth engage at rated load, Kiyosawa et al.,
    JSME 1989), with a Gompertz (1825) growth curve; deficit
    delta(a) = D [G(a) - G(1)] / [1 - G(1)], G(a) = exp(-b (e^{c a} - 1)); Ke = 1 - delta, Ke = 1 at a >= 1.
    D set so that Ke(0.58) = 0.93 +- spread (graph 023-1 / seed 000 p.023)."""
    b, c = rng.uniform(0.3, 1.5), rng.uniform(1.5, 3.5)
    G = lambda s: np.exp(-b * (np.exp(c * s) - 1))
    shape = lambda s: (G(np.clip(s, 0, 1)) - G(1.0)) / (1 - G(1.0))
    target = 0.07 * rng.uniform(0.6, 1.6)
    D = min(target / max(shape(0.58), 1e-3), 0.7)
    return 1 - D * shape(a), f"gompertz b={b:.2f} c={c:.2f}"


def _ke_loglogistic(rng, a):
    """Ke from a log-logistic (Fisk) distribution of asperity-contact load share:
    delta(a) = D [S(a) - S(1)]/[S(0) - S(1)], S(a) = 1/(1 + (a/a50)^m) (Fisk 1961);
    anchored to Ke(0.58) = 0.93 +- spread."""
    m_, a50 = rng.uniform(1.5, 3.0), rng.uniform(0.15, 0.4)
    S = lambda s: 1 / (1 + (np.clip(s, 0, 1) / a50) ** m_)
    shape = lambda s: (S(s) - S(1.0)) / (1 - S(1.0))
    target = 0.07 * rng.uniform(0.6, 1.6)
    D = min(target / max(shape(0.58), 1e-3), 0.7)
    return 1 - D * shape(a), f"log-logistic m={m_:.2f} a50={a50:.2f}"


def _nu_lewis_squires(T, nu40):
    # Lewis & Squires (1934) viscosity-temperature chart: nu^-0.2661 = nu40^-0.2661 + (T-40)/233
    v = nu40 ** -0.2661 + (T - 40.0) / 233.0
    return np.maximum(v, 1e-6) ** (-1 / 0.2661)


def _mu_mehrotra(T, mu40):
    # Mehrotra (1991) one-parameter law: log10(mu + 0.8) = 100 (0.01 T_K)^b, b from mu(40 C)
    b = math.log(math.log10(mu40 + 0.8) / 100) / math.log(0.01 * 313.15)
    return 10 ** (100 * (0.01 * (T + 273.15)) ** b) - 0.8


def _temp_lewis(rng, T, n):
    """Multiplicative boundary-layer drag loss ~ sqrt(nu n) (laminar Blasius/Schlichting drag on
    the WG and flexspline), viscosity by Lewis-Squires: eta = eta0 Ke (1 - k sqrt(nu n/(nu25 1000)))
    / (1 - k)."""
    nu40 = rng.uniform(30, 150)
    kk = rng.uniform(0.03, 0.1)
    ratio = np.sqrt(_nu_lewis_squires(T, nu40) / _nu_lewis_squires(25.0, nu40) * n / 1000.0)
    return (1 - kk * ratio) / (1 - kk), True, f"lewis-squires nu40={nu40:.0f} sqrt(nu n) drag"


def _temp_mehrotra(rng, T, n):
    """Additive loss -c ln(mu(T)/mu(25)) (n/1000)^0.5 percentage points, viscosity by Mehrotra."""
    mu40 = rng.uniform(40, 200)
    c = rng.uniform(1.5, 4.0)
    return -c * np.log(_mu_mehrotra(T, mu40) / _mu_mehrotra(25.0, mu40)) * np.sqrt(n / 1000.0), \
        False, f"mehrotra mu40={mu40:.0f} additive"


_LL_FORMS = {"gompertz": _ke_gompertz, "loglogistic": _ke_loglogistic}
_TEMP_FORMS = {"lewissquires": _temp_lewis, "mehrotra": _temp_mehrotra}


def _eff_grid(rng, m):
    speeds = [v for v in (500, 1000, 2000, 3500) if v <= m["vmax_avg"]]
    if rng.random() < 0.5:
        alphas = np.array([0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.85, 1.0, 1.1])
        temps = np.array([0, 10, 20, 30, 40.0])
        proto = "factorial, oven blocks ascending"
        order_blocks = list(range(temps.size))
    else:
        alphas = np.sort(rng.uniform(0.08, 1.1, 9))
        temps = np.array([-5, 5, 15, 25, 35, 45.0])
        proto = "factorial, oven blocks in random order, repeated reference point"
        order_blocks = list(rng.permutation(temps.size))
    rows = []
    for bi in order_blocks:
        blk = [(v, a, temps[bi]) for v in speeds for a in alphas] + [(1000.0, 1.0, temps[bi])]
        for j in rng.permutation(len(blk)):
            rows.append(blk[j])
    arr = np.array(rows, float)
    n, a, T = arr[:, 0], arr[:, 1], arr[:, 2]
    return n, a, T, proto


def _eff_bases(a, T, n):
    Tc = (T - T.mean()) / (np.ptp(T) + 1e-9)
    sn = n / 1000.0
    d = np.clip(1 - a, 0, None)
    return {"low_load_efficiency": ([d, d ** 2, d ** 4, 1 / np.maximum(a, 0.05)], "free"),
            "temperature_dependence": ([Tc, Tc ** 2, Tc * np.sqrt(sn), Tc ** 2 * np.sqrt(sn)], "free")}


def _gen_efficiency(rng, cat, category, effects, forms, decoy=None):
    for _attempt in range(80):
        m = cat.models[int(rng.integers(len(cat.models)))]
        n, a, T, proto = _eff_grid(rng, m)
        N = n.size
        load = a * m["rated"]
        lvl = rng.uniform(62, 86)
        base = np.full(N, lvl)
        nuis = {"efficiency_level_pct": lvl}
        cols, lb, ub = [np.ones(N)], [-INF], [INF]
        bl = _eff_bases(a, T, n)
        bases = {k: v[0] for k, v in bl.items()}
        nk, outl = _pick_noise(rng)
        descs, meas, equiv = [], (), ()
        ke, mult, add = np.ones(N), np.ones(N), np.zeros(N)
        for eff, form in zip(effects, forms):
            if eff == "low_load_efficiency":
                ke, ds = _LL_FORMS[form](rng, a)
            else:
                v, is_mult, ds = _TEMP_FORMS[form](rng, T, n)
                if is_mult:
                    mult = v
                else:
                    add = v
            descs.append(ds)
        contribs = []
        if "low_load_efficiency" in effects:
            contribs.append(lvl * (ke - 1))
        if "temperature_dependence" in effects:
            contribs.append(lvl * ke * (mult - 1) + add)
        y = base.copy()
        if category == "clean":
            sigma = rng.uniform(0.2, 0.8)
        elif contribs:
            sigma, contribs, ok = _scale_effects(rng, contribs)
            if not ok:
                continue
            if not _visible_free(base, contribs, cols, lb, ub, sigma,
                                 [bases[e] for e in effects]):
                continue
            y = y + sum(contribs)
        else:
            tt = np.arange(N, dtype=float)
            if decoy == "wrong_units":
                y, meas, ds = base / 100.0, ("wrong_units",), "efficiency as a fraction"
            elif decoy == "sensor_gain":
                g = rng.choice([rng.uniform(0.88, 0.96), rng.uniform(1.04, 1.12)])
                y, meas, ds = base / g, ("sensor_gain",), f"input-torque gain {g:.3f}"
            elif decoy == "level":
                lvl2 = rng.uniform(50, 60)
                y, ds = np.full(N, lvl2), "efficiency level at the low end"
                nuis["efficiency_level_pct"] = lvl2
                base = y.copy()
            elif decoy == "thermal_drift":
                # calorimetric/torque reading drift in test time, re-zeroed at each oven block
                blk = np.concatenate([[0], np.cumsum(np.diff(T) != 0)])
                tb = tt - np.array([tt[blk == b].min() for b in blk])
                d0 = rng.choice([-1, 1]) * rng.uniform(2.5, 5.0)
                y = base + _hyperbolic_drift(tb, d0, rng.uniform(5, 20))
                meas, ds = ("thermal_drift",), "hyperbolic drift reset per oven block"
            elif decoy == "windage":
                # absorber (dynamometer) windage loss torque ~ n^2 (fan law) charged to the gear:
                # eta = eta_g T/(T + Tw(n)) -> reads as low-load efficiency
                Tw = m["rated"] * rng.uniform(0.02, 0.05) * (n / 2000.0) ** 2
                y = base * load / (load + Tw)
                equiv, ds = ("low_load_efficiency",), "absorber windage (fan law) uncorrected"
            elif decoy == "ferrofluid_seal":
                # magnetic-fluid seal on the rig's input shaft: viscous drag ~ mu(T) n (Rosensweig,
                # Ferrohydrodynamics 1985) charged to the gear -> temperature- and load-dependent
                mu = _mu_mehrotra(T, 80.0) / _mu_mehrotra(25.0, 80.0)
                Td = m["rated"] * rng.uniform(0.01, 0.03) * mu * (n / 1000.0)
                y = base * load / (load + Td)
                equiv = ("temperature_dependence", "low_load_efficiency")
                ds = "ferrofluid seal drag uncorrected"
            descs.append(ds)
            sigma, ok, equiv = _decoy_sigma(rng, y, base, cols, lb, ub, bases, meas, equiv,
                                            rng.uniform(0.2, 0.8),
                                            decoy not in ("wrong_units", "sensor_gain"))
            if decoy == "wrong_units":
                sigma = rng.uniform(0.2, 0.8) / 100.0
            if not ok:
                continue
            if decoy in ("sensor_gain", "thermal_drift", "level", "wrong_units"):
                badl = [e for e, b in bases.items()
                        if _resid(y, cols + b, lb + [-INF] * len(b), ub + [INF] * len(b)) < 2 * sigma
                        and _resid(y, cols, lb, ub) >= 3 * sigma
                        and decoy != "wrong_units"]
                if badl:
                    continue
                equiv = ()
        e, nrms, nd = _noise(rng, N, sigma, nk, outl)
        y = y + e
        eff_sum = sum(contribs) if contribs else (y - e - base)
        snr = _rms(eff_sum - (eff_sum.mean() if decoy else 0)) / nrms if category != "clean" else 0.0
        cat_out = category
        if category.startswith("decoy"):
            cat_out = "decoy_equivalent" if equiv else "decoy_separable"
        return dict(kind="efficiency", model=m["code"],
                    columns={"input_speed_rpm": n, "load_torque_Nm": load, "temperature_C": T,
                             "efficiency_pct": y},
                    gear_effects=tuple(effects), measurement_effects=meas, nuisance=nuis,
                    category=cat_out, equivalent_effects=tuple(equiv), noise_rms=nrms,
                    formulation="; ".join([f"protocol {proto}"] + descs + [f"noise {nd}"]),
                    snr=snr, load_inertia_kgm2=None)
    raise RuntimeError("efficiency draw failed")


# --------------------------------------------------------------------------------------------
# VIBRATION
# --------------------------------------------------------------------------------------------
def _runup_gompertz(rng, tau):
    """Gompertz speed curve (Gompertz 1825; a soft-started drive whose acceleration peaks early
    and decays double-exponentially), normalised to run from 0 to 1."""
    b, c = rng.uniform(2, 5), rng.uniform(3, 6)
    g = np.exp(-b * np.exp(-c * tau))
    return (g - g[0]) / (g[-1] - g[0]), f"gompertz run-up b={b:.1f} c={c:.1f}"


def _runup_bezier(rng, tau):
    """Cubic Bezier (Bernstein) speed profile with control values 0 <= p1 <= p2 <= 1 (monotone):
    B = 3 p1 t (1-t)^2 + 3 p2 t^2 (1-t) + t^3 -- a CNC/servo trajectory planner's profile
    (Farin, Curves and Surfaces for CAGD)."""
    p1, p2 = np.sort(rng.uniform(0.1, 0.9, 2))
    t = tau
    return 3 * p1 * t * (1 - t) ** 2 + 3 * p2 * t * t * (1 - t) + t ** 3, \
        f"bezier run-up p=({p1:.2f},{p2:.2f})"


def _disc_ss_bdf2(J, c, K, h):
    """BDF2 (Gear 1971) on y' = A y + b f: (3 y_{n+1} - 4 y_n + y_{n-1}) = 2h (A y_{n+1} + b f_{n+1}),
    written as an LTI recursion (state (y_n, y_{n-1}))."""
    A = np.array([[0, 1], [-K / J, -c / J]])
    b = np.array([[0], [1 / J]])
    M = np.linalg.inv(3 * np.eye(2) - 2 * h * A)
    Ad = np.block([[4 * M, -M], [np.eye(2), np.zeros((2, 2))]])
    Bd = np.vstack([2 * h * M @ b, np.zeros((2, 1))])
    return Ad, Bd, np.array([[1, 0, 0, 0]])


def _disc_ss_hht(J, c, K, h, alpha):
    """HHT-alpha (Hilber, Hughes & Taylor 1977, Earthquake Eng. Struct. Dyn. 5): M a_{n+1} +
    (1+al) C v_{n+1} - al C v_n + (1+al) K x_{n+1} - al K x_n = (1+al) F_{n+1} - al F_n,
    Newmark gamma = (1-2al)/2, beta = (1-al)^2/4, al in [-1/3, 0]; state (x, v, a, F_n)."""
    al = alpha
    gam, bet = (1 - 2 * al) / 2, (1 - al) ** 2 / 4
    den = J + (1 + al) * gam * h * c + (1 + al) * bet * h * h * K
    # a_{n+1} = [ (1+al)F1 - al F0 + al c v + al K x - (1+al) c (v + h(1-g) a)
    #             - (1+al) K (x + h v + h^2 (1/2 - b) a) ] / den
    ax = (al * K - (1 + al) * K) / den
    av = (al * c - (1 + al) * c - (1 + al) * K * h) / den
    aa = (-(1 + al) * c * h * (1 - gam) - (1 + al) * K * h * h * (0.5 - bet)) / den
    aF0 = -al / den
    aF1 = (1 + al) / den
    rowa = np.array([ax, av, aa, aF0])
    rowx = np.array([1, h, h * h * (0.5 - bet), 0]) + h * h * bet * rowa
    rowv = np.array([0, 1, h * (1 - gam), 0]) + h * gam * rowa
    Ad = np.vstack([rowx, rowv, rowa, [0, 0, 0, 0]])
    Bd = np.array([[h * h * bet * aF1], [h * gam * aF1], [aF1], [1.0]])
    return Ad, Bd, np.array([[1, 0, 0, 0]])


def _simulate(Ad, Bd, C, f):
    """x_k = Ad x_{k-1} + Bd u_k, out_k = C x_k  ==  w_{k+1} = Ad w_k + Bd u_k, out = C Ad w + C Bd u;
    run through a transfer function with scipy.signal.lfilter (C speed)."""
    num, den = signal.ss2tf(Ad, Bd, C @ Ad, C @ Bd)
    return signal.lfilter(num[0], den, f)


def _gen_vibration(rng, cat, category, effects, forms, decoy=None):
    for _attempt in range(40):
        m = cat.tx_models[int(rng.integers(len(cat.tx_models)))]
        s = _kumaraswamy_scale(rng)
        K = m["K1"] * s
        fn = rng.uniform(6, 16)
        J = m["K1"] / (2 * np.pi * fn) ** 2          # J chosen from the catalog K1 (the user's value)
        fn_true = math.sqrt(K / J) / (2 * np.pi)
        zeta = rng.uniform(0.03, 0.10)
        c = 2 * zeta * math.sqrt(K * J)
        dur = rng.uniform(25, 45)
        fs = 50 * fn
        fa, fb = 0.3 * fn_true, min(1.45 * fn_true, m["vmax"] / 60 * 0.95)
        lead = 4 / (zeta * 2 * np.pi * fn_true)
        nl = int(lead * fs)
        N = int(dur * fs)
        tau = np.linspace(0, 1, N)
        prof, rdesc = (_runup_gompertz if rng.random() < 0.5 else _runup_bezier)(rng, tau)
        f_in = np.concatenate([np.full(nl, fa), fa + (fb - fa) * prof])
        h = 1 / fs
        x_in = 2 * np.pi * np.concatenate([[0], np.cumsum(0.5 * (f_in[1:] + f_in[:-1]) * h)])
        if rng.random() < 0.5:
            Ad, Bd, C = _disc_ss_bdf2(J, c, K, h)
            integ = "BDF2"
        else:
            al = rng.uniform(-0.3, -0.05)
            Ad, Bd, C = _disc_ss_hht(J, c, K, h, al)
            integ = f"HHT-alpha {al:.2f}"
        relative = rng.random() < 0.5
        damp = "Kelvin (relative) damping" if relative else "absolute (grease-drag) damping"

        def respond(e):
            # J phi'' + c phi' + K phi = K e   (absolute damping)
            # J phi'' + c (phi' - e') + K (phi - e) = 0   (Kelvin-Voigt damping in the gear)
            f = K * e + (c * np.gradient(e, h) if relative else 0.0)
            return _simulate(Ad, Bd, C, f)[nl:]

        time = np.arange(N) * h
        rpm = f_in[nl:] * 60
        xin = x_in[nl:]
        nuis = {"stiffness_scale": s, "damping_ratio": zeta}
        cols, lb, ub = [np.ones(N)], [-INF], [INF]
        basis_cache = {}

        def basis(eff):
            if eff not in basis_cache:
                k = 1 if eff == "te_1x" else 2
                basis_cache[eff] = [respond(np.cos(k * x_in)), respond(np.sin(k * x_in))]
            return basis_cache[eff]

        nk, outl = _pick_noise(rng)
        contribs, descs, meas, equiv = [], [], (), ()
        for eff, form in zip(effects, forms):
            _, fnc, k = [ff for ff in _TE_FORMS[eff] if ff[0] == form][0]
            amp = m["acc"] * rng.uniform(0.15, 0.45)
            e, ds = fnc(rng, x_in, amp, k)
            contribs.append(respond(e))
            descs.append(ds)
        base = np.zeros(N)
        y = base.copy()
        if category == "clean":
            sigma = m["acc"] * rng.uniform(0.01, 0.03)
        elif contribs:
            sigma, contribs, ok = _scale_effects(rng, contribs)
            if not ok:
                continue
            if not _visible_free(base, contribs, cols, lb, ub, sigma, [basis(e) for e in effects]):
                continue
            y = y + sum(contribs)
        else:
            acc = m["acc"]
            if decoy == "thermal_drift":
                y = _hyperbolic_drift(time, rng.choice([-1, 1]) * acc * rng.uniform(0.2, 0.6),
                                      rng.uniform(2, 15))
                meas, ds = ("thermal_drift",), "hyperbolic warm-up drift"
            elif decoy == "angle_offset":
                i = int(rng.integers(N // 5, 4 * N // 5))
                y = rng.choice([-1, 1]) * acc * rng.uniform(0.1, 0.4) * (np.arange(N) >= i)
                meas, ds = ("angle_offset",), "encoder re-zero step"
            elif decoy == "encoder_eccentricity":
                y = acc * rng.uniform(0.1, 0.4) * np.sin(xin / m["ratio"] + rng.uniform(0, 6.3))
                meas, ds = ("encoder_eccentricity",), "once per output revolution"
            elif decoy in ("flexure_1x", "flexure_2x"):
                # rig's flexure (disc) coupling on the input, misaligned: parallel offset gives a
                # 1x, angular misalignment a 2x velocity ripple (Hooke-joint kinematics, Mancuso,
                # Couplings and Joints, 1999) -> the WG angle carries the same error as a TE
                k = 1 if decoy == "flexure_1x" else 2
                a = acc * rng.uniform(0.15, 0.45)
                y = respond(a * np.cos(k * x_in + rng.uniform(0, 6.3)))
                equiv = ("te_1x",) if k == 1 else ("te_2x",)
                ds = f"misaligned input flexure coupling {k}x"
            descs.append(ds)
            bases = {"te_1x": basis("te_1x"), "te_2x": basis("te_2x")}
            r0 = _resid(y, cols, lb, ub)
            sigma = r0 / rng.uniform(4, 12)
            if not equiv:
                bad = [e for e, b in bases.items()
                       if _resid(y, cols + b, lb + [-INF] * 2, ub + [INF] * 2) < 2 * sigma]
                if bad:
                    continue
        e, nrms, nd = _noise(rng, N, sigma, nk, outl)
        y = y + e
        eff_sum = sum(contribs) if contribs else (y - e)
        snr = _rms(eff_sum - (eff_sum.mean() if decoy else 0)) / nrms if category != "clean" else 0.0
        cat_out = category
        if category.startswith("decoy"):
            cat_out = "decoy_equivalent" if equiv else "decoy_separable"
        return dict(kind="vibration", model=m["code"],
                    columns={"time_s": time, "input_speed_rpm": rpm, "output_vibration_rad": y},
                    gear_effects=tuple(effects), measurement_effects=meas, nuisance=nuis,
                    category=cat_out, equivalent_effects=tuple(equiv), noise_rms=nrms,
                    formulation="; ".join([rdesc, integ, damp] + descs + [f"noise {nd}"]),
                    snr=snr, load_inertia_kgm2=float(J))
    raise RuntimeError("vibration draw failed")


# --------------------------------------------------------------------------------------------
# cells
# --------------------------------------------------------------------------------------------
def _cells():
    cells = []
    # torsion
    tf = {e: [f[0] for f in v] for e, v in _TORSION_EFFECTS.items()}
    cells.append(("torsion", "clean", (), (), None))
    for e, fl in tf.items():
        for f in fl:
            cells.append(("torsion", "single", (e,), (f,), None))
    for a, b in (("hysteresis", "backlash"), ("hysteresis", "housing_compliance"),
                 ("backlash", "housing_compliance")):
        for i in range(2):
            cells.append(("torsion", "pair", (a, b), (tf[a][i], tf[b][1 - i]), None))
    for d in ("sensor_gain", "angle_offset", "thermal_drift", "wrong_units", "stiffness_in_spread"):
        cells.append(("torsion", "decoy_separable", (), (), d))
    for d in ("servo_lock", "ballscrew_play", "indicator_play"):
        cells.append(("torsion", "decoy_equivalent", (), (), d))
    # transmission
    xf = {e: [f[0] for f in v] for e, v in _TE_FORMS.items()}
    cells.append(("transmission", "clean", (), (), None))
    for e, fl in xf.items():
        for f in fl:
            cells.append(("transmission", "single", (e,), (f,), None))
    for i in range(2):
        cells.append(("transmission", "pair", ("te_1x", "te_2x"), (xf["te_1x"][i], xf["te_2x"][1 - i]),
                      None))
    for d in ("encoder_eccentricity", "angle_offset", "thermal_drift", "wrong_units"):
        cells.append(("transmission", "decoy_separable", (), (), d))
    for d in ("seal_drag_1x", "split_clamp_2x"):
        cells.append(("transmission", "decoy_equivalent", (), (), d))
    # efficiency
    cells.append(("efficiency", "clean", (), (), None))
    for f in _LL_FORMS:
        cells.append(("efficiency", "single", ("low_load_efficiency",), (f,), None))
    for f in _TEMP_FORMS:
        cells.append(("efficiency", "single", ("temperature_dependence",), (f,), None))
    for fl, ft in (("gompertz", "mehrotra"), ("loglogistic", "lewissquires")):
        cells.append(("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"),
                      (fl, ft), None))
    for d in ("wrong_units", "sensor_gain", "level", "thermal_drift"):
        cells.append(("efficiency", "decoy_separable", (), (), d))
    for d in ("windage", "ferrofluid_seal"):
        cells.append(("efficiency", "decoy_equivalent", (), (), d))
    # vibration
    cells.append(("vibration", "clean", (), (), None))
    for e, fl in xf.items():
        for f in fl:
            cells.append(("vibration", "single", (e,), (f,), None))
    cells.append(("vibration", "pair", ("te_1x", "te_2x"), ("cubicrunout", "superellipse"), None))
    cells.append(("vibration", "pair", ("te_1x", "te_2x"), ("poisson", "poisson"), None))
    for d in ("thermal_drift", "angle_offset", "encoder_eccentricity"):
        cells.append(("vibration", "decoy_separable", (), (), d))
    for d in ("flexure_1x", "flexure_2x"):
        cells.append(("vibration", "decoy_equivalent", (), (), d))
    return cells


_GEN = {"torsion": _gen_torsion, "transmission": _gen_transmission,
        "efficiency": _gen_efficiency, "vibration": _gen_vibration}

_SHORT = {"hysteresis": "hyst", "backlash": "backlash", "housing_compliance": "housing",
          "te_1x": "te1x", "te_2x": "te2x", "low_load_efficiency": "lowload",
          "temperature_dependence": "temp"}


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list:
    rng = np.random.default_rng(seed)
    cat = _Catalog(catalog_dir)
    out, counter = [], {}
    for kind, category, effects, forms, decoy in _cells():
        for _ in range(per_cell):
            r = _GEN[kind](rng, cat, category, effects, forms, decoy)
            if effects:
                tag = "+".join(_SHORT[e] for e in effects) + "-" + "+".join(forms)
            elif decoy:
                tag = decoy.replace("_", "")
            else:
                tag = "noise"
            stem = f"q-{kind}-{r['category']}-{tag}"
            counter[stem] = counter.get(stem, 0) + 1
            out.append(TruthCase(name=f"{stem}-{counter[stem]:03d}", **r))
    return out


if __name__ == "__main__":
    import sys
    import time
    t0 = time.time()
    cs = generate_cases(int(sys.argv[1]) if len(sys.argv) > 1 else 11,
                        Path(__file__).with_name("catalog"), 1)
    print(len(cs), f"{time.time() - t0:.1f}s")
