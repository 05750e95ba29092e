"""Truth suite K: independent synthetic "measured" data for hdcad reconcile.

Written from the contract (truths/CONTRACT.md), the catalog tables and the physics
literature only.  numpy + scipy, nothing from hdcad.  See NOTES_k.md.

    python truth_k.py /work/main/catalog      # self-check over 24 seeds
"""
from __future__ import annotations

import csv
import math
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import signal, special
from scipy.interpolate import CubicSpline, PchipInterpolator

SUITE = "k"

KINDS = ("torsion", "transmission", "efficiency", "vibration")
COLUMNS = {
    "torsion": ("torque_Nm", "twist_rad"),
    "transmission": ("input_angle_rad", "output_angle_rad"),
    "efficiency": ("input_speed_rpm", "load_torque_Nm", "temperature_C", "efficiency_pct"),
    "vibration": ("time_s", "input_speed_rpm", "output_vibration_rad"),
}
ROW_LIMITS = {"torsion": 3000, "transmission": 6000, "efficiency": 2000, "vibration": 6000}
GEAR_EFFECTS = {
    "torsion": ("hysteresis", "backlash", "housing_compliance"),
    "transmission": ("te_1x", "te_2x"),
    "efficiency": ("low_load_efficiency", "temperature_dependence"),
    "vibration": ("te_1x", "te_2x"),
}
MEAS_EFFECTS = ("sensor_gain", "angle_offset", "encoder_eccentricity", "thermal_drift", "wrong_units")
CATEGORIES = ("clean", "single", "pair", "decoy_separable", "decoy_equivalent")
KGF = 9.80665


# --------------------------------------------------------------------------- case
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
        names = list(self.columns)
        cols = [np.asarray(self.columns[n], dtype=float) for n in names]
        with open(path, "w", newline="") as fh:
            fh.write(",".join(names) + "\n")
            for row in zip(*cols):
                fh.write(",".join(repr(float(v)) for v in row) + "\n")


# --------------------------------------------------------------------------- catalog
def _read(path: Path) -> list[dict]:
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _f(x):
    return float(x) if x not in (None, "") else None


_CAT_CACHE: dict = {}


def load_catalog(catalog_dir) -> dict:
    d = Path(catalog_dir)
    key = str(d.resolve())
    if key in _CAT_CACHE:
        return _CAT_CACHE[key]
    stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
    hyst = _read(d / "gh_hysteresis_052_060.csv")
    back = _read(d / "gh_backlash_052-2_060-2.csv")
    perf = _read(d / "gh_performance_051-1_059-1.csv")
    rat = _read(d / "gh_ratings_050-1_058-1.csv")
    ke = _read(d / "ke_curve_023-1.csv")
    comp = _read(d / "component_examples.csv")
    lub = _read(d / "lubricant_temperature_016-2_019.csv")
    fdeff = _read(d / "fd_efficiency_313.csv")

    def in_class(row, ratio):
        lo = _f(row["ratio_min"])
        hi = _f(row["ratio_max"])
        return lo <= ratio and (hi is None or ratio <= hi)

    models = []
    for r in rat:
        series, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
        st = [s for s in stiff if s["series"] == series and int(s["size"]) == size and in_class(s, ratio)]
        hy = [h for h in hyst if h["series"] == series and in_class(h, ratio)]
        bk = [b for b in back if b["series"] == series and int(b["size"]) == size and int(b["ratio"]) == ratio]
        pf = [p for p in perf if p["series"] == series and int(p["size"]) == size and int(p["ratio"]) == ratio]
        if not (st and hy and bk and pf):
            continue
        s = st[0]
        acc = next((_f(p["accuracy_rad"]) for p in pf if _f(p["accuracy_rad"])), None)
        models.append(dict(
            code=f"{series.split('-')[0]}-{size}-{ratio}-GH", series=series, size=size, ratio=ratio,
            T1=_f(s["T1_Nm"]), T2=_f(s["T2_Nm"]), K1=_f(s["K1_Nm_per_rad"]), K2=_f(s["K2_Nm_per_rad"]),
            K3=_f(s["K3_Nm_per_rad"]), hyst=_f(hy[0]["hysteresis_rad"]), backlash=_f(bk[0]["backlash_rad"]),
            accuracy=acc, rated=_f(r["rated_torque_2000_Nm"]), max_rpm=_f(r["max_input_speed_rpm"]),
            running_cNm=_f(pf[0]["running_torque_cNm"])))
    kep = [(float(k["alpha"]), float(k["Ke"])) for k in ke]
    ke_pt = min(kep, key=lambda p: p[0])  # the one read point (0.58, 0.93)
    etaR = [_f(c["efficiency_rated_pct"]) for c in comp if _f(c["efficiency_rated_pct"])]
    fd = [_f(x["efficiency_pct"]) for x in fdeff if _f(x["efficiency_pct"])]
    lubs = {}
    for l in lub:
        if l["table"] == "016-2" and _f(l["use_min_C"]) is not None:
            lubs.setdefault(l["lubricant"], (float(l["use_min_C"]), float(l["use_max_C"])))
    cat = dict(models=models, ke_point=ke_pt, eta_levels=etaR + fd, lubricants=lubs,
               te_models=[m for m in models if m["accuracy"]])
    _CAT_CACHE[key] = cat
    return cat


# --------------------------------------------------------------------------- helpers
def _rms(x):
    x = np.asarray(x, float)
    return float(np.sqrt(np.mean(x * x)))


def _unit_noise(rng, n, form):
    """Unit-RMS noise: white or AR(1) (phi in [0.3, 0.8]); '+outliers' adds 0.5 % of rows
    at 8-15 x the Gaussian part; the whole vector is then normalised to RMS 1."""
    e = rng.standard_normal(n)
    if form.startswith("ar1"):
        phi = rng.uniform(0.3, 0.8)
        zi = np.array([phi * e[0] / math.sqrt(1.0 - phi * phi)])  # stationary start
        x = signal.lfilter([1.0], [1.0, -phi], e, zi=zi)[0] * math.sqrt(1.0 - phi * phi)
    else:
        x = e
    x = x / _rms(x)
    if form.endswith("+outliers"):
        m = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, m, replace=False)
        x[idx] += rng.choice([-1.0, 1.0], m) * rng.uniform(8.0, 15.0, m)
    return x / _rms(x)


def _noise_form(rng):
    return str(rng.choice(["white", "ar1", "white+outliers", "ar1+outliers"], p=[0.35, 0.35, 0.15, 0.15]))


def _eff_rms(x, center):
    x = np.asarray(x, float)
    return _rms(x - x.mean()) if center else _rms(x)


def _scale_effects(comps: dict, rng, center: bool):
    """Catalog-anchored components -> (scaled comps, sigma, snr, factors, order).
    Single: k in [4, 12], sigma = rms/k.  Pair: k_i in [4.5, 8]; sigma from the first
    (catalog-anchored) component, the second rescaled to k_2*sigma; the combined snr is
    then held in [4, 12] by adjusting sigma."""
    names = list(comps)
    r = {n: _eff_rms(comps[n], center) for n in names}
    factors = {}
    if len(names) == 1:
        k = rng.uniform(4.0, 12.0)
        sigma = r[names[0]] / k
        return comps, sigma, k, factors, names
    ks = {n: rng.uniform(4.5, 8.0) for n in names}
    sigma = r[names[0]] / ks[names[0]]
    out = {names[0]: comps[names[0]]}
    for n in names[1:]:
        f = ks[n] * sigma / r[n]
        out[n] = comps[n] * f
        factors[f"{n}_amp_factor"] = float(f)
    total = sum(out.values())
    snr = _eff_rms(total, center) / sigma
    if snr > 12.0:
        sigma = _eff_rms(total, center) / 12.0
    elif snr < 4.0:
        sigma = _eff_rms(total, center) / 4.0
    snr = _eff_rms(total, center) / sigma
    order = sorted(names, key=lambda n: -_eff_rms(out[n], center))
    return out, sigma, snr, factors, order


def _pick(rng, models):
    return models[int(rng.integers(len(models)))]


# --------------------------------------------------------------------------- torsion
def _H_int(x, a, w):
    """int_0^x H((u-a)/w) du with H(z) = 1/2 + atan(z)/pi (arctan-smoothed step)."""
    def G(z):
        return 0.5 * z + (z * np.arctan(z / w) - 0.5 * w * np.log1p((z / w) ** 2)) / np.pi
    return G(x - a) - G(-a)


def _twist_curve(T, m, w):
    """Catalog three-segment curve written as an arctan-smoothed tangent compliance
    (corner width w), integrated in closed form; odd in T."""
    x = np.abs(T)
    c1, c2, c3 = 1.0 / m["K1"], 1.0 / m["K2"], 1.0 / m["K3"]
    th = c1 * x + (c2 - c1) * _H_int(x, m["T1"], w) + (c3 - c2) * _H_int(x, m["T2"], w)
    return np.sign(T) * th


def _segments(T):
    d = np.sign(np.diff(T))
    d[d == 0] = 1
    cut = np.flatnonzero(d[1:] != d[:-1]) + 1
    starts = np.concatenate([[0], cut])
    ends = np.concatenate([cut, [len(T) - 1]])
    return [(a, b, d[a]) for a, b in zip(starts, ends)]


def _play_bank(T, r):
    """Play (backlash) operators of half-widths r driven by T, exact per monotone segment."""
    Y = np.empty((len(T), len(r)))
    y0 = np.zeros(len(r))
    Y[0] = y0
    for a, b, s in _segments(T):
        seg = T[a:b + 1, None]
        Ys = np.maximum(y0, seg - r) if s > 0 else np.minimum(y0, seg + r)
        Y[a:b + 1] = Ys
        y0 = Ys[-1]
    return Y


def _lag(T, t, tau):
    """First-order lag p, tau p' + p = T, exact for piecewise-linear T (uniform step)."""
    h = t[1] - t[0]
    a = math.exp(-h / tau)
    b = tau * (1.0 - a) / h
    return signal.lfilter([1.0 - b, -(a - b)], [1.0, -a], T)


def _loop_width(th, idx_down, idx_up):
    return th[idx_down] - th[idx_up]


def _hyst(form, T, t, T0, omega, width, rng, iz):
    idx_down, idx_up = iz
    if form == "iwan-powerlaw":
        chi = rng.uniform(0.0, 1.5)
        rmax = rng.uniform(0.25, 0.5) * T0
        M = 48
        r = rmax * ((np.arange(M) + 0.5) / M) ** (1.0 / (chi + 1.0))  # equal-weight quantiles of r^chi
        th = (_play_bank(T, r) - T[:, None]).sum(axis=1)
        par = {"iwan_chi": chi, "iwan_rmax_over_T0": rmax / T0}
    elif form == "prony":
        tau = omega ** -1 * 10.0 ** rng.uniform(-0.8, 0.8, 3)
        c = rng.dirichlet(np.ones(3))
        th = sum(cj * _lag(T, t, tj) for cj, tj in zip(c, tau))
        th = th - np.sum(c / (1.0 + (omega * tau) ** 2)) * T  # remove the in-phase (storage) part
        par = {}
    elif form == "fractional":
        beta = rng.uniform(0.1, 0.4)
        h = t[1] - t[0]
        n = len(T)
        w = np.empty(n)
        w[0] = 1.0
        k = np.arange(1, n)
        w[1:] = np.cumprod((k - 1 + beta) / k)
        th = signal.fftconvolve(T, w)[:n] * h ** beta
        th = th - omega ** (-beta) * math.cos(beta * math.pi / 2) * T
        par = {"creep_exponent": beta}
    else:
        raise ValueError(form)
    wsim = _loop_width(th, idx_down, idx_up)
    return th * (width / wsim), par


def _sig_alg(T, eps):
    return T / np.sqrt(T * T + eps * eps)


def _backlash(form, T, T0, b, rng):
    if form == "wear-grown":
        eps = rng.uniform(0.005, 0.02) * T0
        wr = rng.uniform(0.05, 0.2)
        sgn = np.sign(T)
        sgn[sgn == 0] = 1
        ncross = np.concatenate([[0], np.cumsum(sgn[1:] != sgn[:-1])])
        bn = b * (1.0 + wr * ncross) / (1.0 + wr * ncross[-1] / 2)
        return 0.5 * bn * _sig_alg(T, eps), {"wear_per_reversal": wr}
    if form == "lognormal-engagement":
        Tm = rng.uniform(0.01, 0.04) * T0
        sl = rng.uniform(0.4, 1.0)
        x = np.abs(T)
        S = np.where(x > 0, special.ndtr(np.log(np.maximum(x, 1e-300) / Tm) / sl), 0.0)
        return 0.5 * b * np.sign(T) * S, {}
    if form == "gravity-biased-oldham":
        Tg = rng.choice([-1, 1]) * rng.uniform(0.02, 0.06) * T0
        eps = rng.uniform(0.005, 0.02) * T0
        x = np.clip((T - Tg) / (2 * eps) + 0.5, 0.0, 1.0)
        return 0.5 * b * (2.0 * (6 * x ** 5 - 15 * x ** 4 + 10 * x ** 3) - 1.0), {"gravity_bias_over_T0": Tg / T0}
    raise ValueError(form)


def _housing(form, T, m, rng):
    if form == "tolerance-ring":
        Kh = rng.uniform(1.5, 5.0) * m["K3"]
    elif form == "vlasov-bracket":
        lamL = rng.uniform(0.5, 3.0)
        Kh_target = rng.uniform(2.0, 8.0) * m["K1"]
        # phi = T/(GJ) (L - tanh(lam L)/lam): the warping factor only sets how GJ maps to Kh
        _ = 1.0 - math.tanh(lamL) / lamL
        Kh = Kh_target
    else:
        raise ValueError(form)
    return T / Kh, {}


TORSION_CELLS = [
    ("clean", (), "white", {}),
    ("clean", (), "ar1", {}),
    ("clean", (), "ar1+outliers", {}),
    ("single", ("hysteresis",), "iwan-powerlaw", {"hysteresis": "iwan-powerlaw"}),
    ("single", ("hysteresis",), "prony", {"hysteresis": "prony"}),
    ("single", ("hysteresis",), "fractional", {"hysteresis": "fractional"}),
    ("single", ("backlash",), "wear-grown", {"backlash": "wear-grown"}),
    ("single", ("backlash",), "lognormal-engagement", {"backlash": "lognormal-engagement"}),
    ("single", ("backlash",), "gravity-biased-oldham", {"backlash": "gravity-biased-oldham"}),
    ("single", ("housing_compliance",), "tolerance-ring", {"housing_compliance": "tolerance-ring"}),
    ("single", ("housing_compliance",), "vlasov-bracket", {"housing_compliance": "vlasov-bracket"}),
    ("pair", ("hysteresis", "backlash"), "iwan-powerlaw+wear-grown", {"hysteresis": "iwan-powerlaw", "backlash": "wear-grown"}),
    ("pair", ("hysteresis", "backlash"), "prony+lognormal-engagement", {"hysteresis": "prony", "backlash": "lognormal-engagement"}),
    ("pair", ("hysteresis", "housing_compliance"), "iwan-powerlaw+tolerance-ring", {"hysteresis": "iwan-powerlaw", "housing_compliance": "tolerance-ring"}),
    ("pair", ("hysteresis", "housing_compliance"), "fractional+vlasov-bracket", {"hysteresis": "fractional", "housing_compliance": "vlasov-bracket"}),
    ("pair", ("backlash", "housing_compliance"), "gravity-biased-oldham+tolerance-ring", {"backlash": "gravity-biased-oldham", "housing_compliance": "tolerance-ring"}),
    ("pair", ("backlash", "housing_compliance"), "lognormal-engagement+vlasov-bracket", {"backlash": "lognormal-engagement", "housing_compliance": "vlasov-bracket"}),
    ("decoy_separable", (), "torque-in-kgfm", {}),
    ("decoy_separable", (), "encoder-stator-slot-play", {}),
    ("decoy_separable", (), "spline-drift", {}),
    ("decoy_separable", (), "shunt-cal-gain", {}),
    ("decoy_equivalent", (), "torque-arm-lock-elasticity", {}),
    ("decoy_equivalent", (), "clevis-pin-clearance", {}),
    ("decoy_equivalent", (), "elastomer-coupling-prony", {}),
]


def _torsion(rng, cat, cell):
    category, effects, form, forms = cell
    m = _pick(rng, cat["models"])
    T0 = m["rated"]
    n_c = int(rng.integers(2, 4))
    Nq = int(rng.integers(150, (ROW_LIMITS["torsion"] - 1) // (4 * n_c) + 1))
    phi = np.linspace(0.0, 2 * np.pi * n_c, 4 * Nq * n_c + 1)
    T = T0 * np.sin(phi)
    T[np.arange(0, len(T), 2 * Nq)] = 0.0  # exact zero crossings
    period = rng.uniform(40.0, 120.0)
    omega = 2 * np.pi / period
    t = phi / omega
    iz = (len(T) - 1 - 2 * Nq, len(T) - 1)  # last down- and up-crossing of T = 0
    s = rng.uniform(0.95, 1.05) * rng.uniform(0.95, 1.05)  # FS-lot x CS-lot stiffness scatter
    w = rng.uniform(0.01, 0.03) * m["T1"]
    theta = _twist_curve(T, m, w) / s
    nuis = {"stiffness_scale": float(s)}
    gear, meas, equiv = (), (), ()
    torque = T.copy()
    comps = {}
    for eff in effects:
        f = forms[eff]
        if eff == "hysteresis":
            width = m["hyst"] * rng.uniform(0.7, 1.3)
            comps[eff], par = _hyst(f, T, t, T0, omega, width, rng, iz)
        elif eff == "backlash":
            b = m["backlash"] * rng.uniform(0.5, 1.0)
            comps[eff], par = _backlash(f, T, T0, b, rng)
        else:
            comps[eff], par = _housing(f, T, m, rng)
        nuis.update({k: float(v) for k, v in par.items()})
    snr = 0.0
    if comps:
        comps, sigma, snr, fac, order = _scale_effects(comps, rng, center=False)
        nuis.update(fac)
        theta = theta + sum(comps.values())
        gear = tuple(order)
        formulation = " + ".join(f"{e}:{forms[e]}" for e in order)
    else:
        sigma = m["hyst"] / rng.uniform(4.0, 12.0)  # clean/decoy noise anchored on the catalog loop
        formulation = form
    if category in ("decoy_separable", "decoy_equivalent") and form not in ("torque-in-kgfm", "shunt-cal-gain"):
        if form == "encoder-stator-slot-play":
            d = np.sign(np.gradient(T))
            d[d == 0] = 1
            rise = signal.lfilter([0.5], [1.0, -0.5], d, zi=[0.5 * d[0]])[0]  # stator crosses the slot in a few samples
            comp = -0.5 * rise
            meas = ("angle_offset",)
        elif form == "spline-drift":
            nk = int(rng.integers(5, 8))
            tk = np.linspace(t[0], t[-1], nk)
            vk = np.concatenate([[0.0], np.cumsum(rng.standard_normal(nk - 1))])
            comp = CubicSpline(tk, vk, bc_type="natural")(t)
            meas = ("thermal_drift",)
        elif form == "torque-arm-lock-elasticity":
            k_arm = rng.uniform(1.5, 5.0) * m["K3"] / m["ratio"] ** 2
            comp = T / (m["ratio"] ** 2 * k_arm)
            equiv = ("housing_compliance",)
        elif form == "clevis-pin-clearance":
            comp = 0.5 * m["backlash"] * _sig_alg(T, rng.uniform(0.003, 0.015) * T0)
            equiv = ("backlash",)
        elif form == "elastomer-coupling-prony":
            tau = 10.0 ** rng.uniform(-0.8, 0.8, 2) / omega
            c = rng.dirichlet(np.ones(2))
            comp = sum(cj * _lag(T, t, tj) for cj, tj in zip(c, tau)) / m["K3"]
            equiv = ("hysteresis", "housing_compliance")
        k = rng.uniform(4.0, 12.0)
        comp = comp * (k * sigma / _rms(comp))
        theta = theta + comp
        snr = k
    elif form == "torque-in-kgfm":
        torque = T / KGF
        meas = ("wrong_units",)
    elif form == "shunt-cal-gain":
        g = 1.0 + rng.choice([-1, 1]) * rng.uniform(0.06, 0.15)
        torque = g * T
        meas = ("sensor_gain",)
        nuis["torque_gain"] = float(g)
        snr = _rms(_twist_curve(T, m, w) - _twist_curve(g * T, m, w)) / s / sigma
    n = _unit_noise(rng, len(T), form if category == "clean" else _noise_form(rng))
    twist = theta + sigma * n
    nform = form if category == "clean" else ""
    return dict(kind="torsion", model=m["code"], columns={"torque_Nm": torque, "twist_rad": twist},
                load_inertia_kgm2=None, gear_effects=gear, measurement_effects=meas, nuisance=nuis,
                category=category, equivalent_effects=equiv, noise_rms=float(sigma),
                formulation=formulation if not nform else f"noise:{nform}", snr=float(snr))


# --------------------------------------------------------------------------- TE waveforms
def _jacobi_sn(phi, k, m_ell, ph0):
    K = special.ellipk(m_ell)
    u = 4.0 * K * (k * phi + ph0) / (2 * np.pi)
    return special.ellipj(u, m_ell)[0]


def _jitter_sin(phi, k, ph0, sig, rng, phi0):
    rev = (phi - phi0) / (2 * np.pi)
    nrev = int(np.ceil(rev[-1])) + 2
    knots = np.arange(-1, nrev) + 0.5
    vals = rng.normal(0.0, sig, len(knots))
    jit = PchipInterpolator(knots, vals)(rev)
    return np.sin(k * phi + ph0 + jit)


def _te_wave(form, phi, k, rng, phi0):
    ph0 = rng.uniform(0, 2 * np.pi)
    if form == "jacobi-sn":
        m_ell = rng.uniform(0.6, 0.9)
        return _jacobi_sn(phi, k, m_ell, ph0), {f"sn_modulus_{k}x": m_ell}
    if form == "phase-jitter":
        sig = rng.uniform(0.05, 0.2)
        return _jitter_sin(phi, k, ph0, sig, rng, phi0), {f"phase_jitter_rad_{k}x": sig}
    raise ValueError(form)


def _pp_norm(x, pp):
    return x * (pp / (x.max() - x.min()))


# --------------------------------------------------------------------------- transmission
TRANSMISSION_CELLS = [
    ("clean", (), "white", {}),
    ("clean", (), "ar1+outliers", {}),
    ("single", ("te_1x",), "jacobi-sn", {"te_1x": "jacobi-sn"}),
    ("single", ("te_1x",), "phase-jitter", {"te_1x": "phase-jitter"}),
    ("single", ("te_2x",), "jacobi-sn", {"te_2x": "jacobi-sn"}),
    ("single", ("te_2x",), "phase-jitter", {"te_2x": "phase-jitter"}),
    ("pair", ("te_1x", "te_2x"), "jacobi-sn+jacobi-sn", {"te_1x": "jacobi-sn", "te_2x": "jacobi-sn"}),
    ("pair", ("te_1x", "te_2x"), "phase-jitter+phase-jitter", {"te_1x": "phase-jitter", "te_2x": "phase-jitter"}),
    ("decoy_separable", (), "eccentric-tilted-disc", {}),
    ("decoy_separable", (), "logger-resync-step", {}),
    ("decoy_separable", (), "input-in-revolutions", {}),
    ("decoy_separable", (), "matern-drift", {}),
    ("decoy_separable", (), "resolution-misconfig-gain", {}),
    ("decoy_equivalent", (), "logger-skew-1x-speed-ripple", {}),
    ("decoy_equivalent", (), "logger-skew-2x-speed-ripple", {}),
]


def _matern_path(rng, x, ell):
    g = np.linspace(x[0], x[-1], 60)
    d = np.abs(g[:, None] - g[None, :]) * math.sqrt(3.0) / ell
    C = (1.0 + d) * np.exp(-d) + 1e-9 * np.eye(len(g))
    v = np.linalg.cholesky(C) @ rng.standard_normal(len(g))
    return CubicSpline(g, v)(x)


def _transmission(rng, cat, cell):
    category, effects, form, forms = cell
    m = _pick(rng, cat["te_models"])
    R = m["ratio"]
    n_rev = int(rng.integers(4, 9))
    spr = min(900, (ROW_LIMITS["transmission"] - 1) // n_rev)
    rows = n_rev * spr + 1
    phi0 = rng.uniform(0, 2 * np.pi)
    thi = phi0 + np.linspace(0.0, 2 * np.pi * n_rev, rows)
    off = rng.uniform(-0.5, 0.5)
    out = thi / R + off
    nuis = {"offset_rad": float(off)}
    gear, meas, equiv = (), (), ()
    comps = {}
    for eff in effects:
        k = 1 if eff == "te_1x" else 2
        wave, par = _te_wave(forms[eff], thi, k, rng, phi0)
        comps[eff] = _pp_norm(wave, m["accuracy"] * rng.uniform(0.25, 0.8))
        nuis.update(par)
    inp = thi.copy()
    snr = 0.0
    if comps:
        comps, sigma, snr, fac, order = _scale_effects(comps, rng, center=True)
        nuis.update(fac)
        out = out + sum(comps.values())
        gear = tuple(order)
        formulation = " + ".join(f"{e}:{forms[e]}" for e in order)
    else:
        sigma = 0.25 * m["accuracy"] / rng.uniform(4.0, 12.0)
        formulation = form
    comp = None
    if form == "eccentric-tilted-disc":
        tho = thi / R
        comp = np.sin(tho + rng.uniform(0, 2 * np.pi)) + rng.uniform(0.1, 0.4) * np.sin(2 * tho + rng.uniform(0, 2 * np.pi))
        meas = ("encoder_eccentricity",)
    elif form == "logger-resync-step":
        p = rng.uniform(0.25, 0.75)
        comp = (np.arange(rows) > p * rows).astype(float) * rng.choice([-1.0, 1.0])
        meas = ("angle_offset",)
    elif form == "matern-drift":
        comp = _matern_path(rng, thi, (thi[-1] - thi[0]) * rng.uniform(0.3, 0.6))
        comp -= comp[0]
        meas = ("thermal_drift",)
    elif form in ("logger-skew-1x-speed-ripple", "logger-skew-2x-speed-ripple"):
        k = 1 if "1x" in form else 2
        wbar = 2 * np.pi * rng.uniform(15.0, 30.0)  # rad/s WG speed (900-1800 r/min)
        delta = rng.uniform(1e-3, 5e-3)  # s, channel-to-channel skew of the logger
        rho = rng.uniform(0.02, 0.08)  # speed ripple (fraction of mean speed) at k x per WG rev
        ph = rng.uniform(0, 2 * np.pi)
        tt = (thi - phi0) / wbar

        def th_of(tv):
            return phi0 + wbar * tv - (rho / k) * np.cos(k * wbar * tv + ph)
        inp = th_of(tt)
        comp = (th_of(tt + delta) - inp - wbar * delta) / R  # physical size: noise follows from k
        equiv = ("te_1x",) if k == 1 else ("te_2x",)
        nuis.update({"logger_skew_s": float(delta), "speed_ripple_fraction": float(rho)})
        out = inp / R + off
        sigma = _eff_rms(comp, True) / rng.uniform(4.0, 12.0)
    if comp is not None:
        k = rng.uniform(4.0, 12.0) if not equiv else _eff_rms(comp, True) / sigma
        comp = comp * (k * sigma / _eff_rms(comp, True))
        out = out + comp
        snr = k
    if form == "input-in-revolutions":
        inp = inp / (2 * np.pi)
        meas = ("wrong_units",)
    noise = sigma * _unit_noise(rng, rows, form if category == "clean" else _noise_form(rng))
    if form == "resolution-misconfig-gain":
        g = float(rng.choice([2 ** 20 / 1e6, 1e6 / 2 ** 20, 2 ** 17 / 125000.0]))
        snr = _eff_rms((g - 1.0) * out, True) / sigma
        out = g * out
        meas = ("sensor_gain",)
        nuis["angle_gain"] = g
    out = out + noise
    return dict(kind="transmission", model=m["code"], columns={"input_angle_rad": inp, "output_angle_rad": out},
                load_inertia_kgm2=None, gear_effects=gear, measurement_effects=meas, nuisance=nuis,
                category=category, equivalent_effects=equiv, noise_rms=float(sigma),
                formulation=formulation if category != "clean" else f"noise:{form}", snr=float(snr))


# --------------------------------------------------------------------------- efficiency
EFFICIENCY_CELLS = [
    ("clean", (), "white", {}),
    ("clean", (), "ar1+outliers", {}),
    ("single", ("low_load_efficiency",), "constant+quadratic-loss", {"low_load_efficiency": "constant+quadratic-loss"}),
    ("single", ("low_load_efficiency",), "ocvirk-short-bearing", {"low_load_efficiency": "ocvirk-short-bearing"}),
    ("single", ("temperature_dependence",), "thermal-preload-hinge", {"temperature_dependence": "thermal-preload-hinge"}),
    ("single", ("temperature_dependence",), "litt-viscosity+asperity-share", {"temperature_dependence": "litt-viscosity+asperity-share"}),
    ("pair", ("low_load_efficiency", "temperature_dependence"), "constant+quadratic-loss+thermal-preload-hinge",
     {"low_load_efficiency": "constant+quadratic-loss", "temperature_dependence": "thermal-preload-hinge"}),
    ("pair", ("low_load_efficiency", "temperature_dependence"), "ocvirk-short-bearing+litt-viscosity+asperity-share",
     {"low_load_efficiency": "ocvirk-short-bearing", "temperature_dependence": "litt-viscosity+asperity-share"}),
    ("decoy_separable", (), "speed-in-rad-per-s", {}),
    ("decoy_separable", (), "torque-span-gain", {}),
    ("decoy_separable", (), "log-creep-per-tare", {}),
    ("decoy_separable", (), "load-in-kNm", {}),
    ("decoy_equivalent", (), "torque-tare-error", {}),
    ("decoy_equivalent", (), "motor-kt-ndfeb-tempco", {}),
]


def _ocvirk_eps(W):
    """Solve the Ocvirk short-bearing load number W = e*sqrt(16 e^2 + pi^2 (1-e^2))/(1-e^2)^2 for e."""
    lo = np.zeros_like(W)
    hi = np.full_like(W, 0.999)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        f = mid * np.sqrt(16 * mid ** 2 + np.pi ** 2 * (1 - mid ** 2)) / (1 - mid ** 2) ** 2
        big = f > W
        hi = np.where(big, mid, hi)
        lo = np.where(big, lo, mid)
    return 0.5 * (lo + hi)


def _ke(form, alpha, K58, rng):
    a58 = 0.58
    if form == "constant+quadratic-loss":
        beta = rng.uniform(0.0, 1.0)
        a = a58 * (K58 - 1.0) / (a58 * (1 + beta) - K58 * (1 + a58 ** 2 * beta))
        ke = (1 + a + beta * a) * alpha / (alpha + a + beta * a * alpha ** 2)
        par = {"loss_const": a, "loss_quad_over_const": beta}
    elif form == "ocvirk-short-bearing":
        lam = rng.uniform(5.0, 40.0)  # Ocvirk load number at rated torque: eps(1) ~ 0.6-0.85
        g = lambda al: 1.0 / np.sqrt(1.0 - _ocvirk_eps(lam * np.asarray(al, float)) ** 2)
        g1, g58 = float(g(1.0)), float(g(a58))
        tau0 = a58 * (1.0 - K58) / (K58 * g58 - a58 * g1)
        ke = alpha * (1 + tau0 * g1) / (alpha + tau0 * g(alpha))
        par = {"ocvirk_load_number": lam, "petroff_loss_ratio": tau0}
    else:
        raise ValueError(form)
    return np.where(alpha >= 1.0, 1.0, ke), par


def _ftemp(form, T, Tmin, Tmax, rng):
    span = Tmax - Tmin
    drop = rng.uniform(0.04, 0.12)  # relative efficiency change across the range (FD: grease ~10 % below oil)
    if form == "thermal-preload-hinge":
        Topen = Tmin + rng.uniform(0.4, 0.8) * span
        dl = 0.1 * span
        x = Topen - T
        h = np.where(x > dl, x, np.where(x < -dl, 0.0, (x + dl) ** 2 / (4 * dl)))
        f = 1.0 - drop * h / (Topen - Tmin)
        par = {"preload_open_C": Topen}
    elif form == "litt-viscosity+asperity-share":
        B = rng.uniform(10.0, 12.0)  # Litt exponent, ISO VG68 mineral oil ~11.8
        nu = ((T + 273.15) / 313.15) ** (-B)
        lam40 = rng.uniform(0.8, 1.5)
        lam = lam40 * nu ** 0.7  # Dowson-Higginson h ~ (eta u)^0.7
        av, ab = rng.uniform(0.02, 0.08), rng.uniform(0.1, 0.3)
        loss = av * np.sqrt(nu) + ab * special.ndtr(-lam)
        f = 1.0 - loss
        grid = np.linspace(Tmin, Tmax, 50)
        nug = ((grid + 273.15) / 313.15) ** (-B)
        fg = 1.0 - (av * np.sqrt(nug) + ab * special.ndtr(-lam40 * nug ** 0.7))
        f = 1.0 + (f - fg.max()) * drop / max(fg.max() - fg.min(), 1e-9)
        par = {"litt_exponent": B, "lambda_40C": lam40}
    else:
        raise ValueError(form)
    return f, par


def _efficiency(rng, cat, cell):
    category, effects, form, forms = cell
    m = _pick(rng, cat["models"])
    Tr = m["rated"]
    speeds = [s for s in (500, 1000, 1500, 2000, 2500, 3000, 3500) if s <= m["max_rpm"]]
    ns = int(rng.integers(3, min(5, len(speeds)) + 1))
    speeds = np.sort(rng.choice(speeds, ns, replace=False))
    alphas = np.array([0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.58, 0.7, 0.85, 1.0, 1.1])
    alphas = np.sort(rng.choice(alphas, int(rng.integers(8, 12)), replace=False))
    lub = sorted(cat["lubricants"])[int(rng.integers(len(cat["lubricants"])))]
    Tmin, Tmax = cat["lubricants"][lub]
    temps = np.linspace(Tmin, Tmax, int(rng.integers(4, 7)))
    reps = int(rng.integers(1, 3))
    rows_n, rows_a, rows_T, rows_t = [], [], [], []
    for Tc in rng.permutation(temps):
        grid = [(n, a) for n in speeds for a in alphas for _ in range(reps)]
        order = rng.permutation(len(grid))
        for j, i in enumerate(order):
            rows_n.append(grid[i][0]); rows_a.append(grid[i][1]); rows_T.append(Tc); rows_t.append(j)
    n_rpm = np.array(rows_n, float)
    alpha = np.array(rows_a, float)
    temp = np.array(rows_T, float)
    tblock = np.array(rows_t, float) * rng.uniform(1.0, 3.0)  # minutes since the block's tare
    lvl_c = cat["eta_levels"]
    level = rng.uniform(min(lvl_c) - 6.0, max(lvl_c) - 4.0)  # 72-86 %: around eta_R 78 and FD 80/90
    K58 = cat["ke_point"][1] * rng.uniform(0.98, 1.02)
    eta = np.full(len(alpha), level)
    nuis = {"efficiency_level_pct": float(level)}
    comps = {}
    for eff in effects:
        if eff == "low_load_efficiency":
            ke, par = _ke(forms[eff], alpha, K58, rng)
            comps[eff] = level * (ke - 1.0)
        else:
            ft, par = _ftemp(forms[eff], temp, Tmin, Tmax, rng)
            comps[eff] = level * (ft - 1.0)
        nuis.update({k: float(v) for k, v in par.items()})
    gear, meas, equiv = (), (), ()
    snr = 0.0
    load = alpha * Tr
    speed_col = n_rpm.copy()
    if comps:
        # the two effects multiply: eta = level*Ke*f  (cross term kept)
        comps, sigma, snr, fac, order = _scale_effects(comps, rng, center=True)
        nuis.update(fac)
        if len(comps) == 2:
            c = list(comps.values())
            eta = level * (1 + c[0] / level) * (1 + c[1] / level)
            snr = _eff_rms(eta - level, True) / sigma
            if not 4.0 <= snr <= 12.0:
                sigma = _eff_rms(eta - level, True) / float(np.clip(snr, 4.0, 12.0))
                snr = _eff_rms(eta - level, True) / sigma
        else:
            eta = eta + sum(comps.values())
        gear = tuple(order)
        formulation = " + ".join(f"{e}:{forms[e]}" for e in order)
    else:
        sigma = level * (1 - cat["ke_point"][1]) * 0.5 / rng.uniform(4.0, 12.0)
        formulation = form
    if form == "speed-in-rad-per-s":
        speed_col = n_rpm * np.pi / 30.0
        meas = ("wrong_units",)
    elif form == "load-in-kNm":
        load = load * 1e-3
        meas = ("wrong_units",)
    elif form == "torque-span-gain":
        g = 1.0 + rng.choice([-1, 1]) * rng.uniform(0.04, 0.10)
        load = load * g
        eta = eta * g
        meas = ("sensor_gain",)
        nuis["torque_gain"] = float(g)
        snr = 0.0  # a pure level change: absorbed by the level nuisance
    elif form == "log-creep-per-tare":
        tau = rng.uniform(2.0, 10.0)
        comp = np.log1p(tblock / tau)
        k = rng.uniform(4.0, 12.0)
        comp = comp * (k * sigma / _eff_rms(comp, True))
        eta = eta + comp
        snr = k
        meas = ("thermal_drift",)
    elif form == "torque-tare-error":
        d = rng.uniform(0.02, 0.06) * Tr
        true = alpha * Tr
        load = true - d
        ratio = load / true
        comp = eta * (ratio - 1.0)
        k = rng.uniform(4.0, 12.0)
        sigma = _eff_rms(comp, True) / k
        eta = eta * ratio
        snr = k
        equiv = ("low_load_efficiency",)
        nuis["torque_tare_Nm"] = float(d)
    elif form == "motor-kt-ndfeb-tempco":
        kap = -rng.uniform(0.0009, 0.0013)
        Tref = 20.0
        comp = eta * kap * (temp - Tref)
        k = rng.uniform(4.0, 12.0)
        sigma = _eff_rms(comp, True) / k
        eta = eta + comp
        snr = k
        equiv = ("temperature_dependence",)
        nuis["kt_tempco_per_K"] = float(kap)
    noise = sigma * _unit_noise(rng, len(eta), form if category == "clean" else _noise_form(rng))
    cols = {"input_speed_rpm": speed_col, "load_torque_Nm": load, "temperature_C": temp,
            "efficiency_pct": eta + noise}
    return dict(kind="efficiency", model=m["code"], columns=cols, load_inertia_kgm2=None, gear_effects=gear,
                measurement_effects=meas, nuisance=nuis, category=category, equivalent_effects=equiv,
                noise_rms=float(sigma), formulation=formulation if category != "clean" else f"noise:{form}",
                snr=float(snr))


# --------------------------------------------------------------------------- vibration
VIBRATION_CELLS = [
    ("clean", (), "white", {}),
    ("clean", (), "ar1+outliers", {}),
    ("single", ("te_1x",), "jacobi-sn|sqrt-power-runup", {"te_1x": "jacobi-sn"}),
    ("single", ("te_1x",), "phase-jitter|exp-approach-runup", {"te_1x": "phase-jitter"}),
    ("single", ("te_2x",), "jacobi-sn|sqrt-power-runup", {"te_2x": "jacobi-sn"}),
    ("single", ("te_2x",), "phase-jitter|exp-approach-runup", {"te_2x": "phase-jitter"}),
    ("pair", ("te_1x", "te_2x"), "jacobi-sn+jacobi-sn|sqrt-power-runup", {"te_1x": "jacobi-sn", "te_2x": "jacobi-sn"}),
    ("pair", ("te_1x", "te_2x"), "phase-jitter+phase-jitter|exp-approach-runup", {"te_1x": "phase-jitter", "te_2x": "phase-jitter"}),
    ("decoy_separable", (), "eccentric-shrink-disc-hub", {}),
    ("decoy_separable", (), "drift-by-cumulative-revs", {}),
    ("decoy_separable", (), "speed-in-rad-per-s", {}),
    ("decoy_equivalent", (), "resolver-1x-error", {}),
    ("decoy_equivalent", (), "resolver-2x-error", {}),
]


def _duhamel(F, dt, J, wn, zeta):
    wd = wn * math.sqrt(1.0 - zeta ** 2)
    tt = np.arange(len(F)) * dt
    h = np.exp(-zeta * wn * tt) * np.sin(wd * tt) / (J * wd)
    return signal.fftconvolve(F, h)[:len(F)] * dt


def _vibration(rng, cat, cell):
    category, effects, form, forms = cell
    m = _pick(rng, cat["te_models"])
    R = m["ratio"]
    s = rng.uniform(0.95, 1.05) * rng.uniform(0.95, 1.05)
    K = m["K1"] * s
    zeta = rng.uniform(0.03, 0.12)
    fmax = min(30.0, m["max_rpm"] / 60.0 / 1.45)
    fn = rng.uniform(8.0, fmax)
    wn = 2 * np.pi * fn
    J = m["K1"] / wn ** 2  # chosen from the catalog K1; the true K carries the scatter
    wn = math.sqrt(K / J)
    c = 2 * zeta * math.sqrt(K * J)
    fs = 200.0
    D = rng.uniform(20.0, (ROW_LIMITS["vibration"] - 1) / fs)
    M = 8
    dt = 1.0 / (fs * M)
    Tpre = min(6.0 / (zeta * wn), 8.0)
    t = np.arange(-int(Tpre / dt), int(round(D / dt)) + 1) * dt
    n0 = 0.35 * 30.0 * fn
    n1 = 1.45 * 60.0 * fn
    tp = np.clip(t, 0.0, None)
    profile = "exp" if "exp-approach" in form or form.startswith("phase") or form == "resolver-2x-error" else "sqrt"
    if profile == "sqrt":
        n = np.sqrt(n0 ** 2 + (n1 ** 2 - n0 ** 2) * tp / D)
    else:
        tau = D / rng.uniform(1.5, 3.0)
        n = n0 + (n1 - n0) * (1 - np.exp(-tp / tau)) / (1 - math.exp(-D / tau))
    phi0 = rng.uniform(0, 2 * np.pi)
    th = phi0 + np.concatenate([[0.0], np.cumsum(0.5 * (n[1:] + n[:-1]) * dt)]) * 2 * np.pi / 60.0
    keep = t >= -1e-12
    idx = np.flatnonzero(keep)[::M]
    nuis = {"stiffness_scale": float(s), "damping_ratio": float(zeta)}

    def respond(e):
        F = K * e + c * np.gradient(e, dt)
        return _duhamel(F, dt, J, wn, zeta)[idx]

    comps = {}
    for eff in effects:
        k = 1 if eff == "te_1x" else 2
        wave, par = _te_wave(forms[eff], th, k, rng, phi0)
        e = _pp_norm(wave, m["accuracy"] * rng.uniform(0.2, 0.6))
        comps[eff] = respond(e)
        nuis.update(par)
    gear, meas, equiv = (), (), ()
    snr = 0.0
    y = np.zeros(len(idx))
    speed_col = n[idx].copy()
    if comps:
        comps, sigma, snr, fac, order = _scale_effects(comps, rng, center=False)
        nuis.update(fac)
        y = y + sum(comps.values())
        gear = tuple(order)
        formulation = " + ".join(f"{e}:{forms[e]}" for e in order) + f"|{'sqrt-power' if profile == 'sqrt' else 'exp-approach'}-runup|duhamel-fft"
    else:
        sigma = 0.75 * m["accuracy"] / rng.uniform(4.0, 12.0)
        formulation = form
    comp = None
    if form == "eccentric-shrink-disc-hub":
        comp = np.sin(th[idx] / R + rng.uniform(0, 2 * np.pi))
        meas = ("encoder_eccentricity",)
    elif form == "drift-by-cumulative-revs":
        rev = (th[idx] - th[idx][0])
        comp = rev / rev[-1] * rng.choice([-1.0, 1.0])
        meas = ("thermal_drift",)
    elif form in ("resolver-1x-error", "resolver-2x-error"):
        k = 1 if "1x" in form else 2
        eps_r = rng.uniform(5.0, 10.0) / 60.0 * np.pi / 180.0  # +/-5-10 arc-min resolver accuracy
        e = -(eps_r / R) * np.sin(k * th + rng.uniform(0, 2 * np.pi))
        comp = respond(e)
        equiv = ("te_1x",) if k == 1 else ("te_2x",)
        nuis["resolver_error_rad"] = float(eps_r)
        kk = rng.uniform(4.0, 12.0)
        sigma = _rms(comp) / kk
        formulation = form + f"|{'sqrt-power' if profile == 'sqrt' else 'exp-approach'}-runup|duhamel-fft"
    if comp is not None:
        kk = rng.uniform(4.0, 12.0) if not equiv else _rms(comp) / sigma
        comp = comp * (kk * sigma / _rms(comp))
        y = y + comp
        snr = kk
    if form == "speed-in-rad-per-s":
        speed_col = speed_col * np.pi / 30.0
        meas = ("wrong_units",)
    noise = sigma * _unit_noise(rng, len(idx), form if category == "clean" else _noise_form(rng))
    cols = {"time_s": t[idx] - t[idx][0], "input_speed_rpm": speed_col, "output_vibration_rad": y + noise}
    return dict(kind="vibration", model=m["code"], columns=cols, load_inertia_kgm2=float(J), gear_effects=gear,
                measurement_effects=meas, nuisance=nuis, category=category, equivalent_effects=equiv,
                noise_rms=float(sigma), formulation=formulation if category != "clean" else f"noise:{form}",
                snr=float(snr))


# --------------------------------------------------------------------------- registry
CELLS = ([("torsion",) + c for c in TORSION_CELLS] + [("transmission",) + c for c in TRANSMISSION_CELLS]
         + [("efficiency",) + c for c in EFFICIENCY_CELLS] + [("vibration",) + c for c in VIBRATION_CELLS])
_BUILDERS = {"torsion": _torsion, "transmission": _transmission, "efficiency": _efficiency, "vibration": _vibration}


def _slug(s):
    return "".join(ch if ch.isalnum() else "-" for ch in s.lower()).strip("-").replace("--", "-")


def cell_id(cell):
    kind, category, effects, form, _ = cell
    eff = "+".join(effects) if effects else "none"
    return f"{kind}-{category}-{_slug(eff)}-{_slug(form)}"


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    cat = load_catalog(catalog_dir)
    rng = np.random.default_rng(seed)
    cases = []
    for cell in CELLS:
        kind = cell[0]
        for i in range(per_cell):
            d = _BUILDERS[kind](rng, cat, cell[1:])
            cases.append(TruthCase(name=f"{SUITE}-{cell_id(cell)}-{i:03d}", **d))
    return cases


# --------------------------------------------------------------------------- self-check
def _check_case(c: TruthCase, cat) -> list[str]:
    err = []
    if list(c.columns) != list(COLUMNS[c.kind]):
        err.append(f"{c.name}: columns {list(c.columns)}")
    n = {len(v) for v in c.columns.values()}
    if len(n) != 1:
        err.append(f"{c.name}: ragged columns")
    rows = n.pop()
    if not 10 <= rows <= ROW_LIMITS[c.kind]:
        err.append(f"{c.name}: rows {rows}")
    for k, v in c.columns.items():
        if not np.all(np.isfinite(v)):
            err.append(f"{c.name}: non-finite {k}")
    if c.category not in CATEGORIES:
        err.append(f"{c.name}: category")
    if any(e not in GEAR_EFFECTS[c.kind] for e in c.gear_effects + c.equivalent_effects):
        err.append(f"{c.name}: effect names")
    if any(e not in MEAS_EFFECTS for e in c.measurement_effects):
        err.append(f"{c.name}: measurement names")
    need = {"clean": 0, "single": 1, "pair": 2, "decoy_separable": 0, "decoy_equivalent": 0}[c.category]
    if len(c.gear_effects) != need or len(set(c.gear_effects)) != need:
        err.append(f"{c.name}: gear_effects {c.gear_effects}")
    if c.category == "decoy_equivalent" and not c.equivalent_effects:
        err.append(f"{c.name}: equivalent_effects empty")
    if c.category != "decoy_equivalent" and c.equivalent_effects:
        err.append(f"{c.name}: stray equivalent_effects")
    if c.category == "decoy_separable" and not c.measurement_effects:
        err.append(f"{c.name}: separable decoy without a measurement effect")
    if c.category in ("clean", "single", "pair") and c.measurement_effects:
        err.append(f"{c.name}: measurement effect in {c.category}")
    if (c.load_inertia_kgm2 is None) != (c.kind != "vibration"):
        err.append(f"{c.name}: load inertia")
    if c.kind == "vibration" and not c.load_inertia_kgm2 > 0:
        err.append(f"{c.name}: load inertia <= 0")
    if not (c.noise_rms > 0 and math.isfinite(c.noise_rms) and math.isfinite(c.snr)):
        err.append(f"{c.name}: noise/snr not finite")
    if c.category in ("single", "pair", "decoy_equivalent") and not 4.0 - 1e-9 <= c.snr <= 12.0 + 1e-9:
        err.append(f"{c.name}: snr {c.snr:.3f} outside [4, 12]")
    if c.category == "clean" and c.snr != 0.0:
        err.append(f"{c.name}: clean snr {c.snr}")
    if c.model not in {m["code"] for m in cat["models"]}:
        err.append(f"{c.name}: model {c.model}")
    if not all(math.isfinite(v) for v in c.nuisance.values()):
        err.append(f"{c.name}: nuisance")
    if c.kind in ("torsion", "vibration") and not 0.9 <= c.nuisance.get("stiffness_scale", 0) <= 1.1025 + 1e-12:
        err.append(f"{c.name}: stiffness scale")
    return err


def _same(a: list, b: list) -> bool:
    if [x.name for x in a] != [x.name for x in b]:
        return False
    for x, y in zip(a, b):
        if x.snr != y.snr or x.noise_rms != y.noise_rms or x.nuisance != y.nuisance:
            return False
        for k in x.columns:
            if not np.array_equal(x.columns[k], y.columns[k]):
                return False
    return True


def self_check(catalog_dir, seeds=range(24), per_cell=2) -> int:
    import tempfile
    cat = load_catalog(catalog_dir)
    print(f"suite {SUITE}: {len(CELLS)} cells")
    print(f"{'kind':13s} {'category':17s} {'effects':40s} formulation")
    for cell in CELLS:
        kind, category, effects, form, _ = cell
        print(f"{kind:13s} {category:17s} {'+'.join(effects) or '-':40s} {form}")
    per_kind = {}
    for cell in CELLS:
        per_kind[cell[0]] = per_kind.get(cell[0], 0) + 1
    print("cells per kind:", per_kind)
    errors, times, snrs = [], [], {}
    for sd in seeds:
        t0 = time.perf_counter()
        cases = generate_cases(sd, catalog_dir, per_cell=per_cell)
        times.append(time.perf_counter() - t0)
        names = [c.name for c in cases]
        if len(set(names)) != len(names):
            errors.append(f"seed {sd}: duplicate names")
        for c in cases:
            errors.extend(f"seed {sd}: {e}" for e in _check_case(c, cat))
            snrs.setdefault(c.category, []).append(c.snr)
        if sd < 3:
            again = generate_cases(sd, catalog_dir, per_cell=per_cell)
            if not _same(cases, again):
                errors.append(f"seed {sd}: not deterministic")
    other = generate_cases(1, catalog_dir, per_cell=per_cell)
    first = generate_cases(0, catalog_dir, per_cell=per_cell)
    if _same(first, other):
        errors.append("seeds 0 and 1 give identical data")
    with tempfile.TemporaryDirectory() as td:
        for c in first[:: max(1, len(first) // 12)]:
            p = Path(td) / f"{c.name}.csv"
            c.write_csv(p)
            with open(p) as fh:
                head = fh.readline().strip().split(",")
                nrows = sum(1 for _ in fh)
            if head != list(COLUMNS[c.kind]) or nrows != len(next(iter(c.columns.values()))):
                errors.append(f"write_csv {c.name}")
            back = np.loadtxt(p, delimiter=",", skiprows=1)
            if not np.array_equal(back, np.column_stack([c.columns[k] for k in head])):
                errors.append(f"write_csv round trip {c.name}")
    kinds = {}
    for c in first:
        kinds[c.kind] = kinds.get(c.kind, 0) + 1
    print(f"cases per kind (per_cell={per_cell}):", kinds, "total", len(first))
    print("snr by category: " + ", ".join(f"{k} [{min(v):.2f}, {max(v):.2f}]" for k, v in snrs.items()))
    print(f"generate_cases(per_cell={per_cell}) over {len(times)} seeds: mean {np.mean(times):.2f} s, "
          f"max {np.max(times):.2f} s")
    if max(times) > 6.0:
        errors.append(f"too slow: {max(times):.2f} s")
    for e in errors[:40]:
        print("FAIL", e)
    print("SELF-CHECK", "PASSED" if not errors else f"FAILED ({len(errors)} problems)")
    return 0 if not errors else 1


if __name__ == "__main__":
    cd = sys.argv[1] if len(sys.argv) > 1 else str(Path(__file__).resolve().parents[1] / "main" / "catalog")
    sys.exit(self_check(cd))
