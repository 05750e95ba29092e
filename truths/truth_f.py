"""Truth suite "f" for ``hdcad reconcile`` -- synthetic strain-wave-gear test data.

Written only from truths/CONTRACT.md, the catalog tables (catalog/*.csv), the catalog seed
texts (shared/seeds/) and the physics literature (see NOTES.md).  numpy + scipy only.

    generate_cases(seed, catalog_dir, per_cell=4) -> list[TruthCase]

Every cell is a (kind, category, effect-combination, formulation) combination; ``per_cell``
cases are drawn for each cell with one ``numpy.random.default_rng(seed)`` stream, so the same
seed always gives the same cases.

Conventions (details and references in NOTES.md):
* noise is added only to the measured column (twist_rad, output_angle_rad, efficiency_pct,
  output_vibration_rad); ``noise_rms`` is the RMS of the noise actually added, expressed in the
  column's nominal SI unit (for wrong_units cases: before the unit error);
* an effect's RMS is the RMS of its contribution = (data with the effect) - (same data without
  it), noise free; for transmission and efficiency the mean is removed first (a constant
  is the baseline's offset / level);
* single/decoy cases: effect RMS = k * noise_rms, k ~ U[4, 12]; pairs: each effect's k in
  [4, 12] and the combined RMS of both effects also in [4, 12]; ``snr`` is the combined RMS /
  noise_rms (for a single effect that is its own k).  Unit errors (wrong_units) cannot be
  scaled: their actual (large) ratio is recorded.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import optimize, signal

SUITE = "f"

KINDS = ("torsion", "transmission", "efficiency", "vibration")
CATEGORIES = ("clean", "single", "pair", "decoy_separable", "decoy_equivalent")
DEG = 180.0 / math.pi


# ----------------------------------------------------------------------------------------------
# the case record
# ----------------------------------------------------------------------------------------------
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
        """Header row + one row per sample, floats in repr precision."""
        names = list(self.columns)
        cols = [np.asarray(self.columns[c], dtype=float).tolist() for c in names]
        with open(path, "w", newline="") as fh:
            fh.write(",".join(names) + "\n")
            for row in zip(*cols):
                fh.write(",".join(repr(float(v)) for v in row) + "\n")


# ----------------------------------------------------------------------------------------------
# catalog
# ----------------------------------------------------------------------------------------------
@dataclass
class _Model:
    code: str
    series: str
    size: int
    ratio: int
    TR: float          # rated torque at 2000 r/min input [N m]
    T1: float
    T2: float
    K1: float
    K2: float
    K3: float
    backlash: float    # rad
    hyst: float        # rad (hysteresis loss B-B')
    accuracy: float    # rad (angular transmission accuracy; 2.9e-4 when not tabulated)
    run_torque_in: float  # no-load running torque at the input [N m]
    max_speed: float   # max input speed [r/min]


def _f(x):
    x = (x or "").strip()
    return float(x) if x else None


def _read(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _load_models(catalog_dir) -> list[_Model]:
    d = Path(catalog_dir)
    ratings = _read(d / "gh_ratings_050-1_058-1.csv")
    stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
    back = _read(d / "gh_backlash_052-2_060-2.csv")
    hyst = _read(d / "gh_hysteresis_052_060.csv")
    perf = _read(d / "gh_performance_051-1_059-1.csv")

    def ratio_ok(row, ratio):
        rmin, rmax = _f(row["ratio_min"]), _f(row["ratio_max"])
        if rmax is not None:
            return rmin <= ratio <= rmax
        return ratio >= rmin

    models = []
    for r in ratings:
        series, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
        st = [s for s in stiff if s["series"] == series and int(s["size"]) == size
              and ratio_ok(s, ratio)]
        bl = [b for b in back if b["series"] == series and int(b["size"]) == size
              and int(b["ratio"]) == ratio]
        hy = [h for h in hyst if h["series"] == series and ratio_ok(h, ratio)]
        pf = [p for p in perf if p["series"] == series and int(p["size"]) == size
              and int(p["ratio"]) == ratio]
        if not (st and bl and hy):
            continue
        s = st[0]
        acc = None
        run = None
        for p in pf:
            if acc is None and _f(p["accuracy_rad"]) is not None:
                acc = _f(p["accuracy_rad"])
            if run is None and _f(p["running_torque_cNm"]) is not None:
                run = _f(p["running_torque_cNm"]) / 100.0
        prefix = series.split("-")[0]
        models.append(_Model(
            code=f"{prefix}-{size}-{ratio}-GH", series=series, size=size, ratio=ratio,
            TR=_f(r["rated_torque_2000_Nm"]), T1=_f(s["T1_Nm"]), T2=_f(s["T2_Nm"]),
            K1=_f(s["K1_Nm_per_rad"]), K2=_f(s["K2_Nm_per_rad"]), K3=_f(s["K3_Nm_per_rad"]),
            backlash=_f(bl[0]["backlash_rad"]), hyst=_f(hy[0]["hysteresis_rad"]),
            accuracy=acc if acc is not None else 2.9e-4,
            run_torque_in=run if run is not None else 0.1,
            max_speed=_f(r["max_input_speed_rpm"])))
    if not models:
        raise RuntimeError("no usable catalog models found in %s" % d)
    return models


def _twist_cat(T, m: _Model, s=1.0):
    """Catalog three-segment twist curve (odd in T); all spring constants x s."""
    T = np.asarray(T, dtype=float)
    a = np.abs(T)
    K1, K2, K3 = m.K1 * s, m.K2 * s, m.K3 * s
    th1 = m.T1 / K1
    th2 = th1 + (m.T2 - m.T1) / K2
    th = np.where(a <= m.T1, a / K1,
                  np.where(a <= m.T2, th1 + (a - m.T1) / K2, th2 + (a - m.T2) / K3))
    return np.sign(T) * th


# ----------------------------------------------------------------------------------------------
# small helpers
# ----------------------------------------------------------------------------------------------
def _rms(x):
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def _rms0(x):
    """RMS after removing the mean (a constant is absorbed by offset / level)."""
    x = np.asarray(x, dtype=float)
    return _rms(x - x.mean())


def _u(rng, a, b):
    return float(rng.uniform(a, b))


def _pm(rng):
    return 1.0 if rng.random() < 0.5 else -1.0


def _noise(rng, n, rms, kind="white"):
    """Noise with empirical RMS exactly ``rms``.  Returns (noise, description)."""
    if kind == "auto":
        kind = "white" if rng.random() < 0.5 else "ar1"
    if kind == "white":
        w = rng.standard_normal(n)
        desc = "white"
    elif kind == "ar1":
        phi = _u(rng, 0.3, 0.8)
        e = rng.standard_normal(n)
        e[0] /= math.sqrt(1.0 - phi * phi)
        w = signal.lfilter([1.0], [1.0, -phi], e)
        desc = "ar1 phi=%.2f" % phi
    elif kind == "laplace":
        w = rng.laplace(size=n)
        desc = "laplace"
    elif kind == "student_t":
        nu = _u(rng, 3.0, 6.0)
        w = rng.standard_t(nu, size=n)
        desc = "student-t nu=%.1f" % nu
    else:
        raise ValueError(kind)
    w *= rms / _rms(w)
    return w, desc


def _add_outliers(rng, w, base_rms):
    n = w.size
    k = max(1, int(round(0.005 * n)))
    idx = rng.choice(n, size=k, replace=False)
    w = w.copy()
    w[idx] += np.array([_pm(rng) * _u(rng, 8.0, 15.0) for _ in range(k)]) * base_rms
    return w


def _clean_noise(rng, y, rms, kind, quant_step=None):
    """Noise for clean cases.  Returns (measured, actual noise rms, formulation)."""
    n = y.size
    if kind == "quantised":
        dither, _ = _noise(rng, n, quant_step * _u(rng, 0.15, 0.4), "white")
        meas = quant_step * np.round((y + dither) / quant_step)
        return meas, _rms(meas - y), "quantised q=%.3g" % quant_step
    if kind == "outliers":
        base = "white" if rng.random() < 0.5 else "ar1"
        w, desc = _noise(rng, n, rms, base)
        w = _add_outliers(rng, w, rms)
        return y + w, _rms(w), desc + " + 0.5% outliers 8-15x"
    w, desc = _noise(rng, n, rms, kind)
    return y + w, _rms(w), desc


def _pair_ks(rng, u1, u2):
    """Draw k1, k2 in [4, 12] such that the combined RMS of k1*u1 + k2*u2 (u1, u2 unit-RMS
    contributions) is also in [4, 12]."""
    for _ in range(200):
        k1, k2 = _u(rng, 4.2, 11.0), _u(rng, 4.2, 11.0)
        kc = _rms(k1 * u1 + k2 * u2)
        if 4.2 <= kc <= 11.8:
            return k1, k2, kc
    k1 = k2 = 4.5
    return k1, k2, _rms(k1 * u1 + k2 * u2)


def _pair_noise(rng, zz, scal, rmsf, ratio_range=(0.4, 2.5)):
    """Noise level for two physical contributions zz[0], zz[1] such that each effect's RMS and
    their combined RMS are 4.2..11.8 x noise.  Contribution ``scal`` is rescaled first when
    its RMS ratio to the other one lies outside ``ratio_range`` (then a ratio is drawn
    log-uniformly inside it)."""
    zz = [np.asarray(z, dtype=float).copy() for z in zz]
    other = 1 - scal
    lr = (math.log(ratio_range[0]), math.log(ratio_range[1]))
    rho = rmsf(zz[scal]) / rmsf(zz[other])
    if not (ratio_range[0] <= rho <= ratio_range[1]):
        zz[scal] *= math.exp(_u(rng, *lr)) / rho
    for attempt in range(20):
        r = [rmsf(zz[0]), rmsf(zz[1]), rmsf(zz[0] + zz[1])]
        lo, hi = max(r) / 11.8, min(r) / 4.2
        if lo < hi:
            return math.exp(_u(rng, math.log(lo), math.log(hi))), zz
        zz[scal] *= math.exp(_u(rng, *lr)) * rmsf(zz[other]) / rmsf(zz[scal])
    raise RuntimeError("pair scaling failed")


def _mkname(kind, category, combo, formulation, idx):
    slug = "".join(c if (c.isalnum() or c in "+_") else "-" for c in formulation.lower())
    while "--" in slug:
        slug = slug.replace("--", "-")
    return f"{SUITE}-{kind}-{category}-{combo}-{slug.strip('-')}-{idx:03d}"


# ----------------------------------------------------------------------------------------------
# TORSION
# ----------------------------------------------------------------------------------------------
@dataclass
class _TorsionProto:
    T: np.ndarray        # sampled torque (time order)
    t: np.ndarray        # test time [s]
    Tf: np.ndarray       # fine-grid torque (includes samples and turning points)
    idx: np.ndarray      # indices of the samples in the fine grid
    T0: float
    ncyc: int
    minor: bool


def _torsion_protocol(rng, m: _Model) -> _TorsionProto:
    T0 = _u(rng, 0.5, 1.2) * m.TR
    ncyc = int(rng.integers(1, 5))
    minor = bool(rng.random() < 0.4)
    pts = [0.0, T0]
    for _ in range(ncyc):
        for target in (-T0, T0):
            if minor and rng.random() < 0.6:
                cur = pts[-1]
                u1 = cur + _u(rng, 0.45, 0.85) * (target - cur)
                u2 = u1 - _u(rng, 0.12, 0.35) * (target - cur)
                pts += [u1, u2]
            pts.append(target)
    if rng.random() < 0.5:
        pts.append(0.0)
    pts = np.array(pts)
    P = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(pts)))])
    L = P[-1]
    n = int(rng.integers(350, 1400))
    inc = rng.gamma(_u(rng, 0.7, 3.0), 1.0, size=n - 1)
    p = np.concatenate([[0.0], np.cumsum(inc)])
    p *= L / p[-1]
    p[-1] = L
    grid = np.linspace(0.0, L, int(math.ceil(L / (T0 / 250.0))) + 1)
    pf = np.unique(np.concatenate([grid, P, p]))
    Tf = np.interp(pf, P, pts)
    idx = np.searchsorted(pf, p)
    rate = _u(rng, 0.01, 0.05) * T0          # N m / s
    t = p / rate
    return _TorsionProto(T=Tf[idx], t=t, Tf=Tf, idx=idx, T0=T0, ncyc=ncyc, minor=minor)


def _std_loop(n_per_half=400):
    """Normalised standard protocol 0 -> 1 -> -1 -> 1 -> -1 (u = T/T_R)."""
    seg = [np.linspace(0, 1, n_per_half // 2 + 1)]
    for a, b in ((1, -1), (-1, 1), (1, -1)):
        seg.append(np.linspace(a, b, n_per_half + 1)[1:])
    u = np.concatenate(seg)
    return u


def _loop_metrics(u, w):
    """Width at u = 0 (descending minus ascending, last cycle) and tip secant slope."""
    # locate last three branches from the known construction
    half = (u.size - 1) // 7 * 2  # n_per_half
    i0 = half // 2                # index of first tip (+1)
    a1 = slice(i0 + half, i0 + 2 * half + 1)  # -1 -> +1
    d2 = slice(i0 + 2 * half, i0 + 3 * half + 1)
    ua, wa = u[a1], w[a1]
    ud, wd = u[d2][::-1], w[d2][::-1]
    w_asc0 = np.interp(0.0, ua, wa)
    w_desc0 = np.interp(0.0, ud, wd)
    tip_p = w[i0 + 2 * half]
    tip_m = w[i0 + 3 * half]
    return w_desc0 - w_asc0, (tip_p - tip_m) / 2.0


def _integrate_ri(u, rhs, w0=0.0, state0=None):
    """Integrate a rate-independent model dw/du = rhs(u, w, s, st) along the (fine) input path
    u with RK4 per step; s = sign(du) is constant within a step.  ``st`` is a small mutable
    dict for slow states (updated once per step by rhs with key '_post')."""
    w = np.empty_like(u)
    w[0] = w0
    st = {} if state0 is None else dict(state0)
    wi = w0
    for i in range(1, u.size):
        du = u[i] - u[i - 1]
        if du == 0.0:
            w[i] = wi
            continue
        s = 1.0 if du > 0 else -1.0
        ua = u[i - 1]
        k1 = rhs(ua, wi, s, st)
        k2 = rhs(ua + 0.5 * du, wi + 0.5 * du * k1, s, st)
        k3 = rhs(ua + 0.5 * du, wi + 0.5 * du * k2, s, st)
        k4 = rhs(ua + du, wi + du * k3, s, st)
        wn = wi + du * (k1 + 2 * k2 + 2 * k3 + k4) / 6.0
        post = st.get("_post")
        if post is not None:
            post(ua, wi, u[i], wn, s, st)
        wi = wn
        w[i] = wi
    return w


# ---- hysteresis operators (input u = T/T_R on the fine grid, output in "model units") -------
def _hyst_rayleigh(u, p):
    """Rayleigh quadratic loop with Masing branches and Madelung memory (wiping out)."""
    eta = 1.0
    w = np.empty_like(u)
    stack = []          # reversal points (u_r, w_r)
    d = 0.0
    virgin = lambda x: math.copysign(eta * x * x, x)
    w[0] = virgin(u[0])
    for i in range(1, u.size):
        du = u[i] - u[i - 1]
        if du == 0.0:
            w[i] = w[i - 1]
            continue
        nd = 1.0 if du > 0 else -1.0
        if d != 0.0 and nd != d:
            stack.append((u[i - 1], w[i - 1]))
        d = nd
        x = u[i]
        while len(stack) >= 2 and (x - stack[-2][0]) * d >= 0.0:
            stack.pop()
            stack.pop()
        if len(stack) == 1 and (x + stack[0][0]) * d >= 0.0 and abs(x) >= abs(stack[0][0]):
            stack.pop()
        if not stack:
            w[i] = virgin(x)
        else:
            ur, wr = stack[-1]
            w[i] = wr + d * 0.5 * eta * (x - ur) ** 2
    return w


def _hyst_valanis(u, p):
    """Valanis endochronic model (force-like orientation)."""
    E0, Et, kap, lam = 1.0, p["Et"], p["kappa"], p["lam"]
    a = lam / E0

    def rhs(x, w, s, st):
        xi = s * (Et * x - w)
        return E0 * (1.0 + a * xi) / (1.0 + kap * a * xi)
    return _integrate_ri(u, rhs)


def _hyst_bw_asym(u, p):
    """Asymmetric (Song & Der Kiureghian) Bouc-Wen with Baber-Wen degradation."""
    A, n, beta, gamma, b6 = 1.0, p["n"], p["beta"], p["gamma"], p["beta6"]
    dnu, deta, eref = p["dnu"], p["deta"], p["eref"]
    st0 = {"eps": 0.0}

    def rhs(x, w, s, st):
        e = st["eps"] / eref
        nu = 1.0 + dnu * e
        et = 1.0 + deta * e
        sw = 1.0 if s * w >= 0 else -1.0
        sx = 1.0 if x >= 0 else -1.0
        return (A - nu * abs(w) ** n * (beta * sw + gamma + b6 * sx)) / et

    def post(ua, wa, ub, wb, s, st):
        st["eps"] += 0.5 * (abs(wa) + abs(wb)) * abs(ub - ua)
    st0["_post"] = post
    return _integrate_ri(u, rhs, state0=st0)


def _hyst_duhem(u, p):
    """Rate-independent Duhem model with amplitude-dependent loop height:
    dw = lam |du| (-s h(A_r) - w),  h = (A_r)^p, A_r = half of the last half-cycle excursion."""
    lam, pw = p["lam"], p["p"]
    w = np.empty_like(u)
    w[0] = 0.0
    d = 0.0
    rev = [0.0, 0.0]     # previous and last reversal inputs
    h = 0.0
    wi = 0.0
    for i in range(1, u.size):
        du = u[i] - u[i - 1]
        if du == 0.0:
            w[i] = wi
            continue
        nd = 1.0 if du > 0 else -1.0
        if d != 0.0 and nd != d:
            rev = [rev[1], u[i - 1]]
            h = (0.5 * abs(rev[1] - rev[0])) ** pw
        elif d == 0.0:
            h = 0.0
        d = nd
        target = -d * h
        # exact solution of dw/d|u| = lam (target - w) over the step
        wi = target + (wi - target) * math.exp(-lam * abs(du))
        w[i] = wi
    return w


_HYST = {
    "rayleigh-masing": (_hyst_rayleigh, +1.0, True),   # (operator, orientation, anchor)
    "valanis-endochronic": (_hyst_valanis, -1.0, True),
    "bouc-wen-asym-degrading": (_hyst_bw_asym, -1.0, True),
    "duhem-ampdep": (_hyst_duhem, +1.0, False),
}


def _hyst_params(rng, form):
    if form == "rayleigh-masing":
        return {}
    if form == "valanis-endochronic":
        return {"Et": _u(rng, 0.12, 0.4), "kappa": _u(rng, 0.0, 0.6), "lam": _u(rng, 2.5, 8.0)}
    if form == "bouc-wen-asym-degrading":
        n = _u(rng, 1.0, 2.0)
        wsat = _u(rng, 0.3, 0.6)
        tot = 1.0 / wsat ** n
        f = _u(rng, 0.55, 0.8)
        return {"n": n, "beta": f * tot, "gamma": (1 - f) * tot,
                "beta6": _pm(rng) * _u(rng, 0.1, 0.25) * tot,
                "dnu": _u(rng, 0.01, 0.03), "deta": _u(rng, 0.01, 0.03), "eref": 4.0 * wsat}
    if form in ("duhem-ampdep", "rig-lock-duhem"):
        if form == "rig-lock-duhem":
            return {"lam": _u(rng, 3.0, 6.0), "p": _u(rng, 1.6, 2.4)}
        return {"lam": _u(rng, 2.0, 4.0), "p": _u(rng, 1.0, 1.8)}
    raise ValueError(form)


def _cat_slope(T, m: _Model, s=1.0):
    """Local catalog compliance d(theta)/dT (1/K1, 1/K2 or 1/K3)."""
    a = np.abs(T)
    return np.where(a <= m.T1, 1.0 / (m.K1 * s),
                    np.where(a <= m.T2, 1.0 / (m.K2 * s), 1.0 / (m.K3 * s)))


def _hysteresis_contrib(rng, proto: _TorsionProto, m: _Model, form, H_target):
    """Twist contribution (rad) on the sample points; loop width at zero torque after a
    rated-torque loop equals H_target.  Loops of the anchored models pass through the
    catalog curve at the loop tips.  Guard: the loaded/unloaded branches stay monotone --
    the apparent stiffness right after a reversal may be at most 4x the catalog value;
    otherwise the model's transition is made smoother (or, last resort, H is reduced)."""
    op_name = "duhem-ampdep" if form == "rig-lock-duhem" else form
    op, orient, anchor = _HYST[op_name]
    p = _hyst_params(rng, form)
    us = _std_loop()
    uf = proto.Tf / m.TR
    dT = np.diff(proto.Tf)
    ok = dT != 0.0
    slope_cat = _cat_slope(0.5 * (proto.Tf[1:] + proto.Tf[:-1]), m)[ok]
    H = H_target
    for attempt in range(40):
        ws = orient * op(us, p)
        width, c = _loop_metrics(us, ws)
        if not anchor:
            c = 0.0
        wf = orient * op(uf, p) - c * uf
        zf = (H / width) * wf
        ratio = (np.diff(zf)[ok] / dT[ok]) / slope_cat
        if ratio.min() >= -0.75:
            break
        if op_name in ("valanis-endochronic", "duhem-ampdep") and attempt < 8:
            p["lam"] *= 0.75
        else:
            H *= 0.85
    desc = form
    if form == "valanis-endochronic":
        desc += " (Et=%.2f kappa=%.2f lambda=%.2f" % (p["Et"], p["kappa"], p["lam"])
    elif form == "bouc-wen-asym-degrading":
        desc += " (n=%.2f beta=%.2f gamma=%.2f beta6=%.2f" % (p["n"], p["beta"], p["gamma"], p["beta6"])
    elif op_name == "duhem-ampdep":
        desc += " (lambda=%.2f p=%.2f" % (p["lam"], p["p"])
    else:
        desc += " ("
    desc += "%sH=%.3g rad)" % ("" if desc.endswith("(") else ", ", H)
    return zf[proto.idx], desc


# ---- backlash operators ---------------------------------------------------------------------
def _backlash_contrib(rng, proto: _TorsionProto, m: _Model, form, b):
    """Twist contribution of a play of total clearance b (rad)."""
    T = proto.Tf
    TR = m.TR
    if form == "asym-clearance-quadratic":
        a = _pm(rng) * _u(rng, 0.2, 0.5)
        bp, bm = 0.5 * b * (1 + a), 0.5 * b * (1 - a)
        Te = _u(rng, 0.01, 0.04) * TR
        x = np.clip(np.abs(T) / Te, 0, 1)
        q = x * (2.0 - x)
        z = np.where(T >= 0, bp * q, -bm * q)
        desc = "%s (b+=%.3g b-=%.3g rad, Te=%.3g Nm)" % (form, bp, bm, Te)
    elif form == "hertz32-closing":
        Te = _u(rng, 0.01, 0.05) * TR
        z = np.sign(T) * 0.5 * b * np.minimum(1.0, (np.abs(T) / Te) ** (2.0 / 3.0))
        desc = "%s (b=%.3g rad, Te=%.3g Nm)" % (form, b, Te)
    elif form == "karnopp-stiction-play":
        Ts = _u(rng, 0.005, 0.03) * TR
        z = np.empty_like(T)
        pos = 0.0
        for i, Ti in enumerate(T):
            if Ti >= Ts:
                pos = 0.5 * b
            elif Ti <= -Ts:
                pos = -0.5 * b
            z[i] = pos
        desc = "%s (b=%.3g rad, breakaway=%.3g Nm)" % (form, b, Ts)
    elif form == "rig-coupling-play":
        Te = _u(rng, 0.005, 0.03) * TR
        z = np.sign(T) * 0.5 * b * np.minimum(1.0, np.abs(T) / Te)
        desc = "%s (b=%.3g rad, linear closing over %.3g Nm)" % (form, b, Te)
    else:
        raise ValueError(form)
    return z[proto.idx], desc


# ---- housing compliance ---------------------------------------------------------------------
def _housing_contrib(rng, proto: _TorsionProto, m: _Model, form, s):
    T = proto.T
    Ksec = proto.T0 / float(_twist_cat(proto.T0, m, s))
    r = _u(rng, 0.15, 0.45)               # extra compliance / gear secant compliance at T0
    c = r / Ksec
    if form == "softening-bolted-joint":
        a = _u(rng, 0.1, 0.3)
        z = c * T * (1.0 + a * np.abs(T) / m.TR) / (1.0 + a * proto.T0 / m.TR)
        desc = "%s (Kh=%.4g Nm/rad, a=%.2f)" % (form, 1 / c, a)
    elif form == "shaft-plus-flange":
        # Saint-Venant hollow shaft + linear flange-contact compliance, in series
        fs = _u(rng, 0.4, 0.8)
        G = 79.3e9
        Do = _u(rng, 1.0, 1.4) * m.size * 2.54e-3 * 0.5   # output shaft diameter ~ half pitch dia.
        Di = _u(rng, 0.0, 0.5) * Do
        Jp = math.pi * (Do ** 4 - Di ** 4) / 32.0
        Ls = fs * c * G * Jp                                 # shaft length giving fs of the compliance
        z = c * T
        desc = "%s (Kh=%.4g Nm/rad; shaft D=%.0f mm L=%.0f mm carries %.0f%%)" % (
            form, 1 / c, Do * 1e3, Ls * 1e3, 100 * fs)
    elif form == "soft-gear":
        z = c * T
        desc = "%s (extra compliance %.3g rad/Nm in every segment)" % (form, c)
    else:
        raise ValueError(form)
    return z, desc, c


def _torsion_case(rng, m, category, effects, form, idx, combo, variant=None):
    proto = _torsion_protocol(rng, m)
    T = proto.T
    nuis = {}
    if category == "clean":
        s = _u(rng, 0.9, 1.1)
    elif variant == "stiffness_scale":
        s = 1.0 + _pm(rng) * _u(rng, 0.05, 0.10)
    else:
        s = _u(rng, 0.93, 1.07)
    nuis["stiffness_scale"] = s
    base = _twist_cat(T, m, s)
    thmax = float(np.max(np.abs(base)))
    meas_eff, gear_eff, equiv = (), tuple(effects), ()
    torque_col = T.copy()
    formulation = form
    unit_factor = 1.0

    if category == "clean":
        rms = thmax * _u(rng, 0.002, 0.01)
        q = None
        if form == "quantised":
            bits = int(round(math.log2(2 * math.pi / (thmax * _u(rng, 0.002, 0.008)))))
            q = 2 * math.pi / 2 ** bits
        meas, nrms, formulation = _clean_noise(rng, base, rms, form, q)
        if form == "quantised":
            formulation = "quantised %d-bit encoder (q=%.3g rad)" % (bits, q)
        return _finish("torsion", category, combo, formulation, idx, m,
                       {"torque_Nm": torque_col, "twist_rad": meas}, None, (), (), nuis,
                       (), nrms, 0.0, name_form=form)

    contribs = []     # list of (contribution array, description)
    sizes = []
    if category in ("single", "pair"):
        forms = form.split("+")
        for eff, fm in zip(effects, forms):
            if eff == "hysteresis":
                H = m.hyst * _u(rng, 0.6, 1.5)
                z, d = _hysteresis_contrib(rng, proto, m, fm, H)
                sizes.append(None)
            elif eff == "backlash":
                b = m.backlash * (_u(rng, 1.5, 3.0) if category == "pair" else _u(rng, 0.8, 2.5))
                z, d = _backlash_contrib(rng, proto, m, fm, b)
                sizes.append(("b", b))
            elif eff == "housing_compliance":
                z, d, ch = _housing_contrib(rng, proto, m, fm, s)
                sizes.append(("Kh", 1.0 / ch))
            contribs.append((z, d))
        formulation = " + ".join(d for _, d in contribs)
    elif category == "decoy_equivalent":
        eq = effects[0]
        gear_eff = ()
        equiv = (eq,)
        if form == "soft-gear":
            z, d, c = _housing_contrib(rng, proto, m, form, s)
            nuis["gear_extra_compliance_rad_per_Nm"] = c
        elif form == "rig-coupling-play":
            z, d = _backlash_contrib(rng, proto, m, form, m.backlash * _u(rng, 1.0, 3.0))
        elif form == "rig-lock-duhem":
            z, d = _hysteresis_contrib(rng, proto, m, form, m.hyst * _u(rng, 0.6, 1.5))
        contribs.append((z, d))
        formulation = d
    elif category == "decoy_separable":
        gear_eff = ()
        if variant == "stiffness_scale":
            # fixed 2026-11-26 after the blind score: ``base`` already carries s, so adding
            # base - catalog applied the scale twice (the data were 15-17 % softer while the
            # case says "inside the spread"); the reference is now the catalog curve itself
            z = base - _twist_cat(T, m, 1.0)
            base = _twist_cat(T, m, 1.0)
            d = "stiffness scale %.3f (inside the catalog's +-10 %% spread)" % s
        elif variant == "sensor_gain":
            g = 1.0 + _pm(rng) * _u(rng, 0.03, 0.08)
            torque_col = g * T
            z = base - _twist_cat(torque_col, m, s)      # twist difference at the measured torque
            meas_eff = ("sensor_gain",)
            nuis["torque_sensor_gain"] = g
            d = "torque-sensor gain %.4f" % g
        elif variant == "angle_offset_const":
            z = np.full_like(T, _pm(rng) * 1.0)
            meas_eff = ("angle_offset",)
            d = "constant twist offset"
        elif variant == "angle_offset_step":
            f = _u(rng, 0.3, 0.7)
            z = np.where(proto.t >= f * proto.t[-1], _pm(rng), 0.0)
            meas_eff = ("angle_offset",)
            d = "twist offset step at %.0f %% of the test" % (100 * f)
        elif variant == "thermal_drift_linear":
            z = _pm(rng) * proto.t / proto.t[-1]
            meas_eff = ("thermal_drift",)
            d = "linear thermal drift of the twist"
        elif variant == "thermal_drift_warmup":
            tw, tau = _u(rng, 0.2, 0.5) * proto.t[-1], _u(rng, 0.08, 0.2) * proto.t[-1]
            lg = 1.0 / (1.0 + np.exp(-(proto.t - tw) / tau))
            z = _pm(rng) * (lg - lg[0])
            meas_eff = ("thermal_drift",)
            d = "warm-up (logistic) thermal drift, t_w=%.0f s tau=%.0f s" % (tw, tau)
        elif variant in ("wrong_units_deg", "wrong_units_kNm"):
            meas_eff = ("wrong_units",)
            z = None
        else:
            raise ValueError(variant)
        if z is not None:
            contribs.append((z, d))
            formulation = d
    # ---- noise & scaling
    if category == "pair":
        (z1, _), (z2, _) = contribs
        # hysteresis is never rescaled (its size is limited by the monotonicity guard);
        # hysteresis+backlash: the play is rescaled; pairs with housing_compliance: the
        # housing spring is rescaled (kept clearly larger than the play / the loop)
        if effects == ("hysteresis", "backlash"):
            scal, rr = 1, (0.35, 0.9)
        elif effects == ("hysteresis", "housing_compliance"):
            scal, rr = 1, (1.2, 2.8)
        else:  # backlash + housing_compliance
            scal, rr = 1, (1.6, 2.8)
        zz = [z1, z2]
        nrms, zz = _pair_noise(rng, zz, scal, _rms, rr)
        total = zz[0] + zz[1]
        snr = _rms(total) / nrms
        kinfo = " [k: %s=%.2f, %s=%.2f]" % (effects[0], _rms(zz[0]) / nrms,
                                            effects[1], _rms(zz[1]) / nrms)
        fac = _rms(zz[1]) / _rms(z2)
        if abs(fac - 1.0) > 1e-9:
            key, val = sizes[1]
            val = val * fac if key == "b" else val / fac
            formulation += " [%s rescaled x%.3g: %s=%.4g %s]" % (
                effects[1], fac, key, val, "rad" if key == "b" else "Nm/rad")
        formulation += kinfo
    elif contribs:
        z = contribs[0][0]
        k = _u(rng, 4.0, 12.0)
        if variant in ("angle_offset_const", "angle_offset_step", "thermal_drift_linear",
                       "thermal_drift_warmup"):
            # these decoys are scaled to the noise: choose noise from the twist range
            nrms = thmax * _u(rng, 0.002, 0.01)
            z = z / _rms(z) * k * nrms
        else:
            nrms = _rms(z) / k
        total = z
        snr = _rms(total) / nrms
    else:  # wrong units
        nrms = thmax * _u(rng, 0.002, 0.01)
        total = np.zeros_like(T)
        snr = 0.0
    w, _ = _noise(rng, T.size, nrms, "auto")
    twist = base + total + w
    if variant == "wrong_units_deg":
        twist_out = twist * DEG
        snr = _rms(twist_out - twist) / nrms
        formulation = "twist column in degrees (x57.2958)"
        return _finish("torsion", category, combo, formulation, idx, m,
                       {"torque_Nm": torque_col, "twist_rad": twist_out}, None, gear_eff,
                       meas_eff, nuis, equiv, nrms, snr, name_form=form)
    if variant == "wrong_units_kNm":
        torque_col = T * 1e-3
        snr = _rms(base - _twist_cat(torque_col, m, s)) / nrms
        formulation = "torque column in kN m (x1e-3)"
    return _finish("torsion", category, combo, formulation, idx, m,
                   {"torque_Nm": torque_col, "twist_rad": twist}, None, gear_eff, meas_eff,
                   nuis, equiv, nrms, snr, name_form=form)


def _finish(kind, category, combo, formulation, idx, m, columns, J, gear, meas, nuis, equiv,
            nrms, snr, name_form=None):
    nf = name_form if name_form is not None else formulation.split(" (")[0]
    return TruthCase(name=_mkname(kind, category, combo, nf, idx),
                     kind=kind, model=m.code, columns=columns, load_inertia_kgm2=J,
                     gear_effects=tuple(gear), measurement_effects=tuple(meas),
                     nuisance=dict(nuis), category=category, equivalent_effects=tuple(equiv),
                     noise_rms=float(nrms), formulation=formulation, snr=float(snr))


# ----------------------------------------------------------------------------------------------
# TRANSMISSION
# ----------------------------------------------------------------------------------------------
def _te_signal(rng, form, k, phi, t, th_out, A):
    """Transmission error at k cycles per input revolution, RMS-normalisable."""
    psi = _u(rng, 0, 2 * math.pi)
    if form == "harmonic-series":
        e = np.sin(k * phi + psi)
        parts = []
        for m_ in ((3, 5) if k == 1 else (4, 6)):
            a = _u(rng, 0.05, 0.2)
            e = e + a * np.sin(m_ * phi + _u(rng, 0, 2 * math.pi))
            parts.append("%dx:%.2f" % (m_, a))
        d = "harmonic-series (%s)" % ", ".join(parts)
    elif form == "thermal-phase-drift":
        dpsi = _pm(rng) * _u(rng, 0.3, 1.0)
        tau = _u(rng, 0.2, 0.8) * t[-1]
        e = np.sin(k * phi + psi + dpsi * (1 - np.exp(-t / tau)))
        d = "thermal-phase-drift (dpsi=%.2f rad, tau=%.3g s)" % (dpsi, tau)
    elif form == "output-angle-modulated":
        j = int(rng.integers(1, 3))
        mm = _u(rng, 0.2, 0.5)
        chi = _u(rng, 0, 2 * math.pi)
        e = (1 + mm * np.sin(j * th_out + chi)) * np.sin(k * phi + psi)
        d = "output-angle-modulated (m=%.2f, %dx per output rev)" % (mm, j)
    else:
        raise ValueError(form)
    e = e - e.mean()
    return A * e / _rms(e) * (1 / math.sqrt(2)), d


def _transmission_case(rng, m, category, effects, form, idx, combo, variant=None):
    R = m.ratio
    nrev = _u(rng, 3.0, 10.0)
    spr = int(rng.choice([64, 90, 128, 180, 256, 360, 512, 720]))
    N = int(nrev * spr) + 1
    phi0 = _u(rng, 0, 2 * math.pi)
    phi = phi0 + np.linspace(0.0, nrev * 2 * math.pi, N)
    n_in = float(rng.choice([30, 60, 120, 300, 600]))
    t = (phi - phi0) / (2 * math.pi * n_in / 60.0)
    off = _u(rng, -0.5, 0.5)
    base = phi / R + off
    th_out = base
    nuis = {"output_offset_rad": off}
    acc = m.accuracy
    gear_eff, meas_eff, equiv = tuple(effects), (), ()
    in_col = phi.copy()
    if category == "clean":
        rms = _u(rng, 2e-6, 2e-5)
        q = None
        if form == "quantised":
            bits = int(rng.integers(16, 19))
            q = 2 * math.pi / 2 ** bits
        meas, nrms, formulation = _clean_noise(rng, base, rms, form, q)
        if form == "quantised":
            formulation = "quantised %d-bit output encoder (q=%.3g rad)" % (bits, q)
        return _finish("transmission", category, combo, formulation, idx, m,
                       {"input_angle_rad": in_col, "output_angle_rad": meas}, None, (), (),
                       nuis, (), nrms, 0.0, name_form=form)
    contribs = []
    if category in ("single", "pair"):
        forms = form.split("+")
        for eff, fm in zip(effects, forms):
            k = 1 if eff == "te_1x" else 2
            A = acc * _u(rng, 0.15, 0.5)
            e, d = _te_signal(rng, fm, k, phi, t, th_out, A)
            contribs.append((e, "%s: %s" % (eff, d)))
        formulation = " + ".join(d for _, d in contribs)
    elif category == "decoy_equivalent":
        gear_eff = ()
        k = 1 if effects[0] == "te_1x" else 2
        equiv = (effects[0],)
        # input-encoder error (rad at the input shaft), e.g. disc eccentricity / ellipticity
        a_in = _u(rng, 2e-4, 2e-3)
        psi = _u(rng, 0, 2 * math.pi)
        err_in = a_in * np.sin(k * phi + psi)
        in_col = phi + err_in
        contribs.append((-err_in / R, "input-encoder %s error %.3g rad at the input (%dx/input rev)"
                         % ("eccentricity" if k == 1 else "ellipticity", a_in, k)))
        formulation = contribs[0][1]
        nuis["input_encoder_error_rad"] = a_in
    elif category == "decoy_separable":
        gear_eff = ()
        if variant == "encoder_eccentricity":
            a = _u(rng, 2e-4, 1.2e-3)
            z = a * np.sin(th_out + _u(rng, 0, 2 * math.pi))
            meas_eff = ("encoder_eccentricity",)
            d = "output-encoder eccentricity, once per output rev"
        elif variant == "angle_offset_step":
            f = _u(rng, 0.3, 0.7)
            z = np.where(t >= f * t[-1], _pm(rng), 0.0)
            meas_eff = ("angle_offset",)
            d = "output-angle offset step at %.0f %% of the run" % (100 * f)
        elif variant == "thermal_drift_exp":
            tau = _u(rng, 0.2, 1.0) * t[-1]
            z = _pm(rng) * (1 - np.exp(-t / tau))
            meas_eff = ("thermal_drift",)
            d = "exponential thermal drift (tau=%.3g s)" % tau
        elif variant == "sensor_gain":
            g = 1.0 + _pm(rng) * _u(rng, 1e-4, 1e-3)
            z = (g - 1.0) * base
            meas_eff = ("sensor_gain",)
            nuis["output_encoder_gain"] = g
            d = "output-encoder gain %.5f" % g
        elif variant == "wrong_units_deg":
            z = None
            meas_eff = ("wrong_units",)
            d = "output angle in degrees (x57.2958)"
        else:
            raise ValueError(variant)
        if z is not None:
            contribs.append((z, d))
        formulation = d
    if category == "pair":
        (z1, _), (z2, _) = contribs
        u1, u2 = z1 / _rms0(z1), z2 / _rms0(z2)
        k1, k2, _ = _pair_ks(rng, u1 - u1.mean(), u2 - u2.mean())
        nrms = _rms0(z1) / k1
        total = z1 + u2 * k2 * nrms
        formulation += " [k: te_1x=%.2f, te_2x=%.2f]" % (_rms0(z1) / nrms, _rms0(u2 * k2 * nrms) / nrms)
    elif contribs:
        z = contribs[0][0]
        k = _u(rng, 4.0, 12.0)
        if variant in ("angle_offset_step", "thermal_drift_exp"):
            nrms = _u(rng, 2e-6, 2e-5)
            z = z / _rms0(z) * k * nrms
        else:
            nrms = _rms0(z) / k
        total = z
    else:
        nrms = _u(rng, 2e-6, 2e-5)
        total = np.zeros_like(base)
    snr = _rms0(total) / nrms
    w, _ = _noise(rng, N, nrms, "auto")
    out = base + total + w
    if variant == "wrong_units_deg":
        snr = _rms0(out * DEG - out) / nrms
        out = out * DEG
    return _finish("transmission", category, combo, formulation, idx, m,
                   {"input_angle_rad": in_col, "output_angle_rad": out}, None, gear_eff,
                   meas_eff, nuis, equiv, nrms, snr, name_form=form)


# ----------------------------------------------------------------------------------------------
# EFFICIENCY
# ----------------------------------------------------------------------------------------------
def _visc_ratio(law, T, Tref, p):
    """Viscosity ratio mu(T)/mu(Tref)."""
    T = np.asarray(T, dtype=float)
    if law == "roelands":
        l0 = math.log10(p["mu_ref"]) + 1.2
        lg = l0 * ((Tref + 135.0) / (T + 135.0)) ** p["S0"] - 1.2
        return 10.0 ** lg / p["mu_ref"]
    if law == "slotte":
        return ((p["b"] + Tref) / (p["b"] + T)) ** p["c"]
    if law == "reynolds":
        return np.exp(-p["beta"] * (T - Tref))
    raise ValueError(law)


def _visc_params(rng, law):
    if law == "roelands":
        return {"mu_ref": _u(rng, 30.0, 150.0), "S0": _u(rng, 1.0, 1.5)}
    if law == "slotte":
        return {"b": _u(rng, 15.0, 45.0), "c": _u(rng, 2.0, 3.2)}
    if law == "reynolds":
        return {"beta": _u(rng, 0.025, 0.05)}
    raise ValueError(law)


def _eff_grid(rng, m):
    nT = int(rng.integers(3, 6))
    T_start = _u(rng, -5.0, 15.0)
    step = _u(rng, 12.0, 20.0)
    temps = T_start + step * np.arange(nT)
    temps = temps[temps <= 85.0]
    speeds_pool = [n for n in (250, 500, 1000, 1500, 2000, 2500, 3000, 3500)
                   if n <= 0.95 * m.max_speed]
    nN = int(rng.integers(3, min(5, len(speeds_pool)) + 1))
    speeds = np.sort(rng.choice(speeds_pool, size=nN, replace=False)).astype(float)
    nL = int(rng.integers(4, 8))
    alphas = np.sort(rng.choice(np.round(np.arange(0.1, 1.01, 0.1), 2), size=nL, replace=False))
    TT, NN, AA = np.meshgrid(temps, speeds, alphas, indexing="ij")
    temp = TT.ravel() + rng.uniform(-0.4, 0.4, TT.size)
    n = NN.ravel()
    alpha = AA.ravel() * (1 + rng.uniform(-0.005, 0.005, AA.size))
    order = "grid order"
    if rng.random() < 0.4:
        perm = rng.permutation(temp.size)
        temp, n, alpha = temp[perm], n[perm], alpha[perm]
        order = "random order"
    return temp, n, alpha, order


def _ke_noload(alpha, tau):
    """Efficiency ratio for a load-independent no-load torque tau*T_R (output-referred),
    normalised to 1 at rated torque: Ke = alpha (1+tau) / (alpha + tau)."""
    return alpha * (1.0 + tau) / (alpha + tau)


def _ke_iso(alpha, tau, mu, c2):
    """ISO/TR 14179-type loss split: P_loss = P0 + mu P + c2 P^2/P_R (fixed speed)."""
    f = lambda a: a / (a * (1 + mu) + tau + c2 * a * a)
    return f(alpha) / f(1.0)


def _efficiency_case(rng, m, category, effects, form, idx, combo, variant=None):
    temp, n, alpha, order = _eff_grid(rng, m)
    load = alpha * m.TR
    Tref, nref = 40.0, 2000.0
    lvl = _u(rng, 65.0, 85.0)
    nuis = {"efficiency_level": lvl}
    gear_eff, meas_eff, equiv = tuple(effects), (), ()
    base = np.full(temp.size, lvl)
    load_col = load.copy()
    cols = lambda eta: {"input_speed_rpm": n, "load_torque_Nm": load_col,
                        "temperature_C": temp, "efficiency_pct": eta}
    if category == "clean":
        rms = _u(rng, 0.1, 0.6)
        meas, nrms, formulation = _clean_noise(rng, base, rms, form)
        return _finish("efficiency", category, combo, formulation + ", " + order, idx, m,
                       cols(meas), None, (), (), nuis, (), nrms, 0.0, name_form=form)

    def lowload_model(fm):
        if fm == "no-load-torque":
            tau = math.exp(_u(rng, math.log(0.05), math.log(0.3)))
            return (lambda sc: lvl * _ke_noload(alpha, tau * sc)), \
                "no-load-torque (tau=T_nl/T_R=%.3f)" % tau
        if fm == "iso14179-loss-split":
            tau = math.exp(_u(rng, math.log(0.05), math.log(0.25)))
            mu = _u(rng, 0.05, 0.15)
            c2 = _u(rng, 0.02, 0.08)
            return (lambda sc: lvl * _ke_iso(alpha, tau * sc, mu, c2)), \
                "iso14179-loss-split (tau=%.3f mu=%.2f c2=%.2f)" % (tau, mu, c2)
        raise ValueError(fm)

    def temp_model(fm):
        if fm == "roelands-churning-mult":
            p = _visc_params(rng, "roelands")
            a = _u(rng, 0.3, 0.6)
            c = _u(rng, 0.03, 0.08)
            vr = _visc_ratio("roelands", temp, Tref, p)
            L = lambda sc: np.minimum(0.6, c * sc * (vr * n / nref) ** a)
            L0 = lambda sc: min(0.6, c * sc)
            return (lambda sc: (1 - L(sc)) / (1 - L0(sc)), "mult"), \
                "roelands-churning-mult (mu40=%.0f mPa s, S0=%.2f, a=%.2f)" % (p["mu_ref"], p["S0"], a)
        if fm == "slotte-additive":
            p = _visc_params(rng, "slotte")
            c = _u(rng, 2.0, 5.0)
            lv = np.log(_visc_ratio("slotte", temp, Tref, p))
            return (lambda sc: -c * sc * lv, "add"), \
                "slotte-additive (b=%.0f C, c=%.2f, %.1f pp per e-fold)" % (p["b"], p["c"], c)
        if fm == "reynolds-mult":
            p = _visc_params(rng, "reynolds")
            a = _u(rng, 0.03, 0.08)
            vr = _visc_ratio("reynolds", temp, Tref, p)
            return (lambda sc: vr ** (-a * sc), "mult"), \
                "reynolds-mult (beta=%.3f 1/K, a=%.3f)" % (p["beta"], a)
        raise ValueError(fm)

    def apply_temp(eta, tm, sc):
        f, how = tm
        if how == "mult":
            return eta * f(sc)
        return eta + f(sc)

    def size_effect(fun):
        """fun(sc) -> efficiency array.  Draw k; noise = physical RMS / k, kept within
        0.1..1.0 pp by rescaling the effect's strength sc if necessary."""
        k = _u(rng, 4.0, 12.0)
        r1 = _rms0(np.clip(fun(1.0), 1.0, 99.5) - base)
        nrms = min(1.0, max(0.1, r1 / k))
        sc = 1.0
        if abs(r1 / k - nrms) > 1e-12:
            g = lambda ls: _rms0(np.clip(fun(math.exp(ls)), 1.0, 99.5) - base) - k * nrms
            lo, hi = (-8.0, 0.0) if r1 / k > nrms else (0.0, 3.0)
            if g(lo) < 0.0 < g(hi):
                sc = math.exp(optimize.brentq(g, lo, hi, xtol=1e-12))
        eta = np.clip(fun(sc), 1.0, 99.5)
        nrms = _rms0(eta - base) / k
        return eta, nrms, sc

    if category == "single":
        eff = effects[0]
        if eff == "low_load_efficiency":
            fn, formulation = lowload_model(form)
        else:
            tm, formulation = temp_model(form)
            fn = lambda sc: apply_temp(base, tm, sc)
        eta, nrms, sc = size_effect(fn)
        if sc != 1.0:
            formulation += " [strength x%.3g]" % sc
        total = eta - base
    elif category == "pair":
        if form == "palmgren-coupled":
            # no-load torque from Palmgren's load-independent drag M0 ~ (nu n)^(2/3)
            p = _visc_params(rng, "roelands")
            vr = _visc_ratio("roelands", temp, Tref, p)
            tau_r = math.exp(_u(rng, math.log(0.05), math.log(0.25)))
            sens = [1.0]

            def eta_of(sc_tau, sc_T, temps_on=True):
                v = vr ** sc_T if temps_on else 1.0
                tau = tau_r * sc_tau * (v * n / nref) ** (2.0 / 3.0)
                tau_n = tau_r * sc_tau
                return lvl * alpha * (1 + tau_n) / (alpha + tau)
            formulation = ("palmgren-coupled: T_nl ~ (nu(T) n)^(2/3), roelands viscosity "
                           "(mu40=%.0f mPa s, S0=%.2f), tau_ref=%.3f") % (p["mu_ref"], p["S0"], tau_r)

            def contribs(a1, a2):
                full = eta_of(a1, a2)
                no_t = eta_of(a1, a2, temps_on=False)
                c_low = no_t - base
                c_tmp = full - no_t
                return full, c_low, c_tmp
        else:  # "iso14179+slotte-additive"
            fn, d1 = lowload_model("iso14179-loss-split")
            tm, d2 = temp_model("slotte-additive")
            formulation = d1 + " + " + d2

            def contribs(a1, a2):
                low = fn(a1)
                full = apply_temp(low, tm, a2)
                return full, low - base, full - low
        # tune: effect 1 physical (a1 = 1), then choose k's and tune a2 (and a1 if coupled)
        full, c1, c2 = contribs(1.0, 1.0)
        nrms0 = None
        for _attempt in range(20):
            k1, k2, _ = _pair_ks(rng, (c1 - c1.mean()) / _rms0(c1), (c2 - c2.mean()) / _rms0(c2))
            if nrms0 is None:
                nrms0 = _u(rng, 0.2, 0.8)   # realistic efficiency noise [pp]; both effects tuned
            nrms = nrms0
            a1, a2 = 1.0, 1.0
            for _ in range(6):
                g2 = lambda la: _rms0(contribs(a1, math.exp(la))[2]) - k2 * nrms
                lo, hi = -6.0, 3.0
                if g2(lo) < 0 < g2(hi):
                    a2 = math.exp(optimize.brentq(g2, lo, hi, xtol=1e-10))
                g1 = lambda la: _rms0(contribs(math.exp(la), a2)[1]) - k1 * nrms
                if g1(lo) < 0 < g1(hi):
                    a1 = math.exp(optimize.brentq(g1, lo, hi, xtol=1e-10))
            full, c1, c2 = contribs(a1, a2)
            kk = [_rms0(c1) / nrms, _rms0(c2) / nrms,
                  _rms0(np.clip(full, 1.0, 99.5) - base) / nrms]
            if all(4.0 <= k_ <= 12.0 for k_ in kk):
                break
        else:
            raise RuntimeError("efficiency pair tuning failed")
        eta = np.clip(full, 1.0, 99.5)
        total = eta - base
        formulation += " [tuned: low-load strength x%.3g, temperature strength x%.3g]" % (a1, a2)
        formulation += " [k: low_load_efficiency=%.2f, temperature_dependence=%.2f]" % (
            _rms0(c1) / nrms, _rms0(c2) / nrms)
    elif category == "decoy_equivalent":
        gear_eff = ()
        equiv = (effects[0],)
        if form == "rig-drag":
            # drag torque of rig bearings/seals between the input torque sensor and the gear:
            # eta_meas = T w_out / ((T_in + T_d) w_in) = eta T / (T + eta R T_d)
            Td0 = _u(rng, 0.05, 0.3) * m.run_torque_in
            et = lvl / 100.0
            fn = lambda sc: 100.0 * et * load / (load + et * m.ratio * Td0 * sc)
            eta, nrms, sc = size_effect(fn)
            Td = Td0 * sc
            formulation = "rig-drag (drag torque %.3g N m at the input)" % Td
            nuis["rig_drag_torque_Nm"] = Td
        else:  # temp-sensitive torque sensor
            kap0 = _pm(rng) * _u(rng, 3e-4, 1.5e-3)
            Tcal = 23.0
            fn = lambda sc: base * (1 + kap0 * sc * (temp - Tcal))
            eta, nrms, sc = size_effect(fn)
            kap = kap0 * sc
            formulation = "temp-sensitive-torque-sensor (gain TC %.2g 1/K)" % kap
            nuis["torque_sensor_gain_tc_per_K"] = kap
        total = eta - base
    else:  # decoy_separable
        gear_eff = ()
        k = _u(rng, 4.0, 12.0)
        dev = None
        total = np.zeros(temp.size)
        if variant == "efficiency_level":
            dev = _pm(rng) * _u(rng, 8.0, 14.0)
            lvl = 78.0 + dev
            nuis["efficiency_level"] = lvl
            base = np.full(temp.size, lvl)
            formulation = "efficiency level %.1f %% (vs the catalog example eta_R = 78 %%)" % lvl
        elif variant == "sensor_gain":
            g = 1.0 + _pm(rng) * _u(rng, 0.02, 0.06)
            load_col = g * load
            dev = lvl * (g - 1.0)
            total = np.full(temp.size, dev)
            formulation = "output torque-sensor gain %.4f (load column and efficiency scaled)" % g
            meas_eff = ("sensor_gain",)
            nuis["torque_sensor_gain"] = g
        else:  # wrong_units_fraction
            meas_eff = ("wrong_units",)
            formulation = "efficiency as a fraction instead of percent"
        nrms = abs(dev) / k if dev is not None else _u(rng, 0.1, 0.6)
    w, _ = _noise(rng, temp.size, nrms, "auto")
    eta_meas = base + total + w
    if category == "decoy_separable":
        snr = abs(dev) / nrms if dev is not None else 0.0
        if variant == "wrong_units_fraction":
            snr = _rms(eta_meas / 100.0 - eta_meas) / nrms
            eta_meas = eta_meas / 100.0
    else:
        snr = _rms0(total) / nrms
    return _finish("efficiency", category, combo, formulation + ", " + order, idx, m,
                   cols(eta_meas), None, gear_eff, meas_eff, nuis, equiv, nrms, snr, name_form=form)


# ----------------------------------------------------------------------------------------------
# VIBRATION
# ----------------------------------------------------------------------------------------------
def _newmark(dt, p, J, spring, damp, linear=None):
    """Average-acceleration Newmark (beta = 1/4, gamma = 1/2) with Newton iterations for
    J d'' + Fd(d, v) + Fs(d) = p.  ``linear = (c, K)`` selects the exact linear update."""
    N = p.size
    d = np.zeros(N)
    v = np.zeros(N)
    beta, gam = 0.25, 0.5
    a0 = 1.0 / (beta * dt * dt)
    a1 = 1.0 / (beta * dt)
    a2 = 1.0 / (2 * beta) - 1.0
    g1 = gam / (beta * dt)
    dn, vn, an = 0.0, 0.0, p[0] / J
    if linear is not None:
        c, K = linear
        Keff = J * a0 + c * g1 + K
        for i in range(1, N):
            # effective load
            rhs = (p[i] + J * (a0 * dn + a1 * vn + a2 * an)
                   + c * (g1 * dn + (gam / beta - 1) * vn + dt * (gam / (2 * beta) - 1) * an))
            dn1 = rhs / Keff
            an1 = a0 * (dn1 - dn) - a1 * vn - a2 * an
            vn1 = vn + dt * ((1 - gam) * an + gam * an1)
            dn, vn, an = dn1, vn1, an1
            d[i], v[i] = dn, vn
        return d, v
    for i in range(1, N):
        x = dn + dt * vn + 0.5 * dt * dt * an   # predictor
        for _it in range(30):
            a = a0 * (x - dn) - a1 * vn - a2 * an
            vv = vn + dt * ((1 - gam) * an + gam * a)
            Fs, Ks = spring(x)
            Fd, Dd, Dv = damp(x, vv)
            r = p[i] - J * a - Fd - Fs
            jac = J * a0 + Dv * g1 + Dd + Ks
            dx = r / jac
            x += dx
            if abs(dx) <= 1e-13 + 1e-10 * abs(x):
                break
        a = a0 * (x - dn) - a1 * vn - a2 * an
        vv = vn + dt * ((1 - gam) * an + gam * a)
        dn, vn, an = x, vv, a
        d[i], v[i] = dn, vn
    return d, v


@dataclass
class _VibProto:
    t: np.ndarray
    n: np.ndarray
    phi: np.ndarray
    om: np.ndarray
    al: np.ndarray
    fn: float
    zeta: float
    J: float
    K1: float
    s: float
    dt: float


def _vib_protocol(rng, m: _Model) -> _VibProto:
    s = _u(rng, 0.93, 1.07)
    zeta = _u(rng, 0.03, 0.08)
    fmax = min(40.0, 0.95 * m.max_speed / (60.0 * 1.3))
    fn = _u(rng, 8.0, max(9.0, fmax))
    K1 = m.K1 * s
    J = K1 / (2 * math.pi * fn) ** 2
    n0 = _u(rng, 0.35, 0.6) * 30.0 * fn
    n1 = min(_u(rng, 1.3, 1.55) * 60.0 * fn, 0.97 * m.max_speed)
    dfw = 2 * zeta * fn
    r = _u(rng, 0.3, 2.0)
    ndot = 60.0 * r * dfw * dfw
    Td = (n1 - n0) / ndot
    if Td > 18.0:
        Td = 18.0
    if Td < 3.0:
        Td = 3.0
    fs = _u(rng, 25.0, 32.0) * fn
    if Td * fs > 12000:
        Td = 12000.0 / fs
    N = int(Td * fs) + 1
    t = np.linspace(0.0, Td, N)
    n = n0 + (n1 - n0) * t / Td
    om = 2 * math.pi * n / 60.0
    al = np.full(N, 2 * math.pi * (n1 - n0) / Td / 60.0)
    phi0 = _u(rng, 0, 2 * math.pi)
    phi = phi0 + 2 * math.pi / 60.0 * (n0 * t + 0.5 * (n1 - n0) * t * t / Td)
    return _VibProto(t=t, n=n, phi=phi, om=om, al=al, fn=fn, zeta=zeta, J=J, K1=K1, s=s,
                     dt=t[1] - t[0])


def _harm(pr: _VibProto, comps):
    """e, e_ddot for e = sum A sin(k phi + psi)."""
    e = np.zeros_like(pr.t)
    edd = np.zeros_like(pr.t)
    for A, k, psi in comps:
        arg = k * pr.phi + psi
        sn, cs = np.sin(arg), np.cos(arg)
        e += A * sn
        edd += A * (-(k * pr.om) ** 2 * sn + k * pr.al * cs)
    return e, edd


def _vib_response(pr: _VibProto, m: _Model, comps, form, extra):
    """Output vibration angle x = e + delta of the load inertia."""
    if not comps:
        return np.zeros_like(pr.t)
    e, edd = _harm(pr, comps)
    p = -pr.J * edd
    c = 2 * pr.zeta * math.sqrt(pr.K1 * pr.J)
    if form == "stiffening-3seg":
        K1, K2, K3 = m.K1 * pr.s, m.K2 * pr.s, m.K3 * pr.s
        T1, T2 = m.T1, m.T2
        th1 = T1 / K1
        th2 = th1 + (T2 - T1) / K2

        def spring(x):
            a = abs(x)
            if a <= th1:
                return K1 * x, K1
            if a <= th2:
                return math.copysign(T1 + K2 * (a - th1), x), K2
            return math.copysign(T2 + K3 * (a - th2), x), K3

        def damp(x, v):
            return c * v, 0.0, c
        d, _ = _newmark(pr.dt, p, pr.J, spring, damp)
    elif form == "ampdep-damping":
        beta, dref = extra["beta"], extra["dref"]
        wn = 2 * math.pi * pr.fn
        K = pr.K1

        def spring(x):
            return K * x, K

        def damp(x, v):
            q = (x * x + (v / wn) ** 2) / (dref * dref)
            f = c * v * (1 + beta * q)
            dfd = c * v * beta * 2 * x / (dref * dref)
            dfv = c * (1 + beta * q) + c * v * beta * 2 * v / (wn * wn * dref * dref)
            return f, dfd, dfv
        d, _ = _newmark(pr.dt, p, pr.J, spring, damp)
    else:  # linear viscous
        d, _ = _newmark(pr.dt, p, pr.J, None, None, linear=(c, pr.K1))
    return e + d


def _vibration_case(rng, m, category, effects, form, idx, combo, variant=None):
    pr = _vib_protocol(rng, m)
    nuis = {"stiffness_scale": pr.s, "damping_ratio": pr.zeta}
    gear_eff, meas_eff, equiv = tuple(effects), (), ()
    N = pr.t.size
    cols = lambda x: {"time_s": pr.t, "input_speed_rpm": pr.n, "output_vibration_rad": x}
    extra = {}
    if category == "clean":
        rms = _u(rng, 1e-6, 1e-5)
        meas, nrms, formulation = _clean_noise(rng, np.zeros(N), rms, form)
        return _finish("vibration", category, combo, formulation, idx, m, cols(meas), pr.J,
                       (), (), nuis, (), nrms, 0.0, name_form=form)
    th1 = m.T1 / (m.K1 * pr.s)
    Q = 1.0 / (2 * pr.zeta)
    desc_dyn = {"linear-viscous": "linear spring K1, viscous damping",
                "stiffening-3seg": "three-segment stiffening spring (K1/K2/K3), viscous damping",
                "ampdep-damping": "linear spring, amplitude-dependent damping"}
    if category in ("single", "pair"):
        dyn = form
        if dyn == "ampdep-damping":
            extra = {"beta": _u(rng, 0.5, 2.0), "dref": 0.0}
        comps = []
        for eff in effects:
            k = 1 if eff == "te_1x" else 2
            if dyn == "stiffening-3seg":
                A = th1 * _u(rng, 1.5, 3.0) / Q
            else:
                A = m.accuracy * _u(rng, 0.1, 0.4)
            comps.append([A, k, _u(rng, 0, 2 * math.pi)])
        if dyn == "ampdep-damping":
            extra["dref"] = max(c[0] for c in comps) * Q * _u(rng, 0.5, 1.0)
        if category == "single":
            x = _vib_response(pr, m, comps, dyn, extra)
            k = _u(rng, 4.0, 12.0)
            nrms = _rms(x) / k
            total = x
        else:
            def contrib(A2):
                cc = [list(comps[0]), [A2, comps[1][1], comps[1][2]]]
                full = _vib_response(pr, m, cc, dyn, extra)
                wo1 = _vib_response(pr, m, cc[1:], dyn, extra)
                wo2 = _vib_response(pr, m, cc[:1], dyn, extra)
                return full, full - wo1, full - wo2
            full, c1, c2 = contrib(comps[1][0])
            k1, k2, _ = _pair_ks(rng, c1 / _rms(c1), c2 / _rms(c2))
            nrms = _rms(c1) / k1
            A2 = comps[1][0]
            iters = 1 if dyn == "linear-viscous" else 3
            for _ in range(iters):
                A2 *= k2 * nrms / _rms(c2)
                full, c1, c2 = contrib(A2)
                nrms = _rms(c1) / k1
            comps[1][0] = A2
            total = full
            if not (4.0 <= _rms(total) / nrms <= 12.0 and 4.0 <= _rms(c2) / nrms <= 12.0):
                # re-level the noise inside the feasible band (both effects and the sum)
                r = [_rms(c1), _rms(c2), _rms(total)]
                lo, hi = max(r) / 11.9, min(r) / 4.1
                if lo >= hi:
                    raise RuntimeError("vibration pair scaling failed")
                nrms = math.sqrt(lo * hi)
            kinfo = " [k: te_1x=%.2f, te_2x=%.2f]" % (_rms(c1) / nrms, _rms(c2) / nrms)
        formulation = "; ".join("%s A=%.3g rad" % (eff, c_[0]) for eff, c_ in zip(effects, comps))
        formulation = "%s (%s, zeta=%.3f, fn=%.1f Hz, Newmark-beta)" % (
            dyn, formulation, pr.zeta, pr.fn)
        if category == "pair":
            formulation += kinfo
    elif category == "decoy_equivalent":
        gear_eff = ()
        equiv = (effects[0],)
        k = 1 if effects[0] == "te_1x" else 2
        if k == 1:
            a_in = _u(rng, 5e-4, 3e-3)
            d = "motor-coupling-eccentricity (input shaft angular error %.3g rad, 1x/input rev)" % a_in
        else:
            b = math.radians(_u(rng, 2.0, 5.0))
            a_in = b * b / 4.0
            d = "cardan-misalignment (%.1f deg -> %.3g rad at 2x/input rev)" % (math.degrees(b), a_in)
        comps = [[a_in / m.ratio, k, _u(rng, 0, 2 * math.pi)]]
        nuis["rig_input_error_rad"] = a_in
        x = _vib_response(pr, m, comps, "linear-viscous", extra)
        kk = _u(rng, 4.0, 12.0)
        nrms = _rms(x) / kk
        total = x
        formulation = d + ", linear-viscous, Newmark-beta"
    else:  # decoy separable
        gear_eff = ()
        t = pr.t
        if variant == "thermal_drift_warmup":
            tw, tau = _u(rng, 0.2, 0.5) * t[-1], _u(rng, 0.08, 0.2) * t[-1]
            lg = 1.0 / (1.0 + np.exp(-(t - tw) / tau))
            z = lg - lg[0]
            meas_eff = ("thermal_drift",)
            formulation = "warm-up (logistic) thermal drift of the vibration angle"
        elif variant == "angle_offset_step":
            f = _u(rng, 0.3, 0.7)
            z = np.where(t >= f * t[-1], 1.0, 0.0)
            meas_eff = ("angle_offset",)
            formulation = "angle offset step at %.0f %% of the run-up" % (100 * f)
        elif variant == "encoder_eccentricity":
            th_out = (pr.phi - pr.phi[0]) / m.ratio
            z = np.sin(th_out + _u(rng, 0, 2 * math.pi))
            meas_eff = ("encoder_eccentricity",)
            formulation = "output-encoder eccentricity, once per output rev"
        nrms = _u(rng, 1e-6, 1e-5)
        total = _pm(rng) * z / _rms(z) * _u(rng, 4.0, 12.0) * nrms
    w, _ = _noise(rng, N, nrms, "auto")
    snr = _rms(total) / nrms
    return _finish("vibration", category, combo, formulation, idx, m, cols(total + w), pr.J,
                   gear_eff, meas_eff, nuis, equiv, nrms, snr, name_form=form)


# ----------------------------------------------------------------------------------------------
# cells
# ----------------------------------------------------------------------------------------------
def _cells():
    """(kind, category, effects, combo-tag, formulation, variant)"""
    C = []
    # ---- torsion
    for f in ("white", "ar1", "student_t", "quantised", "outliers"):
        C.append(("torsion", "clean", (), "none", f, None))
    for f in ("rayleigh-masing", "valanis-endochronic", "bouc-wen-asym-degrading", "duhem-ampdep"):
        C.append(("torsion", "single", ("hysteresis",), "hysteresis", f, None))
    for f in ("asym-clearance-quadratic", "hertz32-closing", "karnopp-stiction-play"):
        C.append(("torsion", "single", ("backlash",), "backlash", f, None))
    for f in ("softening-bolted-joint", "shaft-plus-flange"):
        C.append(("torsion", "single", ("housing_compliance",), "housing_compliance", f, None))
    for eff, forms in (
            (("hysteresis", "backlash"), ("rayleigh-masing+karnopp-stiction-play",
                                         "valanis-endochronic+asym-clearance-quadratic")),
            (("hysteresis", "housing_compliance"), ("duhem-ampdep+shaft-plus-flange",
                                                   "bouc-wen-asym-degrading+softening-bolted-joint")),
            (("backlash", "housing_compliance"), ("hertz32-closing+shaft-plus-flange",
                                                 "asym-clearance-quadratic+softening-bolted-joint"))):
        for f in forms:
            C.append(("torsion", "pair", eff, "+".join(eff), f, None))
    for v in ("sensor_gain", "angle_offset_const", "angle_offset_step", "thermal_drift_linear",
              "thermal_drift_warmup", "wrong_units_deg", "wrong_units_kNm", "stiffness_scale"):
        tag = {"angle_offset_const": "angle_offset", "angle_offset_step": "angle_offset",
               "thermal_drift_linear": "thermal_drift", "thermal_drift_warmup": "thermal_drift",
               "wrong_units_deg": "wrong_units", "wrong_units_kNm": "wrong_units"}.get(v, v)
        C.append(("torsion", "decoy_separable", (), tag, v, v))
    C.append(("torsion", "decoy_equivalent", ("housing_compliance",), "housing_compliance",
              "soft-gear", None))
    C.append(("torsion", "decoy_equivalent", ("backlash",), "backlash", "rig-coupling-play", None))
    C.append(("torsion", "decoy_equivalent", ("hysteresis",), "hysteresis", "rig-lock-duhem", None))
    # ---- transmission
    for f in ("white", "ar1", "quantised", "outliers"):
        C.append(("transmission", "clean", (), "none", f, None))
    for eff in ("te_1x", "te_2x"):
        for f in ("harmonic-series", "thermal-phase-drift", "output-angle-modulated"):
            C.append(("transmission", "single", (eff,), eff, f, None))
    for f in ("harmonic-series+harmonic-series", "thermal-phase-drift+output-angle-modulated"):
        C.append(("transmission", "pair", ("te_1x", "te_2x"), "te_1x+te_2x", f, None))
    for v in ("encoder_eccentricity", "angle_offset_step", "thermal_drift_exp", "sensor_gain",
              "wrong_units_deg"):
        tag = {"angle_offset_step": "angle_offset", "thermal_drift_exp": "thermal_drift",
               "wrong_units_deg": "wrong_units"}.get(v, v)
        C.append(("transmission", "decoy_separable", (), tag, v, v))
    for eff in ("te_1x", "te_2x"):
        C.append(("transmission", "decoy_equivalent", (eff,), eff, "input-encoder-error", None))
    # ---- efficiency
    for f in ("white", "ar1", "laplace", "outliers"):
        C.append(("efficiency", "clean", (), "none", f, None))
    for f in ("no-load-torque", "iso14179-loss-split"):
        C.append(("efficiency", "single", ("low_load_efficiency",), "low_load_efficiency", f, None))
    for f in ("roelands-churning-mult", "slotte-additive", "reynolds-mult"):
        C.append(("efficiency", "single", ("temperature_dependence",), "temperature_dependence",
                  f, None))
    for f in ("palmgren-coupled", "iso14179+slotte-additive"):
        C.append(("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"),
                  "low_load_efficiency+temperature_dependence", f, None))
    for v in ("efficiency_level", "sensor_gain", "wrong_units_fraction"):
        tag = {"wrong_units_fraction": "wrong_units"}.get(v, v)
        C.append(("efficiency", "decoy_separable", (), tag, v, v))
    C.append(("efficiency", "decoy_equivalent", ("low_load_efficiency",), "low_load_efficiency",
              "rig-drag", None))
    C.append(("efficiency", "decoy_equivalent", ("temperature_dependence",),
              "temperature_dependence", "temp-sensitive-torque-sensor", None))
    # ---- vibration
    for f in ("white", "ar1", "outliers"):
        C.append(("vibration", "clean", (), "none", f, None))
    for eff in ("te_1x", "te_2x"):
        for f in ("linear-viscous", "stiffening-3seg", "ampdep-damping"):
            C.append(("vibration", "single", (eff,), eff, f, None))
    for f in ("linear-viscous", "stiffening-3seg"):
        C.append(("vibration", "pair", ("te_1x", "te_2x"), "te_1x+te_2x", f, None))
    for v in ("thermal_drift_warmup", "angle_offset_step", "encoder_eccentricity"):
        tag = {"thermal_drift_warmup": "thermal_drift", "angle_offset_step": "angle_offset"}.get(v, v)
        C.append(("vibration", "decoy_separable", (), tag, v, v))
    for eff in ("te_1x", "te_2x"):
        C.append(("vibration", "decoy_equivalent", (eff,), eff,
                  "rig-coupling-1x" if eff == "te_1x" else "rig-coupling-2x", None))
    return C


CELLS = _cells()

_BUILDERS = {"torsion": _torsion_case, "transmission": _transmission_case,
             "efficiency": _efficiency_case, "vibration": _vibration_case}


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    """``per_cell`` cases for every cell, deterministic in ``seed``."""
    rng = np.random.default_rng(seed)
    models = _load_models(catalog_dir)
    cases = []
    idx = 0
    for kind, category, effects, combo, form, variant in CELLS:
        for _ in range(per_cell):
            m = models[int(rng.integers(len(models)))]
            if kind == "torsion" and effects == ("backlash", "housing_compliance"):
                # a play comparable with a housing spring needs a gear whose catalog backlash
                # is not negligible against its twist (small sizes / ratio 50)
                pool = [mm for mm in models
                        if mm.backlash / float(_twist_cat(mm.TR, mm)) >= 0.04]
                m = pool[int(rng.integers(len(pool)))]
            case = _BUILDERS[kind](rng, m, category, effects, form, idx, combo, variant)
            cases.append(case)
            idx += 1
    return cases


__all__ = ["SUITE", "TruthCase", "generate_cases"]
