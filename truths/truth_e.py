"""Truth suite E for `hdcad reconcile` (independent, held-out).

Generates synthetic "measured" strain-wave-gear test-rig data with known hidden physical
effects.  Written from CONTRACT.md, the catalog tables and the seeds only (no hdcad code).
numpy + scipy only.  See NOTES.md for every formulation and its literature reference.

    from truth_e import generate_cases
    cases = generate_cases(11, "/work/main/catalog", per_cell=2)
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path
from types import SimpleNamespace

import numpy as np
from scipy.interpolate import PchipInterpolator
from scipy.signal import lfilter
from scipy.special import erf

SUITE = "e"
RAD2DEG = 180.0 / math.pi


# --------------------------------------------------------------------------------------------
# contract dataclass
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
    # --- suite-E extras (defaulted, informational only) ---
    effect_snr: dict = field(default_factory=dict)   # per hidden effect: RMS / noise_rms
    noise_kind: str = ""                             # white | ar1 | ar2 | pink | hetero (+outliers)
    protocol: str = ""                               # test protocol / sampling description
    added_noise: np.ndarray | None = field(default=None, repr=False)  # noise added to the measured column

    def write_csv(self, path) -> None:
        path = Path(path)
        if path.parent and not path.parent.exists():
            path.parent.mkdir(parents=True, exist_ok=True)
        names = list(self.columns)
        cols = [np.asarray(self.columns[k], dtype=float) for k in names]
        lines = [",".join(names)]
        for row in zip(*cols):
            lines.append(",".join(repr(float(v)) for v in row))
        path.write_text("\n".join(lines) + "\n")


# --------------------------------------------------------------------------------------------
# catalog
# --------------------------------------------------------------------------------------------
def _num(x):
    x = (x or "").strip()
    return float(x) if x else None


class Catalog:
    def __init__(self, catalog_dir):
        d = Path(catalog_dir)

        def read(name):
            with open(d / name, newline="", encoding="utf-8") as fh:
                return list(csv.DictReader(fh))

        ratings = read("gh_ratings_050-1_058-1.csv")
        stiff = read("gh_stiffness_052-1_060-1.csv")
        hyst = read("gh_hysteresis_052_060.csv")
        back = read("gh_backlash_052-2_060-2.csv")
        perf = read("gh_performance_051-1_059-1.csv")
        ke = read("ke_curve_023-1.csv")
        self.ke_anchor = (0.58, 0.93)
        for r in ke:
            a, k = _num(r["alpha"]), _num(r["Ke"])
            if a is not None and k is not None and a < 1.0:
                self.ke_anchor = (a, k)

        def in_range(ratio, r):
            lo, hi = _num(r["ratio_min"]), _num(r["ratio_max"])
            return ratio >= lo and (hi is None or ratio <= hi)

        self.models = []
        for r in ratings:
            series, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
            st = [x for x in stiff if x["series"] == series and int(x["size"]) == size
                  and in_range(ratio, x)]
            if not st:
                continue
            st = st[0]
            hy = [x for x in hyst if x["series"] == series and in_range(ratio, x)]
            bk = [x for x in back if x["series"] == series and int(x["size"]) == size
                  and int(x["ratio"]) == ratio]
            acc = [_num(x["accuracy_rad"]) for x in perf if x["series"] == series
                   and int(x["size"]) == size and int(x["ratio"]) == ratio]
            acc = [a for a in acc if a is not None]
            T1, T2 = _num(st["T1_Nm"]), _num(st["T2_Nm"])
            K1, K2, K3 = (_num(st["K1_Nm_per_rad"]), _num(st["K2_Nm_per_rad"]),
                          _num(st["K3_Nm_per_rad"]))
            th1 = T1 / K1                     # continuous three-segment curve (NOTES.md)
            th2 = th1 + (T2 - T1) / K2
            self.models.append(SimpleNamespace(
                code=f"{series.split('-')[0]}-{size}-{ratio}-GH", series=series, size=size,
                ratio=ratio, T1=T1, T2=T2, K1=K1, K2=K2, K3=K3, th1=th1, th2=th2,
                rated=_num(r["rated_torque_2000_Nm"]),
                max_speed=_num(r["max_input_speed_rpm"]),
                hyst=_num(hy[0]["hysteresis_rad"]) if hy else 2.9e-4,
                backlash=_num(bk[0]["backlash_rad"]) if bk else 3e-5,
                accuracy=(acc[0] if acc else 2.9e-4),
                accuracy_from_table=bool(acc)))
        if not self.models:
            raise RuntimeError("no GH model with stiffness data found in catalog")

    def pick(self, rng, pred=None):
        ms = [m for m in self.models if pred is None or pred(m)]
        return ms[int(rng.integers(len(ms)))]


# --------------------------------------------------------------------------------------------
# helpers
# --------------------------------------------------------------------------------------------
def _rms(x):
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def theta_cat(T, m):
    a = np.abs(np.asarray(T, dtype=float))
    y = np.where(a <= m.T1, a / m.K1,
                 np.where(a <= m.T2, m.th1 + (a - m.T1) / m.K2, m.th2 + (a - m.T2) / m.K3))
    return np.sign(T) * y


def _theta_cat_s(T, m):
    a = abs(T)
    if a <= m.T1:
        y = a / m.K1
    elif a <= m.T2:
        y = m.th1 + (a - m.T1) / m.K2
    else:
        y = m.th2 + (a - m.T2) / m.K3
    return y if T >= 0 else -y


def _compliance_s(T, m):
    a = abs(T)
    return 1.0 / m.K1 if a <= m.T1 else (1.0 / m.K2 if a <= m.T2 else 1.0 / m.K3)


def torque_cat_s(th, m, s):
    """inverse of theta_cat(T)/s for a scalar twist"""
    a = abs(th) * s
    if a <= m.th1:
        T = a * m.K1
    elif a <= m.th2:
        T = m.T1 + (a - m.th1) * m.K2
    else:
        T = m.T2 + (a - m.th2) * m.K3
    return T if th >= 0 else -T


def _smoothstep(x):
    x = np.clip(x, 0.0, 1.0)
    return x * x * (3.0 - 2.0 * x)


def _solve_amp(fn, target, a0, tries=60):
    """find amplitude a (>0) with _rms(fn(a)) == target; fn monotone in a."""
    r0 = _rms(fn(a0))
    if r0 <= 0:
        raise ValueError("effect with zero RMS")
    lo, hi = a0, a0
    rlo = rhi = r0
    k = 0
    while rlo > target and k < 60:
        lo /= 2.0
        rlo = _rms(fn(lo))
        k += 1
    k = 0
    while rhi < target and k < 60:
        hi *= 2.0
        rhi = _rms(fn(hi))
        k += 1
    for _ in range(tries):
        mid = math.sqrt(lo * hi)
        rm = _rms(fn(mid))
        if rm < target:
            lo = mid
        else:
            hi = mid
        if hi / lo - 1.0 < 1e-7:
            break
    return math.sqrt(lo * hi)


def _plan(rng, sig_range, ranges, rho=0.0, tries=20000):
    """Draw noise RMS sigma and one k in [4, 12] per effect so that every effect's RMS k_i*sigma
    lies in its physically plausible range (lo_i, hi_i), sigma lies in sig_range and (pairs) the
    combined RMS sqrt(k1^2 + k2^2 + 2 rho k1 k2) stays in [4, 11.5]."""
    n = len(ranges)
    for relax in (False, True):
        for _ in range(tries):
            ks = rng.uniform(4.0, 12.0, n)
            if n == 2:
                c = math.sqrt(max(ks[0] ** 2 + ks[1] ** 2 + 2 * rho * ks[0] * ks[1], 0.0))
                if not 4.0 <= c <= 11.5:
                    continue
            los = [r[0] / k for r, k in zip(ranges, ks)]
            his = [r[1] / k for r, k in zip(ranges, ks)]
            lo = max(los + ([] if relax else [sig_range[0]]))
            hi = min(his + ([] if relax else [sig_range[1]]))
            if lo <= hi:
                sigma = math.exp(rng.uniform(math.log(lo), math.log(hi)))
                return float(sigma), [float(k) for k in ks]
    raise RuntimeError(f"no feasible noise level for ranges {ranges} sigma {sig_range}")


def _corr(a, b):
    na, nb = np.linalg.norm(a), np.linalg.norm(b)
    return float(np.dot(a, b) / (na * nb)) if na > 0 and nb > 0 else 0.0


NOISE_KINDS = ("white", "ar1", "white", "ar1", "ar2", "pink", "hetero")


def make_noise(rng, n, sigma, ref=None, kind=None, outlier_p=0.3, allow=NOISE_KINDS):
    """noise vector with RMS exactly sigma. Returns (noise, description)."""
    if kind is None:
        kind = str(allow[int(rng.integers(len(allow)))])
    if kind == "hetero" and (ref is None or np.max(np.abs(ref)) <= 0):
        kind = "white"
    e = rng.standard_normal(n)
    desc = kind
    if kind == "ar1":
        phi = float(rng.uniform(0.3, 0.8))
        e[0] /= math.sqrt(1.0 - phi * phi)
        e = lfilter([1.0], [1.0, -phi], e)
        desc = f"ar1(phi={phi:.2f})"
    elif kind == "ar2":
        r = float(rng.uniform(0.5, 0.85))
        w = float(rng.uniform(0.2, 1.2))
        a1, a2 = 2 * r * math.cos(w), -r * r
        e = lfilter([1.0], [1.0, -a1, -a2], np.concatenate([rng.standard_normal(200), e]))[200:]
        desc = f"ar2(r={r:.2f},w={w:.2f})"
    elif kind == "pink":
        f = np.fft.rfftfreq(n)
        f[0] = f[1] if n > 1 else 1.0
        spec = (rng.standard_normal(f.size) + 1j * rng.standard_normal(f.size)) / np.sqrt(f)
        spec[0] = 0.0
        e = np.fft.irfft(spec, n)
        desc = "pink(1/f)"
    elif kind == "hetero":
        w = np.abs(np.asarray(ref, dtype=float))
        w = w / np.max(w)
        fl = float(rng.uniform(0.2, 0.5))
        e = e * (fl + w)
        desc = f"hetero(floor={fl:.2f})"
    e = e - np.mean(e)
    e = e / _rms(e)
    if rng.uniform() < outlier_p:
        m = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, m, replace=False)
        e[idx] = rng.choice([-1.0, 1.0], m) * rng.uniform(8.0, 15.0, m)
        desc += f"+outliers({m})"
    e = e * (sigma / _rms(e))
    return e, desc


def _finish(contribs, sigma):
    """per-effect and combined RMS/noise ratios"""
    per = {k: _rms(v) / sigma for k, v in contribs.items()}
    tot = _rms(sum(contribs.values())) / sigma if contribs else 0.0
    return per, tot


# --------------------------------------------------------------------------------------------
# TORSION
# --------------------------------------------------------------------------------------------
def _torsion_turning_points(rng, T0, proto, ncyc=None):
    if proto == "standard":
        nc = int(rng.integers(1, 4)) if ncyc is None else ncyc
        tp = [0.0] + [T0, -T0] * nc + [T0]
        if rng.uniform() < 0.5:
            tp.append(0.0)
        return tp, f"standard({nc} cycles)"
    if proto == "decaying":
        a2, a3 = rng.uniform(0.5, 0.72), rng.uniform(0.18, 0.35)
        tp = [0.0, T0, -T0, T0, -T0, a2 * T0, -a2 * T0, a3 * T0, -a3 * T0, 0.0]
        return tp, f"decaying(1,{a2:.2f},{a3:.2f})"
    if proto == "nested":
        m1, m2 = rng.uniform(0.1, 0.35), rng.uniform(0.5, 0.8)
        tp = [0.0, T0, -T0, T0, m1 * T0, m2 * T0, -T0, -m1 * T0, -m2 * T0, T0]
        return tp, f"nested(minor {m1:.2f}/{m2:.2f})"
    raise ValueError(proto)


def _sample_path(rng, tps, n, jitter=True):
    tps = np.asarray(tps, dtype=float)
    seg = np.abs(np.diff(tps))
    cum = np.concatenate([[0.0], np.cumsum(seg)])
    u = np.linspace(0.0, cum[-1], n)
    if jitter:
        du = cum[-1] / (n - 1)
        u[1:-1] += rng.uniform(-0.4, 0.4, n - 2) * du
    u = np.unique(np.concatenate([u, cum]))
    return np.interp(u, cum, tps), u / cum[-1]


# ---- hysteresis, torque driven -------------------------------------------------------------
def _ch_dev(T, m, s, gamma, alpha, sub=6):
    """Coleman-Hodgdon (Duhem) deviation e = y - f(T); dy = a|dT|(f - y) + g dT, g=(1-gamma) f'"""
    out = np.zeros(len(T))
    e = 0.0
    for i in range(1, len(T)):
        T0, T1 = T[i - 1], T[i]
        h = (T1 - T0) / sub
        if h == 0.0:
            out[i] = e
            continue
        E = math.exp(-alpha * abs(h))
        sg = 1.0 if h > 0 else -1.0
        for j in range(sub):
            Tm = T0 + (j + 0.5) * h
            q = -gamma * _compliance_s(Tm, m) / s
            e = e * E + q * sg * (1.0 - E) / alpha
        out[i] = e
    return out


def _ja_dev(T, m, s, kJ, c, sub=8):
    """Jiles-Atherton-like: theta = c*theta_an + (1-c)*theta_irr,
    d(theta_irr)/dT = (theta_an - theta_irr)/(k delta) only when delta*(theta_an-theta_irr) > 0"""
    out = np.zeros(len(T))
    irr = 0.0
    for i in range(1, len(T)):
        T0, T1 = T[i - 1], T[i]
        h = (T1 - T0) / sub
        if h != 0.0:
            dl = 1.0 if h > 0 else -1.0
            r = abs(h) / kJ
            for j in range(1, sub + 1):
                an = _theta_cat_s(T0 + j * h, m) / s
                if dl * (an - irr) > 0:
                    irr = (irr + r * an) / (1.0 + r)
        out[i] = (1.0 - c) * (irr - _theta_cat_s(T1, m) / s)
    return out


# ---- hysteresis, displacement driven: generalized Maxwell-slip -----------------------------
def _gms_elem_step(F, d, k, Fm, beta):
    if d == 0.0:
        return F
    sg = 1.0 if d > 0 else -1.0
    ad = abs(d)
    Fs = F * sg
    thr = beta * Fm
    dist = np.maximum((thr - Fs) / k, 0.0)
    stick = np.minimum(ad, dist)
    Fs_new = Fs + k * stick
    rem = ad - stick
    slip = rem > 0
    base = np.maximum(Fs_new, thr)
    Fs_new = np.where(slip, Fm - (Fm - base) * np.exp(-k * rem / ((1.0 - beta) * Fm)), Fs_new)
    return Fs_new * sg


class _GMS:
    """Generalized Maxwell-slip (Al-Bender, Lampaert, Swevers 2005) elements in parallel with the
    catalog spring, displacement (twist) controlled, reversal at the torque targets."""

    def __init__(self, rng, m, s, T0):
        self.m, self.s, self.T0 = m, s, T0
        N = int(rng.integers(6, 11))
        self.w = rng.dirichlet(np.full(N, 2.0))
        th0 = float(theta_cat(np.array([T0]), m)[0]) / s
        self.th0 = th0
        self.thy = np.geomspace(rng.uniform(0.015, 0.04), rng.uniform(0.5, 0.9), N) * th0
        self.beta = float(rng.uniform(0.6, 0.85))
        self.keq1 = None

    def _elements(self, amp):
        Fm = amp * self.T0 * self.w
        k = Fm / self.thy
        return Fm, k

    def _keq(self, dth):
        if self.keq1 is None:
            Fm, k = self._elements(1.0)
            F = np.zeros_like(Fm)
            th = 0.0
            for tgt in (self.th0, -self.th0, self.th0):
                while (tgt - th) * (1 if tgt > th else -1) > 1e-15:
                    step = math.copysign(min(dth, abs(tgt - th)), tgt - th)
                    F = _gms_elem_step(F, step, k, Fm, self.beta)
                    th += step
            self.keq1 = float(np.sum(F)) / self.th0
        return self.keq1

    def path(self, targets, n_rows, amp):
        m, s = self.m, self.s
        travel = sum(abs(float(theta_cat(np.array([b]), m)[0]) - float(theta_cat(np.array([a]), m)[0]))
                     for a, b in zip(targets[:-1], targets[1:])) / s
        dth = travel / n_rows
        keq = self._keq(dth) * amp
        Fm, k = self._elements(amp)
        F = np.zeros_like(Fm)
        th, T = 0.0, 0.0
        ths, Ts = [0.0], [0.0]
        for tgt in targets[1:]:
            dl = 1.0 if tgt > T else -1.0
            guard = 0
            while dl * (T - tgt) < 0 and guard < 20 * n_rows:
                th += dl * dth
                F = _gms_elem_step(F, dl * dth, k, Fm, self.beta)
                T = torque_cat_s(th, m, s) + float(np.sum(F)) - keq * th
                ths.append(th)
                Ts.append(T)
                guard += 1
        T = np.array(Ts)
        th = np.array(ths)
        return T, th, th - theta_cat(T, m) / s


# ---- backlash ------------------------------------------------------------------------------
def _friction_play(T, b, Tf, Tc):
    """play across clearance b, coupling held by friction Tf, finite contact ramp Tc"""
    out = np.zeros(len(T))
    p = 0.0
    for i in range(1, len(T)):
        if T[i] > T[i - 1]:
            p = max(p, -b / 2 + b * float(_smoothstep((T[i] - Tf) / Tc)))
        elif T[i] < T[i - 1]:
            p = min(p, b / 2 - b * float(_smoothstep((-T[i] - Tf) / Tc)))
        out[i] = p
    return out


def _smooth_clamp(x, w):
    a = np.abs(x)
    y = np.where(a <= 1 - w, a, np.where(a >= 1 + w, 1.0, a - (a - (1 - w)) ** 2 / (4 * w)))
    return np.sign(x) * y


def _linear_gap(T, b, Tg, w):
    return 0.5 * b * _smooth_clamp(T / Tg, w)


# ---- housing -------------------------------------------------------------------------------
def _tapered_y(t, expo=0.9):
    """solve u(1+y) - u(1-y) = t, u(x) = max(x,0)^(1/expo) (Palmgren line contact, preload 1)"""
    t = np.asarray(t, dtype=float)
    p = 1.0 / expo
    a = np.abs(t)
    lo = np.zeros_like(a)
    hi = a ** expo + 1.0
    for _ in range(70):
        mid = 0.5 * (lo + hi)
        f = np.maximum(1 + mid, 0) ** p - np.maximum(1 - mid, 0) ** p
        big = f > a
        hi = np.where(big, mid, hi)
        lo = np.where(big, lo, mid)
    return np.sign(t) * 0.5 * (lo + hi)


def _torsion_effect(rng, form, m, s, T0, bl_max=5.0):
    """-> (make(Tpath) -> fn(amp) -> twist deviation, linear?, range_fn(Tpath, thmax), params)"""
    th_T0 = float(theta_cat(np.array([T0]), m)[0]) / s
    hyst_range = lambda Tp, thmax: (0.025 * thmax, 0.10 * thmax)
    if form == "coleman-hodgdon":
        alpha = rng.uniform(1.8, 4.0) / T0
        make = lambda Tp: (lambda g: _ch_dev(Tp, m, s, g, alpha))
        return make, True, hyst_range, {"alpha*T0": alpha * T0}
    if form == "jiles-atherton":
        c = rng.uniform(0.1, 0.4)
        make = lambda Tp: (lambda a: _ja_dev(Tp, m, s, a * T0, c))
        return make, False, hyst_range, {"c_rev": c}
    if form in ("friction-play", "linear-gap"):
        if form == "friction-play":
            Tf, Tc = rng.uniform(0.005, 0.02) * T0, rng.uniform(0.01, 0.05) * T0
            make = lambda Tp: (lambda b: _friction_play(Tp, b, Tf, Tc))
            par = {"Tf/T0": Tf / T0, "Tc/T0": Tc / T0}
        else:
            Tg, w = rng.uniform(0.02, 0.06) * T0, rng.uniform(0.15, 0.4)
            make = lambda Tp: (lambda b: _linear_gap(Tp, b, Tg, w))
            par = {"Tg/T0": Tg / T0}
        rf = lambda Tp, thmax: tuple(_rms(make(Tp)(1.0)) * m.backlash * np.array([0.7, bl_max]))
        return make, True, rf, par
    if form == "linear-series":
        make = lambda Tp: (lambda c: c * Tp)
        unit = th_T0 / T0            # amplitude giving housing twist = gear twist at T0
        rf = lambda Tp, thmax: tuple(_rms(make(Tp)(unit)) * np.array([0.22, 0.5]))
        return make, True, rf, {}
    if form == "tapered-preload":
        Tp_ = rng.uniform(0.15, 0.4) * T0
        rho = rng.uniform(0.3, 1.0)
        make = lambda Tp: (lambda a: a * (rho * Tp / Tp_ + _tapered_y(Tp / Tp_)))
        unit = th_T0 / float(rho * T0 / Tp_ + _tapered_y(np.array([T0 / Tp_]))[0])
        rf = lambda Tp, thmax: tuple(_rms(make(Tp)(unit)) * np.array([0.22, 0.5]))
        return make, True, rf, {"Tpreload/T0": Tp_ / T0, "rho_lin": rho}
    raise ValueError(form)


def _amp_for(fn, lin, target, a0):
    if lin:
        return target / _rms(fn(1.0))
    return _solve_amp(fn, target, a0)


def _torsion_case(rng, cat, cell):
    m = cat.pick(rng)
    category = cell["category"]
    effects = tuple(cell.get("effects", ()))
    forms = tuple(cell.get("forms", ()))
    meas = cell.get("meas")
    equiv = cell.get("equiv")
    # housing compliance must read as a stiffness beyond the catalog spread: scale <= 1 then
    s = float(rng.uniform(0.9, 1.0 if "housing_compliance" in effects else 1.1))
    T0 = float(rng.uniform(0.5, 1.2)) * m.rated
    n_rows = int(rng.integers(400, 2001))
    proto_name = cell.get("protocol")
    if proto_name is None:
        if meas == "thermal_drift" or equiv == "rig-friction":
            proto_name = "standard"
        else:
            proto_name = ("standard", "decaying", "nested")[int(rng.integers(3))]
    ncyc = int(rng.integers(2, 4)) if meas == "thermal_drift" else (
        int(rng.integers(1, 3)) if equiv == "rig-friction" else None)
    tps, proto_desc = _torsion_turning_points(rng, T0, proto_name, ncyc)
    nuis = {"stiffness_scale": s}
    contribs = {}
    meas_fx, equiv_fx = (), ()
    desc = []
    sigma = None
    sig_frac = (0.003, 0.03)
    gms = None
    if "gms" in forms:
        gms = _GMS(rng, m, s, T0)
        T, th_g, dev_nom = gms.path(tps, n_rows, 0.08)
        protocol = proto_desc + ", twist-controlled (uniform twist steps, reversal at torque target)"
    else:
        jit = bool(rng.uniform() < 0.6)
        T, tt = _sample_path(rng, tps, n_rows, jitter=jit)
        protocol = proto_desc + ", torque-controlled" + (", uneven torque steps" if jit else "")
    base = theta_cat(T, m) / s
    thmax = float(np.max(np.abs(base)))
    sig_range = (sig_frac[0] * thmax, sig_frac[1] * thmax)

    if effects:
        objs = []
        for eff, form in zip(effects, forms):
            if form == "gms":
                objs.append((eff, form, None, False, (0.025 * thmax, 0.10 * thmax)))
            else:
                # a worn coupling (up to 10x the catalog maximum) only where the pair needs it
                blm = 10.0 if ("backlash" in effects and "housing_compliance" in effects) else 5.0
                make, lin, rf, par = _torsion_effect(rng, form, m, s, T0, blm)
                objs.append((eff, form, make, lin, rf(T, thmax)))
                if par:
                    desc.append(form + ": " + ", ".join(f"{k}={v:.3g}" for k, v in par.items()))
        rho = 0.0
        if len(objs) == 2:
            shapes = []
            for eff, form, make, lin, (lo, hi) in objs:
                mid = math.sqrt(lo * hi)
                if form == "gms":
                    shapes.append(dev_nom)
                else:
                    fn = make(T)
                    shapes.append(fn(_amp_for(fn, lin, mid, 0.1)))
            rho = _corr(shapes[0], shapes[1])
        sigma, ks = _plan(rng, sig_range, [o[4] for o in objs], rho)
        for (eff, form, make, lin, _), k in zip(objs, ks):
            if form == "gms":
                fn_g = lambda a: gms.path(tps, n_rows, a)[2]
                a = _solve_amp(fn_g, k * sigma, 0.08)
                T, th_g, dev = gms.path(tps, n_rows, a)
                base = theta_cat(T, m) / s
                contribs[eff] = dev
                desc.append(f"gms: {len(gms.w)} elements, amp={a:.3g} T0, beta={gms.beta:.2f}")
            else:
                fn = make(T)
                a = _amp_for(fn, lin, k * sigma, 0.1)
                contribs[eff] = fn(a)
                desc.append(f"{form} amp={a:.3g}")
    if gms is not None:
        tt = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(T)))])
        tt = tt / tt[-1]
    twist = base + sum(contribs.values()) if contribs else base.copy()
    torque = T.copy()

    # ---------------- decoys ----------------
    if meas == "sensor_gain":
        sg = float(rng.choice([-1.0, 1.0]))
        s_app0 = float(rng.uniform(0.93, 1.07))

        def fn(ga):
            g = sg * ga
            s_ = s_app0 / (1 + g)
            return theta_cat(T / (1 + g), m) / s_ - theta_cat(T, m) / s_
        lo, hi = _rms(fn(0.02)), _rms(fn(0.08))
        sigma, (k,) = _plan(rng, sig_range, [(lo, hi)])
        ga = _solve_amp(fn, k * sigma, 0.05)
        g = sg * ga
        s = s_app0 / (1 + g)
        nuis["stiffness_scale"] = s
        torque = T.copy()                       # measured torque (the rig controls on it)
        twist = theta_cat(T / (1 + g), m) / s   # gear sees the true torque
        contribs = {"sensor_gain": fn(ga)}
        meas_fx = ("sensor_gain",)
        desc.append(f"torque gain {1 + g:.4f}, apparent scale {s_app0:.3f}")
    elif meas == "angle_offset":
        tstep = rng.uniform(0.3, 0.7)
        shape = np.where(tt >= tstep, 1.0, 0.0) * rng.choice([-1.0, 1.0])
        sigma, (k,) = _plan(rng, sig_range, [tuple(_rms(shape) * thmax * np.array([0.03, 0.25]))])
        c = shape * k * sigma / _rms(shape)
        contribs = {"angle_offset": c}
        twist = base + c
        meas_fx = ("angle_offset",)
        desc.append(f"stepped offset {c[-1]:.3g} rad at t={tstep:.2f}")
    elif meas == "thermal_drift":
        tau = rng.uniform(0.3, 2.0)
        shape = (1 - np.exp(-tt / tau)) / (1 - math.exp(-1 / tau)) * rng.choice([-1.0, 1.0])
        sigma, (k,) = _plan(rng, sig_range, [tuple(_rms(shape) * thmax * np.array([0.03, 0.25]))])
        c = shape * k * sigma / _rms(shape)
        contribs = {"thermal_drift": c}
        twist = base + c
        meas_fx = ("thermal_drift",)
        desc.append(f"warm-up drift {c[-1]:.3g} rad, tau={tau:.2f} of test time")
    elif meas == "wrong_units":
        meas_fx = ("wrong_units",)
        desc.append("twist column in degrees")
    elif meas == "nuisance-scale":
        s = float(rng.uniform(0.9, 0.925) if rng.uniform() < 0.5 else rng.uniform(1.075, 1.1))
        nuis["stiffness_scale"] = s
        base = theta_cat(T, m) / s
        twist = base.copy()
        desc.append(f"stiffness scale {s:.3f} at the edge of the +-10 % spread")

    if equiv == "soft-gear":
        th_cat = theta_cat(T, m)
        lo, hi = _rms(th_cat) * (1 / 0.8 - 1), _rms(th_cat) * (1 / 0.68 - 1)
        sigma, (k,) = _plan(rng, sig_range, [(lo, hi)])
        x = k * sigma / _rms(th_cat)          # = 1/s - 1
        s = 1.0 / (1.0 + x)
        nuis["stiffness_scale"] = s
        twist = th_cat / s
        contribs = {"soft_gear": twist - th_cat}
        equiv_fx = ("housing_compliance",)
        desc.append(f"gear at {s:.3f} x catalog stiffness (beyond the +-10 % spread)")
    elif equiv == "rig-friction":
        thp = rng.uniform(0.02, 0.08) * thmax

        def rigf(Fc):
            F, thprev = 0.0, 0.0
            outs = np.zeros(len(T))
            for i in range(1, len(T)):
                for j in range(1, 5):
                    Tm = T[i - 1] + (T[i] - T[i - 1]) * j / 4
                    thn = _theta_cat_s(Tm - F, m) / s
                    d = thn - thprev
                    if d != 0.0:
                        sgn = 1.0 if d > 0 else -1.0
                        F = sgn * Fc + (F - sgn * Fc) * math.exp(-abs(d) / thp)
                    thprev = thn
                outs[i] = _theta_cat_s(T[i] - F, m) / s
            return outs - base
        sigma, (k,) = _plan(rng, sig_range, [(0.025 * thmax, 0.10 * thmax)])
        Fc = _solve_amp(rigf, k * sigma, 0.02 * T0)
        c = rigf(Fc)
        twist = base + c
        contribs = {"rig_friction": c}
        equiv_fx = ("hysteresis",)
        desc.append(f"rig support-bearing Dahl friction Fc={Fc / T0:.3f} T0 in the torque channel")
    elif equiv == "input-lock-play":
        Tw = rng.uniform(0.01, 0.04) * T0
        shape = 0.5 * erf(T / Tw)
        sigma, (k,) = _plan(rng, sig_range, [tuple(_rms(shape) * m.backlash * np.array([0.7, 5.0]))])
        b = k * sigma / _rms(shape)
        c = b * shape
        twist = base + c
        contribs = {"input_lock_play": c}
        equiv_fx = ("backlash",)
        desc.append(f"input-side lock play {b:.3g} rad, erf width {Tw / T0:.3f} T0")

    if sigma is None:
        sigma = math.exp(rng.uniform(math.log(sig_range[0]), math.log(sig_range[1])))
    if meas == "wrong_units":
        noise, ndesc = make_noise(rng, len(T), sigma * RAD2DEG, ref=twist)
        col = twist * RAD2DEG + noise
        contribs = {"wrong_units": twist * RAD2DEG - twist}
    else:
        noise, ndesc = make_noise(rng, len(T), sigma, ref=twist)
        col = twist + noise
    nr = _rms(noise)
    per, tot = _finish(contribs, nr)
    if category == "clean" or meas == "nuisance-scale":
        per, tot = {}, 0.0
    return dict(kind="torsion", model=m.code,
                columns={"torque_Nm": torque, "twist_rad": col},
                load_inertia_kgm2=None, gear_effects=effects, measurement_effects=meas_fx,
                nuisance=nuis, equivalent_effects=equiv_fx, noise_rms=nr, added_noise=noise,
                snr=tot, effect_snr=per, noise_kind=ndesc,
                protocol=protocol + f", T0={T0:.4g} Nm ({T0 / m.rated:.2f} x rated)"
                + ("; " + "; ".join(desc) if desc else ""))


# --------------------------------------------------------------------------------------------
# TRANSMISSION
# --------------------------------------------------------------------------------------------
def _te_shape(form, k, th_in, t, R, rng):
    phi = rng.uniform(0, 2 * math.pi)
    if form == "steady":
        y, d = np.sin(k * th_in + phi), f"{k}x steady"
    elif form == "thermal-growth":
        kap, tau = rng.uniform(0.3, 0.6), rng.uniform(0.2, 0.8)
        env = 1.0 - kap * np.exp(-t / (tau * t[-1]))
        y, d = env * np.sin(k * th_in + phi), f"{k}x amplitude grows from {1 - kap:.2f} (tau {tau:.2f})"
    elif form == "output-sidebands":
        mdep, psi = rng.uniform(0.2, 0.5), rng.uniform(0, 2 * math.pi)
        env = 1.0 + mdep * np.sin(th_in / R + psi)
        y, d = env * np.sin(k * th_in + phi), f"{k}x AM once per output rev (depth {mdep:.2f})"
    else:
        raise ValueError(form)
    return y / np.max(np.abs(y)), d


def _transmission_case(rng, cat, cell):
    meas = cell.get("meas")
    equiv = cell.get("equiv")
    if meas == "encoder_eccentricity":
        m = cat.pick(rng, lambda mm: mm.ratio <= 120)
        n_rev = int(round(m.ratio * rng.uniform(0.8, 1.3)))
        spr = int(max(10, min(24, 3000 // n_rev)))
    else:
        m = cat.pick(rng)
        n_rev = int(rng.integers(3, 31))
        spr = int(max(24, min(int(rng.integers(48, 161)), 3000 // n_rev)))
    R = m.ratio
    n = n_rev * spr + 1
    rpm = rng.uniform(5, 60)
    t_rev = 60.0 / rpm
    t = np.linspace(0.0, n_rev * t_rev, n)
    th0 = rng.uniform(0, 2 * math.pi)
    ripple = (cell.get("formulation") == "speed-ripple") or (
        cell["category"] != "clean" and rng.uniform() < 0.4)
    if ripple:
        rho, order = rng.uniform(0.02, 0.1), rng.uniform(2.3, 7.7)
        w0 = 2 * math.pi / t_rev
        th_in = th0 + w0 * t + rho / order * np.sin(order * w0 * t)
        samp = f"constant speed {rpm:.1f} rpm with ripple {rho:.2f} at {order:.1f}/rev (uneven angle steps)"
    else:
        th_in = th0 + 2 * math.pi * t / t_rev
        samp = f"constant speed {rpm:.1f} rpm"
    off = rng.uniform(-0.05, 0.05)
    base = th_in / R + off
    acc = m.accuracy
    sig_range = (0.005 * acc, 0.05 * acc)
    nuis = {"offset_rad": off}
    effects = tuple(cell.get("effects", ()))
    forms = tuple(cell.get("forms", ()))
    contribs = {}
    sigma = None
    meas_fx, equiv_fx = (), ()
    desc = []
    in_col = th_in.copy()
    out_clean = base.copy()
    if effects:
        shapes = []
        for eff, form in zip(effects, forms):
            shp, d = _te_shape(form, 1 if eff == "te_1x" else 2, th_in, t, R, rng)
            shapes.append((eff, shp))
            desc.append(d)
        ranges = [tuple(_rms(sh) * acc * np.array([0.1, 0.6])) for _, sh in shapes]
        rho = _corr(shapes[0][1], shapes[1][1]) if len(shapes) == 2 else 0.0
        sigma, ks = _plan(rng, sig_range, ranges, rho)
        for (eff, sh), k in zip(shapes, ks):
            contribs[eff] = sh * (k * sigma / _rms(sh))
        desc.append("peak amplitudes " + ", ".join(f"{np.max(np.abs(v)):.3g}" for v in contribs.values()) + " rad")
        out_clean = base + sum(contribs.values())
    if meas in ("encoder_eccentricity", "thermal_drift", "angle_offset", "sensor_gain"):
        if meas == "encoder_eccentricity":
            shape = np.sin(th_in / R + rng.uniform(0, 2 * math.pi))
            rng_amp = acc * np.array([0.2, 2.0])
            desc.append(f"output encoder eccentricity, {n_rev / R:.2f} output revs")
        elif meas == "thermal_drift":
            tau = rng.uniform(0.2, 1.5)
            shape = (1 - np.exp(-t / (tau * t[-1]))) / (1 - math.exp(-1 / tau)) * rng.choice([-1, 1])
            rng_amp = acc * np.array([0.2, 2.0])
            desc.append(f"warm-up drift, tau={tau:.2f} of test time")
        elif meas == "angle_offset":
            shape = np.where(t >= rng.uniform(0.3, 0.7) * t[-1], 1.0, 0.0) * rng.choice([-1, 1])
            rng_amp = acc * np.array([0.2, 2.0])
            desc.append("stepped offset (encoder re-zero glitch)")
        else:
            shape = base * rng.choice([-1, 1])
            rng_amp = np.array([2e-5, 3e-3])
            desc.append("output angle channel gain error")
        sigma, (k,) = _plan(rng, sig_range, [tuple(_rms(shape) * rng_amp)])
        c = shape * (k * sigma / _rms(shape))
        contribs = {meas: c}
        out_clean = base + c
        meas_fx = (meas,)
        if meas == "sensor_gain":
            desc.append(f"gain {1 + c[-1] / base[-1]:.6f}")
        else:
            desc.append(f"amplitude {np.max(np.abs(c)):.3g} rad")
    if equiv == "input-encoder-eccentricity":
        psi = rng.uniform(0, 2 * math.pi)
        shape = np.sin(th_in + psi)
        sigma, (k,) = _plan(rng, sig_range, [tuple(_rms(shape) / R * np.array([3e-4, 5e-3]))])
        e_in = k * sigma * R / _rms(shape)
        th_meas = th_in + e_in * shape
        in_col = th_meas
        c = base - (th_meas / R + off)             # residual vs catalog at the measured input
        contribs = {"input_encoder_1x": c}
        equiv_fx = ("te_1x",)
        desc.append(f"input encoder eccentricity {e_in:.3g} rad (1x per input rev)")
    elif equiv == "cardan-coupling":
        def fn(beta):
            diff = np.arctan2(np.sin(th_in), np.cos(th_in) * math.cos(beta)) - th_in
            return np.angle(np.exp(1j * diff)) / R
        lo, hi = _rms(fn(math.radians(1.5))), _rms(fn(math.radians(8.0)))
        sigma, (k,) = _plan(rng, sig_range, [(lo, hi)])
        beta = _solve_amp(fn, k * sigma, math.radians(4.0))
        c = fn(beta)                              # input encoder on the motor side
        out_clean = base + c
        contribs = {"cardan_2x": c}
        equiv_fx = ("te_2x",)
        desc.append(f"misaligned input coupling beta={math.degrees(beta):.2f} deg (2x per input rev)")
    if sigma is None:
        sigma = math.exp(rng.uniform(math.log(sig_range[0]), math.log(sig_range[1])))
    if meas == "wrong_units":
        noise, nd = make_noise(rng, n, sigma * RAD2DEG)
        col = out_clean * RAD2DEG + noise
        contribs = {"wrong_units": out_clean * RAD2DEG - out_clean}
        meas_fx = ("wrong_units",)
        desc.append("output angle in degrees")
    else:
        noise, nd = make_noise(rng, n, sigma, ref=(out_clean - base) if contribs else None)
        col = out_clean + noise
    nr = _rms(noise)
    per, tot = _finish(contribs, nr)
    if cell["category"] == "clean":
        per, tot = {}, 0.0
    return dict(kind="transmission", model=m.code,
                columns={"input_angle_rad": in_col, "output_angle_rad": col},
                load_inertia_kgm2=None, gear_effects=effects, measurement_effects=meas_fx,
                nuisance=nuis, equivalent_effects=equiv_fx, noise_rms=nr, added_noise=noise, snr=tot,
                effect_snr=per, noise_kind=nd,
                protocol=f"{n_rev} input revs, {spr} samples/rev, {samp}"
                + ("" if m.accuracy_from_table else "; (accuracy blank in 051-1: 2.9e-4 rad scale used)")
                + ("; " + "; ".join(desc) if desc else ""))


# --------------------------------------------------------------------------------------------
# EFFICIENCY
# --------------------------------------------------------------------------------------------
def _nu_ratio(Tc, B, Tref=40.0):
    """Andrade (Arrhenius-type) viscosity ratio nu(T)/nu(Tref)"""
    return np.exp(B * (1.0 / (Tc + 273.15) - 1.0 / (Tref + 273.15)))


def _eff_grid(rng, m, need_temps, scattered=False):
    speeds_all = [250, 500, 1000, 1500, 2000, 2500, 3000, 3500]
    speeds_ok = [v for v in speeds_all if v <= m.max_speed]
    if scattered:
        n = int(rng.integers(150, 401))
        sp = rng.uniform(min(speeds_ok), max(speeds_ok), n).round(0)
        al = rng.uniform(0.1, 1.1, n)
        tc = rng.uniform(0.0, 50.0, n).round(1)
        return sp, al, tc, f"{n} scattered operating points"
    ns = int(rng.integers(3, 6))
    sp = np.sort(rng.choice(speeds_ok, size=min(ns, len(speeds_ok)), replace=False)).astype(float)
    nl = int(rng.integers(6, 11))
    al = np.geomspace(rng.uniform(0.1, 0.2), rng.uniform(1.0, 1.15), nl).round(3)
    nt = int(rng.choice([3, 4, 5])) if need_temps else int(rng.choice([1, 3, 4]))
    if nt == 1:
        tcs = np.array([float(rng.choice([20.0, 25.0, 30.0]))])
    else:
        tcs = np.linspace(rng.uniform(0, 10), rng.uniform(35, 50), nt).round(1)
    G = np.array(np.meshgrid(sp, al, tcs, indexing="ij")).reshape(3, -1)
    reps = max(int(math.ceil(100 / G.shape[1])), int(rng.integers(1, 3)))
    G = np.tile(G, reps)
    return G[0], G[1], G[2], f"grid {len(sp)} speeds x {nl} loads x {len(tcs)} temperatures x {reps} repeats"


def _eff_effect(rng, form, alpha, speed, temp, cat):
    """-> (factor_fn(amp) multiplying the level, (amp_lo, amp_hi), params)"""
    a_anchor, ke_anchor = cat.ke_anchor
    if form == "hyperbolic-clamped":
        c_cat = a_anchor * (1 - ke_anchor) / (ke_anchor - a_anchor)   # Ke(0.58)=0.93 -> 0.116
        fn = lambda c: np.minimum(1.0, alpha * (1 + c) / (alpha + c))
        return fn, (0.4 * c_cat, 2.0 * c_cat), {"c_catalog": c_cat}
    if form == "pchip-graph":
        u = [rng.uniform(0.55, 0.75), rng.uniform(0.3, 0.42), rng.uniform(0.14, 0.2)]
        drop_anchor = 1.0 - ke_anchor

        def fn(q):
            ys = np.maximum([1 - q * u[0], 1 - q * u[1], 1 - q * u[2], 1 - q * drop_anchor, 1.0, 1.0], 0.05)
            f = PchipInterpolator([0.0, 0.1, 0.3, a_anchor, 1.0, 1.6], ys)
            return np.where(alpha >= 1.0, 1.0, f(np.clip(alpha, 0, 1.6)))
        return fn, (0.4, 1.8), {}
    if form == "andrade-palmgren":
        B = rng.uniform(3500, 5500)
        L = (_nu_ratio(temp, B) * speed / 2000.0) ** (2.0 / 3.0)
        fn = lambda lam: 1.0 - lam * (L - 1.0)
        return fn, (0.001, 0.06), {"B_K": B}
    if form == "stribeck-hersey":
        B = rng.uniform(3500, 5500)
        lam_ref = rng.uniform(0.8, 2.0)
        Lam = lam_ref * (_nu_ratio(temp, B) * speed / 2000.0) ** 0.7
        mu_v = rng.uniform(0.006, 0.015)
        mu = lambda L: 0.03 + 0.07 * np.exp(-L ** 1.5) + mu_v * L
        mref = mu(lam_ref)
        fn = lambda G: 1.0 - G * (mu(Lam) - mref)
        return fn, (0.05, 5.0), {"B_K": B, "film_ref": lam_ref}
    raise ValueError(form)


def _efficiency_case(rng, cat, cell):
    m = cat.pick(rng)
    effects = tuple(cell.get("effects", ()))
    forms = tuple(cell.get("forms", ()))
    meas = cell.get("meas")
    equiv = cell.get("equiv")
    need_t = ("temperature_dependence" in effects) or equiv == "temp-sensitive-sensor"
    sp, al, tc, proto = _eff_grid(rng, m, need_t, scattered=cell.get("formulation") == "scattered")
    n = len(sp)
    if meas == "thermal_drift":
        perm = rng.permutation(n)          # test run in randomised order
        sp, al, tc = sp[perm], al[perm], tc[perm]
        proto += ", randomised test order"
    level = float(rng.uniform(65, 85))
    nuis = {"efficiency_level_pct": level}
    load = al * m.rated
    sig_range = (0.2, 2.5)
    contribs = {}
    sigma = None
    meas_fx, equiv_fx = (), ()
    desc = []
    eta = np.full(n, level)
    if effects:
        objs = []
        for eff, form in zip(effects, forms):
            fn, (alo, ahi), par = _eff_effect(rng, form, al, sp, tc, cat)
            dfn = (lambda f: (lambda a: level * (f(a) - 1.0)))(fn)
            objs.append((eff, form, fn, dfn, (_rms(dfn(alo)), _rms(dfn(ahi))), math.sqrt(alo * ahi)))
            if par:
                desc.append(form + ": " + ", ".join(f"{k}={v:.3g}" for k, v in par.items()))
        rho = _corr(objs[0][3](objs[0][5]), objs[1][3](objs[1][5])) if len(objs) == 2 else 0.0
        sigma, ks = _plan(rng, sig_range, [o[4] for o in objs], rho)
        fac = np.ones(n)
        for (eff, form, fn, dfn, _, a0), k in zip(objs, ks):
            a = _solve_amp(dfn, k * sigma, a0)
            contribs[eff] = dfn(a)
            fac = fac * fn(a)
            desc.append(f"{form} amp={a:.3g}" + (f" (Ke at alpha=0.58: {float(fn(a)[np.argmin(np.abs(al - 0.58))]):.3f})"
                                                 if eff == "low_load_efficiency" else ""))
        eta = level * fac
    if meas == "nuisance-level":
        level = float(rng.uniform(50, 60) if rng.uniform() < 0.5 else rng.uniform(88, 93))
        nuis["efficiency_level_pct"] = level
        eta = np.full(n, level)
        desc.append(f"efficiency level {level:.1f} % (outside the usual range)")
    elif meas == "thermal_drift":
        tau = rng.uniform(0.3, 1.5)
        tt = np.linspace(0, 1, n)
        shape = (1 - np.exp(-tt / tau)) / (1 - math.exp(-1 / tau)) * rng.choice([-1, 1])
        sigma, (k,) = _plan(rng, sig_range, [tuple(_rms(shape) * np.array([1.0, 6.0]))])
        c = shape * k * sigma / _rms(shape)
        eta = eta + c
        contribs = {"thermal_drift": c}
        meas_fx = ("thermal_drift",)
        desc.append(f"torque-sensor zero drift, {c[-1]:.2f} pct-pts at test end")
    elif meas == "sensor_gain":
        g = rng.choice([-1, 1]) * rng.uniform(0.05, 0.15)
        load = load * (1 + g)
        meas_fx = ("sensor_gain",)
        desc.append(f"load torque channel gain {1 + g:.3f}")
    if equiv == "rig-drag":
        fn = lambda d: level * (al / (al + d) - 1.0)
        sigma, (k,) = _plan(rng, sig_range, [(_rms(fn(0.005)), _rms(fn(0.08)))])
        d = _solve_amp(fn, k * sigma, 0.02)
        c = fn(d)
        eta = level + c
        contribs = {"rig_drag": c}
        equiv_fx = ("low_load_efficiency",)
        desc.append(f"rig bearing drag {d:.4f} x rated torque on the load side")
    elif equiv == "temp-sensitive-sensor":
        sgn = rng.choice([-1, 1])
        Tcal = 20.0
        fn = lambda gm: level * (1.0 / (1.0 + sgn * gm * (tc - Tcal)) - 1.0)
        sigma, (k,) = _plan(rng, sig_range, [(_rms(fn(2e-4)), _rms(fn(4e-3)))])
        gm = _solve_amp(fn, k * sigma, 1e-3)
        c = fn(gm)
        eta = level + c
        contribs = {"temp_sensor_gain": c}
        equiv_fx = ("temperature_dependence",)
        desc.append(f"input torque sensor gain {sgn * gm:.2e}/K about {Tcal:.0f} C")
    if sigma is None:
        sigma = math.exp(rng.uniform(math.log(sig_range[0]), math.log(sig_range[1])))
    ref = 1.0 / np.maximum(al, 0.03)   # heteroscedastic: worse at low load
    if meas == "wrong_units" and cell.get("unit") == "fraction":
        noise, nd = make_noise(rng, n, sigma / 100.0, ref=ref)
        col = eta / 100.0 + noise
        contribs = {"wrong_units": eta / 100.0 - eta}
        meas_fx = ("wrong_units",)
        desc.append("efficiency column as a fraction")
    else:
        noise, nd = make_noise(rng, n, sigma, ref=ref)
        col = eta + noise
        if meas == "wrong_units":
            load = load * 1e-3
            meas_fx = ("wrong_units",)
            desc.append("load torque column in kN m")
    nr = _rms(noise)
    if effects:
        per = {k: _rms(v) / nr for k, v in contribs.items()}
        tot = _rms(eta - level) / nr           # exact combined contribution (incl. interaction)
    else:
        per, tot = _finish(contribs, nr)
    if cell["category"] == "clean" or meas == "nuisance-level":
        per, tot = {}, 0.0
    return dict(kind="efficiency", model=m.code,
                columns={"input_speed_rpm": sp, "load_torque_Nm": load, "temperature_C": tc,
                         "efficiency_pct": col},
                load_inertia_kgm2=None, gear_effects=effects, measurement_effects=meas_fx,
                nuisance=nuis, equivalent_effects=equiv_fx, noise_rms=nr, added_noise=noise, snr=tot,
                effect_snr=per, noise_kind=nd,
                protocol=proto + f", rated torque {m.rated} Nm" + ("; " + "; ".join(desc) if desc else ""))


# --------------------------------------------------------------------------------------------
# VIBRATION
# --------------------------------------------------------------------------------------------
def _vib_simulate(t_fine, th_fine, w_fine, sub, wn, zeta, excs, nonlin=None):
    """RK4 with step h = t_fine[2]-t_fine[0] (t_fine holds half steps); excs: (A, k, phi).
    Load angle x; gear output angle error e(t) = sum A sin(k theta_in + phi) (kinematic);
    J x'' = -K r (1 - eps r^2/u^2) - c r' - c2 |r'| r',   r = x - e.
    Returns x at every `sub`-th step (the sample times)."""
    nf = len(t_fine)
    e = np.zeros(nf)
    ed = np.zeros(nf)
    for A, k, phi in excs:
        e += A * np.sin(k * th_fine + phi)
        ed += A * k * w_fine * np.cos(k * th_fine + phi)
    h = t_fine[2] - t_fine[0]
    w2 = wn * wn
    c1 = 2 * zeta * wn
    if nonlin is None:
        eps, c2, u2 = 0.0, 0.0, 1.0
    else:
        eps, c2, u = nonlin
        u2 = u * u
    e = e.tolist()
    ed = ed.tolist()
    x, v = e[0], ed[0]
    nsteps = (nf - 1) // 2
    out = [x]

    def acc(xx, vv, j):
        r = xx - e[j]
        rd = vv - ed[j]
        return -w2 * r * (1.0 - eps * r * r / u2) - c1 * rd - c2 * abs(rd) * rd

    for i in range(nsteps):
        j0, j1, j2 = 2 * i, 2 * i + 1, 2 * i + 2
        k1x, k1v = v, acc(x, v, j0)
        k2x, k2v = v + 0.5 * h * k1v, acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v, j1)
        k3x, k3v = v + 0.5 * h * k2v, acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v, j1)
        k4x, k4v = v + h * k3v, acc(x + h * k3x, v + h * k3v, j2)
        x += h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x)
        v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v)
        if (i + 1) % sub == 0:
            out.append(x)
    return np.array(out)


def _vibration_case(rng, cat, cell):
    m = cat.pick(rng)
    form = cell.get("formulation", "linear-ramp")
    effects = tuple(cell.get("effects", ()))
    meas = cell.get("meas")
    equiv = cell.get("equiv")
    s = float(rng.uniform(0.9, 1.1))
    f_cat = rng.uniform(6.0, 18.0)                # resonance the catalog K1 predicts with J
    J = m.K1 / (2 * math.pi * f_cat) ** 2
    fn_ = math.sqrt(m.K1 * s / J) / (2 * math.pi)
    zeta = rng.uniform(0.02, 0.08)
    fs = 12.0 * f_cat
    dur = min(rng.uniform(8.0, 16.0), 2950.0 / fs)
    n = int(dur * fs) + 1
    t = np.arange(n) / fs
    sub = int(math.ceil(30 * 2.6 * f_cat / fs))
    t_fine = np.arange(2 * sub * (n - 1) + 1) * (1.0 / fs) / (2 * sub)
    f_lo, f_hi = rng.uniform(0.25, 0.38) * f_cat, rng.uniform(1.2, 1.45) * f_cat
    th0 = rng.uniform(0, 2 * math.pi)
    if form == "s-curve-ripple":
        S = _smoothstep(t_fine / t_fine[-1])
        fbase = f_lo + (f_hi - f_lo) * S
        rho, order = rng.uniform(0.01, 0.04), int(rng.integers(5, 8))
        th = np.empty_like(t_fine)
        th[0] = th0
        hf = t_fine[1] - t_fine[0]
        fb = fbase.tolist()
        for j in range(len(t_fine) - 1):      # d(theta)/dt = 2 pi fbase (1 + rho sin(order theta))
            a1 = 2 * math.pi * fb[j] * (1 + rho * math.sin(order * th[j]))
            tmp = th[j] + hf * a1
            a2 = 2 * math.pi * fb[j + 1] * (1 + rho * math.sin(order * tmp))
            th[j + 1] = th[j] + 0.5 * hf * (a1 + a2)
        w = 2 * math.pi * fbase * (1 + rho * np.sin(order * th))
        proto = (f"S-curve run-up {f_lo * 60:.0f}->{f_hi * 60:.0f} rpm, motor speed ripple "
                 f"{rho:.3f} at {order}/rev")
    else:
        fr = f_lo + (f_hi - f_lo) * t_fine / t_fine[-1]
        th = th0 + 2 * math.pi * (f_lo * t_fine + 0.5 * (f_hi - f_lo) * t_fine ** 2 / t_fine[-1])
        w = 2 * math.pi * fr
        proto = f"linear run-up {f_lo * 60:.0f}->{f_hi * 60:.0f} rpm"
    speed_rpm = w[np.arange(n) * 2 * sub] * 60 / (2 * math.pi)
    proto += f" in {t[-1]:.1f} s at {fs:.0f} Hz; true f_n={fn_:.2f} Hz (catalog K1 and J: {f_cat:.2f} Hz)"
    nuis = {"stiffness_scale": s, "damping_ratio": zeta}
    acc = m.accuracy
    sig_range = (0.005 * acc, 0.2 * acc)
    contribs = {}
    sigma = None
    meas_fx, equiv_fx = (), ()
    desc = []
    x = np.zeros(n)
    exc = []
    if effects:
        exc = [(1 if e_ == "te_1x" else 2, e_, (0.05 * acc, 0.5 * acc)) for e_ in effects]
    elif equiv == "input-drive-1x":
        exc = [(1, "input_drive_1x", (1e-3 / m.ratio, 1.5e-2 / m.ratio))]
        equiv_fx = ("te_1x",)
    elif equiv == "cardan-2x":
        exc = [(2, "cardan_2x", (math.radians(2.0) ** 2 / 4 / m.ratio,
                                 math.radians(8.0) ** 2 / 4 / m.ratio))]
        equiv_fx = ("te_2x",)
    if exc:
        wn = 2 * math.pi * fn_
        phis = [rng.uniform(0, 2 * math.pi) for _ in exc]
        nonlin = None
        if form == "microslip-duffing":
            eps = rng.uniform(0.05, 0.15)
            eta2 = rng.uniform(0.3, 1.0)
            u = 1.0 / (2 * zeta)          # normalised units: unit excitation -> resonant response ~Q
            c2 = eta2 * 2 * zeta * wn / (wn * u)
            nonlin = (eps, c2, u)
            desc.append(f"microslip joint: softening eps={eps:.3f} at r=Q*A, quadratic damping "
                        f"{eta2:.2f} x viscous at that amplitude")
        singles = [_vib_simulate(t_fine, th, w, sub, wn, zeta, [(1.0, k, p)], nonlin)
                   for (k, _, _), p in zip(exc, phis)]
        ranges = [tuple(_rms(sg) * np.array(r)) for sg, (_, _, r) in zip(singles, exc)]
        rho = _corr(singles[0], singles[1]) if len(exc) == 2 else 0.0
        sigma, ks = _plan(rng, sig_range, ranges, rho)
        amps = [k * sigma / _rms(sg) for k, sg in zip(ks, singles)]
        if len(exc) == 1:
            x = amps[0] * singles[0]
            contribs[exc[0][1]] = x
        elif nonlin is None:
            contribs = {exc[0][1]: amps[0] * singles[0], exc[1][1]: amps[1] * singles[1]}
            x = contribs[exc[0][1]] + contribs[exc[1][1]]
        else:
            r21 = amps[1] / amps[0]
            both = _vib_simulate(t_fine, th, w, sub, wn, zeta,
                                 [(1.0, exc[0][0], phis[0]), (r21, exc[1][0], phis[1])], nonlin)
            s2 = _vib_simulate(t_fine, th, w, sub, wn, zeta, [(r21, exc[1][0], phis[1])], nonlin)
            x = amps[0] * both
            contribs = {exc[0][1]: amps[0] * singles[0], exc[1][1]: amps[0] * s2}
        desc.append("excitation amplitudes " + ", ".join(f"{a:.3g}" for a in amps) + " rad at the output")
        if equiv == "input-drive-1x":
            desc.append(f"input drive runout {amps[0] * m.ratio:.3g} rad at 1x per input rev")
        if equiv == "cardan-2x":
            desc.append(f"misaligned input coupling beta={math.degrees(math.sqrt(4 * amps[0] * m.ratio)):.2f} deg")
    if meas in ("thermal_drift", "angle_offset", "pickup"):
        if meas == "thermal_drift":
            tau = rng.uniform(0.2, 1.5)
            shape = (1 - np.exp(-t / (tau * t[-1]))) / (1 - math.exp(-1 / tau)) * rng.choice([-1, 1])
            desc.append(f"warm-up drift, tau={tau:.2f} of test time")
        elif meas == "angle_offset":
            shape = np.where(t >= rng.uniform(0.3, 0.7) * t[-1], 1.0, 0.0) * rng.choice([-1, 1])
            desc.append("stepped offset")
        else:
            fp = rng.uniform(1.8, 3.0) * f_cat
            shape = np.sin(2 * math.pi * fp * t + rng.uniform(0, 2 * math.pi))
            desc.append(f"electrical pickup at fixed {fp:.1f} Hz (not locked to input speed)")
        sigma, (k,) = _plan(rng, sig_range, [tuple(_rms(shape) * acc * np.array([0.02, 0.3]))])
        x = shape * (k * sigma / _rms(shape))
        contribs = {meas: x}
        meas_fx = (meas,) if meas != "pickup" else ()
    if sigma is None:
        sigma = math.exp(rng.uniform(math.log(sig_range[0]), math.log(sig_range[1])))
    noise, nd = make_noise(rng, n, sigma, ref=x if contribs else None)
    nr = _rms(noise)
    per, tot = _finish(contribs, nr)
    if len(contribs) > 1:
        tot = _rms(x) / nr
    if cell["category"] == "clean":
        per, tot = {}, 0.0
    return dict(kind="vibration", model=m.code,
                columns={"time_s": t, "input_speed_rpm": speed_rpm,
                         "output_vibration_rad": x + noise},
                load_inertia_kgm2=float(J), gear_effects=effects,
                measurement_effects=meas_fx, nuisance=nuis, equivalent_effects=equiv_fx,
                noise_rms=nr, added_noise=noise, snr=tot, effect_snr=per, noise_kind=nd,
                protocol=proto + ("; " + "; ".join(desc) if desc else ""))


# --------------------------------------------------------------------------------------------
# cells
# --------------------------------------------------------------------------------------------
def _cells():
    C = []

    def add(kind, category, formulation, **kw):
        C.append(dict(kind=kind, category=category, formulation=formulation, **kw))

    # torsion
    for p in ("standard", "decaying", "nested"):
        add("torsion", "clean", f"catalog x scale, {p} cycles", protocol=p)
    for f in ("coleman-hodgdon", "jiles-atherton", "gms"):
        add("torsion", "single", f, effects=("hysteresis",), forms=(f,))
    for f in ("friction-play", "linear-gap"):
        add("torsion", "single", f, effects=("backlash",), forms=(f,))
    for f in ("linear-series", "tapered-preload"):
        add("torsion", "single", f, effects=("housing_compliance",), forms=(f,))
    for e, f in ((("hysteresis", "backlash"), ("coleman-hodgdon", "linear-gap")),
                 (("hysteresis", "backlash"), ("gms", "friction-play")),
                 (("hysteresis", "housing_compliance"), ("jiles-atherton", "tapered-preload")),
                 (("hysteresis", "housing_compliance"), ("coleman-hodgdon", "linear-series")),
                 (("backlash", "housing_compliance"), ("friction-play", "tapered-preload"))):
        add("torsion", "pair", "+".join(f), effects=e, forms=f)
    add("torsion", "decoy_separable", "torque-sensor gain", meas="sensor_gain")
    add("torsion", "decoy_separable", "stepped angle offset", meas="angle_offset")
    add("torsion", "decoy_separable", "warm-up drift", meas="thermal_drift")
    add("torsion", "decoy_separable", "twist in degrees", meas="wrong_units")
    add("torsion", "decoy_separable", "stiffness scale at spread edge", meas="nuisance-scale")
    add("torsion", "decoy_equivalent", "soft gear (scale 0.68-0.80)", equiv="soft-gear")
    add("torsion", "decoy_equivalent", "rig bearing friction (Dahl)", equiv="rig-friction")
    add("torsion", "decoy_equivalent", "input-lock play (erf)", equiv="input-lock-play")
    # transmission
    add("transmission", "clean", "uniform")
    add("transmission", "clean", "speed-ripple")
    for e in ("te_1x", "te_2x"):
        for f in ("steady", "thermal-growth", "output-sidebands"):
            add("transmission", "single", f, effects=(e,), forms=(f,))
    for f in ("steady", "thermal-growth", "output-sidebands"):
        add("transmission", "pair", f"{f}+{f}", effects=("te_1x", "te_2x"), forms=(f, f))
    for mfx, f in (("encoder_eccentricity", "output encoder eccentricity"),
                   ("thermal_drift", "warm-up drift"), ("angle_offset", "stepped angle offset"),
                   ("sensor_gain", "output angle gain"), ("wrong_units", "output in degrees")):
        add("transmission", "decoy_separable", f, meas=mfx)
    add("transmission", "decoy_equivalent", "input encoder eccentricity (1x)",
        equiv="input-encoder-eccentricity")
    add("transmission", "decoy_equivalent", "misaligned input coupling (2x)",
        equiv="cardan-coupling")
    # efficiency
    add("efficiency", "clean", "grid")
    add("efficiency", "clean", "scattered")
    for f in ("hyperbolic-clamped", "pchip-graph"):
        add("efficiency", "single", f, effects=("low_load_efficiency",), forms=(f,))
    for f in ("andrade-palmgren", "stribeck-hersey"):
        add("efficiency", "single", f, effects=("temperature_dependence",), forms=(f,))
    for f in (("hyperbolic-clamped", "andrade-palmgren"), ("pchip-graph", "stribeck-hersey")):
        add("efficiency", "pair", "+".join(f),
            effects=("low_load_efficiency", "temperature_dependence"), forms=f)
    add("efficiency", "decoy_separable", "efficiency level outside usual range",
        meas="nuisance-level")
    add("efficiency", "decoy_separable", "efficiency as fraction", meas="wrong_units",
        unit="fraction")
    add("efficiency", "decoy_separable", "load torque in kN m", meas="wrong_units", unit="kNm")
    add("efficiency", "decoy_separable", "load-torque sensor gain", meas="sensor_gain")
    add("efficiency", "decoy_separable", "sensor zero drift, randomised order",
        meas="thermal_drift")
    add("efficiency", "decoy_equivalent", "rig bearing drag", equiv="rig-drag")
    add("efficiency", "decoy_equivalent", "temperature-sensitive torque sensor",
        equiv="temp-sensitive-sensor")
    # vibration
    add("vibration", "clean", "linear-ramp")
    add("vibration", "clean", "s-curve-ripple")
    for e in ("te_1x", "te_2x"):
        for f in ("linear-ramp", "microslip-duffing", "s-curve-ripple"):
            add("vibration", "single", f, effects=(e,))
    for f in ("linear-ramp", "microslip-duffing"):
        add("vibration", "pair", f, effects=("te_1x", "te_2x"))
    add("vibration", "decoy_separable", "warm-up drift", meas="thermal_drift")
    add("vibration", "decoy_separable", "stepped angle offset", meas="angle_offset")
    add("vibration", "decoy_separable", "electrical pickup at fixed frequency", meas="pickup")
    add("vibration", "decoy_equivalent", "input drive runout 1x", equiv="input-drive-1x")
    add("vibration", "decoy_equivalent", "misaligned input coupling 2x", equiv="cardan-2x")
    return C


_BUILDERS = {"torsion": _torsion_case, "transmission": _transmission_case,
             "efficiency": _efficiency_case, "vibration": _vibration_case}


def _slug(s):
    out = "".join(ch if ch.isalnum() else "-" for ch in s.lower())
    while "--" in out:
        out = out.replace("--", "-")
    return out.strip("-")


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list:
    rng = np.random.default_rng(seed)
    cat = Catalog(catalog_dir)
    cases = []
    idx = 0
    for cell in _cells():
        for _ in range(per_cell):
            d = _BUILDERS[cell["kind"]](rng, cat, cell)
            combo = "+".join(d["gear_effects"]) or "+".join(d["measurement_effects"]) or \
                ("equiv-" + "+".join(d["equivalent_effects"]) if d["equivalent_effects"] else "none")
            name = f"e-{cell['kind']}-{cell['category']}-{combo}-{_slug(cell['formulation'])}-{idx:03d}"
            cols = {k: np.asarray(v, dtype=float) for k, v in d["columns"].items()}
            cases.append(TruthCase(
                name=name, kind=d["kind"], model=d["model"], columns=cols,
                load_inertia_kgm2=d["load_inertia_kgm2"], gear_effects=tuple(d["gear_effects"]),
                measurement_effects=tuple(d["measurement_effects"]),
                nuisance={k: float(v) for k, v in d["nuisance"].items()},
                category=cell["category"], equivalent_effects=tuple(d["equivalent_effects"]),
                noise_rms=float(d["noise_rms"]), formulation=cell["formulation"],
                snr=float(d["snr"]), effect_snr={k: float(v) for k, v in d["effect_snr"].items()},
                noise_kind=d["noise_kind"], protocol=d["protocol"],
                added_noise=np.asarray(d["added_noise"], dtype=float)))
            idx += 1
    return cases
