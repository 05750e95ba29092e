"""Suite J -- an independent truth simulator for ``hdcad reconcile``.

Generates synthetic "measured" data of strain wave gears (CSF-GH / CSG-GH gear heads) with
KNOWN hidden effects, following ``truths/CONTRACT.md``.  numpy + scipy only; nothing from hdcad.

Every formulation used here is new with respect to the eight earlier suites (see NOTES_j.md):
  torsion      hysteresis: Segalman 4-parameter Iwan (Masing branches), Dieterich-Ruina
               rate-and-state slider in a standard-linear-solid arrangement, Perzyna power-law
               overstress viscoplastic slider (creep during holds);
               backlash: thermally drifting Oldham clearance (algebraic regularisation),
               progressive multi-key engagement, Palmgren line-contact (Q^0.9) play;
               housing: Roark tapered shaft, Volkersen torsional shear-lag press fit.
  transmission te_2x: two-frame (CS-fixed + FS-fixed) ovality beat, flexspline tooth-thickness
               2x with 4x overtone; te_1x: Jeffcott whirl (amplitude ~ omega^2),
               FS-frame eccentricity with unequal zone weights (detuned 1x).
  efficiency   low_load: engaged-tooth-count loss, Tabor elastic-hysteresis rolling loss,
               Weibull-CDF graph model of 023-1; temperature: WLF viscosity + Benedict-Kelley
               friction, Bair-Winer limiting-shear-stress traction.
  vibration    Chung-Hulbert generalised-alpha integration; logarithmic and quadratic run-ups;
               viscous / velocity-squared / warming (time-varying) damping.
  noise        white, Ornstein-Uhlenbeck (first-order sensor bandwidth, exact sampling),
               AR(1) with drifting innovation variance, 0.5 % gross outliers.
Run ``python truth_j.py [catalog_dir]`` for the self-check.
"""
from __future__ import annotations

import csv
import glob
import math
import re
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy.optimize import brentq
from scipy.signal import lfilter
from scipy.special import erfc

SUITE = "j"

ARCMIN_PER_RAD = 180.0 * 60.0 / math.pi
ARCSEC_PER_RAD = 180.0 * 3600.0 / math.pi
G_STEEL = 79.3e9  # Pa, shear modulus of steel


# =============================================================================================
# Contract dataclass
# =============================================================================================
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
        cols = [np.asarray(self.columns[k], dtype=float) for k in names]
        n = len(cols[0])
        with open(path, "w", newline="", encoding="utf-8") as f:
            w = csv.writer(f)
            w.writerow(names)
            for i in range(n):
                w.writerow([repr(float(c[i])) for c in cols])


# =============================================================================================
# Catalog (read at generation time, columns found by their headers)
# =============================================================================================
def _read_table(catalog_dir: Path, pattern: str) -> list[dict]:
    hits = sorted(glob.glob(str(Path(catalog_dir) / pattern)))
    if not hits:
        raise FileNotFoundError(f"catalog table {pattern} not found in {catalog_dir}")
    with open(hits[0], newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def _hdr(rows: list[dict], regex: str) -> str:
    """The first header matching ``regex`` (case-insensitive, full match)."""
    for h in rows[0].keys():
        if re.fullmatch(regex, h.strip(), flags=re.IGNORECASE):
            return h
    raise KeyError(f"no column matching {regex!r} in {list(rows[0].keys())}")


def _f(x):
    x = (x or "").strip()
    return float(x) if x else None


@dataclass
class GearModel:
    series: str           # "CSF-GH" / "CSG-GH"
    size: int
    ratio: int
    code: str             # "CSF-32-100-GH"
    T_rated: float        # rated torque at 2000 r/min input, N m (050-1 / 058-1)
    T_peak: float         # allowed peak torque at start/stop, N m
    N_max: float          # allowed max input speed, r/min
    T1: float
    T2: float
    K1: float
    K2: float
    K3: float
    hyst: float           # hysteresis loss, rad (052 / 060 text)
    backlash: float       # max backlash, rad (052-2 / 060-2)
    accuracy: float | None  # angular transmission accuracy, rad (051-1 / 059-1), max value

    def twist(self, T, s=1.0, p=None):
        """Catalog three-segment twist (seed 000 p.020 / 003 p.046), odd in T, divided by s.
        ``p``: optional p-norm soft minimum of the three segment lines (corner rounding)."""
        a = np.abs(np.asarray(T, dtype=float))
        th1 = self.T1 / self.K1
        th2 = th1 + (self.T2 - self.T1) / self.K2
        L1 = a / self.K1
        L2 = th1 + (a - self.T1) / self.K2
        L3 = th2 + (a - self.T2) / self.K3
        if p is None:
            th = np.where(a <= self.T1, L1, np.where(a <= self.T2, L2, L3))
        else:
            mn = np.minimum(np.minimum(L1, L2), L3)
            safe = np.where(mn > 0, mn, 1.0)
            with np.errstate(divide="ignore", over="ignore"):
                r = (L1 / safe) ** (-p) + (L2 / safe) ** (-p) + (L3 / safe) ** (-p)
                th = np.where(mn > 0, mn * r ** (-1.0 / p), 0.0)
        return np.sign(T) * th / s

    def secant_compliance(self):
        return float(self.twist(np.array([self.T_rated]))[0]) / self.T_rated


class Catalog:
    def __init__(self, catalog_dir):
        d = Path(catalog_dir)
        self.dir = d
        rat = _read_table(d, "gh_ratings_*.csv")
        stf = _read_table(d, "gh_stiffness_*.csv")
        hys = _read_table(d, "gh_hysteresis_*.csv")
        bkl = _read_table(d, "gh_backlash_*.csv")
        prf = _read_table(d, "gh_performance_*.csv")
        ke = _read_table(d, "ke_curve_*.csv")
        cex = _read_table(d, "component_examples.csv")
        lub = _read_table(d, "lubricant_temperature_*.csv")
        self.columns_used = {}

        def note(table, *cols):
            self.columns_used.setdefault(table, []).extend(cols)

        # --- ratings 050-1 / 058-1
        c_ser, c_size, c_rat = _hdr(rat, "series"), _hdr(rat, "size"), _hdr(rat, "ratio")
        c_tr = _hdr(rat, r"rated_torque_2000_nm")
        c_pk = _hdr(rat, r"peak_torque_nm")
        c_nmax = _hdr(rat, r"max_input_speed_rpm")
        note("gh_ratings", c_tr, c_pk, c_nmax)
        # --- stiffness 052-1 / 060-1
        s_ser, s_size = _hdr(stf, "series"), _hdr(stf, "size")
        s_rmin, s_rmax = _hdr(stf, "ratio_min"), _hdr(stf, "ratio_max")
        s_T1, s_T2 = _hdr(stf, r"T1_Nm"), _hdr(stf, r"T2_Nm")
        s_K = [_hdr(stf, rf"K{i}_Nm_per_rad") for i in (1, 2, 3)]
        note("gh_stiffness", s_T1, s_T2, *s_K)
        # --- hysteresis loss
        h_ser, h_rmin, h_rmax = _hdr(hys, "series"), _hdr(hys, "ratio_min"), _hdr(hys, "ratio_max")
        h_val = _hdr(hys, r"hysteresis_rad")
        note("gh_hysteresis", h_val)
        # --- backlash 052-2 / 060-2
        b_ser, b_size, b_rat = _hdr(bkl, "series"), _hdr(bkl, "size"), _hdr(bkl, "ratio")
        b_val = _hdr(bkl, r"backlash_rad")
        note("gh_backlash", b_val)
        # --- performance 051-1 / 059-1 (transmission accuracy)
        p_ser, p_size, p_rat = _hdr(prf, "series"), _hdr(prf, "size"), _hdr(prf, "ratio")
        p_acc = _hdr(prf, r"accuracy_rad")
        note("gh_performance", p_acc)

        def in_group(r, rmin, rmax):
            lo = _f(rmin)
            hi = _f(rmax)
            return r >= lo and (hi is None or r <= hi)

        self.models: list[GearModel] = []
        for row in rat:
            ser, size, ratio = row[c_ser].strip(), int(row[c_size]), int(row[c_rat])
            st = [x for x in stf if x[s_ser].strip() == ser and int(x[s_size]) == size
                  and in_group(ratio, x[s_rmin], x[s_rmax])]
            hy = [x for x in hys if x[h_ser].strip() == ser and in_group(ratio, x[h_rmin], x[h_rmax])]
            bk = [x for x in bkl if x[b_ser].strip() == ser and int(x[b_size]) == size
                  and int(x[b_rat]) == ratio]
            pf = [x for x in prf if x[p_ser].strip() == ser and int(x[p_size]) == size
                  and int(x[p_rat]) == ratio and _f(x[p_acc]) is not None]
            if not (st and hy and bk):
                continue
            st = st[0]
            vals = [_f(st[s_T1]), _f(st[s_T2])] + [_f(st[c]) for c in s_K]
            if any(v is None for v in vals):
                continue
            prefix = ser.split("-")[0]
            self.models.append(GearModel(
                series=ser, size=size, ratio=ratio, code=f"{prefix}-{size}-{ratio}-GH",
                T_rated=_f(row[c_tr]), T_peak=_f(row[c_pk]), N_max=_f(row[c_nmax]),
                T1=vals[0], T2=vals[1], K1=vals[2], K2=vals[3], K3=vals[4],
                hyst=_f(hy[0][h_val]), backlash=_f(bk[0][b_val]),
                accuracy=_f(pf[0][p_acc]) if pf else None))
        # --- Ke anchor (graph 023-1 survives as alpha = 0.58 -> Ke = 0.93)
        k_a, k_k = _hdr(ke, "alpha"), _hdr(ke, "Ke")
        pts = sorted((_f(r[k_a]), _f(r[k_k])) for r in ke)
        self.ke_alpha, self.ke_value = [p for p in pts if p[0] < 1.0][0]
        note("ke_curve", k_a, k_k)
        # --- efficiency level anchor (CSF-20-80 example, 78 % at rated torque, 20 C)
        c_eff = _hdr(cex, r"efficiency_rated_pct")
        self.eta_anchor = [_f(r[c_eff]) for r in cex if _f(r[c_eff]) is not None][0]
        note("component_examples", c_eff)
        # --- lubricant temperature (SK-1A: catalog measuring grease, 016-2)
        l_name, l_min, l_max = _hdr(lub, "lubricant"), _hdr(lub, "use_min_C"), _hdr(lub, "use_max_C")
        sk = [r for r in lub if r[l_name].strip() == "SK-1A"][0]
        self.lub_min = _f(sk[l_min])
        self.lub_max_ambient = _f(sk[l_max])
        self.lub_rise = 40.0  # 016-2 note: temperature rise over ambient kept at 40 C or less
        note("lubricant_temperature", l_min, l_max)

    def pick(self, rng, kind, filt=None) -> GearModel:
        ms = [m for m in self.models if filt is None or filt(m)]
        if kind in ("transmission", "vibration"):
            ms = [m for m in ms if m.accuracy is not None]
        return ms[int(rng.integers(len(ms)))]


# =============================================================================================
# Helpers: noise, sizes
# =============================================================================================
def _rms(x) -> float:
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x)))


def _lu(rng, lo, hi):
    """log-uniform draw"""
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def _unit_noise(rng, n, style: str, outliers: bool, t=None):
    """Noise with RMS exactly 1 (outliers included).  Returns (noise, description)."""
    if style == "white":
        e = rng.standard_normal(n)
        desc = "white"
    elif style == "ou":
        # first-order sensor bandwidth (RC) driven by white noise, sampled exactly:
        # Ornstein-Uhlenbeck transition phi_i = exp(-dt_i / tau), tau chosen so that the
        # median phi is in [0.3, 0.8].
        tt = np.arange(n, dtype=float) if t is None else np.asarray(t, dtype=float)
        dt = np.diff(tt)
        med = float(np.median(dt))
        phi_med = rng.uniform(0.3, 0.8)
        tau = -med / math.log(phi_med)
        phis = np.exp(-dt / tau)
        z = rng.standard_normal(n)
        if np.allclose(dt, med, rtol=1e-6, atol=0):
            u = np.concatenate([[z[0]], math.sqrt(1 - phi_med ** 2) * z[1:]])
            e = lfilter([1.0], [1.0, -phi_med], u)
        else:
            e = np.empty(n)
            e[0] = z[0]
            for i in range(1, n):
                e[i] = phis[i - 1] * e[i - 1] + math.sqrt(1 - phis[i - 1] ** 2) * z[i]
        desc = f"ou-bandwidth(phi={phi_med:.2f})"
    elif style == "ar1drift":
        phi = rng.uniform(0.3, 0.8)
        a = rng.uniform(0.2, 0.5) * (1 if rng.random() < 0.5 else -1)
        scale = 1.0 + a * np.linspace(-1.0, 1.0, n)
        z = rng.standard_normal(n) * scale * math.sqrt(1 - phi ** 2)
        z[0] = z[0] / math.sqrt(1 - phi ** 2)
        e = lfilter([1.0], [1.0, -phi], z)
        desc = f"ar1-drifting-variance(phi={phi:.2f},ramp={a:+.2f})"
    else:
        raise ValueError(style)
    e = e / _rms(e)
    if outliers:
        m = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, size=m, replace=False)
        e[idx] += rng.choice([-1.0, 1.0], size=m) * rng.uniform(8.0, 15.0, size=m)
        desc += "+outliers(0.5%)"
    e = e / _rms(e)
    return e, desc


def _noise_style(rng, allow_outliers=True):
    style = ["white", "ou", "ar1drift"][int(rng.integers(3))]
    out = bool(allow_outliers and rng.random() < 0.25)
    return style, out


def _single_size(rng, comp):
    m = rng.uniform(*comp["range"])
    d = comp["dev"](m)
    r = _rms(d)
    k = rng.uniform(4.0, 12.0)
    return [m], d, r / k


def _pair_size(rng, cA, cB, combine):
    """Magnitudes of two effects so that each RMS and the combined RMS are 4..12 x noise.
    Random draws first (with a ratio correction), then a grid over both magnitude ranges; a
    feasible point is taken at random and sigma drawn log-uniformly in its feasible interval."""
    def feasible(mA, mB, dA=None, dB=None):
        dA = cA["dev"](mA) if dA is None else dA
        dB = cB["dev"](mB) if dB is None else dB
        rA, rB = _rms(dA), _rms(dB)
        dC = combine(mA, mB, dA, dB)
        rC = _rms(dC)
        lo = max(rA, rB, rC) / 12.0
        hi = min(rA, rB, rC) / 4.0
        return lo, hi, dC

    for _ in range(12):
        mA = rng.uniform(*cA["range"])
        mB = rng.uniform(*cB["range"])
        dA, dB = cA["dev"](mA), cB["dev"](mB)
        rA, rB = _rms(dA), _rms(dB)
        q = _lu(rng, 0.6, 1.6)  # target rB / rA
        mB2 = float(np.clip(mB * q * rA / rB, *cB["range"]))
        if mB2 != mB:
            mB, dB = mB2, cB["dev"](mB2)
            rB = _rms(dB)
        if not (0.45 < rB / rA < 2.2):
            mA2 = float(np.clip(mA * rB / (q * rA), *cA["range"]))
            if mA2 != mA:
                mA, dA = mA2, cA["dev"](mA2)
        lo, hi, dC = feasible(mA, mB, dA, dB)
        if lo < 0.98 * hi:
            return [mA, mB], dC, _lu(rng, lo * 1.005, hi * 0.995)
    gA = np.linspace(*cA["range"], 6)
    gB = np.linspace(*cB["range"], 6)
    ok = []
    for mA in gA:
        for mB in gB:
            lo, hi, _ = feasible(mA, mB)
            if lo < 0.98 * hi:
                ok.append((mA, mB))
    if not ok:
        raise RuntimeError("pair sizing failed: no magnitudes in range give 4..12 x noise for both")
    mA, mB = ok[int(rng.integers(len(ok)))]
    # jitter inside the grid cell, keep if still feasible
    jA = float(np.clip(mA + rng.uniform(-0.5, 0.5) * (gA[1] - gA[0]), *cA["range"]))
    jB = float(np.clip(mB + rng.uniform(-0.5, 0.5) * (gB[1] - gB[0]), *cB["range"]))
    lo, hi, dC = feasible(jA, jB)
    if lo < 0.98 * hi:
        mA, mB = jA, jB
    else:
        lo, hi, dC = feasible(mA, mB)
    return [mA, mB], dC, _lu(rng, lo * 1.005, hi * 0.995)


def _sum_combine(mA, mB, dA, dB):
    return dA + dB


# =============================================================================================
# Cells
# =============================================================================================
@dataclass
class Cell:
    kind: str
    category: str
    gear: tuple          # gear effects (single / pair)
    meas: tuple          # measurement effects (decoys)
    tag: str             # formulation slug used in names
    spec: dict = field(default_factory=dict)
    equivalent: tuple = ()

    def slug(self):
        if self.category in ("single", "pair"):
            mid = "-".join(self.gear)
        elif self.category == "clean":
            mid = ""
        else:
            mid = "-".join(self.meas) if self.meas else "nuisance"
        parts = [SUITE, self.kind, self.category] + ([mid] if mid else []) + [self.tag]
        return "-".join(parts)


# =============================================================================================
# TORSION
# =============================================================================================
def _torsion_protocol(rng, kind, T0, n):
    t_ramp = rng.uniform(12.0, 40.0)  # s for 0 -> T0
    rate = T0 / t_ramp
    hold = 0.0
    if kind == "ramp":
        nc = int(rng.integers(2, 4))
        levels = [0.0] + [T0, -T0] * nc + [0.0]
    elif kind == "hold":
        nc = int(rng.integers(2, 4))
        levels = [0.0] + [T0, -T0] * nc + [0.0]
        hold = rng.uniform(0.25, 0.6) * t_ramp
    elif kind == "grow":
        a1, a2 = rng.uniform(0.15, 0.3), rng.uniform(0.45, 0.65)
        levels = [0.0, a1 * T0, -a1 * T0, a2 * T0, -a2 * T0, T0, -T0, T0, 0.0]
    else:
        raise ValueError(kind)
    tk, Tk = [0.0], [levels[0]]
    for i in range(1, len(levels)):
        if hold > 0 and i > 1 and abs(Tk[-1]) > 0:
            tk.append(tk[-1] + hold)
            Tk.append(Tk[-1])
        tk.append(tk[-1] + abs(levels[i] - Tk[-1]) / rate)
        Tk.append(levels[i])
    t = np.linspace(0.0, tk[-1], n)
    # include the exact turning points (replace nearest samples) so reversals are sampled
    T = np.interp(t, tk, Tk)
    for tkk in tk:
        j = int(np.argmin(np.abs(t - tkk)))
        t[j] = tkk
    T = np.interp(t, tk, Tk)
    return t, T, rate, {"protocol": kind, "t_ramp": t_ramp, "hold": hold}


def _cal_cycle(Tr, rate, n=1500, hold=0.0):
    """Calibration cycle 0 -> +Tr -> -Tr -> +Tr (the catalog's hysteresis-loss definition), at the
    test's torque rate and with the test's holds at the extremes (rate-dependent sliders creep
    during holds, so the loss is defined for the same protocol)."""
    r = Tr / rate
    tk = np.array([0.0, r, r + hold, 3 * r + hold, 3 * r + 2 * hold, 5 * r + 2 * hold])
    Tk = np.array([0.0, Tr, Tr, -Tr, -Tr, Tr])
    t = np.linspace(0, tk[-1], n)
    for tkk in tk:
        t[int(np.argmin(np.abs(t - tkk)))] = tkk
    return t, np.interp(t, tk, Tk)


def _loop_width(T, dev):
    """Twist difference at T = 0 between the branch descending from +Tr and the branch ascending
    from -Tr (B - B' of seed fig. 020-1) for the calibration cycle."""
    def plateau_end(i):
        while i + 1 < len(T) and T[i + 1] == T[i]:
            i += 1
        return i
    i_top = plateau_end(int(np.argmax(T)))     # end of the (first) hold at +Tr
    i_bot = plateau_end(int(np.argmin(T)))     # end of the hold at -Tr
    seg_d = slice(i_top, i_bot + 1)
    seg_a = slice(i_bot, len(T))
    Td, dd = T[seg_d][::-1], dev[seg_d][::-1]    # increasing
    Ta, da = T[seg_a], dev[seg_a]
    return float(np.interp(0.0, Td, dd) - np.interp(0.0, Ta, da))


# ---- hysteresis 1: Segalman four-parameter Iwan with Masing branches --------------------------
def _segalman_backbone(chi, beta):
    """Normalised (phi_max = 1, R = 1) Segalman 4-parameter Iwan backbone F(u), u in [0,1]."""
    u = np.linspace(0.0, 1.0, 4001)
    KT = (1.0 + beta) / (chi + 1.0)
    F = KT * u - u ** (chi + 2.0) / ((chi + 1.0) * (chi + 2.0))
    FS = (beta + (chi + 1.0) / (chi + 2.0)) / (chi + 1.0)
    return u, F, KT, FS


def _masing(T, ubb):
    """Masing / extended-Masing response u(T) for a torque history with ideal memory."""
    n = len(T)
    u = np.empty(n)
    stack = []           # reversal points (T_r, u_r)
    direction = 0.0
    Tp = T[0]
    up = ubb(np.array([Tp]))[0]
    u[0] = up
    for i in range(1, n):
        Ti = T[i]
        dT = Ti - Tp
        if dT != 0.0:
            d = 1.0 if dT > 0 else -1.0
            if direction != 0.0 and d != direction:
                stack.append((Tp, up))
            direction = d
            while True:
                if len(stack) >= 2 and (Ti - stack[-2][0]) * d > 0:
                    stack.pop()
                    stack.pop()
                    continue
                if len(stack) == 1 and (Ti + stack[0][0]) * d > 0 and abs(Ti) >= abs(stack[0][0]):
                    stack.pop()
                    continue
                break
            if not stack:
                ui = ubb(np.array([Ti]))[0]
            else:
                To, uo = stack[-1]
                ui = uo + 2.0 * ubb(np.array([(Ti - To) / 2.0]))[0]
        else:
            ui = up
        u[i] = ui
        Tp, up = Ti, ui
    return u


def _hyst_segalman(rng, t, T, Tr, rate, Tmax, hold=0.0):
    chi = rng.uniform(-0.5, -0.05)   # dissipation per cycle ~ T^(3+chi), slope 2.5..2.95
    beta = rng.uniform(0.1, 1.0)
    ug, Fg, KT, FS = _segalman_backbone(chi, beta)
    TS = rng.uniform(1.15, 1.6) * Tmax   # macroslip torque, above every torque of the test

    def ubb(x):
        return np.sign(x) * np.interp(np.abs(x) * FS / TS, Fg, ug)

    def shape(TT):
        u = _masing(TT, ubb)
        return u - (TT * FS / TS) / KT

    tc, Tc = _cal_cycle(Tr, rate)
    w = _loop_width(Tc, shape(Tc))
    return shape(T) / w, f"segalman4-iwan-masing(chi={chi:.2f},beta={beta:.2f},TS/Tmax={TS / Tmax:.2f})"


# ---- hysteresis 2/3: slider in a standard-linear-solid arrangement ----------------------------
def _sls_slider(t, T, rho, vel, nsub=3, state=None):
    """Torque-driven element: spring k_a parallel with (spring k_b + slider).  In torque units
    w = k_a z, slider force f = rho (T - w), rho = k_b / (k_a + k_b).  Extra twist ~ w.
    vel(f, st) -> slip rate dw/dt; implicit Euler, bracketed root per sub-step.
    ``state``: optional (init, update(st, v, h)) for a state variable."""
    n = len(t)
    w = np.zeros(n)
    wc = 0.0
    st = state[0] if state else None
    upd = state[1] if state else None
    for i in range(1, n):
        h = (t[i] - t[i - 1]) / nsub
        for j in range(1, nsub + 1):
            Tn = T[i - 1] + (T[i] - T[i - 1]) * j / nsub
            f0 = rho * (Tn - wc)
            v0 = vel(f0, st)
            if h <= 0.0 or v0 == 0.0 or abs(h * v0) < 1e-13 * (abs(Tn) + 1e-9):
                v = 0.0 if h <= 0.0 else v0
                wn = wc + h * v
            else:
                g = lambda x: x - wc - h * vel(rho * (Tn - x), st)
                lo, hi = (wc, Tn) if v0 > 0 else (Tn, wc)
                glo, ghi = g(lo), g(hi)
                if glo * ghi > 0:
                    wn = wc + h * v0
                else:
                    wn = brentq(g, lo, hi, xtol=1e-12 * (abs(Tn) + abs(wc) + 1e-9), rtol=1e-10)
                v = (wn - wc) / h
            if upd is not None:
                st = upd(st, abs(v), h)
            wc = wn
        w[i] = wc
    return w


def _hyst_perzyna(rng, t, T, Tr, rate, Tmax, hold=0.0):
    rho = rng.uniform(0.3, 0.8)
    ys = rng.uniform(0.35, 0.6) * Tr            # applied torque at which slip starts
    fy = rho * ys
    m = rng.uniform(1.0, 3.0)
    eps = rng.uniform(0.05, 0.3)                 # overstress needed to slip at the ramp rate
    W0 = rate / eps ** m

    def vel(f, st):
        ov = abs(f) / fy - 1.0
        if ov <= 0.0:
            return 0.0
        return math.copysign(W0 * ov ** m, f)

    tc, Tc = _cal_cycle(Tr, rate, n=1200, hold=hold)
    wc = _sls_slider(tc, Tc, rho, vel)
    width = _loop_width(Tc, wc)
    w = _sls_slider(t, T, rho, vel)
    return w / width, f"perzyna-viscoplastic-sls(rho={rho:.2f},Ty/Tr={ys / Tr:.2f},m={m:.2f},eps={eps:.2f})"


def _hyst_ratestate(rng, t, T, Tr, rate, Tmax, hold=0.0):
    rho = rng.uniform(0.3, 0.8)
    ys = rng.uniform(0.35, 0.6) * Tr
    fs = rho * ys
    A = rng.uniform(0.01, 0.03) * fs
    B = rng.uniform(0.5, 0.9) * A               # velocity strengthening (stable, no stick-slip)
    W0 = rate
    Dw = rng.uniform(0.002, 0.01) * Tr
    t_age = _lu(rng, 30.0, 3000.0)              # rest time before the test (aging law)

    def vel(f, st):
        x = (abs(f) - fs) / A - (B / A) * math.log(max(st * W0 / Dw, 1e-300))
        if x < -700:
            return 0.0
        return math.copysign(W0 * math.exp(min(x, 700.0)), f)

    def upd(st, v, h):  # Dieterich aging law, exact for constant v over the sub-step
        if v * h / Dw < 1e-9:
            return st + h
        ss = Dw / v
        return ss + (st - ss) * math.exp(-v * h / Dw)

    tc, Tc = _cal_cycle(Tr, rate, n=1200, hold=hold)
    wc = _sls_slider(tc, Tc, rho, vel, state=(t_age, upd))
    width = _loop_width(Tc, wc)
    w = _sls_slider(t, T, rho, vel, state=(t_age, upd))
    return w / width, (f"dieterich-ruina-rate-state-sls(rho={rho:.2f},Ts/Tr={ys / Tr:.2f},"
                       f"a/mu={A / fs:.3f},b/a={B / A:.2f},t_age={t_age:.0f}s)")


# ---- backlash ---------------------------------------------------------------------------------
def _bl_thermal(rng, t, T, Tr):
    """Oldham clearance that changes with test time (differential expansion during warm-up):
    b(t) = b0 (1 + kappa (1 - exp(-t/tau))); algebraic (Lorentzian-type) regularised sign."""
    kappa = rng.uniform(0.25, 0.6) if rng.random() < 0.5 else -rng.uniform(0.2, 0.4)
    tau = rng.uniform(0.3, 1.0) * t[-1]
    Te = rng.uniform(0.002, 0.01) * Tr
    bt = 1.0 + kappa * (1.0 - np.exp(-t / tau))
    shape = 0.5 * bt * T / np.sqrt(T * T + Te * Te)
    return shape, f"thermal-clearance-play(kappa={kappa:+.2f},tau/t_end={tau / t[-1]:.2f},Te/Tr={Te / Tr:.3f})"


def _bl_multikey(rng, t, T, Tr):
    """Oldham coupling whose key faces engage one after another: nk faces per direction with
    scattered clearances c_i = b/2 (1 - delta_i); the nk-1 first faces are elastic (equal face
    stiffness), the last face (clearance b/2) is the hard stop.  The gap therefore closes in a
    step of the smallest clearance followed by a progressive approach to b/2, reached at the
    engagement torque Te; beyond Te the coupling is rigid (no extra series compliance)."""
    nk = int(rng.integers(2, 5))
    spread = rng.uniform(0.15, 0.5)
    delta = np.sort(rng.uniform(0.02, spread, nk - 1))[::-1]
    c = 0.5 * (1.0 - delta)                      # elastic faces, for b = 1
    Te = rng.uniform(0.01, 0.05) * Tr
    kc = Te / np.sum(0.5 - c)
    th = np.linspace(c.min(), 0.5, 2000)
    Tg = kc * np.maximum(0.0, th[:, None] - c[None, :]).sum(axis=1)
    th_of_T = np.interp(np.abs(T), Tg, th)       # = 0.5 beyond Te (rigid stop)
    shape = np.where(np.abs(T) > 0, np.sign(T) * th_of_T, 0.0)
    return shape, f"multi-key-progressive-engagement(n={nk},spread={spread:.2f},Te/Tr={Te / Tr:.3f})"


def _bl_palmgren(rng, t, T, Tr):
    """Play b with Palmgren roller line-contact approach delta = C |T|^0.9 after closure; the
    gap crossing regularised algebraically over a band Te."""
    Te = rng.uniform(0.002, 0.01) * Tr
    lam = rng.uniform(0.2, 0.6)                  # contact approach at Tr as a fraction of b/2
    Cp = lam * 0.5 / Tr ** 0.9
    shape = 0.5 * T / np.sqrt(T * T + Te * Te) + np.sign(T) * Cp * np.abs(T) ** 0.9
    return shape, f"palmgren-line-contact-play(delta(Tr)/(b/2)={lam:.2f},Te/Tr={Te / Tr:.3f})"


# ---- housing compliance -------------------------------------------------------------------------
def _housing_tapered(rng, m: GearModel):
    """Roark tapered solid shaft (Young & Budynas, Table 10.1):
    theta = 2 T L (r1^2 + r1 r2 + r2^2) / (3 pi G r1^3 r2^3), r2 = q r1.
    Length and taper drawn; the small-end radius r1 follows from the compliance."""
    L = rng.uniform(0.03, 0.12)
    q = rng.uniform(1.1, 1.5)

    def r1_for(C):
        return (2.0 * L * (1 + q + q * q) / (3.0 * math.pi * G_STEEL * q ** 3 * C)) ** 0.25
    return r1_for, f"roark-tapered-shaft(L={L * 1e3:.0f}mm,r2/r1={q:.2f})"


def _shearlag_compliance(a, ro, lr, ki, Lf):
    """Free shaft length Lf plus a Volkersen-type torsional shear-lag press fit (shaft radius a,
    hub outer radius ro*a, overlap l = lr*a, interface shear stiffness ki per unit area), T = 1.
    With A = 1/(G Js), B = 1/(G Jh), kappa = 2 pi a^3 ki, lambda^2 = (A + B) kappa, the slip
    Delta'' = lambda^2 Delta gives the closed form
        theta_joint = [(A^2 + B^2) coth(lambda l) + 2 A B csch(lambda l)] / (lambda (A + B))
                      + A B l / (A + B)
    (-> l/(G Js + G Jh) for a bonded fit, -> infinity for ki -> 0)."""
    Js = math.pi * a ** 4 / 2.0
    Jh = math.pi * ((ro * a) ** 4 - a ** 4) / 2.0
    A = 1.0 / (G_STEEL * Js)
    Bc = 1.0 / (G_STEEL * Jh)
    kap = 2.0 * math.pi * a ** 3 * ki
    ell = lr * a
    lam = math.sqrt((A + Bc) * kap)
    x = lam * ell
    coth = 1.0 / math.tanh(x)
    csch = 1.0 / math.sinh(x) if x < 700 else 0.0
    joint = ((A * A + Bc * Bc) * coth + 2.0 * A * Bc * csch) / (lam * (A + Bc)) + A * Bc * ell / (A + Bc)
    return Lf * A + joint


def _housing_shearlag(rng, m: GearModel):
    """Press-fitted output hub: free shaft length + Volkersen torsional shear lag (Volkersen 1938;
    tubular form Adams & Peppiatt 1977).  Geometry ratios drawn; the shaft radius follows from
    the compliance."""
    ro = rng.uniform(1.6, 2.2)
    lr = rng.uniform(1.0, 2.0)
    ki = _lu(rng, 2e13, 2e14)                    # interface shear stiffness, N/m^3
    Lf = rng.uniform(0.02, 0.08)

    def a_for(C):
        return brentq(lambda a: _shearlag_compliance(a, ro, lr, ki, Lf) - C, 5e-4, 0.15, xtol=1e-7)
    return a_for, f"volkersen-shear-lag-press-fit(Lf={Lf * 1e3:.0f}mm,Ro/a={ro:.2f},l/a={lr:.2f},ki={ki:.2e})"


def _housing_shape(rng, m, T, which):
    """Extra series compliance (linear in T); magnitude c_h as a fraction of the catalog secant
    compliance at rated torque; the geometry giving it is reported for plausibility."""
    Cs = m.secant_compliance()
    if which == "tapered":
        r1_for, desc = _housing_tapered(rng, m)
        info = lambda ch: f"r1={r1_for(ch * Cs) * 1e3:.1f}mm"
    else:
        a_for, desc = _housing_shearlag(rng, m)
        info = lambda ch: f"a={a_for(ch * Cs) * 1e3:.1f}mm"
    return Cs * T, desc, info


# ---- torsion builder ------------------------------------------------------------------------
def _draw_scale(rng, dist):
    if dist == "tri":
        return float(rng.triangular(0.9, 1.0, 1.1)), "triangular(0.9,1,1.1)"
    if dist == "arcsine":
        return float(0.9 + 0.2 * rng.beta(0.5, 0.5)), "arcsine(0.9..1.1)"
    raise ValueError(dist)


def _build_torsion(rng, cat: Catalog, cell: Cell, name: str) -> TruthCase:
    sp = cell.spec
    filt = sp.get("filter")
    m = cat.pick(rng, "torsion", filt)
    s, sdesc = _draw_scale(rng, sp.get("scale", "tri"))
    p = rng.uniform(150.0, 300.0) if sp.get("curve") == "pnorm" else None   # knee deficit <= 0.46 %
    T0 = min(m.T_rated * rng.uniform(0.95, 1.2), 0.9 * m.T_peak)
    n = int(rng.integers(1500, 3001))
    t, T, rate, pinfo = _torsion_protocol(rng, sp.get("protocol", "ramp"), T0, n)
    Tr = m.T_rated
    Tmax = max(T0, Tr)
    y0 = m.twist(T, s, p)
    comps, descs, infos = [], [], []
    for eff, form in sp.get("effects", []):
        if eff == "hysteresis":
            fn = {"segalman": _hyst_segalman, "perzyna": _hyst_perzyna,
                  "ratestate": _hyst_ratestate}[form]
            shp, d = fn(rng, t, T, Tr, rate, Tmax, pinfo["hold"])
            base = m.hyst * shp
            comps.append({"dev": (lambda mm, b=base: mm * b),
                          "range": (0.3, 1.3) if cell.category == "pair" else (0.4, 1.3)})
            descs.append(d)
            infos.append(lambda mm: f"loss={mm:.2f}x{m.hyst:.2e}rad")
        elif eff == "backlash":
            fn = {"thermal": _bl_thermal, "multikey": _bl_multikey, "palmgren": _bl_palmgren}[form]
            shp, d = fn(rng, t, T, Tr)
            base = m.backlash * shp
            comps.append({"dev": (lambda mm, b=base: mm * b), "range": (0.4, 1.0)})
            descs.append(d)
            infos.append(lambda mm: f"b={mm:.2f}x{m.backlash:.2e}rad")
        elif eff == "housing_compliance":
            base, d, info = _housing_shape(rng, m, T, form)
            comps.append({"dev": (lambda mm, b=base: mm * b),
                          "range": (0.06, 0.5) if cell.category == "pair" else (0.12, 0.5)})
            descs.append(d)
            infos.append(lambda mm, info=info: f"c_h={mm:.2f},{info(mm)}")
    nuis = {"stiffness_scale": s}
    twist_true = y0.copy()
    T_rec = T.copy()
    meas = tuple(cell.meas)
    units = None
    cat_ = cell.category
    if cat_ == "clean":
        dev = np.zeros_like(T)
        sigma = m.hyst * 0.35 / rng.uniform(4.0, 12.0)
        descs.append(f"catalog-3seg{'-pnorm(p=%.0f)' % p if p else '-exact'}")
    elif cat_ in ("single", "pair"):
        if len(comps) == 1:
            ms, dev, sigma = _single_size(rng, comps[0])
        else:
            ms, dev, sigma = _pair_size(rng, comps[0], comps[1], _sum_combine)
        descs = [f"{d}[{inf(mm)}]" for d, inf, mm in zip(descs, infos, ms)]
        twist_true = y0 + dev
    else:
        what = sp["what"]
        k = rng.uniform(4.0, 12.0)
        dev = None
        if what == "armlag":        # thermal_drift: twist-arm / probe-stand expansion
            tau = rng.uniform(0.2, 1.0) * t[-1]
            D = rng.uniform(0.1, 0.6) * m.hyst * (1 if rng.random() < 0.5 else -1)
            r = t - tau * (1.0 - np.exp(-t / tau))
            dev = D * r / r[-1]
            descs.append(f"twist-arm-expansion-lagged-ramp(D={D:.2e}rad,tau/t_end={tau / t[-1]:.2f})")
        elif what == "lever":       # sensor_gain on the torque channel (dead-weight lever length)
            g = rng.uniform(1.12, 1.3)
            T_rec = g * T
            y0 = m.twist(T_rec, s, p)
            twist_true = m.twist(T, s, p)
            descs.append(f"dead-weight-lever-length-error(torque gain={g:.3f})")
        elif what == "rezero":      # angle_offset step during a hold
            holds = np.where(np.diff(T) == 0.0)[0]
            ts = t[holds[len(holds) // 2]] if len(holds) else t[len(t) // 2]
            D = rng.uniform(0.2, 1.0) * m.hyst * (1 if rng.random() < 0.5 else -1)
            dev = np.where(t > ts, D, 0.0)
            descs.append(f"encoder-re-zero-step(D={D:.2e}rad,t={ts:.0f}s)")
        elif what == "arcmin":      # wrong_units
            units = ARCMIN_PER_RAD
            descs.append("twist-in-arc-minutes")
        elif what == "stiff":       # nuisance out of spread (stiffer than any gear effect allows)
            s_out = rng.uniform(1.15, 1.35)
            nuis["stiffness_scale"] = s_out
            y0 = m.twist(T, 1.0, p)
            twist_true = m.twist(T, s_out, p)
            descs.append(f"stiff-gear-out-of-spread(s={s_out:.3f})")
        elif what == "diaphragm":   # equivalent to housing_compliance
            ch = rng.uniform(0.12, 0.5)
            Cd = ch * m.secant_compliance()
            ri = rng.uniform(0.25, 0.35) * m.size * 1e-3
            ro = ri * rng.uniform(1.8, 2.4)
            thick = (1.0 / ri ** 2 - 1.0 / ro ** 2) / (4.0 * math.pi * G_STEEL * Cd)
            dev = Cd * T
            nuis["fs_diaphragm_series_compliance_ratio"] = ch
            descs.append(f"fs-diaphragm-annular-plate-torsion(c={ch:.2f},ri={ri * 1e3:.1f}mm,"
                         f"ro={ro * 1e3:.1f}mm,t_eq={thick * 1e3:.2f}mm)")
        elif what == "keyplay":     # equivalent to backlash (offset switching with the torque sign)
            r_key = rng.uniform(0.25, 0.4) * m.size * 1e-3   # fixture shaft radius at the key
            clr = rng.uniform(0.8e-6, 2.5e-6)                  # worn precision key (JIS B 1301)
            beta = clr / r_key
            Te = rng.uniform(0.002, 0.01) * Tr
            dev = 0.5 * beta * T / np.sqrt(T * T + Te * Te)
            nuis["fixture_key_play_rad"] = beta
            descs.append(f"fixture-keyway-play(clearance={clr * 1e6:.2f}um at r={r_key * 1e3:.1f}mm,"
                         f"Te/Tr={Te / Tr:.3f})")
        elif what == "jointslip":   # equivalent to hysteresis (rig bolted lap joint, Segalman)
            shp, d = _hyst_segalman(rng, t, T, Tr, rate, Tmax)
            L = rng.uniform(0.4, 1.2) * m.hyst
            dev = L * shp
            nuis["fixture_joint_loss_rad"] = L
            descs.append("fixture-bolted-lap-joint-" + d)
        else:
            raise ValueError(what)
        if dev is not None:
            twist_true = y0 + dev
        dev = twist_true - y0
        if units is None:
            sigma = _rms(dev) / k
        else:
            sigma = m.hyst * 0.35 / rng.uniform(4.0, 12.0)
    style, out = sp.get("noise") or _noise_style(rng)
    e, ndesc = _unit_noise(rng, len(T), style, out, t)
    noise = sigma * e
    twist_meas = twist_true + noise
    noise_rms = _rms(noise)
    snr = 0.0
    if cat_ != "clean":
        if units is not None:
            twist_meas = twist_meas * units
            noise_rms *= units
            snr = _rms((units - 1.0) * twist_true) / noise_rms
        else:
            snr = _rms(dev) / noise_rms
    form = " + ".join(descs) + f" | {sdesc} | protocol={pinfo['protocol']} | noise={ndesc}"
    cols = {"torque_Nm": T_rec, "twist_rad": twist_meas, "time_s": t}
    return TruthCase(name=name, kind="torsion", model=m.code, columns=cols, load_inertia_kgm2=None,
                     gear_effects=tuple(cell.gear), measurement_effects=meas, nuisance=nuis,
                     category=cat_, equivalent_effects=tuple(cell.equivalent), noise_rms=noise_rms,
                     formulation=form, snr=snr)


# =============================================================================================
# TRANSMISSION
# =============================================================================================
def _te_two_frame(rng, phi, R):
    pc, pf = rng.uniform(0, 2 * np.pi, 2)
    rf = rng.uniform(0.3, 1.0)
    sh = np.sin(2 * phi + pc) + rf * np.sin(2 * phi * (1.0 - 1.0 / R) + pf)
    return sh / (1.0 + rf), f"two-frame-ovality(CS-fixed 2x + FS-fixed 2(1-1/R)x, aF/aC={rf:.2f})"


def _te_overtone(rng, phi, R):
    p2, p4 = rng.uniform(0, 2 * np.pi, 2)
    r4 = rng.uniform(0.1, 0.3)
    sh = np.sin(2 * phi + p2) + r4 * np.sin(4 * phi + p4)
    return sh / (1.0 + r4), f"fs-tooth-thickness-2x+4x-overtone(a4/a2={r4:.2f})"


def _te_whirl(rng, phi, R, N=None, Nref=None):
    p1 = rng.uniform(0, 2 * np.pi)
    if N is None:
        return np.sin(phi + p1), "jeffcott-whirl-1x(amplitude~omega^2)"
    return (N / Nref) ** 2 * np.sin(phi + p1), "jeffcott-whirl-1x(amplitude~omega^2)"


def _te_fsframe(rng, phi, R):
    """FS-fixed first-order error seen through two engagement zones of unequal weight: the two
    zones cancel it only partly; it is swept at the WG-to-FS rate, (1 - 1/R) per input rev."""
    p = rng.uniform(0, 2 * np.pi)
    return np.sin(phi * (1.0 - 1.0 / R) + p), "fs-frame-eccentricity-unequal-zones(detuned 1x)"


_TE = {"twoframe": _te_two_frame, "overtone": _te_overtone, "whirl": _te_whirl, "fsframe": _te_fsframe}


def _build_transmission(rng, cat: Catalog, cell: Cell, name: str) -> TruthCase:
    sp = cell.spec
    m = cat.pick(rng, "transmission")
    R = float(m.ratio)
    acc = m.accuracy
    n_rev = rng.uniform(3.0, 8.0)
    spr = int(rng.integers(240, 601))
    n = min(int(n_rev * spr), 4800)
    N_test = rng.uniform(10.0, 60.0)             # input speed, r/min (slow TE test)
    phi0 = rng.uniform(0, 2 * np.pi)
    phi = phi0 + np.linspace(0.0, 2 * np.pi * n_rev, n)
    t = (phi - phi0) / (2 * np.pi * N_test / 60.0)
    offset = rng.uniform(-np.pi, np.pi)
    y0 = phi / R + offset
    comps, descs = [], []
    for eff, form in sp.get("effects", []):
        sh, d = _TE[form](rng, phi, R)
        base = 0.5 * acc * sh
        comps.append({"dev": (lambda mm, b=base: mm * b), "range": (0.2, 0.8)})
        descs.append(d)
    nuis = {"offset_rad": offset}
    cat_ = cell.category
    inp = phi.copy()
    units = None
    true_out = y0.copy()
    if cat_ == "clean":
        dev = np.zeros(n)
        sigma = 0.3 * 0.5 * acc / rng.uniform(4, 12)
        descs.append("catalog-kinematic-ratio")
    elif cat_ in ("single", "pair"):
        if len(comps) == 1:
            ms, dev, sigma = _single_size(rng, comps[0])
        else:
            ms, dev, sigma = _pair_size(rng, comps[0], comps[1], _sum_combine)
        descs = [f"{d}[a={mm:.2f}x acc/2]" for d, mm in zip(descs, ms)]
        true_out = y0 + dev
    else:
        what = sp["what"]
        th_o = phi / R
        if what == "ovaldisc":          # encoder_eccentricity (once + twice per OUTPUT rev)
            e_um = rng.uniform(2.0, 10.0)
            r_d = rng.uniform(20.0, 60.0)
            e1 = e_um * 1e-3 / r_d
            r2 = rng.uniform(0.2, 0.5)
            q1, q2 = rng.uniform(0, 2 * np.pi, 2)
            dev = e1 * (np.sin(th_o + q1) + r2 * np.sin(2 * th_o + q2))
            descs.append(f"output-encoder-eccentric+ovalised-disc(e={e_um:.1f}um,r={r_d:.0f}mm,ov={r2:.2f})")
        elif what == "index":           # angle_offset step at an index re-reference
            ts = rng.uniform(0.3, 0.7) * t[-1]
            D = rng.uniform(0.2, 1.0) * acc * (1 if rng.random() < 0.5 else -1)
            dev = np.where(t > ts, D, 0.0)
            descs.append(f"index-re-reference-step(D={D:.2e}rad,t={ts:.1f}s)")
        elif what == "tape":            # sensor_gain: thermal expansion of a drum tape scale
            dT = rng.uniform(3.0, 12.0)
            alpha = 10.5e-6
            tau = rng.uniform(0.2, 0.8) * t[-1]
            g = alpha * dT * (1.0 - np.exp(-t / tau))
            dev = g * (phi - phi[0]) / R
            descs.append(f"drum-tape-scale-thermal-gain(alpha={alpha:.1e}/K,dT={dT:.1f}K,tau/t_end={tau / t[-1]:.2f})")
        elif what == "erfc":            # thermal_drift
            D = rng.uniform(0.2, 1.0) * acc * (1 if rng.random() < 0.5 else -1)
            tc = rng.uniform(0.05, 0.5) * t[-1]       # x^2 / (4 kappa)
            dev = D * erfc(np.sqrt(tc / np.maximum(t, 1e-9)))
            descs.append(f"read-head-mount-conduction-erfc-drift(D={D:.2e}rad,x^2/4k={tc:.1f}s)")
        elif what == "arcsec":          # wrong_units
            dev = np.zeros(n)
            units = ARCSEC_PER_RAD
            descs.append("output-angle-in-arc-seconds")
        elif what == "inputecc":        # equivalent to te_1x
            a = rng.uniform(0.2, 0.8) * 0.5 * acc
            eps = a * R
            p = rng.uniform(0, 2 * np.pi)
            inp = phi + eps * np.sin(phi + p)
            # deviation of the output from the catalog model evaluated at the MEASURED input
            dev = y0 - (inp / R + offset)
            y0 = inp / R + offset
            nuis["input_encoder_eccentricity_rad"] = eps
            descs.append(f"input-encoder-eccentricity(eps={eps:.2e}rad at the input)")
        elif what == "coupling2x":      # equivalent to te_2x
            a = rng.uniform(0.2, 0.8) * 0.5 * acc
            eps = a * R
            p = rng.uniform(0, 2 * np.pi)
            dev = eps * np.sin(2 * phi + p) / R
            nuis["input_coupling_2x_error_rad"] = eps
            descs.append(f"input-coupling-ovality-2x(eps={eps:.2e}rad at the WG)")
        else:
            raise ValueError(what)
        if what == "inputecc":
            true_out = phi / R + offset
        else:
            true_out = y0 + dev
        if units is None:
            sigma = _rms(dev) / rng.uniform(4, 12)
        else:
            sigma = 0.3 * 0.5 * acc / rng.uniform(4, 12)
    style, out = sp.get("noise") or _noise_style(rng)
    e, ndesc = _unit_noise(rng, n, style, out, t)
    noise = sigma * e
    out_meas = true_out + noise
    noise_rms = _rms(noise)
    snr = 0.0
    if cat_ != "clean":
        if units is not None:
            out_meas = out_meas * units
            noise_rms *= units
            snr = _rms((units - 1.0) * true_out) / noise_rms
        else:
            snr = _rms(dev) / noise_rms
    form = " + ".join(descs) + f" | {n_rev:.1f} WG revs at {N_test:.0f} r/min | noise={ndesc}"
    cols = {"input_angle_rad": inp, "output_angle_rad": out_meas, "time_s": t}
    return TruthCase(name=name, kind="transmission", model=m.code, columns=cols, load_inertia_kgm2=None,
                     gear_effects=tuple(cell.gear), measurement_effects=tuple(cell.meas), nuisance=nuis,
                     category=cat_, equivalent_effects=tuple(cell.equivalent), noise_rms=noise_rms,
                     formulation=form, snr=snr)


# =============================================================================================
# EFFICIENCY
# =============================================================================================
def _wlf_log10(theta, C1, C2, theta_ref=20.0):
    d = theta - theta_ref
    return -C1 * d / (C2 + d)


def _ke_solve(fun, target, lo, hi):
    """parameter x with fun(x) == target (fun monotone on [lo, hi])."""
    return brentq(lambda x: fun(x) - target, lo, hi, xtol=1e-12)


def _ll_tooth(rng, cat):
    """Loss torque (in units of rated output torque) L(alpha) = c0 + c1 alpha^gamma: a
    load-independent part (WG bearing, flexspline bending) plus an engagement loss growing with
    the number of teeth in contact, n_e ~ alpha^gamma.  Ke = eta(alpha)/eta(1), clamped at 1."""
    gam = rng.uniform(0.3, 0.6)
    rc = rng.uniform(0.5, 3.0)

    def ke_fun(c0, a):
        L = lambda x: c0 + rc * c0 * x ** gam
        return (a / (a + L(a))) * (1.0 + L(1.0))

    def make(mm):
        target = 1.0 - (1.0 - cat.ke_value) * mm
        c0 = _ke_solve(lambda c: ke_fun(c, cat.ke_alpha), target, 1e-6, 10.0)
        return lambda a: np.where(a < 1.0, ke_fun(c0, np.minimum(a, 1.0)), 1.0)
    return make, f"engaged-tooth-count-loss(gamma={gam:.2f},c1/c0={rc:.2f})"


def _ll_tabor(rng, cat):
    """Constant loss c0 + Tabor elastic-hysteresis rolling loss ~ W^(4/3): L = c0 + ct alpha^(4/3)."""
    rt = rng.uniform(0.2, 1.0)

    def ke_fun(c0, a):
        L = lambda x: c0 + rt * c0 * x ** (4.0 / 3.0)
        return (a / (a + L(a))) * (1.0 + L(1.0))

    def make(mm):
        target = 1.0 - (1.0 - cat.ke_value) * mm
        c0 = _ke_solve(lambda c: ke_fun(c, cat.ke_alpha), target, 1e-6, 10.0)
        return lambda a: np.where(a < 1.0, ke_fun(c0, np.minimum(a, 1.0)), 1.0)
    return make, f"tabor-rolling-hysteresis+constant-loss(ct/c0={rt:.2f})"


def _ll_weibull(rng, cat):
    """Graph model of 023-1: Ke = (1 - exp(-(a/lam)^k)) / (1 - exp(-(1/lam)^k))."""
    kk = rng.uniform(0.55, 1.0)   # Ke(0.1) ~ 0.35..0.58 (the graph axis runs down to 0.3)

    def ke_fun(lam, a):
        return (1.0 - np.exp(-(a / lam) ** kk)) / (1.0 - math.exp(-(1.0 / lam) ** kk))

    def make(mm):
        target = 1.0 - (1.0 - cat.ke_value) * mm
        lam = _ke_solve(lambda l: ke_fun(l, cat.ke_alpha), target, 0.02, 3.0)
        return lambda a: np.where(a < 1.0, ke_fun(lam, np.minimum(a, 1.0)), 1.0)
    return make, f"weibull-cdf-graph-model(k={kk:.2f})"


def _td_bk(rng, eta_R):
    """WLF base-oil viscosity + Benedict-Kelley mesh friction mu ~ log10(K/nu): lower viscosity
    (higher temperature) -> higher boundary friction.  g(theta) = (1+l)/(1+l mu/mu_ref)."""
    C1, C2 = rng.uniform(2.5, 4.0), rng.uniform(80.0, 130.0)
    fm = rng.uniform(0.5, 0.9)
    ell = (1.0 - eta_R) / eta_R * fm

    def make(mm):
        lam = 0.5 * mm      # 1/log10(X_ref), X_ref = BK argument at 20 C: 10^1.5..10^3 -> 0.33..0.67
        def g(th):
            mu = np.clip(1.0 - lam * _wlf_log10(th, C1, C2), 0.2, None)
            return (1.0 + ell) / (1.0 + ell * mu)
        return g
    return make, f"wlf(C1={C1:.2f},C2={C2:.0f}K)+benedict-kelley-friction(mesh share={fm:.2f})"


def _td_bw(rng, eta_R):
    """Bair-Winer limiting shear stress: traction coefficient = tau_L/p (the limiting-shear pressure
    coefficient) falling with temperature, mu/mu_ref = exp(-k (theta - 20))."""
    fm = rng.uniform(0.5, 0.9)
    ell = (1.0 - eta_R) / eta_R * fm

    def make(mm):
        kk = 0.007 * mm     # 1/K, temperature coefficient of the limiting-shear pressure coefficient
        def g(th):
            mu = np.exp(-kk * (th - 20.0))
            return (1.0 + ell) / (1.0 + ell * mu)
        return g
    return make, f"bair-winer-limiting-shear-traction(mesh share={fm:.2f})"


def _eff_grid(rng, cat: Catalog, m: GearModel, order: str, min_alpha: float = 0.1):
    speeds_all = [500.0, 1000.0, 1500.0, 2000.0, 3000.0]
    speeds_all = [v for v in speeds_all if v <= m.N_max]
    ns = int(rng.integers(3, min(4, len(speeds_all)) + 1))
    speeds = sorted(rng.choice(speeds_all, size=ns, replace=False).tolist())
    loads_all = [a for a in [0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9] if a >= min_alpha - 1e-12]
    nl = int(rng.integers(5, 8))
    alphas = sorted(rng.choice(loads_all, size=nl, replace=False).tolist()) + [1.0]
    if rng.random() < 0.5:
        alphas.append(1.1)
    tmax = cat.lub_max_ambient + cat.lub_rise
    temps_all = [v for v in range(int(cat.lub_min), int(tmax) + 1, 10) if v <= 70]
    nt = int(rng.integers(4, 6))
    temps = sorted(rng.choice(temps_all, size=nt, replace=False).tolist())
    if 20 not in temps:
        temps[int(np.argmin(np.abs(np.array(temps) - 20)))] = 20
        temps = sorted(set(temps))
    if order == "shuffled":
        temps_order = list(rng.permutation(temps))
        while all(temps_order[i] < temps_order[i + 1] for i in range(len(temps_order) - 1)):
            temps_order = list(rng.permutation(temps))
    else:
        temps_order = list(temps)
    t_soak = rng.uniform(1800.0, 3600.0)
    t_pt = rng.uniform(20.0, 60.0)
    rows = []
    tclock = 0.0
    for b, th in enumerate(temps_order):
        tclock += t_soak
        for N in speeds:
            for a in alphas:
                tclock += t_pt
                rows.append((N, a, float(th), tclock, b))
    arr = np.array(rows)
    return arr[:, 0], arr[:, 1], arr[:, 2], arr[:, 3], arr[:, 4].astype(int), t_soak


def _build_efficiency(rng, cat: Catalog, cell: Cell, name: str) -> TruthCase:
    sp = cell.spec
    m = cat.pick(rng, "efficiency")
    eta_R = rng.uniform(cat.eta_anchor - 12.0, cat.eta_anchor + 8.0) / 100.0
    N, alpha, theta, tsec, blk, t_soak = _eff_grid(rng, cat, m, sp.get("order", "ascending"),
                                                   0.2 if cell.category == "pair" else 0.1)
    load = alpha * m.T_rated
    n = len(N)
    y0 = np.full(n, 100.0 * eta_R)
    nuis = {"efficiency_level_pct": 100.0 * eta_R}
    makers, descs = [], []
    for eff, form in sp.get("effects", []):
        if eff == "low_load_efficiency":
            mk, d = {"tooth": _ll_tooth, "tabor": _ll_tabor, "weibull": _ll_weibull}[form](rng, cat)
            makers.append(("ll", mk))
        else:
            mk, d = {"bk": _td_bk, "bw": _td_bw}[form](rng, eta_R)
            makers.append(("td", mk))
        descs.append(d)

    def eta_with(mults):
        ke = np.ones(n)
        g = np.ones(n)
        for (typ, mk), mm in zip(makers, mults):
            f = mk(mm)
            if typ == "ll":
                ke = ke * f(alpha)
            else:
                g = g * f(theta)
        return 100.0 * eta_R * ke * g

    comps = []
    for i, (typ, mk) in enumerate(makers):
        if typ == "ll":
            rng_ = (0.5, 1.4)
        elif descs[i].startswith("wlf"):
            rng_ = (0.66, 1.6) if cell.category == "pair" else (0.66, 1.34)
        else:
            rng_ = (0.5, 2.5) if cell.category == "pair" else (0.5, 2.0)

        def dev(mm, i=i):
            f = makers[i][1](mm)
            v = alpha if makers[i][0] == "ll" else theta
            return 100.0 * eta_R * f(v) - y0
        comps.append({"dev": dev, "range": rng_})
    cat_ = cell.category
    units = None
    true_eta = y0.copy()
    if cat_ == "clean":
        dev = np.zeros(n)
        sigma = 3.0 / rng.uniform(4, 12)
        descs.append("constant-level")
    elif cat_ in ("single", "pair"):
        if len(comps) == 1:
            ms, dev, sigma = _single_size(rng, comps[0])
        else:
            ms, dev, sigma = _pair_size(rng, comps[0], comps[1],
                                        lambda a, b, dA, dB: eta_with([a, b]) - y0)
        descs = [f"{d}[x{mm:.2f}]" for d, mm in zip(descs, ms)]
        true_eta = y0 + dev
    else:
        what = sp["what"]
        if what == "fraction":
            dev = np.zeros(n)
            units = 0.01
            descs.append("efficiency-as-fraction")
        elif what == "selfheat":        # thermal_drift of the input torque sensor gain
            d = rng.uniform(0.02, 0.06) * (1 if rng.random() < 0.5 else -1)
            tau = rng.uniform(0.2, 0.7) * tsec[-1]
            gain = 1.0 + d * (1.0 - np.exp(-tsec / tau))
            dev = y0 / gain - y0
            descs.append(f"input-torque-bridge-self-heating(d={d:+.3f},tau/t_end={tau / tsec[-1]:.2f})")
        elif what == "rangeswitch":     # sensor_gain step inside a temperature block
            b_mid = int(blk[len(blk) // 2])
            idx = np.where(blk == b_mid)[0]
            j = idx[len(idx) // 2]
            g2 = 1.0 + rng.uniform(0.03, 0.08) * (1 if rng.random() < 0.5 else -1)
            gain = np.where(np.arange(n) >= j, g2, 1.0)
            dev = y0 * gain - y0
            descs.append(f"output-torque-range-switch-gain-step(g={g2:.3f} from row {j})")
        elif what == "cableoffset":     # equivalent to low_load_efficiency
            mm = rng.uniform(0.6, 1.4)
            # input-side offset delta (in output-referred rated-torque units) giving a drag-like
            # apparent Ke(0.58) = 1 - 0.07 mm
            tgt = 1.0 - (1.0 - cat.ke_value) * mm
            f = lambda dl: (1 + dl * eta_R) / (1 + dl * eta_R / cat.ke_alpha) - tgt
            dl = brentq(f, 1e-6, 10.0)
            delta_in = dl * m.T_rated / m.ratio
            true_eta = y0 / (1.0 + dl * eta_R / alpha)
            dev = true_eta - y0
            nuis["input_torque_offset_Nm"] = delta_in
            descs.append(f"input-torque-sensor-cable-strain-offset(delta={delta_in:.3f}N m at the input)")
        elif what == "thixo":           # equivalent to temperature_dependence
            a_m = 1.0 / rng.uniform(2.0 * 3600, 6.0 * 3600)
            b_m = 1.0 / rng.uniform(0.5 * 3600, 1.5 * 3600)
            lam_e = a_m / (a_m + b_m)
            cm = rng.uniform(1.0, 3.0)
            q = rng.uniform(0.5, 1.0)
            fm = rng.uniform(0.5, 0.9)
            ell = (1.0 - eta_R) / eta_R * fm
            nb = int(blk.max()) + 1
            lam = np.empty(nb)
            lm = 1.0
            for b in range(nb):
                lm = lam_e + (lm - lam_e) * math.exp(-(a_m + b_m) * t_soak)
                lam[b] = lm
            v = (1.0 + cm * lam) / (1.0 + cm * lam[0])
            gb = (1.0 + ell) / (1.0 + ell * v ** q)
            true_eta = y0 * gb[blk]
            dev = true_eta - y0
            nuis["grease_structure_final"] = float(lam[-1])
            descs.append(f"moore-thixotropic-grease-breakdown-during-soaks(c={cm:.2f},q={q:.2f},"
                         f"t_soak={t_soak:.0f}s, ascending temperature order)")
        else:
            raise ValueError(what)
        if what not in ("cableoffset", "thixo"):
            true_eta = y0 + dev
        if units is None:
            sigma = _rms(dev) / rng.uniform(4, 12)
        else:
            sigma = 3.0 / rng.uniform(4, 12)
    style, out = sp.get("noise") or _noise_style(rng)
    e, ndesc = _unit_noise(rng, n, style, out, tsec)
    noise = sigma * e
    eta_meas = true_eta + noise
    noise_rms = _rms(noise)
    snr = 0.0
    if cat_ != "clean":
        if units is not None:
            eta_meas = eta_meas * units
            noise_rms *= units
            snr = _rms((units - 1.0) * true_eta) / noise_rms
        else:
            snr = _rms(dev) / noise_rms
    form = " + ".join(descs) + f" | temperature order={sp.get('order', 'ascending')} | noise={ndesc}"
    cols = {"input_speed_rpm": N, "load_torque_Nm": load, "temperature_C": theta,
            "efficiency_pct": eta_meas, "time_s": tsec}
    return TruthCase(name=name, kind="efficiency", model=m.code, columns=cols, load_inertia_kgm2=None,
                     gear_effects=tuple(cell.gear), measurement_effects=tuple(cell.meas), nuisance=nuis,
                     category=cat_, equivalent_effects=tuple(cell.equivalent), noise_rms=noise_rms,
                     formulation=form, snr=snr)


# =============================================================================================
# VIBRATION
# =============================================================================================
def _gen_alpha(wn, F_at, h, nsteps, nsub, rho_inf, zeta_fn, c2, t_int):
    """Chung-Hulbert generalised-alpha integration of x'' + c(t) x' + c2 x'|x'| + wn^2 x = F(t)
    (unit mass).  F_at: forcing at t_{j+1-alpha_f}; returns x at every nsub-th step."""
    am = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0)
    af = rho_inf / (rho_inf + 1.0)
    gam = 0.5 - am + af
    bet = 0.25 * (1.0 - am + af) ** 2
    k = wn * wn
    # start on the quasi-static state (run-up begins far below resonance): x = F/k, v = dF/dt / k
    x = float(F_at[0]) / k
    v = float(F_at[1] - F_at[0]) / (k * h)
    caf = [zeta_fn(tt) * 2.0 * wn for tt in t_int]
    a = float(F_at[0]) - caf[0] * v - c2 * v * abs(v) - k * x
    out = [x]
    Ff = F_at.tolist()
    h2 = h * h
    one_af = 1.0 - af
    for j in range(nsteps):
        c = caf[j]
        X = one_af * (x + h * v + h2 * (0.5 - bet) * a) + af * x
        V = one_af * (v + h * (1.0 - gam) * a) + af * v
        kx = one_af * bet * h2
        kv = one_af * gam * h
        den = (1.0 - am) + c * kv + k * kx
        a1 = (Ff[j] - am * a - c * V - k * X) / den
        if c2 != 0.0:
            for _ in range(4):
                vv = V + kv * a1
                g = (1.0 - am) * a1 + am * a + c * vv + c2 * vv * abs(vv) + k * (X + kx * a1) - Ff[j]
                dg = (1.0 - am) + (c + 2.0 * c2 * abs(vv)) * kv + k * kx
                a1 -= g / dg
        x = x + h * v + h2 * ((0.5 - bet) * a + bet * a1)
        v = v + h * ((1.0 - gam) * a + gam * a1)
        a = a1
        if (j + 1) % nsub == 0:
            out.append(x)
    return np.array(out)


def _build_vibration(rng, cat: Catalog, cell: Cell, name: str) -> TruthCase:
    sp = cell.spec
    m = cat.pick(rng, "vibration")
    R = float(m.ratio)
    acc = m.accuracy
    s, sdesc = _draw_scale(rng, "tri")
    # load inertia: the rated torque accelerates it at 10..100 rad/s^2 (J in [Tr/100, Tr/10]);
    # natural frequency from the catalog K1 (seed 002: f = sqrt(K/J)/2pi), kept where the run-up
    # through both resonances (1x at 60 f, 2x at 30 f r/min) stays below the max input speed
    f_hi_speed = min(25.0, m.N_max / 90.0)
    f_lo_J = math.sqrt(m.K1 / (m.T_rated / 10.0)) / (2 * np.pi)
    f_hi_J = math.sqrt(m.K1 / (m.T_rated / 100.0)) / (2 * np.pi)
    lo, hi = max(6.0, f_lo_J), min(f_hi_speed, f_hi_J)
    if lo >= hi:
        lo, hi = 6.0, f_hi_speed
    f_t = _lu(rng, lo, hi)                                  # catalog-estimated natural frequency
    J = m.K1 / (2 * np.pi * f_t) ** 2
    wn = 2 * np.pi * f_t * math.sqrt(s)
    N0 = 18.0 * f_t * rng.uniform(0.9, 1.1)
    N1 = min(84.0 * f_t * rng.uniform(0.97, 1.05), m.N_max)
    fs = 8.0 * f_t
    n = int(rng.integers(4000, 6001))
    Ttot = (n - 1) / fs
    sweep = sp.get("sweep", "log")
    nsub = 6
    h = 1.0 / (fs * nsub)
    nsteps = (n - 1) * nsub
    rho_inf = rng.uniform(0.8, 1.0)
    af = rho_inf / (rho_inf + 1.0)
    t = np.arange(n) / fs
    t_int = (np.arange(nsteps) + 1.0 - af) * h

    def speed(tt):
        if sweep == "log":
            return N0 * (N1 / N0) ** (tt / Ttot)
        return N0 + (N1 - N0) * (tt / Ttot) ** 2

    def angle(tt):
        if sweep == "log":
            r = N1 / N0
            return 2 * np.pi / 60.0 * N0 * Ttot / math.log(r) * (r ** (tt / Ttot) - 1.0)
        return 2 * np.pi / 60.0 * (N0 * tt + (N1 - N0) * tt ** 3 / (3.0 * Ttot ** 2))

    phi0 = rng.uniform(0, 2 * np.pi)
    phi_s, phi_i = phi0 + angle(t), phi0 + angle(t_int)
    N_s, N_i = speed(t), speed(t_int)
    # damping nuisance
    damp = sp.get("damping", "viscous")
    nuis = {"stiffness_scale": s}
    c2 = 0.0
    if damp == "viscous":
        z = rng.uniform(0.02, 0.08)
        zeta_fn = lambda tt, z=z: z
        nuis["damping_ratio"] = z
        ddesc = f"viscous(zeta={z:.3f})"
    elif damp == "quadratic":
        z = rng.uniform(0.01, 0.03)
        zq = rng.uniform(0.02, 0.05)
        zeta_fn = lambda tt, z=z: z
        X_est = 0.5 * 0.5 * acc / (2.0 * (z + zq))
        c2 = zq * 3.0 * math.pi / (4.0 * X_est)       # equivalent linearisation at X_est
        nuis["damping_ratio"] = z
        nuis["quadratic_damping_per_rad"] = c2
        ddesc = f"viscous(zeta={z:.3f})+velocity-squared(c2={c2:.3g}/rad, zeta_eq~{zq:.3f})"
    else:   # warming: zeta falls as the grease warms (viscosity drop), first order in time
        z0, z1 = rng.uniform(0.06, 0.12), rng.uniform(0.02, 0.05)
        tau = rng.uniform(0.2, 0.6) * Ttot
        zeta_fn = lambda tt, z0=z0, z1=z1, tau=tau: z1 + (z0 - z1) * math.exp(-tt / tau)
        nuis["damping_ratio_start"] = z0
        nuis["damping_ratio_end"] = z1
        ddesc = f"warming-grease(zeta {z0:.3f}->{z1:.3f}, tau/T={tau / Ttot:.2f})"

    def simulate(e_int, extra_F=None):
        F = wn * wn * e_int
        if extra_F is not None:
            F = F + extra_F
        return _gen_alpha(wn, F, h, nsteps, nsub, rho_inf, zeta_fn, c2, t_int)

    linear = c2 == 0.0
    comps, descs = [], []
    for eff, form in sp.get("effects", []):
        if form == "whirl":
            Nref = 60.0 * f_t
            sh_i, d = _te_whirl(rng, phi_i, R, N_i, Nref)
        else:
            sh_i, d = _TE[form](rng, phi_i, R)
        base_i = 0.5 * acc * sh_i
        if linear:
            resp = simulate(base_i)
            comps.append({"dev": (lambda mm, r=resp: mm * r), "range": (0.15, 0.6), "exc": base_i})
        else:
            comps.append({"dev": (lambda mm, b=base_i: simulate(mm * b)), "range": (0.15, 0.6), "exc": base_i})
        descs.append(d)
    cat_ = cell.category
    if cat_ == "clean":
        dev = np.zeros(n)
        sigma = acc * rng.uniform(0.02, 0.1)
        descs.append("no-excitation")
    elif cat_ in ("single", "pair"):
        if len(comps) == 1:
            ms, dev, sigma = _single_size(rng, comps[0])
        else:
            if linear:
                comb = _sum_combine
            else:
                comb = lambda a, b, dA, dB: simulate(a * comps[0]["exc"] + b * comps[1]["exc"])
            ms, dev, sigma = _pair_size(rng, comps[0], comps[1], comb)
        descs = [f"{d}[a={mm:.2f}x acc/2]" for d, mm in zip(descs, ms)]
    else:
        what = sp["what"]
        th_o_s = phi_s / R
        if what == "ovaldisc":      # encoder_eccentricity on the output encoder
            e_um = rng.uniform(1.0, 6.0)
            r_d = rng.uniform(20.0, 60.0)
            e1 = e_um * 1e-3 / r_d
            r2 = rng.uniform(0.2, 0.5)
            q1, q2 = rng.uniform(0, 2 * np.pi, 2)
            dev = e1 * (np.sin(th_o_s + q1) + r2 * np.sin(2 * th_o_s + q2))
            dev = dev - dev.mean()
            descs.append(f"output-encoder-eccentric+ovalised-disc(e={e_um:.1f}um,r={r_d:.0f}mm)")
        elif what == "gravity":     # unbalanced load on a horizontal axis
            Mg = rng.uniform(0.05, 0.4) * acc * m.K1        # torque giving a deflection ~ acc
            q = rng.uniform(0, 2 * np.pi)
            Fg = Mg / J * np.sin(phi_i / R + q)
            dev = simulate(np.zeros(nsteps), Fg)
            nuis["load_unbalance_torque_Nm"] = Mg
            descs.append(f"gravity-torque-of-unbalanced-load(m g r={Mg:.3g}N m)")
        elif what == "erfc":        # thermal_drift
            D = rng.uniform(0.2, 1.0) * acc * (1 if rng.random() < 0.5 else -1)
            tc = rng.uniform(0.05, 0.5) * Ttot
            dev = D * erfc(np.sqrt(tc / np.maximum(t, 1e-9)))
            descs.append(f"encoder-bracket-conduction-erfc-drift(D={D:.2e}rad,x^2/4k={tc:.1f}s)")
        elif what == "index":       # angle_offset step
            ts = rng.uniform(0.3, 0.7) * Ttot
            D = rng.uniform(0.1, 0.5) * acc * (1 if rng.random() < 0.5 else -1)
            dev = np.where(t > ts, D, 0.0)
            descs.append(f"index-re-reference-step(D={D:.2e}rad,t={ts:.1f}s)")
        elif what == "coupling2x":  # equivalent to te_2x
            a = rng.uniform(0.15, 0.6) * 0.5 * acc
            p = rng.uniform(0, 2 * np.pi)
            dev = simulate(a * np.sin(2 * phi_i + p))
            nuis["input_coupling_2x_error_rad"] = a * R
            descs.append(f"input-coupling-ovality-2x(eps={a * R:.2e}rad at the WG)")
        elif what == "motorenc":    # equivalent to te_1x
            a = rng.uniform(0.15, 0.6) * 0.5 * acc
            p = rng.uniform(0, 2 * np.pi)
            dev = simulate(a * np.sin(phi_i + p))
            nuis["motor_encoder_eccentricity_rad"] = a * R
            descs.append(f"motor-encoder-eccentricity-in-speed-loop(eps={a * R:.2e}rad, 1x)")
        else:
            raise ValueError(what)
        sigma = _rms(dev) / rng.uniform(4, 12)
    style, out = sp.get("noise") or _noise_style(rng)
    e, ndesc = _unit_noise(rng, n, style, out, t)
    noise = sigma * e
    vib = dev + noise
    noise_rms = _rms(noise)
    snr = 0.0 if cat_ == "clean" else _rms(dev) / noise_rms
    form = (" + ".join(descs) + f" | damping={ddesc} | sweep={sweep} {N0:.0f}->{N1:.0f} r/min in {Ttot:.1f}s"
            f" | f_n(catalog)={f_t:.2f}Hz | integrator=generalised-alpha(rho_inf={rho_inf:.2f})"
            f" | noise={ndesc}")
    cols = {"time_s": t, "input_speed_rpm": N_s, "output_vibration_rad": vib}
    return TruthCase(name=name, kind="vibration", model=m.code, columns=cols, load_inertia_kgm2=float(J),
                     gear_effects=tuple(cell.gear), measurement_effects=tuple(cell.meas), nuisance=nuis,
                     category=cat_, equivalent_effects=tuple(cell.equivalent), noise_rms=noise_rms,
                     formulation=form, snr=snr)


# =============================================================================================
# Cell table
# =============================================================================================
def _small_b_over_h(m: GearModel):
    """backlash comparable with the hysteresis loss (in the catalog: the size-14 gears, b/H ~ 0.3);
    elsewhere a catalog-sized backlash cannot reach 4 x noise next to a catalog-sized loss <= 12 x."""
    return m.backlash / m.hyst >= 0.25


def _cells() -> list[Cell]:
    C = []
    H, B, HC = "hysteresis", "backlash", "housing_compliance"
    # ---------------- torsion (25) ----------------
    k = "torsion"
    C += [
        Cell(k, "clean", (), (), "exact-tri-white", {"curve": "exact", "scale": "tri", "noise": ("white", False)}),
        Cell(k, "clean", (), (), "pnorm-arcsine-ou", {"curve": "pnorm", "scale": "arcsine", "noise": ("ou", False),
                                                       "protocol": "hold"}),
        Cell(k, "clean", (), (), "exact-grow-ar1drift-outliers", {"curve": "exact", "scale": "tri",
                                                                   "noise": ("ar1drift", True), "protocol": "grow"}),
        Cell(k, "single", (H,), (), "segalman", {"effects": [(H, "segalman")], "protocol": "grow"}),
        Cell(k, "single", (H,), (), "ratestate", {"effects": [(H, "ratestate")], "protocol": "hold"}),
        Cell(k, "single", (H,), (), "perzyna", {"effects": [(H, "perzyna")], "protocol": "hold"}),
        Cell(k, "single", (B,), (), "thermalclearance", {"effects": [(B, "thermal")], "protocol": "ramp"}),
        Cell(k, "single", (B,), (), "multikey", {"effects": [(B, "multikey")], "protocol": "grow"}),
        Cell(k, "single", (B,), (), "palmgren", {"effects": [(B, "palmgren")], "protocol": "ramp"}),
        Cell(k, "single", (HC,), (), "tapered", {"effects": [(HC, "tapered")], "protocol": "ramp"}),
        Cell(k, "single", (HC,), (), "shearlag", {"effects": [(HC, "shearlag")], "protocol": "grow",
                                                   "scale": "arcsine"}),
        Cell(k, "pair", (H, B), (), "segalman-thermalclearance",
             {"effects": [(B, "thermal"), (H, "segalman")], "protocol": "grow", "filter": _small_b_over_h}),
        Cell(k, "pair", (H, B), (), "perzyna-multikey",
             {"effects": [(B, "multikey"), (H, "perzyna")], "protocol": "hold", "filter": _small_b_over_h}),
        Cell(k, "pair", (H, HC), (), "ratestate-tapered",
             {"effects": [(H, "ratestate"), (HC, "tapered")], "protocol": "hold"}),
        Cell(k, "pair", (H, HC), (), "segalman-shearlag",
             {"effects": [(H, "segalman"), (HC, "shearlag")], "protocol": "ramp"}),
        Cell(k, "pair", (B, HC), (), "thermalclearance-shearlag",
             {"effects": [(B, "thermal"), (HC, "shearlag")], "protocol": "ramp", "filter": _small_b_over_h}),
        Cell(k, "pair", (B, HC), (), "palmgren-tapered",
             {"effects": [(B, "palmgren"), (HC, "tapered")], "protocol": "grow", "filter": _small_b_over_h}),
        Cell(k, "decoy_separable", (), ("thermal_drift",), "armlag", {"what": "armlag", "protocol": "ramp"}),
        Cell(k, "decoy_separable", (), ("sensor_gain",), "leverlength", {"what": "lever", "protocol": "grow"}),
        Cell(k, "decoy_separable", (), ("angle_offset",), "rezero", {"what": "rezero", "protocol": "hold"}),
        Cell(k, "decoy_separable", (), ("wrong_units",), "arcmin", {"what": "arcmin", "protocol": "ramp"}),
        Cell(k, "decoy_separable", (), (), "stiffgear", {"what": "stiff", "protocol": "ramp"}),
        Cell(k, "decoy_equivalent", (), (), "diaphragm", {"what": "diaphragm", "protocol": "ramp"},
             equivalent=(HC,)),
        Cell(k, "decoy_equivalent", (), ("angle_offset",), "keyplay", {"what": "keyplay", "protocol": "grow"},
             equivalent=(B,)),
        Cell(k, "decoy_equivalent", (), (), "jointslip", {"what": "jointslip", "protocol": "grow"},
             equivalent=(H,)),
    ]
    # ---------------- transmission (16) ----------------
    k = "transmission"
    T1, T2 = "te_1x", "te_2x"
    C += [
        Cell(k, "clean", (), (), "white", {"noise": ("white", False)}),
        Cell(k, "clean", (), (), "ou-outliers", {"noise": ("ou", True)}),
        Cell(k, "clean", (), (), "ar1drift", {"noise": ("ar1drift", False)}),
        Cell(k, "single", (T2,), (), "twoframe", {"effects": [(T2, "twoframe")]}),
        Cell(k, "single", (T2,), (), "overtone", {"effects": [(T2, "overtone")]}),
        Cell(k, "single", (T1,), (), "whirl", {"effects": [(T1, "whirl")]}),
        Cell(k, "single", (T1,), (), "fsframe", {"effects": [(T1, "fsframe")]}),
        Cell(k, "pair", (T1, T2), (), "fsframe-twoframe", {"effects": [(T1, "fsframe"), (T2, "twoframe")]}),
        Cell(k, "pair", (T1, T2), (), "whirl-overtone", {"effects": [(T1, "whirl"), (T2, "overtone")]}),
        Cell(k, "decoy_separable", (), ("encoder_eccentricity",), "ovaldisc", {"what": "ovaldisc"}),
        Cell(k, "decoy_separable", (), ("angle_offset",), "index", {"what": "index"}),
        Cell(k, "decoy_separable", (), ("sensor_gain",), "tapescale", {"what": "tape"}),
        Cell(k, "decoy_separable", (), ("thermal_drift",), "erfc", {"what": "erfc"}),
        Cell(k, "decoy_separable", (), ("wrong_units",), "arcsec", {"what": "arcsec"}),
        Cell(k, "decoy_equivalent", (), (), "inputencoder", {"what": "inputecc"}, equivalent=(T1,)),
        Cell(k, "decoy_equivalent", (), (), "coupling2x", {"what": "coupling2x"}, equivalent=(T2,)),
    ]
    # ---------------- efficiency (14) ----------------
    k = "efficiency"
    LL, TD = "low_load_efficiency", "temperature_dependence"
    C += [
        Cell(k, "clean", (), (), "white", {"noise": ("white", False)}),
        Cell(k, "clean", (), (), "ou-outliers", {"noise": ("ou", True), "order": "shuffled"}),
        Cell(k, "single", (LL,), (), "toothcount", {"effects": [(LL, "tooth")]}),
        Cell(k, "single", (LL,), (), "tabor", {"effects": [(LL, "tabor")]}),
        Cell(k, "single", (LL,), (), "weibull", {"effects": [(LL, "weibull")], "order": "shuffled"}),
        Cell(k, "single", (TD,), (), "wlf-benedictkelley", {"effects": [(TD, "bk")]}),
        Cell(k, "single", (TD,), (), "bairwiner", {"effects": [(TD, "bw")], "order": "shuffled"}),
        Cell(k, "pair", (LL, TD), (), "toothcount-bairwiner", {"effects": [(LL, "tooth"), (TD, "bw")]}),
        Cell(k, "pair", (LL, TD), (), "weibull-wlf-benedictkelley", {"effects": [(LL, "weibull"), (TD, "bk")]}),
        Cell(k, "decoy_separable", (), ("wrong_units",), "fraction", {"what": "fraction"}),
        Cell(k, "decoy_separable", (), ("thermal_drift",), "selfheating", {"what": "selfheat", "order": "shuffled"}),
        Cell(k, "decoy_separable", (), ("sensor_gain",), "rangeswitch", {"what": "rangeswitch", "order": "shuffled"}),
        Cell(k, "decoy_equivalent", (), (), "cableoffset", {"what": "cableoffset"}, equivalent=(LL,)),
        Cell(k, "decoy_equivalent", (), (), "thixotropy", {"what": "thixo", "order": "ascending"},
             equivalent=(TD,)),
    ]
    # ---------------- vibration (14) ----------------
    k = "vibration"
    C += [
        Cell(k, "clean", (), (), "white", {"noise": ("white", False)}),
        Cell(k, "clean", (), (), "ar1drift-outliers", {"noise": ("ar1drift", True), "sweep": "quad"}),
        Cell(k, "single", (T2,), (), "twoframe-viscous", {"effects": [(T2, "twoframe")], "damping": "viscous"}),
        Cell(k, "single", (T2,), (), "overtone-quadratic", {"effects": [(T2, "overtone")], "damping": "quadratic"}),
        Cell(k, "single", (T1,), (), "whirl-warming", {"effects": [(T1, "whirl")], "damping": "warming"}),
        Cell(k, "single", (T1,), (), "fsframe-quadsweep", {"effects": [(T1, "fsframe")], "sweep": "quad"}),
        Cell(k, "pair", (T1, T2), (), "whirl-twoframe", {"effects": [(T1, "whirl"), (T2, "twoframe")]}),
        Cell(k, "pair", (T1, T2), (), "fsframe-overtone-quadratic",
             {"effects": [(T1, "fsframe"), (T2, "overtone")], "damping": "quadratic", "sweep": "quad"}),
        Cell(k, "decoy_separable", (), ("encoder_eccentricity",), "ovaldisc", {"what": "ovaldisc"}),
        Cell(k, "decoy_separable", (), (), "gravityunbalance", {"what": "gravity"}),
        Cell(k, "decoy_separable", (), ("thermal_drift",), "erfc", {"what": "erfc"}),
        Cell(k, "decoy_separable", (), ("angle_offset",), "index", {"what": "index", "sweep": "quad"}),
        Cell(k, "decoy_equivalent", (), (), "coupling2x", {"what": "coupling2x"}, equivalent=(T2,)),
        Cell(k, "decoy_equivalent", (), (), "motorencoder", {"what": "motorenc", "damping": "warming"},
             equivalent=(T1,)),
    ]
    return C


CELLS = _cells()
_BUILDERS = {"torsion": _build_torsion, "transmission": _build_transmission,
             "efficiency": _build_efficiency, "vibration": _build_vibration}


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    cat = Catalog(catalog_dir)
    rng = np.random.default_rng(seed)
    out = []
    for cell in CELLS:
        for i in range(per_cell):
            name = f"{cell.slug()}-{i:03d}"
            for attempt in range(20):      # deterministic redraw if a pair cannot be sized
                try:
                    case = _BUILDERS[cell.kind](rng, cat, cell, name)
                    break
                except RuntimeError:
                    if attempt == 19:
                        raise
            out.append(case)
    return out


# =============================================================================================
# Self-check
# =============================================================================================
def _selfcheck(catalog_dir) -> bool:
    t0 = time.perf_counter()
    a = generate_cases(11, catalog_dir, per_cell=2)
    t1 = time.perf_counter()
    b = generate_cases(11, catalog_dir, per_cell=2)
    ok = True
    # determinism
    same = len(a) == len(b)
    for x, y in zip(a, b):
        same &= x.name == y.name and x.model == y.model and x.snr == y.snr and x.formulation == y.formulation
        same &= list(x.columns) == list(y.columns) and all(
            np.array_equal(x.columns[k], y.columns[k]) for k in x.columns)
    print(f"determinism (two generations identical): {'OK' if same else 'FAIL'}")
    ok &= same
    names = [c.name for c in a]
    uniq = len(set(names)) == len(names)
    print(f"unique names: {'OK' if uniq else 'FAIL'} ({len(names)} cases)")
    ok &= uniq
    req = {"torsion": ["torque_Nm", "twist_rad"], "transmission": ["input_angle_rad", "output_angle_rad"],
           "efficiency": ["input_speed_rpm", "load_torque_Nm", "temperature_C", "efficiency_pct"],
           "vibration": ["time_s", "input_speed_rpm", "output_vibration_rad"]}
    fin = True
    cols_ok = True
    rows_ok = True
    snr_ok = True
    meta_ok = True
    bad = []
    for c in a:
        fin &= all(np.all(np.isfinite(v)) for v in c.columns.values())
        cols_ok &= list(c.columns)[:len(req[c.kind])] == req[c.kind]
        nrow = len(next(iter(c.columns.values())))
        rows_ok &= all(len(v) == nrow for v in c.columns.values())
        if c.kind == "torsion" and nrow > 3000 or c.kind == "vibration" and nrow > 6000:
            rows_ok = False
        if c.category == "clean":
            good = c.snr == 0.0 and not c.gear_effects and not c.measurement_effects
        elif "wrong_units" in c.measurement_effects:
            good = c.snr > 12.0
        else:
            good = 4.0 - 1e-9 <= c.snr <= 12.0 + 1e-9
        if not good:
            bad.append((c.name, c.snr))
        snr_ok &= good
        m_ok = c.noise_rms > 0 and (c.kind == "vibration") == (c.load_inertia_kgm2 is not None)
        if c.category in ("single", "pair"):
            m_ok &= len(c.gear_effects) == (1 if c.category == "single" else 2)
        else:
            m_ok &= c.gear_effects == ()
        if c.category == "decoy_equivalent":
            m_ok &= len(c.equivalent_effects) >= 1
        else:
            m_ok &= c.equivalent_effects == ()
        meta_ok &= m_ok
    print(f"finite values: {'OK' if fin else 'FAIL'}")
    print(f"required columns first / equal lengths / row limits: "
          f"{'OK' if cols_ok else 'FAIL'} / {'OK' if rows_ok else 'FAIL'}")
    print(f"snr in [4, 12] (clean: 0; wrong_units: > 12): {'OK' if snr_ok else 'FAIL ' + str(bad[:5])}")
    print(f"metadata consistent (effects per category, noise_rms > 0, J for vibration): "
          f"{'OK' if meta_ok else 'FAIL'}")
    ok &= fin and cols_ok and rows_ok and snr_ok and meta_ok
    # table of cells
    print()
    print(f"{'cell':72s} {'n':>2s} {'snr range':>13s} {'rows':>11s}")
    by_cell = {}
    for c in a:
        by_cell.setdefault(c.name[:-4], []).append(c)
    for cell, cs in by_cell.items():
        snrs = [c.snr for c in cs]
        rows = [len(c.columns[list(c.columns)[0]]) for c in cs]
        print(f"{cell:72s} {len(cs):2d} {min(snrs):6.2f}-{max(snrs):6.2f} {min(rows):5d}-{max(rows):5d}")
    print()
    kinds = ["torsion", "transmission", "efficiency", "vibration"]
    catg = ["clean", "single", "pair", "decoy_separable", "decoy_equivalent"]
    print(f"{'kind':14s}" + "".join(f"{g:>18s}" for g in catg) + f"{'cells':>8s}{'cases':>8s}")
    for k in kinds:
        cs = [c for c in a if c.kind == k]
        ncell = len([x for x in CELLS if x.kind == k])
        print(f"{k:14s}" + "".join(f"{sum(c.category == g for c in cs):18d}" for g in catg)
              + f"{ncell:8d}{len(cs):8d}")
    print(f"{'total':14s}" + "".join(f"{sum(c.category == g for c in a):18d}" for g in catg)
          + f"{len(CELLS):8d}{len(a):8d}")
    print()
    print(f"generation time (seed 11, per_cell 2): {t1 - t0:.1f} s")
    print(f"SELFCHECK {'PASSED' if ok else 'FAILED'}")
    return ok


if __name__ == "__main__":
    cdir = sys.argv[1] if len(sys.argv) > 1 else str(Path(__file__).resolve().parents[1] / "main" / "catalog")
    if not Path(cdir).exists():
        cdir = "/work/main/catalog"
    sys.exit(0 if _selfcheck(cdir) else 1)
