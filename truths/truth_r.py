"""Truth suite "r" for `hdcad reconcile` (strain wave gear test-rig data reconciliation).

Written from CONTRACT.md, the catalog tables and the physics literature only; it imports
nothing from hdcad. numpy + scipy only.  See NOTES_r.md for the physics, the references, the
parameter ranges and the interpretations.

    generate_cases(seed, catalog_dir, per_cell=4) -> list[TruthCase]

Every case is drawn from numpy.random.default_rng(seed) in a fixed cell order, so the same seed
gives the same cases.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import interpolate, optimize, special

SUITE = "r"

COLUMNS = {
    "torsion": ("torque_Nm", "twist_rad"),
    "transmission": ("input_angle_rad", "output_angle_rad"),
    "efficiency": ("input_speed_rpm", "load_torque_Nm", "temperature_C", "efficiency_pct"),
    "vibration": ("time_s", "input_speed_rpm", "output_vibration_rad"),
}

SPREAD = 0.10          # catalog stiffness spread used for the nuisance (+-10 %)
NOISE_CODES = {"white": 0.0, "ar1": 1.0, "fgn": 2.0, "skewnormal": 3.0}
DEG = 180.0 / math.pi


# --------------------------------------------------------------------------------------------
# the case record
# --------------------------------------------------------------------------------------------
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
        names = list(self.columns.keys())
        data = [np.asarray(self.columns[c], dtype=float).tolist() for c in names]
        with open(path, "w", newline="") as fh:
            fh.write(",".join(names) + "\n")
            for row in zip(*data):
                fh.write(",".join(repr(float(v)) for v in row) + "\n")


# --------------------------------------------------------------------------------------------
# catalog
# --------------------------------------------------------------------------------------------
def _num(x):
    x = (x or "").strip()
    return float(x) if x else None


def _read(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


class _Catalog:
    def __init__(self, d):
        d = Path(d)
        ratings = _read(d / "gh_ratings_050-1_058-1.csv")
        stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
        hyst = _read(d / "gh_hysteresis_052_060.csv")
        back = _read(d / "gh_backlash_052-2_060-2.csv")
        perf = _read(d / "gh_performance_051-1_059-1.csv")
        self.models = []
        for r in ratings:
            series, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
            st = None
            for s in stiff:
                if s["series"] != series or int(s["size"]) != size:
                    continue
                lo, hi = _num(s["ratio_min"]), _num(s["ratio_max"])
                if ratio >= lo and (hi is None or ratio <= hi):
                    st = s
            if st is None:
                continue
            h = None
            for s in hyst:
                if s["series"] != series:
                    continue
                lo, hi = _num(s["ratio_min"]), _num(s["ratio_max"])
                if ratio >= lo and (hi is None or ratio <= hi):
                    h = _num(s["hysteresis_rad"])
            b = None
            for s in back:
                if s["series"] == series and int(s["size"]) == size and int(s["ratio"]) == ratio:
                    b = _num(s["backlash_rad"])
            acc = None
            for s in perf:
                if s["series"] == series and int(s["size"]) == size and int(s["ratio"]) == ratio:
                    if _num(s["accuracy_rad"]) is not None:
                        acc = _num(s["accuracy_rad"])
                        break
            m = dict(
                code=f"{series.split('-')[0]}-{size}-{ratio}-GH", series=series, size=size,
                ratio=ratio, rated=_num(r["rated_torque_2000_Nm"]),
                avg_speed=_num(r["avg_input_speed_max_rpm"]), max_speed=_num(r["max_input_speed_rpm"]),
                T1=_num(st["T1_Nm"]), T2=_num(st["T2_Nm"]), K1=_num(st["K1_Nm_per_rad"]),
                K2=_num(st["K2_Nm_per_rad"]), K3=_num(st["K3_Nm_per_rad"]),
                hyst=h, backlash=b, accuracy=acc)
            if None in (m["rated"], m["T1"], m["T2"], m["K1"], m["K2"], m["K3"]):
                continue
            self.models.append(m)
        self.torsion = [m for m in self.models if m["hyst"] is not None and m["backlash"] is not None]
        self.accurate = [m for m in self.models if m["accuracy"] is not None]
        self.ratios = {}
        for m in self.models:
            self.ratios.setdefault((m["series"], m["size"]), []).append(m["ratio"])


# --------------------------------------------------------------------------------------------
# small helpers
# --------------------------------------------------------------------------------------------
def _rms(x):
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def _pick(rng, seq):
    return seq[int(rng.integers(len(seq)))]


def _semicircle(rng, half=SPREAD):
    """Wigner semicircle law on 1 +- half (Beta(3/2, 3/2) rescaled)."""
    return 1.0 + half * (2.0 * rng.beta(1.5, 1.5) - 1.0)


def _theta_cat(T, m):
    """Catalog three-segment twist, continuous through theta1 = T1/K1, odd in T."""
    T = np.asarray(T, dtype=float)
    a = np.abs(T)
    th1 = m["T1"] / m["K1"]
    th2 = th1 + (m["T2"] - m["T1"]) / m["K2"]
    th = np.where(a <= m["T1"], a / m["K1"],
                  np.where(a <= m["T2"], th1 + (a - m["T1"]) / m["K2"], th2 + (a - m["T2"]) / m["K3"]))
    return np.sign(T) * th


def _spring(x, m, s):
    """Torque of the (scaled) catalog spring at twist x, and its slope (scalar)."""
    th1 = m["T1"] / m["K1"]
    th2 = th1 + (m["T2"] - m["T1"]) / m["K2"]
    y = s * abs(x)
    if y <= th1:
        t, k = m["K1"] * y, m["K1"]
    elif y <= th2:
        t, k = m["T1"] + m["K2"] * (y - th1), m["K2"]
    else:
        t, k = m["T2"] + m["K3"] * (y - th2), m["K3"]
    return math.copysign(t, x), k * s


def _noise(rng, n, kind, target):
    """Noise of exact RMS `target`; returns (noise, parameter dict)."""
    par = {"noise_kind_code": NOISE_CODES[kind]}
    if kind == "white":
        x = rng.standard_normal(n)
    elif kind == "ar1":
        phi = float(rng.uniform(0.3, 0.8))
        w = rng.standard_normal(n)
        x = np.empty(n)
        x[0] = w[0] / math.sqrt(1 - phi * phi)
        for i in range(1, n):
            x[i] = phi * x[i - 1] + w[i]
        par["noise_ar1_phi"] = phi
    elif kind == "fgn":
        H = float(rng.uniform(0.6, 0.85))
        k = np.arange(n, dtype=float)
        g = 0.5 * (np.abs(k + 1) ** (2 * H) - 2 * k ** (2 * H) + np.abs(k - 1) ** (2 * H))
        c = np.concatenate([g, g[-2:0:-1]]) if n > 2 else np.array([1.0, g[1] if n > 1 else 0.0])
        lam = np.clip(np.fft.fft(c).real, 0.0, None)
        mm = len(c)
        z = rng.standard_normal(mm) + 1j * rng.standard_normal(mm)
        x = np.fft.fft(np.sqrt(lam / (2.0 * mm)) * z).real[:n]
        par["noise_fgn_hurst"] = H
    elif kind == "skewnormal":
        a = float(rng.uniform(3.0, 8.0))
        d = a / math.sqrt(1 + a * a)
        x = d * np.abs(rng.standard_normal(n)) + math.sqrt(1 - d * d) * rng.standard_normal(n)
        x = x - d * math.sqrt(2 / math.pi)
        par["noise_skew_alpha"] = a
    else:
        raise ValueError(kind)
    x = x * (target / _rms(x))
    return x, par


def _outliers(rng, n, noise_rms):
    cnt = max(1, int(round(0.005 * n)))
    idx = rng.choice(n, cnt, replace=False)
    out = np.zeros(n)
    out[idx] = rng.uniform(8.0, 15.0, cnt) * noise_rms * rng.choice([-1.0, 1.0], cnt)
    return out, cnt


def _fit_resid(y, cols, bounds):
    """Least-squares fit of the columns (with bounds on their coefficients) to y; residual."""
    A = np.column_stack(cols)
    nrm = np.sqrt(np.sum(A * A, axis=0))
    nrm[nrm == 0] = 1.0
    An = A / nrm
    lb = np.array([b[0] for b in bounds], dtype=float) * nrm
    ub = np.array([b[1] for b in bounds], dtype=float) * nrm
    if np.all(np.isinf(lb)) and np.all(np.isinf(ub)):
        x, *_ = np.linalg.lstsq(An, y, rcond=None)
    else:
        x = optimize.lsq_linear(An, y, bounds=(lb, ub), method="bvls").x
    return y - An @ x


def _ratio(y, nuis, other=None, bounded=True):
    """RMS of what the nuisance columns (plus, optionally, another effect's column, free)
    leave of y, divided by rms(y).  nuis = list of (column, (lo, hi))."""
    cols = [c for c, _ in nuis]
    bnds = [b if bounded else (-np.inf, np.inf) for _, b in nuis]
    if other is not None:
        cols.append(other)
        bnds.append((-np.inf, np.inf))
    r = _fit_resid(np.asarray(y, float), cols, bnds)
    ry = _rms(y)
    return _rms(r) / ry if ry > 0 else 0.0


def _pick_k(rng, must, prefer=()):
    """k in [4, 12] with k*r >= thr for every (r, thr) in must, and if possible in prefer."""
    lo = 4.0
    for r, thr in must:
        if r <= 0:
            return None
        lo = max(lo, thr / r * 1.02)
    if lo > 12.0:
        return None
    lo2 = lo
    for r, thr in prefer:
        if r > 0:
            lo2 = max(lo2, thr / r * 1.02)
    if lo2 <= 12.0:
        lo = lo2
    return float(rng.uniform(lo, 12.0))


def _size_single(rng, eff, nuis, amp_bounded=True):
    """Noise from k for a single effect; returns (k, noise, ratio_b, ratio_u) or None."""
    rb = _ratio(eff, nuis, bounded=amp_bounded)
    ru = _ratio(eff, nuis, bounded=False)
    k = _pick_k(rng, [(rb, 3.0)], [(ru, 3.0)])
    if k is None:
        return None
    noise = _rms(eff) / k
    return k, noise, k * rb, k * ru


def _size_pair(rng, e1, e2, nuis, g_range):
    """Pair sizing.  e1 keeps its physical size and sets the noise (k1); e2 is rescaled by g
    (within g_range, its physical range) so that its RMS is k2 x noise.  Returns dict or None."""
    r1a = _ratio(e1, nuis)
    r1u = _ratio(e1, nuis, bounded=False)
    r1g = _ratio(e1, nuis, other=e2)
    k1 = _pick_k(rng, [(r1a, 2.5), (r1g, 2.0)], [(r1u, 2.5)])
    if k1 is None:
        return None
    noise = _rms(e1) / k1
    rms2 = _rms(e2)
    klo = max(4.0, g_range[0] * rms2 / noise)
    khi = min(12.0, g_range[1] * rms2 / noise)
    if klo > khi:
        return None
    for _ in range(40):
        k2 = float(rng.uniform(klo, khi))
        g = k2 * noise / rms2
        e2s = e2 * g
        q2a = _rms(_fit_resid(e2s, [c for c, _ in nuis], [b for _, b in nuis])) / noise
        q2g = _ratio(e2s, nuis, other=e1) * k2
        tot = e1 + e2s
        qt = _rms(_fit_resid(tot, [c for c, _ in nuis], [b for _, b in nuis])) / noise
        if q2a >= 2.5 and q2g >= 2.0 and qt >= 3.0:
            return dict(k1=k1, k2=k2, g=g, noise=noise, e2=e2s, q1a=k1 * r1a, q1g=k1 * r1g,
                        q1u=k1 * r1u, q2a=q2a, q2g=q2g, qt=qt,
                        q2u=_ratio(e2s, nuis, bounded=False) * k2,
                        qtu=_ratio(tot, nuis, bounded=False) * _rms(tot) / noise)
    return None


def _line_source(t, tc):
    """Carslaw-Jaeger continuous line source switched on at t = 0: E1(tc / t)."""
    t = np.asarray(t, float)
    out = np.zeros_like(t)
    pos = t > 0
    out[pos] = special.exp1(tc / t[pos])
    return out


def _finish(rng, clean, noise_rms, noise_kind, outliers, nuis):
    """Add noise (exact RMS) and, optionally, gross outliers; update the nuisance record."""
    n = len(clean)
    z, par = _noise(rng, n, noise_kind, noise_rms)
    nuis.update(par)
    y = clean + z
    cnt = 0
    if outliers:
        o, cnt = _outliers(rng, n, noise_rms)
        y = y + o
    nuis["outlier_count"] = float(cnt)
    nuis["outlier_fraction"] = float(cnt) / n
    return y


def _noise_kind(rng, category):
    return _pick(rng, ["white", "ar1", "fgn", "skewnormal"])


# --------------------------------------------------------------------------------------------
# TORSION
# --------------------------------------------------------------------------------------------
class _Protocol:
    """0 -> +T0, then (+T0 -> -T0 -> +T0) x ncyc; legs timed by their torque range."""

    def __init__(self, rng, T0, ncyc=None):
        self.T0 = T0
        self.ncyc = int(rng.integers(1, 3)) if ncyc is None else int(ncyc)
        self.law = _pick(rng, ["cycloid", "twist-trigger"])
        self.legs = [(0.0, T0)] + [(T0, -T0), (-T0, T0)] * self.ncyc
        self.durs = np.array([abs(b - a) / T0 for a, b in self.legs])
        self.starts = np.concatenate([[0.0], np.cumsum(self.durs)])
        self.D = float(self.starts[-1])
        self.leg_time_s = float(rng.uniform(40.0, 120.0))   # seconds per T0 of torque travel
        self.n_samples = int(self.D * rng.uniform(110, 170))

    def torque(self, t):
        t = np.asarray(t, float)
        i = np.clip(np.searchsorted(self.starts, t, side="right") - 1, 0, len(self.legs) - 1)
        tau = np.clip((t - self.starts[i]) / self.durs[i], 0.0, 1.0)
        if self.law == "cycloid":
            c = tau - np.sin(2 * np.pi * tau) / (2 * np.pi)
        else:
            c = tau
        a = np.array([l[0] for l in self.legs])[i]
        b = np.array([l[1] for l in self.legs])[i]
        return a + (b - a) * c

    def dense(self, per_unit=700):
        ts, legid = [], []
        for j in range(len(self.legs)):
            n = int(per_unit * self.durs[j])
            tt = np.linspace(self.starts[j], self.starts[j + 1], n + 1)
            if j > 0:
                tt = tt[1:]
            ts.append(tt)
            legid.append(np.full(len(tt), j))
        t = np.concatenate(ts)
        return t, self.torque(t), np.concatenate(legid)


def _solve_parallel(Td, legid, legs, m, s, elem):
    """Twist of the catalog spring in parallel with a rate-independent friction element,
    driven by torque (safeguarded Newton per sample).  elem(x, state, direction) ->
    (F, dF, new_state); elem.reverse(state, x, F) at each reversal."""
    x = 0.0
    state = elem.init()
    out = np.empty(len(Td))
    tol = 1e-12 * float(np.max(np.abs(Td)))
    Tprev = 0.0
    cur_leg = -1
    F = 0.0
    for i in range(len(Td)):
        T = float(Td[i])
        j = int(legid[i])
        d = 1.0 if legs[j][1] > legs[j][0] else -1.0
        if j != cur_leg:
            state = elem.reverse(state, x, F, d)
            cur_leg = j
        kmin = s * min(m["K1"], m["K2"], m["K3"])
        if d > 0:
            lo, hi = x, x + max(T - Tprev, 0.0) / kmin + 1e-15
        else:
            lo, hi = x - max(Tprev - T, 0.0) / kmin - 1e-15, x
        xn = x
        for _ in range(60):
            ts_, ks_ = _spring(xn, m, s)
            Fe, dFe, _ = elem.force(xn, state, d)
            g = ts_ + Fe - T
            if abs(g) <= tol:
                break
            if g > 0:
                hi = xn
            else:
                lo = xn
            step = g / (ks_ + dFe)
            xt = xn - step
            if not (lo < xt < hi):
                xt = 0.5 * (lo + hi)
            if abs(xt - xn) < 1e-16:
                xn = xt
                break
            xn = xt
        F, _, state = elem.force(xn, state, d)
        x = xn
        Tprev = T
        out[i] = x
    return out


class _Berg:
    """Berg (1998) smooth friction element (twist-driven), memory of the last reversal."""

    def __init__(self, Fm, x2):
        self.Fm, self.x2 = Fm, x2

    def init(self):
        return (0.0, 0.0)          # (x_s, F_s)

    def reverse(self, state, x, F, d):
        return (x, F)

    def force(self, x, state, d):
        xs, Fs = state
        Fm, x2 = self.Fm, self.x2
        a = max(min(Fs / Fm, 1 - 1e-12), -1 + 1e-12)
        r = x - xs
        if d > 0:
            r = max(r, 0.0)
            den = x2 * (1 - a) + r
            F = Fs + r / den * (Fm - Fs)
            dF = (Fm - Fs) * x2 * (1 - a) / den ** 2
        else:
            r = min(r, 0.0)
            den = x2 * (1 + a) - r
            F = Fs + r / den * (Fm + Fs)
            dF = (Fm + Fs) * x2 * (1 + a) / den ** 2
        return F, dF, state


class _PragerVoce:
    """Elasto-plastic element: spring ke, slider with linear kinematic (Prager) and Voce
    isotropic hardening; return mapping per step (twist-driven)."""

    def __init__(self, ke, H, s0, Q, b):
        self.ke, self.H, self.s0, self.Q, self.b = ke, H, s0, Q, b

    def init(self):
        return (0.0, 0.0)          # (theta_p, p)

    def reverse(self, state, x, F, d):
        return state

    def force(self, x, state, d):
        thp, p = state
        ke, H, s0, Q, b = self.ke, self.H, self.s0, self.Q, self.b
        Ftr = ke * (x - thp)
        xi = Ftr - H * thp
        sy = s0 + Q * (1 - math.exp(-b * p))
        if abs(xi) <= sy:
            return Ftr, ke, state
        dp = (abs(xi) - sy) / (ke + H)
        for _ in range(30):
            e = math.exp(-b * (p + dp))
            f = abs(xi) - (ke + H) * dp - (s0 + Q * (1 - e))
            df = -(ke + H) - Q * b * e
            st = f / df
            dp -= st
            if abs(st) <= 1e-15 * (1 + dp):
                break
        dp = max(dp, 0.0)
        thn = thp + math.copysign(dp, xi)
        hiso = Q * b * math.exp(-b * (p + dp))
        return ke * (x - thn), ke * (H + hiso) / (ke + H + hiso), (thn, p + dp)


def _loop_centre(td_twist, Td, legid, legs):
    """Centre line m(T) of the last complete loop and the loss at T = 0."""
    j_dn = max(j for j, (a, b) in enumerate(legs) if b < a)
    j_up = max(j for j, (a, b) in enumerate(legs) if b > a and a < 0)
    up = legid == j_up
    dn = legid == j_dn
    Tu, xu = Td[up], td_twist[up]
    Tn, xn = Td[dn][::-1], td_twist[dn][::-1]
    T0 = legs[0][1]
    G = np.linspace(-T0, T0, 1601)
    gu = np.interp(G, Tu, xu)
    gn = np.interp(G, Tn, xn)
    mid = 0.5 * (gu + gn)
    loss = float(np.interp(0.0, Tn, xn) - np.interp(0.0, Tu, xu))
    return G, mid, loss


def _hysteresis(rng, form, m, s, prot, td, Td, legid):
    """Loop about the catalog curve (its own centre line taken out), on the dense grid."""
    th0 = float(_theta_cat(prot.T0, m))
    target = m["hyst"] * float(rng.uniform(0.6, 1.5))
    info = {}
    if form == "berg":
        x2 = float(rng.uniform(0.04, 0.2)) * th0
        Fm = 0.5 * target * s * m["K1"]
        for _ in range(3):
            el = _Berg(Fm, x2)
            tw = _solve_parallel(Td, legid, prot.legs, m, s, el)
            G, mid, loss = _loop_centre(tw, Td, legid, prot.legs)
            if loss <= 0:
                return None
            Fm *= target / loss
        el = _Berg(Fm, x2)
        info.update(berg_Fmax_Nm=Fm, berg_x2_rad=x2)
    else:
        ke = float(rng.uniform(0.3, 0.8)) * s * m["K1"]
        xy = float(rng.uniform(0.08, 0.25)) * th0
        Hk = float(rng.uniform(0.05, 0.25))
        qv = float(rng.uniform(0.1, 0.5))
        bv = float(rng.uniform(2.0, 6.0)) / th0
        g = 1.0
        for _ in range(3):
            el = _PragerVoce(g * ke, g * Hk * ke, g * ke * xy, g * qv * ke * xy, bv)
            tw = _solve_parallel(Td, legid, prot.legs, m, s, el)
            G, mid, loss = _loop_centre(tw, Td, legid, prot.legs)
            if loss <= 0:
                return None
            g *= target / loss
        el = _PragerVoce(g * ke, g * Hk * ke, g * ke * xy, g * qv * ke * xy, bv)
        info.update(pv_ke_Nm_per_rad=g * ke, pv_H_Nm_per_rad=g * Hk * ke,
                    pv_sigma0_Nm=g * ke * xy, pv_Q_Nm=g * qv * ke * xy, pv_b_per_rad=bv)
    tw = _solve_parallel(Td, legid, prot.legs, m, s, el)
    G, mid, loss = _loop_centre(tw, Td, legid, prot.legs)
    h = tw - np.interp(Td, G, mid)
    info["loss_rad"] = loss
    info["loss_over_catalog"] = loss / m["hyst"]
    if not (0.4 <= loss / m["hyst"] <= 2.0):
        return None
    return h, info


def _backlash_fn(rng, form, m, T0):
    b = m["backlash"] * float(rng.uniform(0.6, 1.0))
    if form == "weibull":
        Tb = float(rng.uniform(0.01, 0.05)) * T0
        beta = float(rng.uniform(1.3, 3.0))

        def f(T, b=b):
            T = np.asarray(T, float)
            return np.sign(T) * 0.5 * b * (1 - np.exp(-(np.abs(T) / Tb) ** beta))
        info = dict(backlash_rad=b, weibull_T_Nm=Tb, weibull_beta=beta)
    else:
        Tc = float(rng.uniform(0.01, 0.06)) * T0

        def f(T, b=b):
            T = np.asarray(T, float)
            return np.sign(T) * 0.5 * b * np.minimum(1.0, np.sqrt(np.abs(T) / Tc))
        info = dict(backlash_rad=b, sneddon_seat_T_Nm=Tc)
    info["backlash_over_catalog"] = b / m["backlash"]
    return f, b, info


_ISO_M = [2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 20.0, 24.0]


def _tate_rosenfeld(d, t1, t2, E1, E2, Eb=206e9, nub=0.3):
    return (1 / (Eb * t1) + 1 / (Eb * t2) + 1 / (E1 * t1) + 1 / (E2 * t2)
            + 32 * (t1 + t2) * (1 + nub) / (9 * Eb * math.pi * d * d)
            + 8 * (t2 ** 3 + 5 * t2 ** 2 * t1 + 5 * t2 * t1 ** 2 + t1 ** 3) / (5 * Eb * math.pi * d ** 4))


def _housing(rng, form, m):
    """Series spring (linear in T) from a physical estimate; 15-55 % of 1/K1."""
    cK = 1.0 / m["K1"]
    size = m["size"]
    for _ in range(200):
        f_t = float(rng.uniform(0.15, 0.55))
        if form == "tate-rosenfeld":
            n = int(_pick(rng, [6, 8, 12]))
            rb = float(rng.uniform(0.9, 1.3)) * size * 1e-3
            t1 = float(rng.uniform(0.2, 0.45)) * size * 1e-3
            t2 = t1 * float(rng.uniform(0.8, 1.25))
            E1 = float(_pick(rng, [70e9, 206e9]))     # aluminium or steel test adapter
            E2 = 206e9
            ctarget = f_t * cK * n * rb * rb
            g = lambda d: _tate_rosenfeld(d, t1, t2, E1, E2) - ctarget
            if g(0.5e-3) < 0 or g(40e-3) > 0:
                continue
            d = optimize.brentq(g, 0.5e-3, 40e-3)
            dstd = min(_ISO_M, key=lambda q: abs(q - d * 1e3)) * 1e-3
            ch = _tate_rosenfeld(dstd, t1, t2, E1, E2) / (n * rb * rb)
            frac = ch / cK
            if 0.15 <= frac <= 0.55 and 0.5 <= t1 / dstd <= 4.0 and dstd >= 2e-3:
                return ch, dict(housing_fraction=frac, tr_bolts=float(n), tr_bolt_d_m=dstd,
                                tr_bolt_circle_r_m=rb, tr_t1_m=t1, tr_t2_m=t2, tr_E_adapter_Pa=E1)
        else:
            r = float(rng.uniform(0.3, 0.5)) * size * 1e-3
            t = float(rng.uniform(0.15, 0.3)) * r
            E, G = 206e9, 79.3e9
            J = 2 * math.pi * r * t ** 3 / 3
            Gam = 2 * math.pi ** 3 * r ** 5 * t / 3
            lam = math.sqrt(G * J / (E * Gam))
            comp = lambda L: (L - math.tanh(lam * L) / lam) / (G * J)
            ct = f_t * cK
            if comp(8 * r) < ct or comp(1.5 * r) > ct:
                continue
            L = optimize.brentq(lambda L: comp(L) - ct, 1.5 * r, 8 * r)
            return comp(L), dict(housing_fraction=comp(L) / cK, vlasov_r_m=r, vlasov_t_m=t,
                                 vlasov_L_m=L, vlasov_lambda_per_m=lam)
    return None


def _torsion_case(rng, cat, cell, idx):
    kind = "torsion"
    category, effects, form, meas, equiv = cell["category"], cell["effects"], cell["form"], \
        cell.get("meas", ()), cell.get("equiv", ())
    models = cat.torsion
    if cell.get("small"):
        models = [mm for mm in models if mm["size"] <= 32]
    for attempt in range(400):
        m = _pick(rng, models)
        nuis = {}
        if form == "stiff-beyond-spread":
            s = float(rng.uniform(1.13, 1.25))
        else:
            s = _semicircle(rng)
        T0 = m["rated"] * float(rng.uniform(*cell.get("T0_range", (0.85, 1.1))))
        prot = _Protocol(rng, T0, cell.get("ncyc"))
        th0 = float(_theta_cat(T0, m))
        offset = float(rng.uniform(-0.05, 0.05)) * th0
        td, Td, legid = prot.dense()
        eff_d = {}           # dense (for hysteresis-like path-dependent parts)
        mem = {}             # memoryless functions of T
        infos = {}
        ok = True
        fparts = form.split("+")
        for e, fo in zip(effects, fparts if len(fparts) == len(effects) else [form] * len(effects)):
            if e == "hysteresis":
                r = _hysteresis(rng, fo, m, s, prot, td, Td, legid)
                if r is None:
                    ok = False
                    break
                eff_d[e], infos[e] = r
            elif e == "backlash":
                f, b, inf = _backlash_fn(rng, fo, m, T0)
                mem[e], infos[e] = f, inf
            elif e == "housing_compliance":
                r = _housing(rng, fo, m)
                if r is None:
                    ok = False
                    break
                ch, inf = r
                mem[e] = (lambda T, ch=ch: ch * np.asarray(T, float))
                infos[e] = inf
        if not ok:
            continue
        # rig (decoy-equivalent) mechanisms
        if category == "decoy_equivalent":
            if form == "belt-lock-stretch":
                rp = float(rng.uniform(8, 20)) * 1e-3
                EA = float(rng.uniform(1.5e4, 6e4))          # GT2/GT3-class glass-cord belt, N
                f_t = float(rng.uniform(0.15, 0.55))
                kin = m["K1"] / f_t / m["ratio"] ** 2          # needed torsional stiffness at input
                kb = kin / rp ** 2
                Lspan = 2 * EA / kb                             # both spans act (pretensioned belt)
                if not (0.05 <= Lspan <= 1.5):
                    continue
                ch = 1.0 / (kb * rp ** 2 * m["ratio"] ** 2)
                mem["rig"] = (lambda T, ch=ch: ch * np.asarray(T, float))
                infos["rig"] = dict(belt_pulley_r_m=rp, belt_EA_N=EA, belt_span_m=Lspan,
                                    belt_fraction_of_gear=ch * m["K1"])
            elif form == "belt-tooth-play":
                rp = float(rng.uniform(8, 20)) * 1e-3
                ct = float(rng.uniform(0.03, 0.15)) * 1e-3
                bb = ct / rp / m["ratio"]
                Te = float(rng.uniform(0.01, 0.05)) * T0

                def fb(T, bb=bb, Te=Te):
                    T = np.asarray(T, float)
                    xx = np.abs(T) / Te
                    return np.sign(T) * 0.5 * bb * xx / (1 + xx)
                mem["rig"] = fb
                infos["rig"] = dict(belt_pulley_r_m=rp, belt_tooth_clearance_m=ct,
                                    reflected_play_rad=bb, take_up_T_Nm=Te)
            elif form == "slip-ring-brush-drag":
                nb = int(rng.integers(4, 25))
                Nb = float(rng.uniform(0.5, 2.0))
                mu = float(rng.uniform(0.2, 0.35))
                rr = float(rng.uniform(10, 30)) * 1e-3
                Fc = nb * Nb * mu * rr
                xbr = float(rng.uniform(2e-6, 1e-5))
                el = _PragerVoce(Fc / xbr, 0.0, Fc, 0.0, 0.0)
                tw = _solve_parallel(Td, legid, prot.legs, m, s, el)
                eff_d["rig"] = tw - _theta_cat(Td, m) / s
                infos["rig"] = dict(brush_count=float(nb), brush_force_N=Nb, brush_mu=mu,
                                    ring_r_m=rr, brush_drag_Nm=Fc, brush_presliding_rad=xbr)
        # sampling
        base_d = _theta_cat(Td, m) / s + offset
        tot_d = base_d.copy()
        for k_, a_ in eff_d.items():
            tot_d += a_
        for k_, f_ in mem.items():
            tot_d += f_(Td)
        if prot.law == "cycloid":
            ts = np.linspace(0.0, prot.D, prot.n_samples)
        else:
            L = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(tot_d)))])
            L = L + 1e-12 * L[-1] * np.arange(len(L)) / len(L)
            ts = np.interp(np.linspace(0, L[-1], prot.n_samples), L, td)
        T = prot.torque(ts)
        base = _theta_cat(T, m) / s + offset
        parts = {}
        for k_, a_ in eff_d.items():
            parts[k_] = np.interp(ts, td, a_)
        for k_, f_ in mem.items():
            parts[k_] = f_(T)
        tsec = ts * prot.leg_time_s
        # nuisance columns: catalog curve (coefficient limited to the spread) and an offset
        cat_col = _theta_cat(T, m)
        lo_c, hi_c = 1 / (1 + SPREAD) - 1 / s, 1 / (1 - SPREAD) - 1 / s
        if form == "stiff-beyond-spread":
            lo_c, hi_c = -np.inf, np.inf
        ncols = [(cat_col, (lo_c, hi_c)), (np.ones_like(T), (-np.inf, np.inf))]
        nuis.update(stiffness_scale=s, T0_Nm=T0, T0_over_rated=T0 / m["rated"],
                    twist_offset_rad=offset, protocol_cycloid=1.0 if prot.law == "cycloid" else 0.0,
                    protocol_cycles=float(prot.ncyc), test_duration_s=prot.D * prot.leg_time_s)
        for e, inf in infos.items():
            for k_, v_ in inf.items():
                nuis[f"{k_}"] = float(v_)
        noise_kind = _noise_kind(rng, category)
        outl = bool(rng.random() < 0.2)
        torque_col = T.copy()
        clean = base.copy()
        snr = 0.0
        if category == "clean":
            noise_kind, outl = cell["noise"], cell["noise_out"]
            noise = th0 * float(rng.uniform(0.002, 0.008))
        elif category == "single":
            e = effects[0]
            r = _size_single(rng, parts[e], ncols)
            if r is None:
                continue
            k, noise, qb, qu = r
            clean = base + parts[e]
            nuis.update({f"k_{e}": k, "after_nuisance_ratio": qb, "after_nuisance_ratio_unbounded": qu})
            snr = k
        elif category == "pair":
            e1, e2 = effects
            a1 = parts[e1]
            a2 = parts[e2]
            g_range = _g_range_torsion(e2, nuis, m, cell.get("b_max", 3.0))
            r = _size_pair(rng, a1, a2, ncols, g_range)
            if r is None:
                continue
            _rescale_info_torsion(e2, nuis, r["g"])
            clean = base + a1 + r["e2"]
            noise = r["noise"]
            snr = _rms(a1 + r["e2"]) / noise
            nuis.update({f"k_{e1}": r["k1"], f"k_{e2}": r["k2"],
                         "after_nuisance_ratio": r["qt"], "after_nuisance_ratio_unbounded": r["qtu"],
                         f"after_nuisance_ratio_{e1}_alone": r["q1a"],
                         f"after_nuisance_ratio_{e2}_alone": r["q2a"],
                         f"after_nuisance_ratio_{e1}_given_{e2}": r["q1g"],
                         f"after_nuisance_ratio_{e2}_given_{e1}": r["q2g"],
                         f"after_nuisance_ratio_{e1}_alone_unbounded": r["q1u"],
                         f"after_nuisance_ratio_{e2}_alone_unbounded": r["q2u"]})
        elif category == "decoy_equivalent":
            r = _size_single(rng, parts["rig"], ncols)
            if r is None:
                continue
            k, noise, qb, qu = r
            clean = base + parts["rig"]
            snr = k
            nuis.update(k_decoy=k, after_nuisance_ratio=qb, after_nuisance_ratio_unbounded=qu)
        else:   # decoy_separable
            noise = th0 * float(rng.uniform(0.002, 0.008))
            if form == "mV/V-sheet-mismatch":
                St, Ss = _pick(rng, [(2.0, 1.5), (2.0, 1.6), (1.5, 1.2), (3.0, 2.0), (2.5, 2.0)])
                torque_col = T * St / Ss
                nuis.update(torque_gain=St / Ss, bridge_true_mV_per_V=St, bridge_set_mV_per_V=Ss)
                snr = _rms(_theta_cat(torque_col, m) / s - base) / noise
            elif form == "line-source-drift":
                tc = float(rng.uniform(0.1, 0.5)) * tsec[-1]
                dshape = _line_source(tsec, tc)
                r = _size_single(rng, dshape, ncols)
                if r is None:
                    continue
                k, nz, qb, qu = r
                amp = float(rng.uniform(0.02, 0.08)) * th0
                dr = dshape / _rms(dshape) * amp
                noise = amp / k
                clean = base + dr
                snr = k
                nuis.update(drift_tc_s=tc, drift_rms_rad=amp, k_decoy=k, after_nuisance_ratio=qb)
            elif form == "absolute-track-step":
                t_step = float(rng.uniform(0.3, 0.8)) * tsec[-1]
                shape = (tsec >= t_step).astype(float)
                r = _size_single(rng, shape, ncols)
                if r is None:
                    continue
                k, nz, qb, qu = r
                step = float(rng.uniform(0.01, 0.05)) * th0 * float(rng.choice([-1, 1]))
                noise = _rms(shape * step) / k
                clean = base + shape * step
                snr = k
                nuis.update(step_rad=step, step_time_s=t_step, k_decoy=k, after_nuisance_ratio=qb)
            elif form == "degrees":
                clean = base * DEG
                noise = noise * DEG
                snr = _rms(base * (DEG - 1)) / noise
                nuis["twist_unit_factor"] = DEG
            elif form == "kNm":
                torque_col = T * 1e-3
                nuis["torque_unit_factor"] = 1e-3
                snr = _rms(_theta_cat(torque_col, m) / s - base) / noise
            elif form == "stiff-beyond-spread":
                snr = _rms(base - _theta_cat(T, m)) / noise
        twist = _finish(rng, clean, noise, noise_kind, outl, nuis)
        if not np.all(np.isfinite(twist)):
            continue
        nuis["snr"] = float(snr)
        return TruthCase(
            name="", kind=kind, model=m["code"],
            columns={"torque_Nm": torque_col, "twist_rad": twist},
            load_inertia_kgm2=None,
            gear_effects=tuple(effects) if category in ("single", "pair") else (),
            measurement_effects=tuple(meas), nuisance=nuis, category=category,
            equivalent_effects=tuple(equiv), noise_rms=float(noise), formulation=cell["label"],
            snr=float(snr))
    raise RuntimeError(f"could not draw a torsion case for {cell}")


def _g_range_torsion(e2, nuis, m, b_max=3.0):
    if e2 == "housing_compliance":
        f = nuis["housing_fraction"]
        return (0.15 / f, 0.55 / f)
    if e2 == "backlash":
        b = nuis["backlash_over_catalog"]
        return (0.3 / b, b_max / b)
    if e2 == "hysteresis":
        h = nuis["loss_over_catalog"]
        return (0.3 / h, 2.0 / h)
    return (0.3, 3.0)


def _rescale_info_torsion(e2, nuis, g):
    nuis["pair_rescale_" + e2] = g
    if e2 == "housing_compliance":
        nuis["housing_fraction"] *= g
    elif e2 == "backlash":
        nuis["backlash_rad"] *= g
        nuis["backlash_over_catalog"] *= g
    elif e2 == "hysteresis":
        nuis["loss_rad"] *= g
        nuis["loss_over_catalog"] *= g


# --------------------------------------------------------------------------------------------
# transmission error waveforms (used by transmission and vibration)
# --------------------------------------------------------------------------------------------
def _te_params(rng, effect, form, acc):
    """Parameters of one TE component; amplitude relative to the catalog accuracy."""
    p = dict(effect=effect, form=form, phi=float(rng.uniform(0, 2 * np.pi)))
    if effect == "te_1x":
        p["a"] = float(rng.uniform(0.12, 0.35)) * acc
        if form == "cage-am":
            p["m"] = float(rng.uniform(0.15, 0.4))
            p["psi"] = float(rng.uniform(0, 2 * np.pi))
        else:  # trilobe
            p["a3"] = float(rng.uniform(0.2, 0.45)) * p["a"]
            p["phi3"] = float(rng.uniform(0, 2 * np.pi))
    else:
        p["a"] = float(rng.uniform(0.12, 0.35)) * acc
        if form == "cage-am":
            p["m"] = float(rng.uniform(0.15, 0.4))
            p["psi"] = float(rng.uniform(0, 2 * np.pi))
        else:  # ring creep
            p["eps"] = float(rng.uniform(0.003, 0.012))
    return p


def _cage_rate(rng):
    gam = float(rng.uniform(0.14, 0.24))           # ball / pitch diameter of the WG bearing
    rho_c = 0.5 * (1 - gam)                         # cage speed / input speed (contact angle 0)
    return gam, 1.0 - rho_c                         # modulation: cage relative to the cam


def _te_eval(p, th, rho_m=None):
    a, phi = p["a"], p["phi"]
    if p["effect"] == "te_1x":
        if p["form"] == "cage-am":
            return a * np.sin(th + phi) * (1 + p["m"] * np.sin(rho_m * th + p["psi"]))
        return a * np.sin(th + phi) + p["a3"] * np.sin(3 * th + p["phi3"])
    if p["form"] == "cage-am":
        return a * np.sin(2 * th + phi) * (1 + p["m"] * np.sin(rho_m * th + p["psi"]))
    return a * np.sin(2 * (1 - p["eps"]) * th + phi)


def _te_info(p, tag):
    out = {}
    for k, v in p.items():
        if isinstance(v, float):
            out[f"{tag}_{k}"] = v
    return out


# --------------------------------------------------------------------------------------------
# TRANSMISSION
# --------------------------------------------------------------------------------------------
def _transmission_case(rng, cat, cell, idx):
    category, effects, form = cell["category"], cell["effects"], cell["form"]
    for attempt in range(400):
        m = _pick(rng, cat.accurate)
        R, acc = m["ratio"], m["accuracy"]
        nrev = float(rng.uniform(5.0, 10.0))
        nper = int(rng.integers(200, 361))
        n = int(nrev * nper)
        th0 = float(rng.uniform(0, 2 * np.pi))
        th = th0 + np.linspace(0, 2 * np.pi * nrev, n)
        offset = float(rng.uniform(-0.05, 0.05))
        out_base = th / R + offset
        nuis = dict(output_offset_rad=offset, input_revolutions=nrev, samples_per_rev=float(nper),
                    input_start_angle_rad=th0)
        gam, rho_m = _cage_rate(rng)
        ncols = [(np.ones(n), (-np.inf, np.inf))]
        parts = {}
        forms = form.split("+")
        for e, fo in zip(effects, forms if len(forms) == len(effects) else [form] * len(effects)):
            p = _te_params(rng, e, fo, acc)
            parts[e] = _te_eval(p, th, rho_m)
            nuis.update(_te_info(p, e))
            if fo == "cage-am":
                nuis.update(wg_ball_to_pitch=gam, cage_modulation_order=rho_m)
        noise_kind = _noise_kind(rng, category)
        outl = bool(rng.random() < 0.2)
        in_col = th.copy()
        clean = out_base.copy()
        snr = 0.0
        base_noise = acc * float(rng.uniform(0.01, 0.04))
        tnorm = np.linspace(0, 1, n)
        if category == "clean":
            noise_kind, outl = cell["noise"], cell["noise_out"]
            noise = base_noise
        elif category == "single":
            e = effects[0]
            r = _size_single(rng, parts[e], ncols)
            if r is None:
                continue
            k, noise, qb, qu = r
            clean = out_base + parts[e]
            snr = k
            nuis.update({f"k_{e}": k, "after_nuisance_ratio": qb})
        elif category == "pair":
            e1, e2 = effects
            r = _size_pair(rng, parts[e1], parts[e2], ncols, (0.3, 3.0))
            if r is None:
                continue
            nuis[f"{e2}_a"] *= r["g"]
            nuis["pair_rescale_" + e2] = r["g"]
            if f"{e2}_a3" in nuis:
                nuis[f"{e2}_a3"] *= r["g"]
            if nuis[f"{e2}_a"] > 0.6 * acc:
                continue
            clean = out_base + parts[e1] + r["e2"]
            noise = r["noise"]
            snr = _rms(parts[e1] + r["e2"]) / noise
            nuis.update({f"k_{e1}": r["k1"], f"k_{e2}": r["k2"], "after_nuisance_ratio": r["qt"],
                         f"after_nuisance_ratio_{e1}_alone": r["q1a"],
                         f"after_nuisance_ratio_{e2}_alone": r["q2a"],
                         f"after_nuisance_ratio_{e1}_given_{e2}": r["q1g"],
                         f"after_nuisance_ratio_{e2}_given_{e1}": r["q2g"]})
        elif category == "decoy_equivalent":
            if form == "tape-butt-joint":
                dg = float(rng.uniform(20, 200)) * 1e-6
                rd = float(rng.uniform(30, 80)) * 1e-3
                w = dg / rd
                jpos = float(rng.uniform(0, 2 * np.pi))
                ph = np.mod(th - jpos, 2 * np.pi)
                err = np.where(ph < 2 * np.pi - w, ph * w / (2 * np.pi - w), 2 * np.pi - ph)
                nuis.update(tape_gap_m=dg, tape_drum_r_m=rd, tape_joint_angle_rad=jpos)
            else:  # oldham middle-disc ring
                eo = float(rng.uniform(0.01, 0.15)) * 1e-3
                rr = float(rng.uniform(20, 50)) * 1e-3
                ph = float(rng.uniform(0, 2 * np.pi))
                err = eo / (2 * rr) * np.sin(2 * th + ph)
                nuis.update(oldham_offset_m=eo, ring_r_m=rr, ring_phase_rad=ph)
            apparent = -err / R
            r = _size_single(rng, apparent, ncols)
            if r is None:
                continue
            k, noise, qb, qu = r
            in_col = th + err
            snr = k
            nuis.update(k_decoy=k, after_nuisance_ratio=qb,
                        apparent_te_rms_over_accuracy=_rms(apparent) / acc)
        else:  # decoy_separable
            noise = base_noise
            th_out = th / R
            if form == "dual-head-residual":
                e_ = float(rng.uniform(5, 30)) * 1e-6
                rdisc = float(rng.uniform(40, 100)) * 1e-3
                gm = float(rng.uniform(0.02, 0.15))
                ph = float(rng.uniform(0, 2 * np.pi))
                d = 0.5 * gm * e_ / rdisc * np.sin(th_out + ph)
                r = _size_single(rng, d, ncols)
                if r is None:
                    continue
                k, noise, qb, qu = r
                clean = out_base + d
                snr = k
                nuis.update(disc_eccentricity_m=e_, disc_r_m=rdisc, head_gain_mismatch=gm,
                            k_decoy=k, after_nuisance_ratio=qb)
            elif form == "degrees":
                clean = out_base * DEG
                noise = base_noise * DEG
                snr = _rms(out_base * (DEG - 1)) / noise
                nuis["output_unit_factor"] = DEG
            elif form == "line-source-drift":
                tc = float(rng.uniform(0.1, 0.5))
                d = _line_source(tnorm, tc)
                r = _size_single(rng, d, ncols)
                if r is None:
                    continue
                k, nz, qb, qu = r
                amp = float(rng.uniform(0.05, 0.3)) * acc
                noise = amp / k
                clean = out_base + d / _rms(d) * amp
                snr = k
                nuis.update(drift_tc_fraction=tc, drift_rms_rad=amp, k_decoy=k, after_nuisance_ratio=qb)
            elif form == "absolute-track-step":
                ts_ = float(rng.uniform(0.25, 0.8))
                shape = (tnorm >= ts_).astype(float)
                r = _size_single(rng, shape, ncols)
                if r is None:
                    continue
                k, nz, qb, qu = r
                step = float(rng.uniform(0.05, 0.4)) * acc * float(rng.choice([-1, 1]))
                noise = _rms(shape * step) / k
                clean = out_base + shape * step
                snr = k
                nuis.update(step_rad=step, step_fraction=ts_, k_decoy=k, after_nuisance_ratio=qb)
        out = _finish(rng, clean, noise, noise_kind, outl, nuis)
        if not np.all(np.isfinite(out)):
            continue
        nuis["snr"] = float(snr)
        return TruthCase(
            name="", kind="transmission", model=m["code"],
            columns={"input_angle_rad": in_col, "output_angle_rad": out}, load_inertia_kgm2=None,
            gear_effects=tuple(effects) if category in ("single", "pair") else (),
            measurement_effects=tuple(cell.get("meas", ())), nuisance=nuis, category=category,
            equivalent_effects=tuple(cell.get("equiv", ())), noise_rms=float(noise),
            formulation=cell["label"], snr=float(snr))
    raise RuntimeError(f"could not draw a transmission case for {cell}")


# --------------------------------------------------------------------------------------------
# EFFICIENCY
# --------------------------------------------------------------------------------------------
_R10 = [0.1, 0.125, 0.16, 0.2, 0.25, 0.315, 0.4, 0.5, 0.63, 0.8, 1.0]


def _ke_from_loss(lam_fn, alpha):
    """Ke(alpha) = [a/(a+lam(a))] / [1/(1+lam(1))], Ke = 1 for alpha >= 1 (catalog)."""
    a = np.asarray(alpha, float)
    raw = a / (a + lam_fn(a))
    ref = 1.0 / (1.0 + float(lam_fn(np.array([1.0]))[0]))
    return np.where(a >= 1.0, 1.0, np.minimum(raw / ref, 1.0))


def _low_load(rng, form):
    kap = float(rng.uniform(0.90, 0.95))
    if form == "goksem-hargreaves":
        w0 = float(rng.uniform(0.5, 3.0))
        base = lambda a, l0: l0 * ((w0 + a) / (w0 + 1.0)) ** 0.246
        info = dict(gh_preload_share=w0)
    else:  # jkr
        aa = float(rng.uniform(0.02, 0.2))
        gfun = lambda p: (p + 1 + np.sqrt(2 * p + 1)) ** (2.0 / 3.0)
        base = lambda a, l0: l0 * gfun(np.asarray(a, float) / aa) / gfun(1.0 / aa)
        info = dict(jkr_adhesion_load_fraction=aa)
    l0 = optimize.brentq(lambda l: float(_ke_from_loss(lambda a: base(a, l), np.array([0.58]))[0]) - kap,
                         1e-6, 20.0)
    info.update(Ke_058=kap, loss_lambda0=l0)
    return (lambda a: _ke_from_loss(lambda x: base(x, l0), a)), info


def _dippr_visc(rng, grade=None):
    """DIPPR-101 ln(nu) = A + B/T + C ln T fitted through nu40 and nu100 of an ISO VG oil."""
    for _ in range(100):
        vg = float(grade or _pick(rng, [32.0, 46.0, 68.0, 100.0]))
        nu40 = vg * float(rng.uniform(0.9, 1.1))
        nu100 = nu40 / float(rng.uniform(6.5, 9.5))
        C = float(rng.uniform(-2.0, 2.0))
        T1, T2 = 313.15, 373.15
        y1, y2 = math.log(nu40) - C * math.log(T1), math.log(nu100) - C * math.log(T2)
        B = (y1 - y2) / (1 / T1 - 1 / T2)
        A = y1 - B / T1
        TT = np.linspace(253.15, 393.15, 200)
        if np.all(-B / TT ** 2 + C / TT < 0):
            f = lambda Tc: np.exp(A + B / (np.asarray(Tc, float) + 273.15) + C * np.log(np.asarray(Tc, float) + 273.15))
            return f, dict(oil_vg=vg, oil_nu40_cSt=nu40, oil_nu100_cSt=nu100, dippr_A=A,
                           dippr_B=B, dippr_C=C)
    raise RuntimeError("viscosity")


def _temperature(rng, form):
    for _ in range(200):
        r = _temperature_draw(rng, form)
        lo = float(np.min(r[0][1](np.array([0.0])))) if r[0][0] == "mult" else 1.0
        if r[0][0] == "add" or 0.6 <= lo <= 0.9:
            return r
    raise RuntimeError("temperature law")


def _temperature_draw(rng, form):
    if form == "casson-dippr":
        visc, info = _dippr_visc(rng)
        ty40 = float(rng.uniform(20, 200))
        by = float(rng.uniform(0.01, 0.03))
        gd = float(rng.uniform(1e3, 1e4))
        Lr = float(rng.uniform(0.03, 0.10))
        rho = 870.0

        def tauC(Tc):
            mu = visc(Tc) * 1e-6 * rho
            ty = ty40 * np.exp(-by * (np.asarray(Tc, float) - 40.0))
            return (np.sqrt(ty) + np.sqrt(mu * gd)) ** 2
        t40 = float(tauC(np.array([40.0]))[0])
        fT = lambda Tc: (1 + Lr) / (1 + Lr * tauC(Tc) / t40)
        info.update(casson_tau_y40_Pa=ty40, casson_beta_per_K=by, shear_rate_per_s=gd, loss_ref=Lr)
        return ("mult", fT), info
    # additive, Hildebrand free-volume fluidity
    av = float(rng.uniform(6.5e-4, 8e-4))
    rho0 = float(rng.uniform(3.0, 8.0))
    one_v0 = 40 * av * rho0 / (rho0 - 1)
    D = float(rng.uniform(2.0, 5.0))

    def dT(Tc):
        Tc = np.asarray(Tc, float)
        r = one_v0 / (one_v0 + av * (Tc - 40.0))
        return -2.0 * D * (r - 1) / (r + 1)
    return ("add", dT), dict(hildebrand_alpha_v_per_K=av, hildebrand_1_minus_v0=one_v0,
                             visc_ratio_0C=rho0, additive_D_pct=D)


def _eff_grid(rng, m):
    speeds = [v for v in [500.0, 1000.0, 1500.0, 2000.0, 3000.0] if v <= m["avg_speed"]]
    ns = int(rng.integers(3, 4 + (len(speeds) > 4)))
    sp = sorted(rng.choice(speeds, size=min(ns, len(speeds)), replace=False).tolist())
    temps_all = [0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0]
    nt = int(rng.integers(4, 6))
    tp = sorted(rng.choice(temps_all, size=nt, replace=False).tolist())
    if 40.0 not in tp:
        tp[int(np.argmin(np.abs(np.array(tp) - 40.0)))] = 40.0
        tp = sorted(set(tp))
    rows = []
    tclock = 0.0
    for bi, Tset in enumerate(tp):                  # oven blocks in rising temperature
        tclock += 30.0                              # soak gap
        sps = sp if bi % 2 == 0 else sp[::-1]       # boustrophedon over speeds and loads
        for si, n in enumerate(sps):
            ll = _R10 if (si + bi) % 2 == 0 else _R10[::-1]
            for a in ll:
                rows.append((n, a, Tset + float(rng.normal(0, 0.3)), tclock))
                tclock += 1.0
    arr = np.array(rows)
    return arr[:, 0], arr[:, 1], arr[:, 2], arr[:, 3]


def _efficiency_case(rng, cat, cell, idx):
    category, effects, form = cell["category"], cell["effects"], cell["form"]
    for attempt in range(400):
        m = _pick(rng, cat.models)
        n_rpm, alpha, temp, tclock = _eff_grid(rng, m)
        N = len(n_rpm)
        load = alpha * m["rated"]
        if form == "level-low":
            L = float(rng.uniform(40.0, 52.0))
        else:
            L = 62.0 + 22.0 * float(rng.beta(2.0, 2.0))
        nuis = dict(efficiency_level_pct=L)
        ncols = [(np.ones(N), (-np.inf, np.inf))]
        forms = form.split("+")
        fmap = dict(zip(effects, forms if len(forms) == len(effects) else [form] * len(effects)))
        ke = None
        tlaw = None
        if "low_load_efficiency" in effects:
            kef, inf = _low_load(rng, fmap["low_load_efficiency"])
            ke = kef(alpha)
            nuis.update(inf)
        if "temperature_dependence" in effects:
            tlaw, inf = _temperature(rng, fmap["temperature_dependence"])
            nuis.update(inf)
        parts = {}
        if ke is not None:
            parts["low_load_efficiency"] = L * (ke - 1.0)
        if tlaw is not None:
            if tlaw[0] == "mult":
                parts["temperature_dependence"] = L * (tlaw[1](temp) - 1.0)
            else:
                parts["temperature_dependence"] = tlaw[1](temp)

        def total_eta(Lx, ke_, tl_, g2=1.0, who2=None):
            ke_v = np.ones(N) if ke_ is None else ke_
            if who2 == "low_load_efficiency":
                ke_v = 1.0 + g2 * (ke_v - 1.0)
            eta = Lx * ke_v
            if tl_ is not None:
                if tl_[0] == "mult":
                    ft = tl_[1](temp)
                    if who2 == "temperature_dependence":
                        ft = 1.0 + g2 * (ft - 1.0)
                    eta = eta * ft
                else:
                    dd = tl_[1](temp)
                    if who2 == "temperature_dependence":
                        dd = g2 * dd
                    eta = eta + dd
            return eta
        noise_kind = _noise_kind(rng, category)
        outl = bool(rng.random() < 0.2)
        base_noise = float(rng.uniform(0.2, 0.8))
        clean = np.full(N, L)
        col_speed, col_load = n_rpm.copy(), load.copy()
        snr = 0.0
        unit = 1.0
        if category == "clean":
            noise_kind, outl = cell["noise"], cell["noise_out"]
            noise = base_noise
        elif category == "single":
            e = effects[0]
            r = _size_single(rng, parts[e], ncols)
            if r is None:
                continue
            k, noise, qb, qu = r
            clean = total_eta(L, ke, tlaw)
            snr = k
            nuis.update({f"k_{e}": k, "after_nuisance_ratio": qb})
        elif category == "pair":
            e1, e2 = effects
            if e2 == "temperature_dependence":
                g_range = (0.4, 2.0)
            else:
                kk = nuis["Ke_058"]
                g_range = (0.04 / (1 - kk), 0.12 / (1 - kk))
            r = _size_pair(rng, parts[e1], parts[e2], ncols, g_range)
            if r is None:
                continue
            clean = total_eta(L, ke, tlaw, r["g"], e2)
            if e2 == "low_load_efficiency":
                nuis["Ke_058"] = 1 - r["g"] * (1 - nuis["Ke_058"])
            nuis["pair_rescale_" + e2] = r["g"]
            noise = r["noise"]
            snr = _rms(clean - L) / noise
            nuis.update({f"k_{e1}": r["k1"], f"k_{e2}": r["k2"], "after_nuisance_ratio": r["qt"],
                         f"after_nuisance_ratio_{e1}_alone": r["q1a"],
                         f"after_nuisance_ratio_{e2}_alone": r["q2a"],
                         f"after_nuisance_ratio_{e1}_given_{e2}": r["q1g"],
                         f"after_nuisance_ratio_{e2}_given_{e1}": r["q2g"]})
        elif category == "decoy_equivalent":
            if form == "brake-residual":
                kap = float(rng.uniform(0.90, 0.96))
                ares = 0.58 * (1 / kap - 1)
                clean = L * alpha / (alpha + ares)
                nuis.update(brake_residual_Nm=ares * m["rated"], brake_residual_fraction=ares,
                            apparent_Ke_058=kap)
            else:  # coupling churning in the bath
                visc, inf = _dippr_visc(rng)
                mexp = float(rng.uniform(0.3, 0.6))
                ell = float(rng.uniform(0.01, 0.05))
                ratio_mu = visc(temp) / float(visc(np.array([40.0]))[0])
                clean = L / (1 + ell * ratio_mu ** mexp / alpha)
                nuis.update(inf)
                nuis.update(churn_loss_ratio_rated_40C=ell, churn_visc_exponent=mexp)
            r = _size_single(rng, clean - L, ncols)
            if r is None:
                continue
            k, noise, qb, qu = r
            snr = k
            nuis.update(k_decoy=k, after_nuisance_ratio=qb)
        else:  # decoy_separable
            noise = base_noise
            if form == "fraction":
                unit = 0.01
                snr = _rms(clean * (1 - unit)) / (noise * unit)
            elif form == "per-mille":
                unit = 10.0
                snr = _rms(clean * (unit - 1)) / (noise * unit)
            elif form == "kNm":
                col_load = load * 1e-3
                nuis["load_unit_factor"] = 1e-3
                snr = 0.0
            elif form == "ratio-label":
                others = [q for q in cat.ratios[(m["series"], m["size"])] if q != m["ratio"]]
                if not others:
                    continue
                Rl = float(_pick(rng, others))
                g = m["ratio"] / Rl
                if L * g > 97.0 or L * g < 30.0:
                    continue
                clean = clean * g
                snr = _rms(clean - L) / noise
                nuis.update(ratio_label=Rl, efficiency_gain=g)
            elif form == "level-low":
                snr = 0.0
        y = _finish(rng, clean * unit, noise * unit, noise_kind, outl, nuis)
        if not np.all(np.isfinite(y)):
            continue
        nuis["snr"] = float(snr)
        nuis["grid_rows"] = float(N)
        return TruthCase(
            name="", kind="efficiency", model=m["code"],
            columns={"input_speed_rpm": col_speed, "load_torque_Nm": col_load,
                     "temperature_C": temp, "efficiency_pct": y},
            load_inertia_kgm2=None,
            gear_effects=tuple(effects) if category in ("single", "pair") else (),
            measurement_effects=tuple(cell.get("meas", ())), nuisance=nuis, category=category,
            equivalent_effects=tuple(cell.get("equiv", ())), noise_rms=float(noise * unit),
            formulation=cell["label"], snr=float(snr))
    raise RuntimeError(f"could not draw an efficiency case for {cell}")


# --------------------------------------------------------------------------------------------
# VIBRATION
# --------------------------------------------------------------------------------------------
def _runup(rng, kind, N0, N1):
    if kind == "arctan":
        a = float(rng.uniform(2.0, 6.0))
        tc = float(rng.uniform(0.35, 0.65))
        lo, hi = math.atan(-a * tc), math.atan(a * (1 - tc))
        f = lambda u: N0 + (N1 - N0) * (np.arctan(a * (u - tc)) - lo) / (hi - lo)
        return f, dict(runup_arctan_a=a, runup_arctan_centre=tc)
    M = int(rng.integers(5, 8))
    uk = np.concatenate([[0.0], np.sort(rng.uniform(0.05, 0.95, M - 2)), [1.0]])
    nk = np.concatenate([[N0], np.sort(rng.uniform(N0, N1, M - 2)), [N1]])
    pc = interpolate.PchipInterpolator(uk, nk)
    return (lambda u: pc(u)), dict(runup_pchip_knots=float(M))


def _integrate(integ, h, U, a, bb, y0, v0):
    """y'' = U(t) - a y - bb y'.  U given on the half-step grid (len 2N-1).  Returns y on the
    full-step grid.  'rkn4' = Runge-Kutta-Nystrom 4th order; 'abm4' = Adams-Bashforth-Moulton
    4th-order PECE started with RKN4."""
    Ul = U.tolist()
    N = (len(Ul) + 1) // 2
    y, v = float(y0), float(v0)
    out = [0.0] * N
    out[0] = y
    hh, h2 = 0.5 * h, h * h

    def rkn_step(n, y, v):
        u0, u1, u2 = Ul[2 * n], Ul[2 * n + 1], Ul[2 * n + 2]
        k1 = u0 - a * y - bb * v
        y2 = y + hh * v + h2 / 8.0 * k1
        k2 = u1 - a * y2 - bb * (v + hh * k1)
        k3 = u1 - a * y2 - bb * (v + hh * k2)
        y4 = y + h * v + 0.5 * h2 * k3
        k4 = u2 - a * y4 - bb * (v + h * k3)
        return y + h * v + h2 / 6.0 * (k1 + k2 + k3), v + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)

    if integ == "rkn4":
        for n in range(N - 1):
            y, v = rkn_step(n, y, v)
            out[n + 1] = y
        return np.array(out)
    fy = [v]
    fv = [Ul[0] - a * y - bb * v]
    for n in range(min(3, N - 1)):
        y, v = rkn_step(n, y, v)
        out[n + 1] = y
        fy.append(v)
        fv.append(Ul[2 * n + 2] - a * y - bb * v)
    c = h / 24.0
    for n in range(3, N - 1):
        yp = y + c * (55 * fy[-1] - 59 * fy[-2] + 37 * fy[-3] - 9 * fy[-4])
        vp = v + c * (55 * fv[-1] - 59 * fv[-2] + 37 * fv[-3] - 9 * fv[-4])
        un = Ul[2 * n + 2]
        fpy, fpv = vp, un - a * yp - bb * vp
        y = y + c * (9 * fpy + 19 * fy[-1] - 5 * fy[-2] + fy[-3])
        v = v + c * (9 * fpv + 19 * fv[-1] - 5 * fv[-2] + fv[-3])
        out[n + 1] = y
        fy.append(v)
        fv.append(un - a * y - bb * v)
        if len(fy) > 4:
            del fy[0]
            del fv[0]
    return np.array(out)


def _vibration_case(rng, cat, cell, idx):
    category, effects, form = cell["category"], cell["effects"], cell["form"]
    for attempt in range(400):
        m = _pick(rng, cat.accurate)
        R, acc, K1 = m["ratio"], m["accuracy"], m["K1"]
        fmax = m["max_speed"] / (1.45 * 60.0)
        fhi = min(40.0, fmax)
        if fhi < 8.0:
            continue
        fn_cat = float(rng.uniform(8.0, fhi))
        J = K1 / (2 * np.pi * fn_cat) ** 2                     # the value passed as --load-inertia
        s = _semicircle(rng)
        dJ = float(rng.uniform(0.0, 0.06))                     # adapter/coupling inertia not in J
        Jt = J * (1 + dJ)
        K = K1 * s
        zeta = float(rng.uniform(0.03, 0.12))
        c = 2 * zeta * math.sqrt(K * Jt)
        fn = math.sqrt(K / Jt) / (2 * np.pi)
        N2, N1r = 30.0 * fn_cat, 60.0 * fn_cat
        Ns = float(rng.uniform(0.35, 0.55)) * N2
        Ne = float(rng.uniform(1.25, 1.45)) * N1r
        if Ne > m["max_speed"]:
            continue
        integ = cell.get("integ") or _pick(rng, ["rkn4", "abm4"])
        rkind = cell.get("runup") or _pick(rng, ["arctan", "pchip"])
        ncyc = float(rng.uniform(350, 500))
        Ttot = ncyc / fn_cat
        fs = 32.0 * fn_cat
        Nn = int(Ttot * fs) + 1
        h = Ttot / (Nn - 1)
        th_half = np.linspace(0, Ttot, 2 * Nn - 1)
        ufun, rinfo = _runup(rng, rkind, Ns, Ne)
        rpm_half = ufun(th_half / Ttot)
        omega = 2 * np.pi * rpm_half / 60.0
        theta0 = float(rng.uniform(0, 2 * np.pi))
        theta = theta0 + np.concatenate([[0.0], np.cumsum(0.5 * (omega[1:] + omega[:-1]) * (h / 2))])
        t = th_half[::2]
        rpm = rpm_half[::2]
        nuis = dict(stiffness_scale=s, inertia_extra_fraction=dJ, damping_ratio=zeta,
                    natural_freq_cat_Hz=fn_cat, natural_freq_true_Hz=fn, runup_start_rpm=Ns,
                    runup_end_rpm=Ne, integrator_abm4=1.0 if integ == "abm4" else 0.0,
                    runup_arctan=1.0 if rkind == "arctan" else 0.0, sample_rate_Hz=fs)
        nuis.update(rinfo)
        gam, rho_m = _cage_rate(rng)

        def response(ehalf, dehalf=None, q=None):
            U = K * ehalf if ehalf is not None else np.zeros_like(th_half)
            if dehalf is not None:
                U = U + c * dehalf
            if q is not None:
                U = U + q
            U = U / Jt
            y0 = float(ehalf[0]) if ehalf is not None else 0.0
            v0 = float(dehalf[0]) if dehalf is not None else 0.0
            return _integrate(integ, h, U, K / Jt, c / Jt, y0, v0)

        parts = {}
        forms = form.split("+")
        fmap = dict(zip(effects, forms if len(forms) == len(effects) else [form] * len(effects)))
        for e in effects:
            p = _te_params(rng, e, fmap[e], acc)
            eh = _te_eval(p, theta, rho_m)
            de = (_te_eval(p, theta + 1e-5, rho_m) - _te_eval(p, theta - 1e-5, rho_m)) / 2e-5 * omega
            parts[e] = response(eh, de)
            nuis.update(_te_info(p, e))
            if fmap[e] == "cage-am":
                nuis.update(wg_ball_to_pitch=gam, cage_modulation_order=rho_m)
        ncols = [(np.ones(Nn), (-np.inf, np.inf))]
        noise_kind = _noise_kind(rng, category)
        outl = bool(rng.random() < 0.2)
        clean = np.zeros(Nn)
        base_noise = acc * float(rng.uniform(0.005, 0.03))
        snr = 0.0
        if category == "clean":
            noise_kind, outl = cell["noise"], cell["noise_out"]
            noise = base_noise
        elif category == "single":
            e = effects[0]
            r = _size_single(rng, parts[e], ncols)
            if r is None:
                continue
            k, noise, qb, qu = r
            clean = parts[e]
            snr = k
            nuis.update({f"k_{e}": k, "after_nuisance_ratio": qb})
        elif category == "pair":
            e1, e2 = effects
            r = _size_pair(rng, parts[e1], parts[e2], ncols, (0.3, 3.0))
            if r is None:
                continue
            nuis[f"{e2}_a"] *= r["g"]
            nuis["pair_rescale_" + e2] = r["g"]
            if nuis[f"{e2}_a"] > 0.6 * acc:
                continue
            clean = parts[e1] + r["e2"]
            noise = r["noise"]
            snr = _rms(clean) / noise
            nuis.update({f"k_{e1}": r["k1"], f"k_{e2}": r["k2"], "after_nuisance_ratio": r["qt"],
                         f"after_nuisance_ratio_{e1}_alone": r["q1a"],
                         f"after_nuisance_ratio_{e2}_alone": r["q2a"],
                         f"after_nuisance_ratio_{e1}_given_{e2}": r["q1g"],
                         f"after_nuisance_ratio_{e2}_given_{e1}": r["q2g"]})
        elif category == "decoy_equivalent":
            # drive phase-current sensor error of a one-pole-pair servo motor -> torque ripple
            amp_eq = float(rng.uniform(0.1, 0.3)) * acc     # equivalent output-side TE amplitude
            ph = float(rng.uniform(0, 2 * np.pi))
            order = 1.0 if form == "current-offset" else 2.0
            Gsl = float(rng.uniform(0.1, 0.5))               # fraction passed by the speed loop
            tau_in = amp_eq * K / (R * Gsl)                  # input torque ripple, N m
            q = K * amp_eq * np.sin(order * theta + ph)
            clean = response(None, None, q)
            r = _size_single(rng, clean, ncols)
            if r is None:
                continue
            k, noise, qb, qu = r
            snr = k
            nuis.update(k_decoy=k, after_nuisance_ratio=qb, ripple_order=order,
                        input_torque_ripple_Nm=tau_in, speed_loop_pass_fraction=Gsl,
                        equivalent_te_over_accuracy=amp_eq / acc)
        else:  # decoy_separable
            noise = base_noise
            tn = t / t[-1]
            if form == "dual-head-residual":
                e_ = float(rng.uniform(5, 30)) * 1e-6
                rd = float(rng.uniform(40, 100)) * 1e-3
                gm = float(rng.uniform(0.02, 0.15))
                ph = float(rng.uniform(0, 2 * np.pi))
                d = 0.5 * gm * e_ / rd * np.sin(theta[::2] / R + ph)
                nuis.update(disc_eccentricity_m=e_, disc_r_m=rd, head_gain_mismatch=gm)
            elif form == "line-source-drift":
                tc = float(rng.uniform(0.1, 0.5))
                d = _line_source(tn, tc)
                d = d / _rms(d) * float(rng.uniform(0.05, 0.3)) * acc
                nuis.update(drift_tc_fraction=tc)
            else:  # absolute-track step
                ts_ = float(rng.uniform(0.25, 0.8))
                d = (tn >= ts_).astype(float) * float(rng.uniform(0.05, 0.3)) * acc * float(rng.choice([-1, 1]))
                nuis.update(step_fraction=ts_)
            r = _size_single(rng, d, ncols)
            if r is None:
                continue
            k, noise, qb, qu = r
            clean = d
            snr = k
            nuis.update(k_decoy=k, after_nuisance_ratio=qb)
        y = _finish(rng, clean, noise, noise_kind, outl, nuis)
        if not np.all(np.isfinite(y)):
            continue
        nuis["snr"] = float(snr)
        return TruthCase(
            name="", kind="vibration", model=m["code"],
            columns={"time_s": t, "input_speed_rpm": rpm, "output_vibration_rad": y},
            load_inertia_kgm2=float(J),
            gear_effects=tuple(effects) if category in ("single", "pair") else (),
            measurement_effects=tuple(cell.get("meas", ())), nuisance=nuis, category=category,
            equivalent_effects=tuple(cell.get("equiv", ())), noise_rms=float(noise),
            formulation=cell["label"], snr=float(snr))
    raise RuntimeError(f"could not draw a vibration case for {cell}")


# --------------------------------------------------------------------------------------------
# cells
# --------------------------------------------------------------------------------------------
def _clean_cells(kind):
    return [dict(kind=kind, category="clean", effects=(), form=f"clean-{nz}", label=f"clean, {lab}",
                 noise=nz0, noise_out=out)
            for nz, nz0, out, lab in [("white", "white", False, "white Gaussian noise"),
                                      ("ar1", "ar1", False, "AR(1) noise"),
                                      ("fgn", "fgn", False, "fractional Gaussian noise (Davies-Harte)"),
                                      ("outliers", "ar1", True, "AR(1) noise + 0.5 % gross outliers")]]


def _cells():
    C = []
    # ---------------- torsion
    C += _clean_cells("torsion")
    T = "torsion"
    for e, f, lab in [("hysteresis", "berg", "Berg (1998) smooth friction element in parallel with the catalog spring, centre line removed"),
                      ("hysteresis", "prager-voce", "elasto-plastic slider with Prager kinematic + Voce isotropic hardening, centre line removed"),
                      ("backlash", "weibull", "Weibull-CDF engagement of the Oldham clearance"),
                      ("backlash", "sneddon", "Sneddon conical-contact closing (theta ~ sqrt T) up to a seat torque"),
                      ("housing_compliance", "tate-rosenfeld", "fitted-bolt circle, Tate-Rosenfeld fastener flexibility"),
                      ("housing_compliance", "vlasov", "slotted tubular adapter, Vlasov warping-restrained open section")]:
        C.append(dict(kind=T, category="single", effects=(e,), form=f, label=lab))
    C.append(dict(kind=T, category="pair", effects=("hysteresis", "backlash"), form="berg+weibull",
                  label="Berg loop + Weibull take-up"))
    C.append(dict(kind=T, category="pair", effects=("hysteresis", "housing_compliance"), form="prager-voce+vlasov",
                  label="Prager-Voce loop + Vlasov adapter"))
    C.append(dict(kind=T, category="pair", effects=("housing_compliance", "backlash"), form="tate-rosenfeld+sneddon",
                  label="Tate-Rosenfeld bolt circle + Sneddon take-up (worn coupling)", T0_range=(0.35, 0.7), b_max=8.0))
    for f, meas, lab in [("mV/V-sheet-mismatch", ("sensor_gain",), "torque amplifier set to the wrong mV/V calibration value"),
                         ("line-source-drift", ("thermal_drift",), "twist drift from a line heat source (Carslaw-Jaeger E1), two full cycles"),
                         ("absolute-track-step", ("angle_offset",), "constant zero offset + coarse/fine-track misread step"),
                         ("degrees", ("wrong_units",), "twist logged in degrees"),
                         ("kNm", ("wrong_units",), "torque logged in kN m"),
                         ("stiff-beyond-spread", (), "gear stiffer than the catalog spread (scale 1.13-1.25), nuisance only")]:
        C.append(dict(kind=T, category="decoy_separable", effects=(), form=f, label=lab, meas=meas,
                      ncyc=2 if f == "line-source-drift" else None))
    for f, eq, lab, small in [("belt-lock-stretch", ("housing_compliance",), "input locked through a synchronous belt: span stretch reflected by R^2", False),
                              ("belt-tooth-play", ("backlash",), "input locked through a synchronous belt: tooth clearance reflected by 1/R", False),
                              ("slip-ring-brush-drag", ("hysteresis",), "slip-ring brushes on the instrumented output shaft (Jenkins element)", True)]:
        C.append(dict(kind=T, category="decoy_equivalent", effects=(), form=f, label=lab, equiv=eq, small=small))
    # ---------------- transmission
    X = "transmission"
    C += _clean_cells(X)
    for e, f, lab in [("te_1x", "cage-am", "1x with WG-bearing cage-rate amplitude modulation"),
                      ("te_1x", "trilobe", "1x runout with a locked 3x from three-point clamping lobing"),
                      ("te_2x", "cage-am", "2x with WG-bearing cage-rate amplitude modulation"),
                      ("te_2x", "ring-creep", "2x precessing with WG bearing inner-ring creep")]:
        C.append(dict(kind=X, category="single", effects=(e,), form=f, label=lab))
    C.append(dict(kind=X, category="pair", effects=("te_2x", "te_1x"), form="cage-am", label="1x and 2x, both cage-rate AM"))
    C.append(dict(kind=X, category="pair", effects=("te_1x", "te_2x"), form="trilobe+ring-creep", label="trilobe 1x + ring-creep 2x"))
    for f, meas, lab in [("dual-head-residual", ("encoder_eccentricity",), "output disc eccentricity left by two read heads of unequal gain (1 per output rev)"),
                         ("degrees", ("wrong_units",), "output angle logged in degrees"),
                         ("line-source-drift", ("thermal_drift",), "output-angle drift from a line heat source (E1)"),
                         ("absolute-track-step", ("angle_offset",), "absolute-encoder track misread step")]:
        C.append(dict(kind=X, category="decoy_separable", effects=(), form=f, label=lab, meas=meas))
    for f, eq, lab in [("tape-butt-joint", ("te_1x", "te_2x"), "input tape-ring encoder butt-joint gap, re-indexed each revolution (sawtooth)"),
                       ("oldham-disc-ring", ("te_2x",), "input encoder ring on the Oldham coupling's middle disc (2x orbit)")]:
        C.append(dict(kind=X, category="decoy_equivalent", effects=(), form=f, label=lab, equiv=eq))
    # ---------------- efficiency
    E = "efficiency"
    C += _clean_cells(E)
    for e, f, lab in [("low_load_efficiency", "goksem-hargreaves", "WG-bearing EHL rolling resistance W^0.246 (Goksem-Hargreaves) as no-load loss"),
                      ("low_load_efficiency", "jkr", "JKR adhesive contact area x interfacial shear strength"),
                      ("temperature_dependence", "casson-dippr", "Casson grease drag, DIPPR-101 base-oil viscosity (multiplicative)"),
                      ("temperature_dependence", "hildebrand", "Hildebrand free-volume fluidity, saturating drag share (additive)")]:
        C.append(dict(kind=E, category="single", effects=(e,), form=f, label=lab))
    C.append(dict(kind=E, category="pair", effects=("low_load_efficiency", "temperature_dependence"),
                  form="goksem-hargreaves+casson-dippr", label="Goksem-Hargreaves Ke x Casson/DIPPR temperature factor"))
    C.append(dict(kind=E, category="pair", effects=("temperature_dependence", "low_load_efficiency"),
                  form="hildebrand+jkr", label="JKR Ke + Hildebrand additive temperature term"))
    for f, meas, lab in [("fraction", ("wrong_units",), "efficiency logged as a fraction"),
                         ("per-mille", ("wrong_units",), "efficiency logged in per mille"),
                         ("kNm", ("wrong_units",), "load torque logged in kN m"),
                         ("ratio-label", ("sensor_gain",), "output speed computed with a neighbouring catalog ratio"),
                         ("level-low", (), "efficiency level below the usual range (40-52 %), nuisance only")]:
        C.append(dict(kind=E, category="decoy_separable", effects=(), form=f, label=lab, meas=meas))
    for f, eq, lab in [("brake-residual", ("low_load_efficiency",), "magnetic-particle brake residual torque not in the logged load"),
                       ("bath-churning", ("temperature_dependence", "low_load_efficiency"), "output coupling churning in the conditioning bath (DIPPR viscosity)")]:
        C.append(dict(kind=E, category="decoy_equivalent", effects=(), form=f, label=lab, equiv=eq))
    # ---------------- vibration
    V = "vibration"
    C += _clean_cells(V)
    for e, f, integ, ru, lab in [("te_1x", "cage-am", "rkn4", "arctan", "RKN4, arctan run-up, cage-AM 1x"),
                                 ("te_1x", "trilobe", "abm4", "pchip", "ABM4 PECE, PCHIP run-up, trilobe 1x"),
                                 ("te_2x", "cage-am", "abm4", "arctan", "ABM4 PECE, arctan run-up, cage-AM 2x"),
                                 ("te_2x", "ring-creep", "rkn4", "pchip", "RKN4, PCHIP run-up, ring-creep 2x")]:
        C.append(dict(kind=V, category="single", effects=(e,), form=f, label=lab, integ=integ, runup=ru))
    C.append(dict(kind=V, category="pair", effects=("te_2x", "te_1x"), form="cage-am", label="RKN4, arctan run-up, cage-AM 1x + 2x",
                  integ="rkn4", runup="arctan"))
    C.append(dict(kind=V, category="pair", effects=("te_1x", "te_2x"), form="trilobe+ring-creep",
                  label="ABM4 PECE, PCHIP run-up, trilobe 1x + ring-creep 2x", integ="abm4", runup="pchip"))
    for f, meas, lab in [("dual-head-residual", ("encoder_eccentricity",), "output-encoder eccentricity residual (1 per output rev)"),
                         ("line-source-drift", ("thermal_drift",), "vibration-channel drift from a line heat source (E1)"),
                         ("absolute-track-step", ("angle_offset",), "absolute-encoder track misread step")]:
        C.append(dict(kind=V, category="decoy_separable", effects=(), form=f, label=lab, meas=meas))
    for f, eq, lab in [("current-offset", ("te_1x",), "phase-current sensor offset of a 1-pole-pair servo (1x torque ripple)"),
                       ("current-gain", ("te_2x",), "phase-current sensor gain mismatch of a 1-pole-pair servo (2x torque ripple)")]:
        C.append(dict(kind=V, category="decoy_equivalent", effects=(), form=f, label=lab, equiv=eq))
    return C


_BUILDERS = {"torsion": _torsion_case, "transmission": _transmission_case,
             "efficiency": _efficiency_case, "vibration": _vibration_case}


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list:
    rng = np.random.default_rng(seed)
    cat = _Catalog(catalog_dir)
    cases = []
    for cell in _cells():
        for i in range(per_cell):
            tc = _BUILDERS[cell["kind"]](rng, cat, cell, i)
            if tc.category == "pair":
                # the member that alone leaves more after the nuisances comes first
                tc.gear_effects = tuple(sorted(
                    tc.gear_effects, key=lambda e: -tc.nuisance[f"after_nuisance_ratio_{e}_alone"]))
            names = tuple(cell["effects"]) or tc.measurement_effects or tc.equivalent_effects or ("none",)
            tag = cell["form"].replace("/", "").replace("+", "_")
            tc.name = f"{SUITE}-{cell['kind']}-{cell['category']}-{'+'.join(names)}-{tag}-{i:03d}"
            tc.formulation = cell["label"]
            cases.append(tc)
    return cases


if __name__ == "__main__":   # pragma: no cover - self check
    import sys
    import time
    from collections import Counter
    t0 = time.time()
    cs = generate_cases(11, Path(__file__).parent / "catalog", int(sys.argv[1]) if len(sys.argv) > 1 else 2)
    print(len(cs), "cases", round(time.time() - t0, 1), "s")
    for k, v in sorted(Counter((c.kind, c.category) for c in cs).items()):
        print(k, v)
