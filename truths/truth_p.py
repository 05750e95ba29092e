"""Truth suite P: synthetic strain-wave-gear (Harmonic Drive) rig data with known hidden effects.

Independent of hdcad (numpy + scipy only). See CONTRACT.md for the interface and NOTES_p.md for
the physics, the literature sources, the sizing rules and the catalog interpretation.

    cases = generate_cases(seed, catalog_dir, per_cell=4)

Every case carries an extra attribute ``_diag`` (not part of the contract) with the noise-free
contribution of every hidden effect (``_diag["effects"][name]``), the baseline, the noise vector,
the drawn parameters and the detectability checks.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq, lsq_linear
from scipy.special import erf, expit, gamma as gamma_fn, gammainc

SUITE = "p"

KINDS = ("torsion", "transmission", "efficiency", "vibration")
CATEGORIES = ("clean", "single", "pair", "decoy_separable", "decoy_equivalent")
GEAR_EFFECTS = {
    "torsion": ("hysteresis", "backlash", "housing_compliance"),
    "transmission": ("te_1x", "te_2x"),
    "vibration": ("te_1x", "te_2x"),
    "efficiency": ("low_load_efficiency", "temperature_dependence"),
}
MEASUREMENT_EFFECTS = ("sensor_gain", "angle_offset", "encoder_eccentricity", "thermal_drift", "wrong_units")
COLUMNS = {
    "torsion": ("torque_Nm", "twist_rad"),
    "transmission": ("input_angle_rad", "output_angle_rad"),
    "efficiency": ("input_speed_rpm", "load_torque_Nm", "temperature_C", "efficiency_pct"),
    "vibration": ("time_s", "input_speed_rpm", "output_vibration_rad"),
}
MEASURED = {"torsion": "twist_rad", "transmission": "output_angle_rad",
            "efficiency": "efficiency_pct", "vibration": "output_vibration_rad"}

SPREAD = (0.9, 1.1)          # stiffness-scale spread (contract: ±10 %, the seeds state none)
K_RANGE = (4.0, 12.0)        # contract: effect RMS = k × noise_rms, k in [4, 12]
MARGIN_SINGLE = 3.0          # suite rule: residual after nuisances >= 3 noise_rms
MARGIN_PAIR_ALONE = 2.5      # each member of a pair alone, after nuisances
MARGIN_PAIR_COND = 2.0       # each member after nuisances AND the other member's shape
MARGIN_DECOY = 3.0           # separable decoy: unexplained by nuisances + gear-effect bases
PAIR_RESCALE_MAX = 4.0      # a pair member's physical amplitude is rescaled by at most 4x
EQUIV_TOL = 0.05             # equivalent decoy: |decoy - gear reading| RMS <= 0.05 noise_rms
RAD2DEG = 180.0 / math.pi


# ----------------------------------------------------------------------------------------------
# contract dataclass
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
        names = list(self.columns.keys())
        arrs = [np.asarray(self.columns[k], dtype=float) for k in names]
        n = len(arrs[0])
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(names)
            for i in range(n):
                w.writerow([repr(float(a[i])) for a in arrs])


# ----------------------------------------------------------------------------------------------
# catalog
# ----------------------------------------------------------------------------------------------
def _read(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _f(x):
    x = (x or "").strip()
    return float(x) if x else None


def _in_group(ratio, rmin, rmax):
    lo = _f(rmin)
    hi = _f(rmax)
    return (lo is None or ratio >= lo) and (hi is None or ratio <= hi)


class Catalog:
    """CSF-GH / CSG-GH gear heads, one model per row of gh_ratings_050-1_058-1.csv."""

    def __init__(self, catalog_dir):
        d = Path(catalog_dir)
        ratings = _read(d / "gh_ratings_050-1_058-1.csv")
        stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
        perf = _read(d / "gh_performance_051-1_059-1.csv")
        hyst = _read(d / "gh_hysteresis_052_060.csv")
        back = _read(d / "gh_backlash_052-2_060-2.csv")
        self.models = {}
        for r in ratings:
            ser = r["series"]                      # "CSG-GH" / "CSF-GH"
            size = int(r["size"])
            ratio = int(r["ratio"])
            code = f"{ser.split('-')[0]}-{size}-{ratio}-GH"
            st = [s for s in stiff if s["series"] == ser and int(s["size"]) == size
                  and _in_group(ratio, s["ratio_min"], s["ratio_max"])]
            if len(st) != 1:
                raise ValueError(f"stiffness row for {code}: {len(st)}")
            st = st[0]
            acc = None
            for p in perf:
                if p["series"] == ser and int(p["size"]) == size and int(p["ratio"]) == ratio:
                    a = _f(p["accuracy_rad"])
                    if a is not None:
                        acc = a
                        break
            hy = [h for h in hyst if h["series"] == ser and _in_group(ratio, h["ratio_min"], h["ratio_max"])]
            bk = [b for b in back if b["series"] == ser and int(b["size"]) == size and int(b["ratio"]) == ratio]
            self.models[code] = dict(
                code=code, series=ser, size=size, ratio=ratio,
                T_r=_f(r["rated_torque_2000_Nm"]), T_peak=_f(r["peak_torque_Nm"]),
                N_avg_max=_f(r["avg_input_speed_max_rpm"]), N_max=_f(r["max_input_speed_rpm"]),
                T1=_f(st["T1_Nm"]), T2=_f(st["T2_Nm"]), K1=_f(st["K1_Nm_per_rad"]),
                K2=_f(st["K2_Nm_per_rad"]), K3=_f(st["K3_Nm_per_rad"]),
                accuracy=acc,
                hysteresis=_f(hy[0]["hysteresis_rad"]) if hy else None,
                backlash=_f(bk[0]["backlash_rad"]) if bk else None,
            )
        self.codes = sorted(self.models)

    def eligible(self, kind):
        if kind in ("transmission", "vibration"):
            return [c for c in self.codes if self.models[c]["accuracy"] is not None]
        return list(self.codes)


def theta_cat(T, m):
    """Catalog twist (odd), continuous: theta1 = T1/K1, theta2 = theta1 + (T2-T1)/K2."""
    T = np.asarray(T, dtype=float)
    a = np.abs(T)
    th1 = m["T1"] / m["K1"]
    th2 = th1 + (m["T2"] - m["T1"]) / m["K2"]
    th = np.where(a <= m["T1"], a / m["K1"],
                  np.where(a <= m["T2"], th1 + (a - m["T1"]) / m["K2"], th2 + (a - m["T2"]) / m["K3"]))
    return np.sign(T) * th


def theta_cat_inv(th, m):
    th = np.asarray(th, dtype=float)
    a = np.abs(th)
    th1 = m["T1"] / m["K1"]
    th2 = th1 + (m["T2"] - m["T1"]) / m["K2"]
    T = np.where(a <= th1, a * m["K1"],
                 np.where(a <= th2, m["T1"] + (a - th1) * m["K2"], m["T2"] + (a - th2) * m["K3"]))
    return np.sign(th) * T


# ----------------------------------------------------------------------------------------------
# generic helpers
# ----------------------------------------------------------------------------------------------
def rms(x):
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def _fit_resid(y, bounded=(), free=()):
    """Residual of y after a least-squares fit on columns; bounded = [(col, lo, hi)]."""
    cols, lo, hi = [], [], []
    for c, a, b in bounded:
        cols.append(np.asarray(c, float)); lo.append(a); hi.append(b)
    for c in free:
        cols.append(np.asarray(c, float)); lo.append(-np.inf); hi.append(np.inf)
    if not cols:
        return np.asarray(y, float).copy()
    A = np.column_stack(cols)
    nrm = np.sqrt(np.mean(A * A, axis=0))
    nrm[nrm == 0] = 1.0
    As = A / nrm
    lo = np.asarray(lo) * nrm
    hi = np.asarray(hi) * nrm
    if np.all(np.isinf(lo)) and np.all(np.isinf(hi)):
        x, *_ = np.linalg.lstsq(As, y, rcond=None)
    else:
        x = lsq_linear(As, y, bounds=(lo, hi), method="bvls", lsmr_tol=None).x
    return y - As @ x


def _stiffness_scale(rng):
    """Two production lots (bimodal Gaussian mixture), truncated to the ±10 % spread."""
    centre = (1.0 if rng.random() < 0.5 else -1.0) * rng.uniform(0.02, 0.05)
    while True:
        s = 1.0 + centre + 0.02 * rng.standard_normal()
        if 0.905 <= s <= 1.095:
            return float(s)


def _noise(rng, n, blocks=None):
    """Unit-RMS Gaussian noise (white or AR(1), phi in [0.3, 0.8]); optional outliers.

    blocks: list of index arrays; AR(1) restarted independently in each block (oven blocks).
    Returns (z, outliers, meta) with rms(z) == 1 exactly; outliers in units of noise_rms.
    """
    kind = "white" if rng.random() < 0.45 else "ar1"
    meta = {"noise_model": kind}
    if kind == "white":
        z = rng.standard_normal(n)
    else:
        phi = float(rng.uniform(0.3, 0.8))
        meta["phi"] = phi
        segs = blocks if blocks is not None else [np.arange(n)]
        if blocks is not None:
            meta["noise_model"] = "ar1-block-restarted"
        z = np.empty(n)
        for seg in segs:
            e = rng.standard_normal(len(seg))
            v = np.empty(len(seg))
            v[0] = e[0] / math.sqrt(1.0 - phi * phi)
            for i in range(1, len(seg)):
                v[i] = phi * v[i - 1] + e[i]
            z[seg] = v
    z = z / rms(z)
    out = np.zeros(n)
    if rng.random() < 0.35:
        n_out = max(1, int(round(0.005 * n)))
        pattern = "paired-burst" if (rng.random() < 0.5 and n_out >= 2) else "isolated"
        one_sided = rng.random() < 0.4
        if pattern == "isolated":
            pos = rng.choice(n, size=n_out, replace=False)
        else:
            starts = rng.choice(n - 1, size=(n_out + 1) // 2, replace=False)
            pos = np.unique(np.concatenate([starts, starts + 1]))[:n_out]
        mag = rng.uniform(8.0, 15.0, size=len(pos))
        sgn = np.ones(len(pos)) if one_sided else np.where(rng.random(len(pos)) < 0.5, -1.0, 1.0)
        if one_sided and rng.random() < 0.5:
            sgn = -sgn
        out[pos] = mag * sgn
        meta.update(outliers=int(len(pos)), outlier_pattern=pattern + ("-one-sided" if one_sided else "-symmetric"))
    else:
        meta["outliers"] = 0
    return z, out, meta


def _size_effects(rng, contribs, absorb, other_cond=True, margin_single=MARGIN_SINGLE, total=None):
    """Draw k and noise_rms for the hidden effects.

    contribs: dict name -> noise-free contribution (sampled).
    absorb(y, extra_free_cols) -> residual of y after the catalog nuisances (and extra columns).
    Returns (k, sigma, checks) or None if no k in [4, 12] gives every effect its margin.
    """
    names = list(contribs)
    if total is None:
        total = sum(contribs.values())
    R = rms(total)
    if R <= 0:
        return None
    need = [K_RANGE[0]]
    checks = {}
    if len(names) == 1:
        r = rms(absorb(total, []))
        checks[f"resid_after_nuisance/{names[0]}"] = r / R
        need.append(margin_single * R / max(r, 1e-300))
    else:
        r_tot = rms(absorb(total, []))
        checks["resid_after_nuisance/total"] = r_tot / R
        need.append(margin_single * R / max(r_tot, 1e-300))
        for nm in names:
            e = contribs[nm]
            r1 = rms(absorb(e, []))
            checks[f"resid_after_nuisance/{nm}"] = r1 / R
            need.append(MARGIN_PAIR_ALONE * R / max(r1, 1e-300))
            if other_cond:
                others = [contribs[o] for o in names if o != nm]
                r2 = rms(absorb(total, others))
                checks[f"resid_after_nuisance_and_other/{nm}"] = r2 / R
                need.append(MARGIN_PAIR_COND * R / max(r2, 1e-300))
    k_lo = max(need)
    if k_lo > K_RANGE[1]:
        return None
    k = float(rng.uniform(k_lo, K_RANGE[1]))
    sigma = R / k
    checks = {key: val * k for key, val in checks.items()}   # in units of noise_rms
    return k, sigma, checks


def _finish_case(kind, name, model, columns, gear, meas, nuis, category, equiv, sigma, formulation,
                 contrib_for_snr, diag, load_inertia=None):
    c = TruthCase(name=name, kind=kind, model=model, columns=columns, load_inertia_kgm2=load_inertia,
                  gear_effects=tuple(gear), measurement_effects=tuple(meas), nuisance=dict(nuis),
                  category=category, equivalent_effects=tuple(equiv), noise_rms=float(sigma),
                  formulation=formulation,
                  snr=float(rms(contrib_for_snr) / sigma) if contrib_for_snr is not None else 0.0)
    c._diag = diag
    return c


# ----------------------------------------------------------------------------------------------
# drifts (thermal_drift) and other measurement-chain signatures
# ----------------------------------------------------------------------------------------------
def _drift_bangbang(rng, t):
    """First-order thermal response of a fixture to a bang-bang (on/off) thermostat of the lab."""
    t = np.asarray(t, float)
    span = t[-1] - t[0] if t[-1] > t[0] else 1.0
    period = span * rng.uniform(0.35, 0.9)
    duty = rng.uniform(0.3, 0.7)
    tau = period * rng.uniform(0.15, 0.5)
    ph = rng.uniform(0, 1)
    tf = np.linspace(t[0], t[-1], 4000)
    u = (((tf - t[0]) / period + ph) % 1.0 < duty).astype(float)
    y = np.empty_like(tf)
    y[0] = duty
    a = math.exp(-(tf[1] - tf[0]) / tau)
    for i in range(1, len(tf)):
        y[i] = a * y[i - 1] + (1 - a) * u[i]
    d = np.interp(t, tf, y)
    d = d - d[0]
    p = dict(drift_form="bang-bang thermostat, first-order", period=period, duty=duty, tau=tau)
    return d / (np.max(np.abs(d)) + 1e-300), p


def _drift_slab(rng, t):
    """Warm-up of a sensor mount as a finite slab heated on one face (Carslaw-Jaeger series)."""
    t = np.asarray(t, float)
    span = t[-1] - t[0] if t[-1] > t[0] else 1.0
    tau = span * rng.uniform(0.15, 0.8)
    x = (t - t[0]) / tau
    s = np.zeros_like(x)
    for nn in range(0, 40):
        k = 2 * nn + 1
        s += 8.0 / (k * k * math.pi ** 2) * np.exp(-(k * k) * math.pi ** 2 * x / 4.0)
    d = 1.0 - s
    d = d - d[0]
    p = dict(drift_form="finite-slab conduction (Carslaw-Jaeger series)", tau=tau)
    return d / (np.max(np.abs(d)) + 1e-300), p


def _step(rng, t):
    t = np.asarray(t, float)
    ts = t[0] + (t[-1] - t[0]) * rng.uniform(0.3, 0.7)
    return (t >= ts).astype(float), dict(step_time=float(ts))


# ----------------------------------------------------------------------------------------------
# torsion: protocols
# ----------------------------------------------------------------------------------------------
TORSION_PROTOCOLS = ("fema461-ladder", "pulsating-R0", "twist-rate")


def _torsion_path(protocol, rng, n_per=250):
    """Dense torque path (units of T0), model time, and the sampling rule."""
    if protocol == "fema461-ladder":
        m = int(rng.integers(5, 7))
        amps = 1.4 ** (-np.arange(m)[::-1].astype(float))
        turns = [0.0]
        for a in amps:
            turns += [a, -a, a, -a]
        turns += [0.0]
    elif protocol == "pulsating-R0":
        n = int(rng.integers(2, 4))
        turns = [0.0] + [1.0, 0.0] * n + [-1.0, 0.0] * n + [1.0, -1.0, 1.0, -1.0, 0.0]
    elif protocol == "twist-rate":
        turns = [0.0, 1.0, -1.0, 1.0, -1.0, 1.0, -1.0, 0.0]
    else:
        raise ValueError(protocol)
    pts = [np.array([turns[0]])]
    for a, b in zip(turns[:-1], turns[1:]):
        n = max(4, int(round(abs(b - a) * n_per)))
        pts.append(np.linspace(a, b, n + 1)[1:])
    T = np.concatenate(pts)
    return T, turns


def _reference_path(amp=1.0, n_per=250):
    turns = [0.0, amp, -amp, amp, -amp, amp, -amp, amp]
    pts = [np.array([0.0])]
    for a, b in zip(turns[:-1], turns[1:]):
        n = max(4, int(round(abs(b - a) * n_per)))
        pts.append(np.linspace(a, b, n + 1)[1:])
    return np.concatenate(pts)


def _model_time(Tn, m, T0, s, protocol):
    """Model time: torque-rate control -> uniform in |dT|; twist-rate control -> uniform in |d theta_cat|."""
    if protocol == "twist-rate":
        th = theta_cat(Tn * T0, m) / s
        d = np.abs(np.diff(th)) / (theta_cat(np.array([T0]), m)[0] / s)
    else:
        d = np.abs(np.diff(Tn))
    return np.concatenate([[0.0], np.cumsum(d)])


# ----------------------------------------------------------------------------------------------
# torsion: hysteresis formulations
# ----------------------------------------------------------------------------------------------
def _masing_voce_raw(Tn, Tv):
    """Masing branches (Madelung memory) on a Voce-saturating hysteretic-compliance backbone.

    g(T) = sign(T) (|T| - Tv (1 - exp(-|T|/Tv)))  (unit amplitude; T in units of T0).
    """
    def g(x):
        a = abs(x)
        return math.copysign(a - Tv * (1.0 - math.exp(-a / Tv)), x) if a > 0 else 0.0

    n = len(Tn)
    h = np.empty(n)
    h[0] = g(Tn[0])
    stack = []
    prev = 0
    for i in range(1, n):
        T = Tn[i]
        dT = T - Tn[i - 1]
        if dT == 0.0:
            h[i] = h[i - 1]
            continue
        d = 1 if dT > 0 else -1
        if prev != 0 and d != prev:
            stack.append((Tn[i - 1], h[i - 1]))
        prev = d
        while True:
            if len(stack) >= 2 and (T - stack[-2][0]) * d >= 0:
                stack.pop(); stack.pop(); continue
            if len(stack) == 1 and (T + stack[0][0]) * d >= 0:
                stack.pop(); continue
            break
        if stack:
            Tr, hr = stack[-1]
            h[i] = hr + 2.0 * g((T - Tr) / 2.0)
        else:
            h[i] = g(T)
    return h


def _bodner_partom_raw(Tn, t, z, nexp, beta):
    """Bodner-Partom viscoplastic element with linear kinematic (Prager) hardening.

    du/dt = beta exp(-0.5 (z/|tau-u|)^(2n)) sign(tau-u); u = backstress / T0; backward Euler.
    """
    n = len(Tn)
    u = 0.0
    out = np.empty(n)
    out[0] = 0.0
    p2 = 2.0 * nexp
    for i in range(1, n):
        dt = t[i] - t[i - 1]
        tau = Tn[i]
        if dt <= 0:
            out[i] = u
            continue
        lo, hi = (u, tau) if tau >= u else (tau, u)
        x = u
        for _ in range(30):
            y = tau - x
            ay = abs(y)
            if ay < 1e-12:
                f = 0.0; fp = 0.0
            else:
                q = (z / ay) ** p2
                e = math.exp(-0.5 * q) if q < 1400 else 0.0
                f = math.copysign(e, y)
                fp = e * nexp * q / ay
            G = x - u - dt * beta * f
            if G > 0:
                hi = x
            else:
                lo = x
            Gp = 1.0 + dt * beta * fp
            xn = x - G / Gp
            if not (lo <= xn <= hi):
                xn = 0.5 * (lo + hi)
            if abs(xn - x) < 1e-14:
                x = xn
                break
            x = xn
        u = x
        out[i] = u
    return out


def _berg_solve(Tabs, s, m, Fmax, x2):
    """Gear spring (catalog curve / s) in parallel with a Berg (1998) friction element.

    Torque-controlled: solve T = T_spring(x) + F_berg(x) along each monotone leg. Returns twist x.
    """
    T = np.asarray(Tabs, float)
    n = len(T)
    x = np.zeros(n)
    xs, Fs = 0.0, 0.0
    dT = np.diff(T)
    dirs = np.sign(dT)
    # leg boundaries
    i = 0
    cur = 0.0
    while i < n - 1:
        d = dirs[i] if dirs[i] != 0 else 1.0
        j = i
        while j < n - 1 and (dirs[j] == d or dirs[j] == 0):
            j += 1
        seg = T[i + 1:j + 1]
        alpha = Fs / Fmax
        if d > 0:
            def F(xx):
                dx = xx - xs
                return Fs + dx / (x2 * (1 - alpha) + dx) * (Fmax - Fs)
            lo = np.full(seg.shape, cur)
            hi = np.full(seg.shape, max(cur, float(theta_cat(np.array([seg.max() + Fmax]), m)[0] / s)) + 1e-9)
        else:
            def F(xx):
                dx = xx - xs
                return Fs + dx / (x2 * (1 + alpha) - dx) * (Fmax + Fs)
            hi = np.full(seg.shape, cur)
            lo = np.full(seg.shape, min(cur, float(theta_cat(np.array([seg.min() - Fmax]), m)[0] / s)) - 1e-9)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            val = theta_cat_inv(s * mid, m) + F(mid) - seg
            pos = val > 0
            hi = np.where(pos, mid, hi)
            lo = np.where(pos, lo, mid)
        xx = 0.5 * (lo + hi)
        x[i + 1:j + 1] = xx
        cur = float(xx[-1])
        Fs = float(F(np.array([cur]))[0])
        xs = cur
        i = j
    return x


def _loop_stats(Tref, href):
    """Centre line and width at T = 0 of the last cycle of a reference loop (normalised T)."""
    n = len(Tref)
    amp = float(np.max(np.abs(Tref)))
    i_min = n - 1 - int(np.argmin(Tref[::-1]))
    i_max = i_min - 1 - int(np.argmax(Tref[:i_min][::-1]))
    up_T, up_h = Tref[i_min:], href[i_min:]
    dn_T, dn_h = Tref[i_max:i_min + 1][::-1], href[i_max:i_min + 1][::-1]
    grid = np.linspace(-amp, amp, 801)
    up = np.interp(grid, up_T, up_h)
    dn = np.interp(grid, dn_T, dn_h)
    centre = 0.5 * (up + dn)
    width = float(np.interp(0.0, grid, dn - up))
    return grid, centre, width


def hysteresis_contrib(form, T_abs, m, s, H, rng, protocol):
    """Hysteretic twist (rad) along a torque path (N.m).

    Everything is normalised by the rated torque T_r: the loop width at T = 0 of a steady
    ±T_r loop (B - B' after loading to rated torque, seed 000 p.020) is H; the loop centre line
    (taken from a steady loop at max(T_r, T0)) is removed, so the loop straddles the catalog curve.
    """
    Tr = m["T_r"]
    Tn = np.asarray(T_abs, float) / Tr
    mode = "twist-rate" if protocol == "twist-rate" else "torque"
    t = _model_time(Tn, m, Tr, s, mode)
    amp_c = max(1.0, float(np.max(np.abs(Tn))))
    Tcal = _reference_path(1.0)
    Tcen = _reference_path(amp_c)
    tcal = _model_time(Tcal, m, Tr, s, mode)
    tcen = _model_time(Tcen, m, Tr, s, mode)
    if form == "masing-voce":
        Tv = float(rng.uniform(0.12, 0.45))
        raw = lambda TT, tt: _masing_voce_raw(TT, Tv)
        par = dict(Tv_over_Tr=Tv)
    elif form == "bodner-partom":
        z = float(rng.uniform(0.2, 0.45))
        nexp = float(rng.uniform(0.6, 1.3))
        beta = float(rng.uniform(3.0, 20.0))
        raw = lambda TT, tt: _bodner_partom_raw(TT, tt, z, nexp, beta)
        par = dict(Z_over_Tr=z, n=nexp, beta=beta)
    elif form == "berg-parallel":
        thr = float(theta_cat(np.array([Tr]), m)[0] / s)
        x2 = float(rng.uniform(0.12, 0.35)) * thr
        base_cal = theta_cat(Tcal * Tr, m) / s

        def width_of(Fm):
            xr = _berg_solve(Tcal * Tr, s, m, Fm, x2)
            return _loop_stats(Tcal, xr - base_cal)[2]
        F0 = s * m["K1"] * H / 2.0
        Fa, wa = F0, width_of(F0)
        Fb = F0 * H / max(wa, 1e-30)
        wb = width_of(Fb)
        for _ in range(5):
            if abs(wb - H) < 1e-3 * H or wb == wa:
                break
            Fa, wa, Fb = Fb, wb, Fb + (H - wb) * (Fb - Fa) / (wb - wa)
            Fb = max(Fb, 1e-6 * F0)
            wb = width_of(Fb)
        Fmax = Fb
        xc = _berg_solve(Tcen * Tr, s, m, Fmax, x2)
        grid, centre, _ = _loop_stats(Tcen, xc - theta_cat(Tcen * Tr, m) / s)
        xd = _berg_solve(Tn * Tr, s, m, Fmax, x2)
        h = xd - theta_cat(Tn * Tr, m) / s - np.interp(Tn, grid, centre)
        par = dict(Fmax_Nm=Fmax, x2_rad=x2, width_at_rated=wb)
        return h, par
    else:
        raise ValueError(form)
    width = _loop_stats(Tcal, raw(Tcal, tcal))[2]
    lam = H / width
    grid, centre, _ = _loop_stats(Tcen, raw(Tcen, tcen))
    h = lam * (raw(Tn, t) - np.interp(Tn, grid, centre))
    par["scale"] = lam
    return h, par


# ----------------------------------------------------------------------------------------------
# torsion: backlash formulations (memoryless take-up laws, odd in T)
# ----------------------------------------------------------------------------------------------
def backlash_contrib(form, T, T0, b, rng):
    T = np.asarray(T, float)
    a = np.abs(T)
    if form == "abaqus-exp-contact":
        xi = float(rng.uniform(0.03, 0.12))           # softened-contact zone c0 / (b/2)
        tp = float(rng.uniform(0.003, 0.02))          # torque at zero overclosure / T0
        c0 = xi * b / 2.0
        q = a / (tp * T0) * (math.e - 1.0)
        y = np.log1p(q) + 0.5
        for _ in range(60):
            ey = np.exp(y)
            f = y * (ey - 1.0) - q
            fp = (ey - 1.0) + y * ey
            y = np.maximum(y - f / fp, 1e-300)
        x = (b / 2.0 - c0) + c0 * y
        x = np.where(a > 0, x, 0.0)
        lm = 2.0 * float(np.max(x))
        return np.sign(T) * x, dict(c0_rad=c0, Tp_Nm=tp * T0, lost_motion_at_max_torque_rad=lm)
    if form == "almen-laszlo-belleville":
        eta = float(rng.uniform(0.9, 1.35))           # h0 / t of the disc spring
        smax = float(rng.uniform(0.6, 1.0)) * eta     # deflection at flank contact / t
        tb = float(rng.uniform(0.01, 0.06))           # torque at flank contact / T0
        sg = np.linspace(0.0, smax, 2001)
        Fg = sg * ((eta - sg) * (eta - sg / 2.0) + 1.0)
        Fg = Fg / Fg[-1]
        r = np.minimum(a / (tb * T0), 1.0)
        sx = np.interp(r, Fg, sg)
        x = (b / 2.0) * sx / smax
        return np.sign(T) * x, dict(h0_over_t=eta, smax_over_t=smax, TB_Nm=tb * T0)
    raise ValueError(form)


# ----------------------------------------------------------------------------------------------
# torsion: housing compliance formulations (linear series springs)
# ----------------------------------------------------------------------------------------------
_BOLT_BY_SIZE = {14: 3e-3, 20: 4e-3, 32: 5e-3, 45: 6e-3, 65: 8e-3}


def housing_contrib(form, T, m, s, rng):
    r_h = float(rng.uniform(0.4, 0.95))             # housing compliance / gear K1 compliance
    c = r_h / (s * m["K1"])
    d = _BOLT_BY_SIZE[m["size"]]
    if form == "tate-rosenfeld":
        nb = int(rng.choice([3, 4, 6]))
        t1 = d * rng.uniform(0.8, 1.6)
        t2 = d * rng.uniform(0.8, 1.6)
        Eb, nub, Ep = 205e9, 0.29, 71e9                 # steel screws, aluminium adaptor plates
        Cf = (1 / (Eb * t1) + 1 / (Eb * t2) + 1 / (Ep * t1) + 1 / (Ep * t2)
              + 32 * (t1 + t2) * (1 + nub) / (9 * Eb * math.pi * d ** 2)
              + 8 * (t2 ** 3 + 5 * t2 ** 2 * t1 + 5 * t2 * t1 ** 2 + t1 ** 3) / (5 * Eb * math.pi * d ** 4))
        rb = math.sqrt(Cf / (nb * c))
        par = dict(r_h=r_h, c_rad_per_Nm=c, screws=nb, d_m=d, t1_m=t1, t2_m=t2,
                   fastener_flex_m_per_N=Cf, implied_bolt_circle_radius_m=rb)
    elif form == "open-slotted-sleeve":
        G = 79e9
        rm = 0.6 * m["size"] * 2.54e-3 / 2.0 * rng.uniform(0.8, 1.2)
        L = rm * rng.uniform(0.6, 1.5)
        tw = (3.0 * L / (G * c * 2.0 * math.pi * rm)) ** (1.0 / 3.0)
        par = dict(r_h=r_h, c_rad_per_Nm=c, mean_radius_m=rm, length_m=L, implied_wall_m=tw)
    else:
        raise ValueError(form)
    return c * np.asarray(T, float), par


# ----------------------------------------------------------------------------------------------
# torsion builder
# ----------------------------------------------------------------------------------------------
def _torsion_bases(Tn, direction):
    """Gear-effect shapes (non-negative amplitudes) used to test that a decoy is separable."""
    hyst1 = -direction * (1.0 - Tn ** 2)
    hyst2 = -direction * (1.0 - np.abs(Tn))
    back = np.tanh(Tn / 0.003)
    return [(Tn, 0.0, np.inf), (back, 0.0, np.inf), (hyst1, 0.0, np.inf), (hyst2, 0.0, np.inf)]


def build_torsion(rng, cat, spec, protocol):
    category = spec["category"]
    m = cat.models[rng.choice(cat.eligible("torsion"))]
    if category == "pair" and "backlash" in spec.get("effects", ()):
        # a catalog-size play is only a few % of the twist at rated torque: the pair protocols with
        # backlash cycle at part load, where play and loop/housing are of comparable size
        hi = 0.45 if "housing_compliance" in spec["effects"] else 0.7
        T0 = float(rng.uniform(0.2 if hi < 0.5 else 0.3, hi)) * m["T_r"]
    else:
        T0 = min(float(rng.uniform(0.9, 1.2)) * m["T_r"], 0.9 * m["T_peak"])
    s = _stiffness_scale(rng)
    nuis = {"stiffness_scale": s}
    Tn_d, turns = _torsion_path(protocol, rng)
    t_d = _model_time(Tn_d, m, T0, s, protocol)
    T_d = Tn_d * T0
    base_d = theta_cat(T_d, m) / s
    params = dict(T0_Nm=T0, protocol=protocol, turns=turns, rated_Nm=m["T_r"])
    gear_d = {}
    equiv_d = {}
    forms = spec.get("forms", ())
    for eff, form in zip(spec.get("effects", ()), forms):
        if eff == "hysteresis":
            H = m["hysteresis"] * float(rng.uniform(0.6, 1.4))
            e, p = hysteresis_contrib(form, T_d, m, s, H, rng, protocol)
            p["loss_BB'_rad"] = H
        elif eff == "backlash":
            b = m["backlash"] * float(rng.uniform(0.6, 1.5))
            e, p = backlash_contrib(form, T_d, T0, b, rng)
            p["backlash_rad"] = b
        elif eff == "housing_compliance":
            e, p = housing_contrib(form, T_d, m, s, rng)
        else:
            raise ValueError(eff)
        gear_d[eff] = e
        params[eff] = dict(formulation=form, **p)

    mech = spec.get("mechanism")
    if category == "decoy_equivalent":
        if mech == "isolation-mount-rocking":
            r_h = float(rng.uniform(0.4, 0.95))
            c = r_h / (s * m["K1"])
            e = c * T_d
            params["mechanism"] = dict(name=mech, mount_compliance_rad_per_Nm=c, r_h=r_h,
                                       equivalent="housing_compliance, linear c*T with the same c")
            eq_reading = c * T_d
        elif mech == "flexspline-body-thinner":
            r_h = float(rng.uniform(0.4, 0.95))
            c = r_h / (s * m["K1"])
            e = c * T_d
            params["mechanism"] = dict(name=mech, extra_gear_compliance_rad_per_Nm=c, r_h=r_h,
                                       note="soft gear (thinner FS cylinder, Bredt twist, linear in T)",
                                       equivalent="housing_compliance c*T")
            eq_reading = c * T_d
        elif mech == "shrink-disc-hub-windup":
            # keyless shrink-disc coupling between output flange and torque arm: the clamped hub
            # twists as a thick-walled tube (Saint-Venant, J = pi (D^4 - d^4) / 32), linear in T
            r_h = float(rng.uniform(0.4, 0.95))
            c = r_h / (s * m["K1"])
            G = 79e9
            D = m["size"] * 2.54e-3 * rng.uniform(0.5, 0.8)
            dd = D * rng.uniform(0.55, 0.8)
            Jp = math.pi * (D ** 4 - dd ** 4) / 32.0
            L = c * G * Jp
            e = c * T_d
            eq_reading = c * T_d
            params["mechanism"] = dict(name=mech, hub_compliance_rad_per_Nm=c, r_h=r_h, hub_od_m=D, hub_id_m=dd,
                                       implied_twisted_length_m=L, equivalent="housing_compliance c*T")
        elif mech == "support-bearing-friction":
            H = m["hysteresis"] * float(rng.uniform(0.6, 1.4))
            th0 = float(theta_cat(np.array([T0]), m)[0] / s)
            x2 = float(rng.uniform(0.15, 0.4)) * th0
            Fmax = s * m["K1"] * H / 2.0 * float(rng.uniform(0.8, 1.1))
            x = _berg_solve(T_d, s, m, Fmax, x2)
            e = x - base_d
            eq_reading = _berg_solve(T_d, s, m, Fmax, x2) - base_d   # gear-internal Berg friction
            params["mechanism"] = dict(name=mech, Fmax_Nm=Fmax, x2_rad=x2,
                                       equivalent="hysteresis: gear-internal Berg friction in parallel, same Fmax, x2")
        elif mech == "ball-detent-clearance":
            b = m["backlash"] * float(rng.uniform(0.8, 2.0))
            form = "almen-laszlo-belleville" if rng.random() < 0.5 else "abaqus-exp-contact"
            st = rng.bit_generator.state
            e, p = backlash_contrib(form, T_d, T0, b, rng)
            rng2 = np.random.default_rng(); rng2.bit_generator.state = st
            eq_reading, _ = backlash_contrib(form, T_d, T0, b, rng2)
            params["mechanism"] = dict(name=mech, clearance_rad=b, take_up=form, **p,
                                       equivalent=f"backlash with the same {form} take-up")
        else:
            raise ValueError(mech)
        equiv_d[mech] = e
        params["equivalence_max_abs_diff"] = float(np.max(np.abs(e - eq_reading)))

    total_d = base_d + sum(gear_d.values()) + sum(equiv_d.values())

    # pair balance: bring the members to a drawn ratio of their RMS (physical amplitude rescaled)
    if category == "pair":
        # balance the members on what the catalog nuisances cannot absorb; the housing spring keeps
        # its physical size (scaling it down would let the stiffness scale swallow it), the other
        # member is rescaled
        names = list(gear_d)
        a, b2 = (names[1], names[0]) if names[1] == "housing_compliance" else (names[0], names[1])
        thd = theta_cat(T_d, m)
        res_d = lambda y: rms(_fit_resid(base_d + y, bounded=[(thd, 1 / SPREAD[1], 1 / SPREAD[0])],
                                         free=[np.ones_like(T_d)]))
        rho = float(rng.uniform(0.5, 1.2)) if a == "housing_compliance" else float(rng.uniform(0.6, 1.6))
        fac = rho * res_d(gear_d[a]) / max(res_d(gear_d[b2]), 1e-300)
        if a == "housing_compliance":
            fa, fb = 1.0, fac
        else:
            fa, fb = fac ** -0.5, fac ** 0.5
        if max(fa, fb, 1 / fa, 1 / fb) > PAIR_RESCALE_MAX:
            return None
        for nm, f in ((a, fa), (b2, fb)):
            gear_d[nm] = gear_d[nm] * f
            params[nm]["pair_rescale"] = f
            for key in ("backlash_rad", "loss_BB'_rad"):
                if key in params[nm]:
                    params[nm][key + "_effective"] = params[nm][key] * f
        total_d = base_d + sum(gear_d.values())

    # sampling
    if protocol == "twist-rate":
        arc = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(total_d)))])
        n_rows = int(rng.integers(700, 1300))
        grid = np.linspace(0.0, arc[-1], n_rows)
        # strictly increasing arc for interpolation
        keep = np.concatenate([[True], np.diff(arc) > 0])
        arc_k = arc[keep]
        samp = lambda v: np.interp(grid, arc_k, np.asarray(v)[keep])
        ti = np.linspace(0.0, 1.0, n_rows)          # logger time (uniform)
    else:
        q = int(rng.integers(3, 6))
        idx = np.arange(0, len(T_d), q)
        samp = lambda v: np.asarray(v)[idx]
        ti = np.linspace(0.0, 1.0, len(idx))
    T = samp(T_d)
    Tn = T / T0
    base = samp(base_d)
    gear = {k: samp(v) for k, v in gear_d.items()}
    equiv = {k: samp(v) for k, v in equiv_d.items()}
    direction = np.sign(np.gradient(T))
    direction[direction == 0] = 1.0
    twist = base + sum(gear.values()) + sum(equiv.values())
    thcol = theta_cat(T, m)

    def absorb(y, extra):
        return _fit_resid(y, bounded=[(thcol, 1 / SPREAD[1], 1 / SPREAD[0])], free=[np.ones_like(T)] + list(extra))

    n = len(T)
    meas = []
    meas_contrib = {}
    torque_col = T.copy()
    units = None
    checks = {}
    if category in ("single", "pair"):
        res = _size_effects(rng, gear, lambda y, ex: absorb(base + y, ex))
        if res is None:
            return None
        k, sigma, checks = res
        snr_vec = sum(gear.values())
    elif category == "decoy_equivalent":
        e = equiv[mech]
        res = _size_effects(rng, {mech: e}, lambda y, ex: absorb(base + y, ex))
        if res is None:
            return None
        k, sigma, checks = res
        snr_vec = e
        checks["equivalence_diff_over_noise"] = params["equivalence_max_abs_diff"] / sigma
        if checks["equivalence_diff_over_noise"] > EQUIV_TOL:
            return None
    elif category == "clean":
        sigma = float(rng.uniform(0.002, 0.01)) * float(np.max(np.abs(base)))
        snr_vec = None
    else:  # decoy_separable
        kind_d = spec["decoy"]
        if kind_d == "torque-gain-high":
            g = float(rng.uniform(1.18, 1.35))
            torque_col = g * T
            c = theta_cat(T, m) / s - theta_cat(torque_col, m) / s   # data minus catalog at logged torque
            meas = ["sensor_gain"]
            params["decoy"] = dict(name=kind_d, torque_gain=g)
        elif kind_d == "twist-gain-low":
            g = float(rng.uniform(0.72, 0.86))
            c = (g - 1.0) * twist
            meas = ["sensor_gain"]
            params["decoy"] = dict(name=kind_d, twist_gain=g)
        elif kind_d == "stiffer-than-spread":
            s_out = float(rng.uniform(1.18, 1.4))
            nuis["stiffness_scale"] = s_out
            base_new = theta_cat(T, m) / s_out
            c = base_new - base
            params["decoy"] = dict(name=kind_d, stiffness_scale=s_out, replaced_in_spread_scale=s)
        elif kind_d == "offset-step":
            u, p = _step(rng, ti)
            c = u * 1.0 + float(rng.uniform(-0.3, 0.3))
            meas = ["angle_offset"]
            params["decoy"] = dict(name=kind_d, **p)
        elif kind_d == "drift-bangbang":
            u, p = _drift_bangbang(rng, ti)
            c = u
            meas = ["thermal_drift"]
            params["decoy"] = dict(name=kind_d, **p)
        elif kind_d == "drift-slab":
            u, p = _drift_slab(rng, ti)
            c = u * (1.0 if rng.random() < 0.5 else -1.0)
            meas = ["thermal_drift"]
            params["decoy"] = dict(name=kind_d, **p)
        elif kind_d == "degrees":
            units = "twist-degrees"
            meas = ["wrong_units"]
            params["decoy"] = dict(name=kind_d, factor=RAD2DEG)
            c = None
        elif kind_d == "kNm":
            units = "torque-kNm"
            meas = ["wrong_units"]
            params["decoy"] = dict(name=kind_d, factor=1e-3)
            c = None
        else:
            raise ValueError(kind_d)
        if c is not None:
            c = np.asarray(c, float)
            R_shape = rms(c)
            r_g = rms(_fit_resid(base + c, bounded=[(thcol if kind_d != "torque-gain-high" else theta_cat(torque_col, m),
                                                     1 / SPREAD[1], 1 / SPREAD[0])] + _torsion_bases(
                torque_col / T0 if kind_d == "torque-gain-high" else Tn, direction), free=[np.ones_like(T)]))
            need = MARGIN_DECOY * R_shape / max(r_g, 1e-300)
            if need > K_RANGE[1]:
                return None
            k = float(rng.uniform(max(K_RANGE[0], need), K_RANGE[1]))
            if kind_d in ("offset-step", "drift-bangbang", "drift-slab"):
                # physical amplitude from a drawn noise level, then k sets the relation
                sigma = float(rng.uniform(0.002, 0.01)) * float(np.max(np.abs(base)))
                c = c * (k * sigma / R_shape)
            else:
                sigma = R_shape / k
            checks = {"resid_after_nuisance_and_gear_bases": r_g / R_shape * k}
            meas_contrib[meas[0] if meas else "stiffness_scale"] = c
            if kind_d == "torque-gain-high":
                pass     # twist itself unchanged; the decoy lives in the torque channel
            else:
                twist = twist + c
            snr_vec = c
        else:
            sigma = float(rng.uniform(0.002, 0.01)) * float(np.max(np.abs(base)))
            snr_vec = None

    z, out, nmeta = _noise(rng, n)
    noise = sigma * (z + out)
    meas_col = twist + noise
    if units == "twist-degrees":
        meas_contrib["wrong_units"] = (RAD2DEG - 1.0) * meas_col
        meas_col = meas_col * RAD2DEG
        snr_vec = meas_contrib["wrong_units"]
    elif units == "torque-kNm":
        meas_contrib["wrong_units"] = theta_cat(T * 1e-3, m) / s - base    # catalog at logged torque vs data
        torque_col = T * 1e-3
        snr_vec = meas_contrib["wrong_units"]
    cols = {"torque_Nm": torque_col, "twist_rad": meas_col}
    gear_names = tuple(spec.get("effects", ())) if category in ("single", "pair") else ()
    diag = dict(effects={**gear, **equiv, **meas_contrib}, baseline=base, noise=noise,
                noise_unit=z, outliers=sigma * out, params=params, noise_meta=nmeta, checks=checks,
                T0_Nm=T0, time_norm=ti)
    return dict(kind="torsion", model=m["code"], columns=cols, gear=gear_names, meas=meas, nuis=nuis,
                equiv=spec.get("equivalent", ()), sigma=sigma, snr_vec=snr_vec, diag=diag)


# ----------------------------------------------------------------------------------------------
# transmission error waveforms (functions of the wave-generator angle x)
# ----------------------------------------------------------------------------------------------
def _gp_path(rng, n_pts, ell):
    r = np.arange(n_pts, dtype=float)
    Kc = np.exp(-0.5 * (r[:, None] - r[None, :]) ** 2 / ell ** 2) + 1e-8 * np.eye(n_pts)
    L = np.linalg.cholesky(Kc)
    return L @ rng.standard_normal(n_pts)


def te_contrib(form, x, amp, rng):
    """amp = half peak-to-peak (rad) of the error at the wave generator angle x (rad)."""
    x = np.asarray(x, float)
    phi = float(rng.uniform(0, 2 * math.pi))
    if form == "signed-square":               # te_1x, odd harmonics 1,3,5,... only
        w = np.sin(x + phi) * np.abs(np.sin(x + phi))
        return amp * w, dict(order=1, phase=phi)
    if form == "gp-modulated":                # te_1x, squared-exponential GP on amplitude and phase
        revs = x / (2 * math.pi)
        r0 = math.floor(revs.min()) - 2
        npt = int(math.ceil(revs.max()) - r0 + 3)
        ell = float(rng.uniform(3.0, 8.0))
        ma = float(rng.uniform(0.15, 0.35))
        mp = float(rng.uniform(0.2, 0.5))
        ga = _gp_path(rng, npt, ell)
        gp = _gp_path(rng, npt, ell)
        rr = np.arange(npt) + r0
        A = 1.0 + ma * CubicSpline(rr, ga)(revs)
        P = phi + mp * CubicSpline(rr, gp)(revs)
        return amp * A * np.sin(x + P), dict(order=1, phase=phi, ell_rev=ell, am=ma, pm=mp)
    if form == "rectified":                   # te_2x, full-wave rectified: even harmonics 2,4,6,...
        w = np.abs(np.sin(x + phi)) - 2.0 / math.pi
        return 2.0 * amp * w, dict(order=2, phase=phi)
    if form == "telegraph-switched":          # te_2x whose amplitude/phase switch between two states
        revs = x / (2 * math.pi)
        a2 = float(rng.uniform(0.4, 0.8))
        dph = float(rng.uniform(0.3, 1.2))
        dwell = float(rng.uniform(3.0, 8.0))
        lo, hi = revs.min(), revs.max()
        sw = []
        p = lo + rng.exponential(dwell)
        while p < hi:
            sw.append(p)
            p += rng.exponential(dwell)
        state = np.zeros_like(revs)
        st0 = float(rng.integers(0, 2))
        width = float(rng.uniform(0.4, 0.8))      # smooth re-seating (revolutions)
        acc = np.full_like(revs, st0)
        for k, p in enumerate(sw):
            sgn = 1.0 if (st0 + k) % 2 == 0 else -1.0
            acc = acc + sgn * expit((revs - p) / width)
        state = np.clip(acc, 0.0, 1.0)
        A = 1.0 + (a2 - 1.0) * state
        P = phi + dph * state
        return amp * A * np.sin(2 * x + P), dict(order=2, phase=phi, amp_ratio=a2, dphase=dph,
                                                 dwell_rev=dwell, switches=len(sw), switch_width_rev=width)
    if form == "sine1":
        return amp * np.sin(x + phi), dict(order=1, phase=phi)
    if form == "sine2":
        return amp * np.sin(2 * x + phi), dict(order=2, phase=phi)
    raise ValueError(form)


def pin_slot_error(x, e_over_r, ph):
    """Kinematic error of a pin-in-radial-slot drive dog whose axes are offset by e (exact)."""
    xx = x + ph
    err = np.arctan2(np.sin(xx), np.cos(xx) - e_over_r) - xx
    return (err + math.pi) % (2 * math.pi) - math.pi


def cardan_pair_error(x, beta, delta, ph):
    """Two Hooke joints at the same angle beta with a yoke phasing error delta (exact kinematics)."""
    def hooke(a, b):
        return np.arctan2(np.sin(a), np.cos(a) * math.cos(b))
    xx = x + ph
    y1 = hooke(xx, beta)                       # first joint, output of intermediate shaft
    # second joint: input yoke rotated by delta against the correct phasing; inverse relation
    y2 = np.arctan2(np.sin(y1 + delta) * math.cos(beta), np.cos(y1 + delta)) - delta
    err = y2 - xx
    return (err + math.pi) % (2 * math.pi) - math.pi


# ----------------------------------------------------------------------------------------------
# transmission builder
# ----------------------------------------------------------------------------------------------
TRANSMISSION_PROTOCOLS = ("incommensurate-clock", "gated-output-revolution")


def _transmission_input(rng, m, protocol):
    R = m["ratio"]
    th0 = float(rng.uniform(0, 2 * math.pi))
    if protocol == "incommensurate-clock":
        spr = float(rng.uniform(40.0, 130.0)) + math.sqrt(2) * 0.01
        n_rev = float(rng.uniform(12.0, 40.0))
        n = min(6000, int(n_rev * spr))
        x = th0 + 2 * math.pi * np.arange(n) / spr
        par = dict(samples_per_rev=spr, revolutions=n / spr)
    else:
        spr = int(rng.integers(48, 97))
        lg = int(rng.integers(1, 3))
        n_g = max(8, min(int(6000 // (spr * lg)), R // 2, 40))
        starts = np.round(np.linspace(0, R - lg, n_g)).astype(int)
        x = np.concatenate([th0 + 2 * math.pi * (st + np.arange(lg * spr) / spr) for st in starts])
        par = dict(samples_per_rev=spr, gate_revs=lg, gates=n_g, span_revs=R)
    return x, par


def build_transmission(rng, cat, spec, protocol):
    category = spec["category"]
    m = cat.models[rng.choice(cat.eligible("transmission"))]
    R = m["ratio"]
    acc = m["accuracy"]
    off = float(rng.uniform(-1.0, 1.0))
    nuis = {"output_offset_rad": off}
    x, ppar = _transmission_input(rng, m, protocol)
    n = len(x)
    base = x / R + off
    params = dict(protocol=protocol, **ppar, ratio=R, accuracy_rad=acc)
    gear = {}
    for eff, form in zip(spec.get("effects", ()), spec.get("forms", ())):
        amp = float(rng.uniform(0.15, 0.5)) * acc
        e, p = te_contrib(form, x, amp, rng)
        gear[eff] = e
        params[eff] = dict(formulation=form, half_pp_rad=amp, **p)
    if category == "pair":
        a, b = list(gear)
        rho = float(rng.uniform(0.6, 1.6))
        fac = rho * rms(gear[a]) / rms(gear[b])
        for nm, f in ((a, fac ** -0.5), (b, fac ** 0.5)):
            gear[nm] = gear[nm] * f
            params[nm]["pair_rescale"] = f
            params[nm]["half_pp_rad_effective"] = params[nm]["half_pp_rad"] * f
    c1, s1, c2, s2 = np.cos(x), np.sin(x), np.cos(2 * x), np.sin(2 * x)
    ones = np.ones(n)

    def absorb(y, extra):
        return _fit_resid(y, free=[ones] + list(extra))

    equiv = {}
    meas, meas_c = [], {}
    checks = {}
    out_col = base + sum(gear.values())
    in_col = x.copy()
    units = None
    mech = spec.get("mechanism")
    if category in ("single", "pair"):
        res = _size_effects(rng, gear, lambda y, ex: absorb(y, ex))
        if res is None:
            return None
        k, sigma, checks = res
        snr_vec = sum(gear.values())
    elif category == "decoy_equivalent":
        amp = float(rng.uniform(0.15, 0.5)) * acc
        ph = float(rng.uniform(0, 2 * math.pi))
        if mech == "pin-slot-drive-offset":
            eor = amp * R                          # error at the input is R x the output error
            e = pin_slot_error(x, eor, ph) / R
            reading = [s1, c1]
            params["mechanism"] = dict(name=mech, e_over_r=eor, phase=ph, equivalent="te_1x sinusoid")
        elif mech == "misphased-double-cardan":
            delta = float(rng.uniform(0.2, 0.8))
            beta = math.sqrt(2.0 * amp * R / math.sin(delta))
            e = cardan_pair_error(x, beta, delta, ph) / R
            reading = [s2, c2, np.sin(4 * x), np.cos(4 * x), np.sin(6 * x), np.cos(6 * x)]
            params["mechanism"] = dict(name=mech, beta_rad=beta, delta_rad=delta, phase=ph,
                                       equivalent="te_2x (pi-periodic: 2x with its even harmonics)")
        else:
            raise ValueError(mech)
        equiv[mech] = e
        out_col = base + e
        res = _size_effects(rng, {mech: e}, lambda y, ex: absorb(y, ex))
        if res is None:
            return None
        k, sigma, checks = res
        diff = rms(_fit_resid(e, free=reading))
        checks["equivalence_diff_over_noise"] = diff / sigma
        if diff / sigma > EQUIV_TOL:
            return None
        snr_vec = e
    elif category == "clean":
        sigma = float(rng.uniform(0.01, 0.05)) * acc
        snr_vec = None
    else:
        kind_d = spec["decoy"]
        t = np.linspace(0.0, 1.0, n)
        if kind_d == "output-gain":
            c = (x / R) * 1.0
            meas = ["sensor_gain"]
            params["decoy"] = dict(name=kind_d)
        elif kind_d == "offset-step":
            c, p = _step(rng, t)
            meas = ["angle_offset"]
            params["decoy"] = dict(name=kind_d, **p)
        elif kind_d == "trefoil-eccentric-ring":
            psi = float(rng.uniform(0, 2 * math.pi))
            psi3 = float(rng.uniform(0, 2 * math.pi))
            r3 = float(rng.uniform(0.2, 0.5))
            xo = x / R
            c = np.sin(xo + psi) + r3 * np.sin(3 * xo + psi3)
            meas = ["encoder_eccentricity"]
            params["decoy"] = dict(name=kind_d, psi=psi, trefoil_ratio=r3, psi3=psi3)
        elif kind_d == "drift-bangbang":
            c, p = _drift_bangbang(rng, t)
            meas = ["thermal_drift"]
            params["decoy"] = dict(name=kind_d, **p)
        elif kind_d in ("output-degrees", "input-degrees"):
            units = kind_d
            meas = ["wrong_units"]
            params["decoy"] = dict(name=kind_d, factor=RAD2DEG)
            c = None
        else:
            raise ValueError(kind_d)
        if c is not None:
            c = np.asarray(c, float)
            c = c - np.mean(c) if kind_d != "output-gain" else c
            R_shape = rms(_fit_resid(c, free=[ones]))
            r_g = rms(_fit_resid(c, free=[ones, s1, c1, s2, c2]))
            need = MARGIN_DECOY * R_shape / max(r_g, 1e-300)
            if need > K_RANGE[1]:
                return None
            k = float(rng.uniform(max(K_RANGE[0], need), K_RANGE[1]))
            sigma = float(rng.uniform(0.01, 0.05)) * acc
            c = c * (k * sigma / R_shape)
            if kind_d == "output-gain":
                params["decoy"]["gain_minus_1"] = float(k * sigma / R_shape)
            meas_c[meas[0]] = c
            out_col = out_col + c
            checks = {"resid_after_nuisance_and_gear_bases": r_g / R_shape * k}
            snr_vec = _fit_resid(c, free=[ones])
        else:
            sigma = float(rng.uniform(0.01, 0.05)) * acc
            snr_vec = None
    z, outl, nmeta = _noise(rng, n)
    noise = sigma * (z + outl)
    meas_col = out_col + noise
    if units == "output-degrees":
        meas_c["wrong_units"] = (RAD2DEG - 1.0) * meas_col
        meas_col = meas_col * RAD2DEG
        snr_vec = meas_c["wrong_units"]
    elif units == "input-degrees":
        meas_c["wrong_units"] = (RAD2DEG - 1.0) * in_col
        in_col = in_col * RAD2DEG
        snr_vec = meas_c["wrong_units"] / R
    cols = {"input_angle_rad": in_col, "output_angle_rad": meas_col}
    gear_names = tuple(spec.get("effects", ())) if category in ("single", "pair") else ()
    diag = dict(effects={**gear, **equiv, **meas_c}, baseline=base, noise=noise, noise_unit=z,
                outliers=sigma * outl, params=params, noise_meta=nmeta, checks=checks)
    return dict(kind="transmission", model=m["code"], columns=cols, gear=gear_names, meas=meas, nuis=nuis,
                equiv=spec.get("equivalent", ()), sigma=sigma, snr_vec=snr_vec, diag=diag)


# ----------------------------------------------------------------------------------------------
# efficiency
# ----------------------------------------------------------------------------------------------
EFFICIENCY_PROTOCOLS = ("factorial-oven-blocks", "warm-up-sweep", "lhs-temperature-ramp")
R_GAS = 8.314462618


def _efficiency_grid(rng, m, protocol):
    Nmax = min(m["N_avg_max"], 3000.0)
    cand = [N for N in (250, 500, 1000, 1500, 2000, 2500, 3000) if N <= Nmax]
    blocks = None
    if protocol == "factorial-oven-blocks":
        nsp = min(len(cand), int(rng.integers(3, 5)))
        speeds = np.sort(rng.choice(cand, size=nsp, replace=False)).astype(float)
        loads = np.round(np.arange(1, 11) / 10.0, 2)
        temps = np.sort(rng.choice([0, 10, 20, 30, 40, 50, 60], size=int(rng.integers(4, 6)), replace=False)).astype(float)
        order = rng.permutation(len(temps))
        reps = 2
        Ns, As, Ts, blocks = [], [], [], []
        for bi, ti in enumerate(order):
            combos = [(N, a) for N in speeds for a in loads for _ in range(reps)]
            perm = rng.permutation(len(combos))
            start = len(Ns)
            for j in perm:
                Ns.append(combos[j][0]); As.append(combos[j][1]); Ts.append(temps[ti])
            blocks.append(np.arange(start, len(Ns)))
        par = dict(speeds=speeds.tolist(), temps_block_order=temps[order].tolist(), reps=reps)
    elif protocol == "warm-up-sweep":
        nsp = min(len(cand), int(rng.integers(3, 5)))
        speeds = np.sort(rng.choice(cand, size=nsp, replace=False)).astype(float)
        loads = np.geomspace(0.08, 1.0, 9)
        passes = int(rng.integers(10, 15))
        Ta, Te = float(rng.uniform(3, 18)), float(rng.uniform(45, 68))
        Ns, As = [], []
        for _ in range(passes):
            for N in speeds:
                for a in loads:
                    Ns.append(N); As.append(a)
        tt = np.arange(len(Ns)) / len(Ns)
        tau = float(rng.uniform(0.25, 0.6))
        Ts = list(Ta + (Te - Ta) * (1 - np.exp(-tt / tau)) / (1 - math.exp(-1 / tau)))
        par = dict(speeds=speeds.tolist(), passes=passes, T_start=Ta, T_end=Te, tau=tau)
    else:
        n = int(rng.integers(300, 451))
        def lhs():
            return (rng.permutation(n) + rng.random(n)) / n
        As = list(np.exp(np.log(0.05) + (np.log(1.0) - np.log(0.05)) * lhs()))
        Ns = list(250.0 + (Nmax - 250.0) * lhs())
        Ts = list(0.0 + 60.0 * lhs())
        o = np.argsort(Ts)
        As = [As[i] for i in o]; Ns = [Ns[i] for i in o]; Ts = [Ts[i] for i in o]
        par = dict(points=n)
    return np.array(Ns, float), np.array(As, float), np.array(Ts, float), blocks, par


def low_load_factor(form, alpha, N, m, level, rng):
    """Multiplicative factor (<= 1) on the efficiency level."""
    if form == "richards":
        f = lambda a, Q: (1.0 + Q * np.exp(-B * a)) ** (-1.0 / nu)
        for _ in range(200):
            B = float(rng.uniform(3.0, 10.0))
            nu = float(rng.uniform(0.5, 2.0))
            kap = float(rng.uniform(0.85, 0.95))
            g = lambda Q: float(f(0.58, Q) / f(1.0, Q)) - kap
            Q = brentq(g, 1e-9, 1e9)
            ke01 = float(f(0.1, Q) / f(1.0, Q))
            if 0.4 <= ke01 <= 0.75:
                break
        Ke = np.where(alpha >= 1.0, 1.0, f(alpha, Q) / f(1.0, Q))
        return Ke, dict(B=B, nu=nu, Q=Q, Ke_058=kap, Ke_010=ke01)
    if form == "taghirad-belanger":
        d = float(rng.uniform(0.025, 0.08))          # eta_m R T_f(1000 rpm) / T_r
        vs = float(rng.uniform(0.2, 0.6))             # viscous share of T_f at 1000 rpm
        eta_m = level / 100.0
        Tf_ref = d * m["T_r"] / (eta_m * m["ratio"])
        Tc = (1 - vs) * Tf_ref
        bv = vs * Tf_ref / 1000.0
        Ts = 0.3 * Tc
        Ns = float(rng.uniform(80.0, 200.0))
        Tf = Tc + bv * N + Ts * np.exp(-(N / Ns) ** 2)
        T = alpha * m["T_r"]
        fac = T / (T + eta_m * m["ratio"] * Tf)
        return fac, dict(d=d, viscous_share=vs, Tc_Nm=Tc, bv_Nm_per_rpm=bv, Ts_Nm=Ts, N_s_rpm=Ns)
    if form == "vring-seal-drag":                     # rig decoy: same algebra, input-side seal
        d = float(rng.uniform(0.025, 0.08))
        vs = float(rng.uniform(0.1, 0.4))
        eta_m = level / 100.0
        Tf_ref = d * m["T_r"] / (eta_m * m["ratio"])
        Tc = (1 - vs) * Tf_ref
        bv = vs * Tf_ref / 1000.0
        T = alpha * m["T_r"]
        fac = T / (T + eta_m * m["ratio"] * (Tc + bv * N))
        return fac, dict(d=d, viscous_share=vs, seal_Tc_Nm=Tc, seal_bv_Nm_per_rpm=bv,
                         equivalent="low_load_efficiency drag law (Taghirad-Belanger with T_s = 0)")
    raise ValueError(form)


def temperature_factor(form, Tc, N, rng):
    TK = Tc + 273.15
    Tref = 25.0 + 273.15
    if form == "cornelissen-waterman":
        C = float(rng.uniform(2.5, 3.5))
        nu40 = float(rng.uniform(50.0, 110.0))
        ratio = float(rng.uniform(7.0, 10.0))
        nu100 = nu40 / ratio
        Bc = (math.log10(nu40) - math.log10(nu100)) / (313.15 ** -C - 373.15 ** -C)
        Ac = math.log10(nu40) - Bc * 313.15 ** -C
        nu = lambda T: 10.0 ** (Ac + Bc * T ** -C)
        lam = float(rng.uniform(0.1, 0.22))
        mexp = float(rng.uniform(0.15, 0.35))
        fac = (1.0 - lam * (nu(TK) / nu(Tref)) ** mexp) / (1.0 - lam)
        return fac, dict(C=C, nu40_cSt=nu40, nu100_cSt=nu100, A=Ac, B=Bc, loss_ref=lam, m=mexp)
    if form == "carreau-yasuda":
        Ea = float(rng.uniform(25e3, 45e3))
        lamg = float(rng.uniform(1.0, 10.0))           # lambda * gamma_dot at 1000 rpm, 25 C
        nn = float(rng.uniform(0.3, 0.7))
        a = float(rng.uniform(1.5, 2.5))
        loss = float(rng.uniform(0.1, 0.22))
        aT = lambda T: np.exp(Ea / R_GAS * (1.0 / T - 1.0 / Tref))
        g = N / 1000.0

        def S(T):
            at = aT(T)
            return at * (1.0 + (lamg * at * g) ** a) ** ((nn - 1.0) / a)
        r = S(TK) / S(np.full_like(TK, Tref))
        fac = (1.0 - loss * r) / (1.0 - loss)
        return fac, dict(Ea_J_per_mol=Ea, lambda_gamma_1000rpm=lamg, n=nn, a=a, loss_ref=loss)
    if form == "lead-wire-desensitisation":           # rig decoy: input torque bridge, 2-wire leads in oven
        rho0 = float(rng.uniform(0.06, 0.2))
        aCu = 0.00393
        rl = rho0 * (1.0 + aCu * (Tc - 20.0))
        fac = (1.0 + rl) / (1.0 + rho0 * (1.0 + aCu * 5.0))
        return fac, dict(RL_over_Rg_20C=rho0, alpha_Cu=aCu,
                         equivalent="temperature_dependence, affine-in-T efficiency factor")
    raise ValueError(form)


def build_efficiency(rng, cat, spec, protocol):
    category = spec["category"]
    m = cat.models[rng.choice(cat.eligible("efficiency"))]
    level = float(rng.uniform(62.0, 86.0))
    nuis = {"efficiency_level": level}
    N, alpha, Tc, blocks, gpar = _efficiency_grid(rng, m, protocol)
    n = len(N)
    load = alpha * m["T_r"]
    params = dict(protocol=protocol, **gpar, rated_Nm=m["T_r"])
    base = np.full(n, level)
    factors = {}
    for eff, form in zip(spec.get("effects", ()), spec.get("forms", ())):
        if eff == "low_load_efficiency":
            f, p = low_load_factor(form, alpha, N, m, level, rng)
        else:
            f, p = temperature_factor(form, Tc, N, rng)
        factors[eff] = f
        params[eff] = dict(formulation=form, **p)
    if category == "pair":
        a, b = list(factors)
        rho = float(rng.uniform(0.6, 1.6))
        # rescale the deviation of b from 1 so that the RMS of level*(f_b - 1) is rho times that of a
        ra = rms(level * (factors[a] - 1.0))
        rb = rms(level * (factors[b] - 1.0))
        fac = rho * ra / rb
        fa, fb = fac ** -0.5, fac ** 0.5
        if max(fa, fb, 1 / fa, 1 / fb) > PAIR_RESCALE_MAX:
            return None
        factors[a] = 1.0 + (factors[a] - 1.0) * fa
        factors[b] = 1.0 + (factors[b] - 1.0) * fb
        params[a]["pair_rescale"] = fa
        params[b]["pair_rescale"] = fb
    prod = np.ones(n)
    for f in factors.values():
        prod = prod * f
    eta = level * prod
    if np.any(eta < 10.0) or np.any(eta > 98.0):
        return None
    gear = {k: level * (f - 1.0) for k, f in factors.items()}
    if len(factors) == 2:
        gear_inter = eta - level - sum(gear.values())
    else:
        gear_inter = None
    ones = np.ones(n)

    def absorb(y, extra):
        return _fit_resid(y, free=[ones] + list(extra))

    meas, meas_c, equiv = [], {}, {}
    checks = {}
    units = None
    mech = spec.get("mechanism")
    if category in ("single", "pair"):
        contrib = dict(gear)
        res = _size_effects(rng, contrib, lambda y, ex: absorb(level + y, ex), total=eta - level)
        if res is None:
            return None
        k, sigma, checks = res
        snr_vec = eta - level
    elif category == "decoy_equivalent":
        if mech == "vring-seal-drag":
            f, p = low_load_factor("vring-seal-drag", alpha, N, m, level, rng)
            # the same numbers read as a gear drag law (Taghirad-Belanger with T_s = 0)
            reading = level * (alpha * m["T_r"] / (alpha * m["T_r"] + (level / 100.0) * m["ratio"]
                                                    * (p["seal_Tc_Nm"] + p["seal_bv_Nm_per_rpm"] * N)))
        elif mech == "lead-wire-desensitisation":
            f, p = temperature_factor("lead-wire-desensitisation", Tc, N, rng)
            rl = p["RL_over_Rg_20C"] * (1.0 + p["alpha_Cu"] * (Tc - 20.0))
            reading = level * (1.0 + rl) / (1.0 + p["RL_over_Rg_20C"] * (1.0 + p["alpha_Cu"] * 5.0))
        else:
            raise ValueError(mech)
        e = level * (f - 1.0)
        eta = level + e
        equiv[mech] = e
        params["mechanism"] = dict(name=mech, **p)
        res = _size_effects(rng, {mech: e}, lambda y, ex: absorb(level + y, ex))
        if res is None:
            return None
        k, sigma, checks = res
        checks["equivalence_diff_over_noise"] = float(np.max(np.abs(eta - reading))) / sigma
        if checks["equivalence_diff_over_noise"] > EQUIV_TOL:
            return None
        snr_vec = e
        if mech == "lead-wire-desensitisation":
            meas = ["sensor_gain"]
    elif category == "clean":
        sigma = float(rng.uniform(0.15, 0.6))
        snr_vec = None
    else:
        kind_d = spec["decoy"]
        t = np.linspace(0, 1, n)
        sigma = float(rng.uniform(0.15, 0.6))
        if kind_d == "input-torque-gain":
            g = float(rng.uniform(0.9, 0.97)) if rng.random() < 0.5 else float(rng.uniform(1.03, 1.1))
            c = eta / g - eta
            meas = ["sensor_gain"]
            params["decoy"] = dict(name=kind_d, input_torque_gain=g)
            eta = eta + c
            meas_c["sensor_gain"] = c
            snr_vec = c
        elif kind_d == "level-outside-typical":
            lv = float(rng.uniform(40.0, 52.0)) if rng.random() < 0.5 else float(rng.uniform(90.0, 95.0))
            c = np.full(n, lv - level)
            nuis["efficiency_level"] = lv
            eta = eta + c
            params["decoy"] = dict(name=kind_d, level=lv)
            meas_c["efficiency_level"] = c
            snr_vec = c
        elif kind_d == "drift-rezeroed-per-block":
            # torque-zero drift restarting at every oven block (re-zero at the block start)
            tau = float(rng.uniform(0.2, 0.6))
            shape = np.zeros(n)
            for blk in blocks:
                u = np.arange(len(blk)) / len(blk)
                shape[blk] = 1.0 - np.exp(-u / tau)
            sgn = 1.0 if rng.random() < 0.5 else -1.0
            shape = sgn * shape
            R_shape = rms(_fit_resid(shape, free=[ones]))
            tb = [Tc, Tc ** 2, Tc ** 3]
            lb = [1.0 / (alpha + dd) for dd in (0.02, 0.05, 0.1, 0.2)]
            r_g = rms(_fit_resid(shape, free=[ones] + tb + lb))
            need = MARGIN_DECOY * R_shape / max(r_g, 1e-300)
            if need > K_RANGE[1]:
                return None
            k = float(rng.uniform(max(K_RANGE[0], need), K_RANGE[1]))
            c = shape * (k * sigma / R_shape)
            meas = ["thermal_drift"]
            params["decoy"] = dict(name=kind_d, tau_block=tau, sign=sgn)
            checks = {"resid_after_nuisance_and_gear_bases": r_g / R_shape * k}
            eta = eta + c
            meas_c["thermal_drift"] = c
            snr_vec = _fit_resid(c, free=[ones])
        elif kind_d in ("fraction", "load-kNm"):
            units = kind_d
            meas = ["wrong_units"]
            params["decoy"] = dict(name=kind_d)
            snr_vec = None
        else:
            raise ValueError(kind_d)
    z, outl, nmeta = _noise(rng, n, blocks=blocks)
    noise = sigma * (z + outl)
    eff_col = eta + noise
    load_col = load.copy()
    if units == "fraction":
        meas_c["wrong_units"] = eff_col / 100.0 - eff_col
        eff_col = eff_col / 100.0
        snr_vec = meas_c["wrong_units"]
    elif units == "load-kNm":
        meas_c["wrong_units"] = load * 1e-3 - load
        load_col = load * 1e-3
        snr_vec = meas_c["wrong_units"]
    cols = {"input_speed_rpm": N, "load_torque_Nm": load_col, "temperature_C": Tc, "efficiency_pct": eff_col}
    gear_names = tuple(spec.get("effects", ())) if category in ("single", "pair") else ()
    eff_d = {**gear, **equiv, **meas_c}
    if gear_inter is not None:
        eff_d["_interaction"] = gear_inter
    diag = dict(effects=eff_d, baseline=base, noise=noise, noise_unit=z, outliers=sigma * outl,
                params=params, noise_meta=nmeta, checks=checks, alpha=alpha)
    return dict(kind="efficiency", model=m["code"], columns=cols, gear=gear_names, meas=meas, nuis=nuis,
                equiv=spec.get("equivalent", ()), sigma=sigma, snr_vec=snr_vec, diag=diag)


# ----------------------------------------------------------------------------------------------
# vibration: run-up profiles and integrators
# ----------------------------------------------------------------------------------------------
def make_runup_erf(rng, Na, Nb, Tdur):
    """Speed follows an error function (Gaussian acceleration pulse); analytic input angle."""
    tc = float(rng.uniform(0.4, 0.6)) * Tdur
    w = float(rng.uniform(0.35, 0.6)) * Tdur
    E0, E1 = erf(-tc / w), erf((Tdur - tc) / w)
    F = lambda uu: uu * erf(uu) + np.exp(-uu * uu) / math.sqrt(math.pi)

    def fun(t):
        t = np.asarray(t, float)
        u = (t - tc) / w
        Nt = Na + (Nb - Na) * (erf(u) - E0) / (E1 - E0)
        intE = w * (F(u) - F(-tc / w))               # int_0^t erf((tau - tc)/w) dtau
        intN = Na * t + (Nb - Na) * (intE - E0 * t) / (E1 - E0)
        return Nt, 2 * math.pi / 60.0 * intN
    return fun, dict(profile="erf", tc=tc, w=w)


def make_runup_weibull(rng, Na, Nb, Tdur):
    """Speed follows a Weibull CDF; analytic input angle via the regularised incomplete gamma."""
    kap = float(rng.uniform(1.5, 3.0))
    lam = float(rng.uniform(0.4, 0.7)) * Tdur
    D = 1.0 - math.exp(-(Tdur / lam) ** kap)
    G = gamma_fn(1.0 / kap)

    def fun(t):
        t = np.asarray(t, float)
        Nt = Na + (Nb - Na) * (1.0 - np.exp(-(t / lam) ** kap)) / D
        int_exp = lam / kap * G * gammainc(1.0 / kap, (t / lam) ** kap)
        intN = Na * t + (Nb - Na) * (t - int_exp) / D
        return Nt, 2 * math.pi / 60.0 * intN
    return fun, dict(profile="weibull", kappa=kap, lam=lam)


_GL_C = (0.5 - math.sqrt(3) / 6, 0.5 + math.sqrt(3) / 6)
_GL_A = ((0.25, 0.25 - math.sqrt(3) / 6), (0.25 + math.sqrt(3) / 6, 0.25))


def integrate_gl2(te_fun, runup, t_out, K, J, zeta0, beta_speed, sub=2, block=32):
    """Gauss-Legendre 2-stage (order 4) implicit RK; relative viscous damping rising with speed.

    J x'' = K (e - x) + c(N) (e' - x'),  c(N) = 2 zeta0 (1 + beta N/1000) sqrt(K J).
    """
    h = (t_out[1] - t_out[0]) / sub
    nsteps = (len(t_out) - 1) * sub
    tj = np.arange(nsteps) * h
    ts1 = tj + _GL_C[0] * h
    ts2 = tj + _GL_C[1] * h
    N1, th1 = runup(ts1)
    N2, th2 = runup(ts2)
    e1, de1 = te_fun(th1)
    e2, de2 = te_fun(th2)
    om1 = 2 * math.pi / 60.0 * N1
    om2 = 2 * math.pi / 60.0 * N2
    ed1 = de1 * om1
    ed2 = de2 * om2
    cc = 2.0 * zeta0 * math.sqrt(K * J)
    kJ = K / J
    y0, y1 = 0.0, 0.0
    # start at rest relative to the quasi-static solution: x = e(0), v = e'(0)
    Nst, ths = runup(np.array([0.0]))
    e0, de0 = te_fun(ths)
    y0 = float(e0[0]); y1 = float(de0[0] * 2 * math.pi / 60.0 * Nst[0])
    xs = np.empty(len(t_out))
    xs[0] = y0
    a11, a12 = _GL_A[0]
    a21, a22 = _GL_A[1]
    j = 0
    Minv = None
    for blk0 in range(0, nsteps, block):
        blk1 = min(nsteps, blk0 + block)
        Nmid = 0.5 * (N1[blk0] + N2[blk1 - 1])
        c = cc * (1.0 + beta_speed * Nmid / 1000.0)
        cJ = c / J
        A = np.array([[0.0, 1.0], [-kJ, -cJ]])
        M = np.eye(4)
        M[0:2, 0:2] -= h * a11 * A
        M[0:2, 2:4] -= h * a12 * A
        M[2:4, 0:2] -= h * a21 * A
        M[2:4, 2:4] -= h * a22 * A
        Mi = np.linalg.inv(M).tolist()
        (m00, m01, m02, m03), (m10, m11, m12, m13), (m20, m21, m22, m23), (m30, m31, m32, m33) = Mi
        for i in range(blk0, blk1):
            ay0 = y1
            ay1 = -kJ * y0 - cJ * y1
            f1 = kJ * e1[i] + cJ * ed1[i]
            f2 = kJ * e2[i] + cJ * ed2[i]
            r0, r1, r2, r3 = ay0, ay1 + f1, ay0, ay1 + f2
            k10 = m00 * r0 + m01 * r1 + m02 * r2 + m03 * r3
            k11 = m10 * r0 + m11 * r1 + m12 * r2 + m13 * r3
            k20 = m20 * r0 + m21 * r1 + m22 * r2 + m23 * r3
            k21 = m30 * r0 + m31 * r1 + m32 * r2 + m33 * r3
            y0 += 0.5 * h * (k10 + k20)
            y1 += 0.5 * h * (k11 + k21)
            if (i + 1) % sub == 0:
                xs[(i + 1) // sub] = y0
    return xs


def integrate_zhai(te_fun, runup, t_out, K, J, cp, alpha, v_eps, sub=2, psi=0.5, phi=0.5):
    """Zhai's (1996) explicit two-step method; absolute sub-linear power-law damping (load drag).

    J x'' = K (e - x) - cp |x'|^alpha sign(x')  (regularised: x' (x'^2 + v_eps^2)^((alpha-1)/2)).
    """
    h = (t_out[1] - t_out[0]) / sub
    nsteps = (len(t_out) - 1) * sub
    tj = np.arange(nsteps + 1) * h
    Nn, th = runup(tj)
    e, de = te_fun(th)
    e = e.tolist()
    x = float(e[0])
    v = float(de[0] * 2 * math.pi / 60.0 * Nn[0])
    am = (alpha - 1.0) / 2.0
    ve2 = v_eps * v_eps

    def acc(i, x, v):
        return (K * (e[i] - x) - cp * v * (v * v + ve2) ** am) / J
    a_prev = None
    a = acc(0, x, v)
    xs = np.empty(len(t_out))
    xs[0] = x
    h2 = h * h
    for i in range(nsteps):
        if a_prev is None:
            xn = x + v * h + 0.5 * a * h2
            vn = v + a * h
        else:
            xn = x + v * h + (0.5 + psi) * a * h2 - psi * a_prev * h2
            vn = v + (1.0 + phi) * a * h - phi * a_prev * h
        a_prev = a
        x, v = xn, vn
        a = acc(i + 1, x, v)
        if (i + 1) % sub == 0:
            xs[(i + 1) // sub] = x
    return xs


def _te_fun_factory(kind, **p):
    if kind == "sine":
        k, a, ph = p["order"], p["amp"], p["phase"]
        return lambda th: (a * np.sin(k * th + ph), a * k * np.cos(k * th + ph))
    if kind == "pin-slot":
        eor, ph, R = p["e_over_r"], p["phase"], p["R"]
        def f(th):
            e = pin_slot_error(th, eor, ph) / R
            d = 1e-6
            de = (pin_slot_error(th + d, eor, ph) - pin_slot_error(th - d, eor, ph)) / (2 * d) / R
            return e, de
        return f
    if kind == "cardan":
        beta, delta, ph, R = p["beta"], p["delta"], p["phase"], p["R"]
        def f(th):
            e = cardan_pair_error(th, beta, delta, ph) / R
            d = 1e-6
            de = (cardan_pair_error(th + d, beta, delta, ph) - cardan_pair_error(th - d, beta, delta, ph)) / (2 * d) / R
            return e, de
        return f
    if kind == "sum":
        fs = p["funs"]
        def f(th):
            e = 0.0; de = 0.0
            for g in fs:
                a, b = g(th)
                e = e + a; de = de + b
            return e, de
        return f
    raise ValueError(kind)


VIBRATION_FORMS = ("gl2-erf-speedvisc", "zhai-weibull-powerlaw")


def build_vibration(rng, cat, spec, form):
    category = spec["category"]
    m = cat.models[rng.choice(cat.eligible("vibration"))]
    R = m["ratio"]
    acc = m["accuracy"]
    s = _stiffness_scale(rng)
    K = m["K1"] * s
    zeta0 = float(rng.uniform(0.035, 0.08))
    effects = tuple(spec.get("effects", ()))
    mech = spec.get("mechanism")
    orders = set()
    for eff in effects:
        orders.add(1 if eff == "te_1x" else 2)
    if mech == "pin-slot-drive-offset":
        orders.add(1)
    if mech == "misphased-double-cardan":
        orders.add(2)
    if not orders:
        orders = {1, 2} if rng.random() < 0.5 else {int(rng.integers(1, 3))}
    kmax = max(orders)
    kmin = min(orders)
    Nlim = min(0.8 * m["N_max"], 3000.0)
    fn_hi = min(35.0, Nlim / 60.0 / 1.5 * kmin) if 1 in orders else min(35.0, Nlim / 30.0 / 1.5)
    fn = float(rng.uniform(12.0, max(12.5, fn_hi)))
    J = K / (2 * math.pi * fn) ** 2
    Nres = {k: 60.0 * fn / k for k in orders}
    Na = float(rng.uniform(0.55, 0.7)) * min(Nres.values())
    Nb = min(float(rng.uniform(1.35, 1.6)) * max(Nres.values()), Nlim)
    # sweep-rate bound: >= 3 build-up times inside the half-power band of the highest order
    Ndot = 80.0 * math.pi * zeta0 ** 2 * fn ** 2 / kmax
    Tdur = 1.5 * (Nb - Na) / Ndot
    fs = max(25.0 * fn, 12.0 * 2.0 * Nb / 60.0, 200.0)
    rows = int(fs * Tdur)
    if rows > 7000:
        rows = 7000
    if rows < 1500:
        rows = 1500
    Tdur = rows / fs
    t = np.arange(rows) / fs
    maker = make_runup_erf if form.startswith("gl2") else make_runup_weibull
    runup, rpar = maker(rng, Na, Nb, Tdur)
    Nt, th = runup(t)
    nuis = {"stiffness_scale": s, "damping_ratio": zeta0}
    params = dict(formulation=form, fn_Hz=fn, J_kgm2=J, K_Nm_per_rad=K, Na_rpm=Na, Nb_rpm=Nb,
                  T_s=Tdur, fs_Hz=fs, runup=rpar, Nres_rpm=Nres, accuracy_rad=acc)
    if form.startswith("gl2"):
        beta_s = float(rng.uniform(0.2, 0.8))
        params["damping"] = dict(law="relative viscous, zeta = zeta0 (1 + beta N/1000)", beta=beta_s)
        sim = lambda f: integrate_gl2(f, runup, t, K, J, zeta0, beta_s)
    else:
        alpha = float(rng.uniform(0.5, 0.8))
        params["damping"] = dict(law="absolute power-law c|v|^alpha", alpha=alpha)

    def make_powerlaw(amp_ref):
        # energy-equivalent viscous damping at the expected resonant amplitude X = amp/(2 zeta0)
        X = amp_ref / (2 * zeta0)
        wn = 2 * math.pi * fn
        c_eq = 2 * zeta0 * math.sqrt(K * J)
        ba = (2 ** (alpha + 2) / math.pi) * gamma_fn(alpha / 2 + 1) ** 2 / gamma_fn(alpha + 2)
        cp = c_eq / (ba * (wn * X) ** (alpha - 1.0))
        return cp, 0.01 * wn * X

    gear_funs = {}
    for eff in effects:
        k_ord = 1 if eff == "te_1x" else 2
        amp = float(rng.uniform(0.2, 0.6)) * acc / 2.0
        ph = float(rng.uniform(0, 2 * math.pi))
        gear_funs[eff] = dict(order=k_ord, amp=amp, phase=ph)
        params[eff] = dict(waveform="sinusoid", order=k_ord, half_pp_rad=amp, phase=ph)
    if category == "pair":
        # balance by quasi-static resonant amplitude (rescaled after simulation below)
        pass
    equiv_fun = None
    if mech == "pin-slot-drive-offset":
        amp = float(rng.uniform(0.2, 0.6)) * acc / 2.0
        ph = float(rng.uniform(0, 2 * math.pi))
        equiv_fun = _te_fun_factory("pin-slot", e_over_r=amp * R, phase=ph, R=R)
        params["mechanism"] = dict(name=mech, e_over_r=amp * R, phase=ph, equivalent="te_1x")
        amp_ref = amp
    elif mech == "misphased-double-cardan":
        amp = float(rng.uniform(0.2, 0.6)) * acc / 2.0
        ph = float(rng.uniform(0, 2 * math.pi))
        delta = float(rng.uniform(0.2, 0.8))
        beta = math.sqrt(2.0 * amp * R / math.sin(delta))
        equiv_fun = _te_fun_factory("cardan", beta=beta, delta=delta, phase=ph, R=R)
        params["mechanism"] = dict(name=mech, beta_rad=beta, delta_rad=delta, phase=ph, equivalent="te_2x")
        amp_ref = amp
    else:
        amp_ref = max([g["amp"] for g in gear_funs.values()], default=0.3 * acc / 2)
    if not form.startswith("gl2"):
        cp, veps = make_powerlaw(amp_ref)
        params["damping"].update(cp=cp, v_eps=veps)
        sim = lambda f: integrate_zhai(f, runup, t, K, J, cp, alpha, veps)

    gear = {}
    for eff, g in gear_funs.items():
        gear[eff] = sim(_te_fun_factory("sine", **g))
    inter = None
    if category == "pair":
        a, b = list(gear)
        rho = float(rng.uniform(0.6, 1.6))
        fac = rho * rms(gear[a]) / rms(gear[b])
        for nm, f in ((a, fac ** -0.5), (b, fac ** 0.5)):
            gear_funs[nm]["amp"] *= f
            params[nm]["half_pp_rad_effective"] = gear_funs[nm]["amp"]
            params[nm]["pair_rescale"] = f
            gear[nm] = sim(_te_fun_factory("sine", **gear_funs[nm]))
        both = sim(_te_fun_factory("sum", funs=[_te_fun_factory("sine", **g) for g in gear_funs.values()]))
        inter = both - gear[a] - gear[b]
        resp = both
    else:
        resp = sum(gear.values()) if gear else np.zeros(rows)
    ones = np.ones(rows)

    def absorb(y, extra):
        return _fit_resid(y, free=[ones] + list(extra))

    meas, meas_c, equiv = [], {}, {}
    checks = {}
    if category in ("single", "pair"):
        res = _size_effects(rng, gear, lambda y, ex: absorb(y, ex), total=resp)
        if res is None:
            return None
        k, sigma, checks = res
        snr_vec = resp
    elif category == "decoy_equivalent":
        e = sim(equiv_fun)
        k_ord = 1 if mech == "pin-slot-drive-offset" else 2
        # equivalent gear reading: the sinusoidal TE of that order with the kinematic error's
        # own Fourier coefficient, run through the same joint dynamics
        xg = np.linspace(0, 2 * math.pi, 4096, endpoint=False)
        eg, _ = equiv_fun(xg)
        a_s = 2 * np.mean(eg * np.sin(k_ord * xg))
        a_c = 2 * np.mean(eg * np.cos(k_ord * xg))
        A_r, ph_r = math.hypot(a_s, a_c), math.atan2(a_c, a_s)
        reading = sim(_te_fun_factory("sine", order=k_ord, amp=A_r, phase=ph_r))
        params["mechanism"].update(reading_half_pp_rad=A_r, reading_phase=ph_r)
        equiv[mech] = e
        resp = e
        res = _size_effects(rng, {mech: e}, lambda y, ex: absorb(y, ex))
        if res is None:
            return None
        k, sigma, checks = res
        diff = rms(e - reading)
        checks["equivalence_diff_over_noise"] = diff / sigma
        if diff / sigma > EQUIV_TOL:
            return None
        snr_vec = e
    elif category == "clean":
        sigma = float(rng.uniform(0.005, 0.03)) * acc
        snr_vec = None
    else:
        kind_d = spec["decoy"]
        tn = t / t[-1]
        if kind_d == "drift-slab":
            c, p = _drift_slab(rng, tn)
            meas = ["thermal_drift"]
        elif kind_d == "offset-step":
            c, p = _step(rng, tn)
            meas = ["angle_offset"]
        elif kind_d == "output-encoder-eccentricity":
            psi = float(rng.uniform(0, 2 * math.pi))
            c = np.sin(th / R + psi)
            p = dict(psi=psi, output_revs=float(th[-1] / R / (2 * math.pi)))
            meas = ["encoder_eccentricity"]
        else:
            raise ValueError(kind_d)
        params["decoy"] = dict(name=kind_d, **p)
        c = np.asarray(c, float) - np.mean(c)
        # gear-effect bases: quasi-stationary 1x/2x responses (frequency response of the joint)
        wn = 2 * math.pi * fn
        om = 2 * math.pi / 60.0 * Nt
        bases = []
        for k_ord in (1, 2):
            w = k_ord * om
            Hc = (K + 1j * 2 * zeta0 * math.sqrt(K * J) * w) / (K - J * w ** 2 + 1j * 2 * zeta0 * math.sqrt(K * J) * w)
            z_ = Hc * np.exp(1j * k_ord * th)
            bases += [z_.real, z_.imag]
        R_shape = rms(c)
        r_g = rms(_fit_resid(c, free=[ones] + bases))
        need = MARGIN_DECOY * R_shape / max(r_g, 1e-300)
        if need > K_RANGE[1]:
            return None
        k = float(rng.uniform(max(K_RANGE[0], need), K_RANGE[1]))
        sigma = float(rng.uniform(0.005, 0.03)) * acc
        c = c * (k * sigma / R_shape)
        meas_c[meas[0]] = c
        resp = resp + c
        checks = {"resid_after_nuisance_and_gear_bases": r_g / R_shape * k}
        snr_vec = c
    z, outl, nmeta = _noise(rng, rows)
    noise = sigma * (z + outl)
    cols = {"time_s": t, "input_speed_rpm": Nt, "output_vibration_rad": resp + noise}
    gear_names = tuple(effects) if category in ("single", "pair") else ()
    eff_d = {**gear, **equiv, **meas_c}
    if inter is not None:
        eff_d["_interaction"] = inter
    diag = dict(effects=eff_d, baseline=np.zeros(rows), noise=noise, noise_unit=z, outliers=sigma * outl,
                params=params, noise_meta=nmeta, checks=checks, input_angle=th)
    return dict(kind="vibration", model=m["code"], columns=cols, gear=gear_names, meas=meas, nuis=nuis,
                equiv=spec.get("equivalent", ()), sigma=sigma, snr_vec=snr_vec, diag=diag, J=J)


# ----------------------------------------------------------------------------------------------
# cells
# ----------------------------------------------------------------------------------------------
def _cells():
    C = []
    add = lambda **kw: C.append(kw)
    # --- torsion
    for p in TORSION_PROTOCOLS:
        add(kind="torsion", category="clean", tag=f"clean-{p}", protocols=(p,))
    for eff, forms in (("hysteresis", ("masing-voce", "bodner-partom", "berg-parallel")),
                       ("backlash", ("abaqus-exp-contact", "almen-laszlo-belleville")),
                       ("housing_compliance", ("tate-rosenfeld", "open-slotted-sleeve"))):
        for f in forms:
            add(kind="torsion", category="single", effects=(eff,), forms=(f,), tag=f"{eff}-{f}")
    for effs, forms in (
            (("hysteresis", "backlash"), ("masing-voce", "abaqus-exp-contact")),
            (("hysteresis", "backlash"), ("bodner-partom", "almen-laszlo-belleville")),
            (("hysteresis", "backlash"), ("berg-parallel", "abaqus-exp-contact")),
            (("hysteresis", "housing_compliance"), ("masing-voce", "open-slotted-sleeve")),
            (("hysteresis", "housing_compliance"), ("bodner-partom", "tate-rosenfeld")),
            (("backlash", "housing_compliance"), ("almen-laszlo-belleville", "tate-rosenfeld")),
            (("backlash", "housing_compliance"), ("abaqus-exp-contact", "open-slotted-sleeve"))):
        add(kind="torsion", category="pair", effects=effs, forms=forms, tag="+".join(effs) + "-" + "+".join(forms))
    for d in ("torque-gain-high", "twist-gain-low", "stiffer-than-spread", "offset-step",
              "drift-bangbang", "drift-slab", "degrees", "kNm"):
        add(kind="torsion", category="decoy_separable", decoy=d, tag=d)
    for mech, eq in (("isolation-mount-rocking", ("housing_compliance",)),
                     ("flexspline-body-thinner", ("housing_compliance",)),
                     ("shrink-disc-hub-windup", ("housing_compliance",)),
                     ("support-bearing-friction", ("hysteresis",)),
                     ("ball-detent-clearance", ("backlash",))):
        add(kind="torsion", category="decoy_equivalent", mechanism=mech, equivalent=eq, tag=mech)
    # --- transmission
    for p in TRANSMISSION_PROTOCOLS:
        add(kind="transmission", category="clean", tag=f"clean-{p}", protocols=(p,))
    for eff, forms in (("te_1x", ("signed-square", "gp-modulated")), ("te_2x", ("rectified", "telegraph-switched"))):
        for f in forms:
            add(kind="transmission", category="single", effects=(eff,), forms=(f,), tag=f"{eff}-{f}")
    for f1 in ("signed-square", "gp-modulated"):
        for f2 in ("rectified", "telegraph-switched"):
            add(kind="transmission", category="pair", effects=("te_1x", "te_2x"), forms=(f1, f2),
                tag=f"te_1x+te_2x-{f1}+{f2}")
    for d in ("output-gain", "offset-step", "trefoil-eccentric-ring", "drift-bangbang",
              "output-degrees", "input-degrees"):
        add(kind="transmission", category="decoy_separable", decoy=d, tag=d)
    for mech, eq in (("pin-slot-drive-offset", ("te_1x",)), ("misphased-double-cardan", ("te_2x",))):
        add(kind="transmission", category="decoy_equivalent", mechanism=mech, equivalent=eq, tag=mech)
    # --- efficiency
    for p in EFFICIENCY_PROTOCOLS:
        add(kind="efficiency", category="clean", tag=f"clean-{p}", protocols=(p,))
    for eff, forms in (("low_load_efficiency", ("richards", "taghirad-belanger")),
                       ("temperature_dependence", ("cornelissen-waterman", "carreau-yasuda"))):
        for f in forms:
            add(kind="efficiency", category="single", effects=(eff,), forms=(f,), tag=f"{eff}-{f}")
    for f1 in ("richards", "taghirad-belanger"):
        for f2 in ("cornelissen-waterman", "carreau-yasuda"):
            add(kind="efficiency", category="pair", effects=("low_load_efficiency", "temperature_dependence"),
                forms=(f1, f2), tag=f"low_load+temperature-{f1}+{f2}")
    for d in ("input-torque-gain", "level-outside-typical", "fraction", "load-kNm"):
        add(kind="efficiency", category="decoy_separable", decoy=d, tag=d)
    add(kind="efficiency", category="decoy_separable", decoy="drift-rezeroed-per-block", tag="drift-rezeroed-per-block",
        protocols=("factorial-oven-blocks",))
    for mech, eq in (("vring-seal-drag", ("low_load_efficiency",)),
                     ("lead-wire-desensitisation", ("temperature_dependence",))):
        add(kind="efficiency", category="decoy_equivalent", mechanism=mech, equivalent=eq, tag=mech)
    # --- vibration
    for f in VIBRATION_FORMS:
        add(kind="vibration", category="clean", tag=f"clean-{f}", vforms=(f,))
    for eff in ("te_1x", "te_2x"):
        for f in VIBRATION_FORMS:
            add(kind="vibration", category="single", effects=(eff,), forms=("sinusoid",), vforms=(f,), tag=f"{eff}-{f}")
    for f in VIBRATION_FORMS:
        add(kind="vibration", category="pair", effects=("te_1x", "te_2x"), forms=("sinusoid", "sinusoid"),
            vforms=(f,), tag=f"te_1x+te_2x-{f}")
    for d in ("drift-slab", "offset-step", "output-encoder-eccentricity"):
        add(kind="vibration", category="decoy_separable", decoy=d, tag=d)
    for mech, eq in (("pin-slot-drive-offset", ("te_1x",)), ("misphased-double-cardan", ("te_2x",))):
        add(kind="vibration", category="decoy_equivalent", mechanism=mech, equivalent=eq, tag=mech)
    return C


_BUILDERS = {"torsion": build_torsion, "transmission": build_transmission,
             "efficiency": build_efficiency, "vibration": build_vibration}
_PROTOCOLS = {"torsion": TORSION_PROTOCOLS, "transmission": TRANSMISSION_PROTOCOLS,
              "efficiency": EFFICIENCY_PROTOCOLS, "vibration": VIBRATION_FORMS}


def _formulation_text(spec, proto):
    cat = spec["category"]
    if cat == "clean":
        return f"clean; protocol {proto}"
    if cat in ("single", "pair"):
        f = " + ".join(spec["forms"])
        if spec["kind"] == "vibration":
            return f"{f} TE; {proto}"
        return f"{f}; protocol {proto}"
    if cat == "decoy_separable":
        return f"decoy {spec['decoy']}; protocol {proto}"
    return f"equivalent {spec['mechanism']}; protocol {proto}"


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list:
    rng = np.random.default_rng(seed)
    cat = Catalog(catalog_dir)
    cases = []
    counter = 0
    for ci, spec in enumerate(_cells()):
        kind = spec["kind"]
        protos = spec.get("protocols") or spec.get("vforms") or _PROTOCOLS[kind]
        for i in range(per_cell):
            proto = protos[(i + ci) % len(protos)]
            out = None
            for attempt in range(60):
                out = _BUILDERS[kind](rng, cat, spec, proto)
                if out is not None:
                    break
            if out is None:
                raise RuntimeError(f"could not draw a detectable case for cell {spec['tag']}")
            counter += 1
            name = f"{SUITE}-{kind}-{spec['category']}-{spec['tag']}-{counter:03d}"
            out["diag"]["attempts"] = attempt + 1
            out["diag"]["cell"] = spec["tag"]
            out["diag"]["protocol"] = proto
            c = _finish_case(kind, name, out["model"], out["columns"], out["gear"], out["meas"], out["nuis"],
                             spec["category"], out["equiv"], out["sigma"], _formulation_text(spec, proto),
                             out["snr_vec"], out["diag"], load_inertia=out.get("J"))
            cases.append(c)
    return cases


if __name__ == "__main__":
    import sys
    import time
    t0 = time.time()
    cs = generate_cases(int(sys.argv[1]) if len(sys.argv) > 1 else 11,
                        Path(__file__).with_name("catalog"), per_cell=int(sys.argv[2]) if len(sys.argv) > 2 else 2)
    print(len(cs), "cases in", round(time.time() - t0, 2), "s")
