"""Truth suite "h": synthetic measured data for strain wave gears with known hidden effects.

Written from the contract (truths/CONTRACT.md), the catalog tables and the physics literature
only.  numpy + scipy; nothing from hdcad.  See NOTES_h.md for the formulations and sources.

    generate_cases(seed, catalog_dir, per_cell=4) -> list[TruthCase]
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import optimize, signal, special

SUITE = "h"


# ----------------------------------------------------------------------------------------------
# the case record (exactly the contract's fields)
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
        cols = list(self.columns)
        arrs = [np.asarray(self.columns[c], dtype=float) for c in cols]
        n = len(arrs[0])
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(cols)
            for i in range(n):
                w.writerow([repr(float(a[i])) for a in arrs])


# ----------------------------------------------------------------------------------------------
# catalog access (read-only)
# ----------------------------------------------------------------------------------------------
def _read(path: Path) -> list[dict]:
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _f(x):
    x = (x or "").strip()
    return float(x) if x else None


class _Catalog:
    def __init__(self, d):
        d = Path(d)
        self.stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
        self.ratings = _read(d / "gh_ratings_050-1_058-1.csv")
        self.backlash = _read(d / "gh_backlash_052-2_060-2.csv")
        self.hyst = _read(d / "gh_hysteresis_052_060.csv")
        self.perf = _read(d / "gh_performance_051-1_059-1.csv")
        self.comp = _read(d / "component_examples.csv")
        self.fd_ratios = _read(d / "fd_ratios_304-1.csv")
        self.fd_rated = _read(d / "fd_rated_torque_310-1.csv")
        self.fd_speed = _read(d / "fd_max_input_speed_313-3_313-4.csv")
        self.fd_lm = _read(d / "fd_lost_motion_spring_314-1.csv")
        self._build()

    # -- gear heads -------------------------------------------------------------------------
    def _stiff_row(self, series, size, ratio):
        for r in self.stiff:
            if r["series"] != series or int(r["size"]) != size:
                continue
            lo = _f(r["ratio_min"]) or 0
            hi = _f(r["ratio_max"]) or 1e9
            if lo <= ratio <= hi:
                return r
        return None

    def _build(self):
        self.gh = []
        for r in self.ratings:
            series, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
            st = self._stiff_row(series, size, ratio)
            if st is None:
                continue
            code = f"{series[:3]}-{size}-{ratio}-GH"
            bl = next((_f(b["backlash_rad"]) for b in self.backlash
                       if b["series"] == series and int(b["size"]) == size and int(b["ratio"]) == ratio), None)
            hl = None
            for h in self.hyst:
                lo = _f(h["ratio_min"]) or 0
                hi = _f(h["ratio_max"]) or 1e9
                if h["series"] == series and lo <= ratio <= hi:
                    hl = _f(h["hysteresis_rad"])
            acc = None
            for p in self.perf:
                if p["series"] == series and int(p["size"]) == size and int(p["ratio"]) == ratio:
                    acc = _f(p["accuracy_rad"]) or acc
            self.gh.append(dict(
                code=code, family="GH", series=series[:3], size=size, ratio=ratio,
                T1=_f(st["T1_Nm"]), T2=_f(st["T2_Nm"]), K1=_f(st["K1_Nm_per_rad"]),
                K2=_f(st["K2_Nm_per_rad"]), K3=_f(st["K3_Nm_per_rad"]),
                th1_tab=_f(st["theta1_rad"]), th2_tab=_f(st["theta2_rad"]),
                rated=_f(r["rated_torque_2000_Nm"]), nmax=_f(r["max_input_speed_rpm"]),
                navg=_f(r["avg_input_speed_max_rpm"]), backlash=bl, hyst=hl,
                accuracy=acc if acc else 2.9e-4))
        # component sets (only the worked-example rows of the seeds)
        self.cs = {}
        for r in self.comp:
            code = f"{r['series']}-{int(r['size'])}-{int(r['ratio'])}-2A-GR"
            self.cs[code] = dict(
                code=code, family="CS", series=r["series"], size=int(r["size"]), ratio=int(r["ratio"]),
                rated=_f(r["rated_torque_Nm"]), eta=_f(r["efficiency_rated_pct"]),
                T1=_f(r["T1_Nm"]), K1=_f(r["K1_Nm_per_rad"]), K2=_f(r["K2_Nm_per_rad"]),
                th1_tab=_f(r["theta1_rad"]), T2=None, K3=None, th2_tab=None,
                nmax=_f(r["max_input_speed_rpm"]), accuracy=2.9e-4)
        # FD
        self.fd = []
        for r in self.fd_ratios:
            size, ratio = int(r["size"]), int(r["ratio"])
            rated = sorted(((float(q["speed_rpm"]), float(q["rated_torque_Nm"])) for q in self.fd_rated
                            if int(q["size"]) == size and int(q["ratio"]) == ratio))
            sp = next(q for q in self.fd_speed if int(q["size"]) == size)
            lm = next(q for q in self.fd_lm if int(q["size"]) == size)
            for typ in ("0", "2"):
                self.fd.append(dict(code=f"FD-{size}-{ratio}-{typ}", family="FD", size=size, ratio=ratio,
                                    rated_by_speed=rated, nmax_oil=float(sp["oil_max_rpm"]),
                                    nmax_grease=float(sp["grease_max_rpm"]),
                                    k_spring=float(lm["spring_constant_Nm_per_rad"]), accuracy=2.9e-4))

    @staticmethod
    def fd_rated_at(m, n):
        """Rated torque at WG speed n: <=500 r/min -> the 500 value, else the next higher listed speed."""
        tab = m["rated_by_speed"]
        for sp, tq in tab:
            if n <= sp + 1e-9:
                return tq
        return tab[-1][1]


# ----------------------------------------------------------------------------------------------
# small numeric helpers
# ----------------------------------------------------------------------------------------------
def _rms(x):
    x = np.asarray(x, float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def _std(x):
    x = np.asarray(x, float)
    return _rms(x - x.mean())


class _Retry(Exception):
    """The drawn case cannot meet its constraints: draw it again (deterministically)."""


def _solve_amp(make, measure, target, a0):
    """Amplitude a with measure(make(a)) == target (measure monotone in a); geometric bracketing."""
    m0 = measure(make(a0))
    if m0 <= 0:
        raise ValueError("effect with zero size")
    a1 = a0 * target / m0
    m1 = measure(make(a1))
    if abs(m1 - target) <= 1e-6 * target:
        return a1
    lo, hi = min(a0, a1), max(a0, a1)
    g = lambda a: measure(make(a)) - target
    k = 0
    while g(lo) > 0 and k < 60:
        lo *= 0.5
        k += 1
    k = 0
    while g(hi) < 0 and k < 60:
        hi *= 2.0
        k += 1
    if g(lo) > 0 or g(hi) < 0:
        raise _Retry("effect size not reachable")
    return optimize.brentq(g, lo, hi, xtol=1e-12 * hi, rtol=1e-10, maxiter=200)


def _foh_lag(u, t, tau, y0=None):
    """Exact first-order lag tau*y' + y = u for u piecewise linear in t (first-order hold)."""
    u = np.asarray(u, float)
    y = np.empty_like(u)
    y[0] = u[0] if y0 is None else y0
    dt = np.diff(t)
    a = np.exp(-dt / tau)
    c = 1.0 - tau / dt * (1.0 - a)
    for k in range(1, len(u)):
        y[k] = a[k - 1] * y[k - 1] + (1 - a[k - 1]) * u[k - 1] + (u[k] - u[k - 1]) * c[k - 1]
    return y


def _noise(rng, n, kind):
    """Unit-RMS noise shape: white or AR(1) (phi in [0.3,0.8]), optionally 0.5 % gross outliers."""
    desc = []
    if "ar1" in kind:
        phi = rng.uniform(0.3, 0.8)
        e = rng.standard_normal(n + 300)
        x = signal.lfilter([1.0], [1.0, -phi], e)[300:]
        desc.append(f"AR(1) phi={phi:.2f}")
    else:
        x = rng.standard_normal(n)
        desc.append("white Gaussian")
    x = x / _rms(x)
    if "outl" in kind:
        m = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, m, replace=False)
        x[idx] += rng.choice([-1.0, 1.0], m) * rng.uniform(8, 15, m)
        desc.append(f"{m} outliers at 8-15x")
    return x / _rms(x), ", ".join(desc)


def _pick_noise(rng, allow_outliers=True):
    r = rng.uniform()
    if r < 0.42:
        return "white"
    if r < 0.84:
        return "ar1"
    return ("white+outl" if rng.uniform() < 0.5 else "ar1+outl") if allow_outliers else "ar1"


def _repeat_map(rng, n, frac):
    """Index map that makes the logger repeat the previous row at a few places (stale samples)."""
    idx = np.arange(n)
    m = max(1, int(round(frac * n)))
    where = rng.choice(np.arange(2, n - 1), m, replace=False)
    idx[where] = idx[where - 1]
    return idx


# ==============================================================================================
# TORSION
# ==============================================================================================
def _twist_cat(T, m, s, table=False):
    """Catalog three-segment curve (odd in T) divided by the stiffness scale s.
    table=False: continuous reading theta1 = T1/K1, theta2 = theta1 + (T2-T1)/K2 (used for the truth);
    table=True: the printed theta1/theta2 (only used to bound the noise floor)."""
    a = np.abs(T)
    T1, K1, K2 = m["T1"], m["K1"], m["K2"]
    th1 = m["th1_tab"] if (table and m.get("th1_tab")) else T1 / K1
    out = np.where(a <= T1, a / K1, th1 + (a - T1) / K2)
    if m.get("T2") is not None:
        th2 = m["th2_tab"] if (table and m.get("th2_tab")) else th1 + (m["T2"] - T1) / K2
        out = np.where(a > m["T2"], th2 + (a - m["T2"]) / m["K3"], out)
    return np.sign(T) * out / s


def _k_max(m):
    return max(v for v in (m["K1"], m["K2"], m.get("K3")) if v)


# ---- protocols ------------------------------------------------------------------------------
def _prot_torsion(rng, key, T0, n):
    if key == "sine-swept":  # growing-amplitude sine, last cycles at full +-T0
        nc = int(rng.integers(3, 5))
        P = rng.uniform(60, 240)
        t = np.linspace(0, nc * P, n)
        e0 = rng.uniform(0.25, 0.5)
        env = np.minimum(e0 + (1 - e0) * t / (0.55 * nc * P), 1.0)
        return t, T0 * env * np.sin(2 * np.pi * t / P), P, "sine with swept amplitude"
    if key == "sine":  # constant amplitude sine, 2-3 cycles
        nc = int(rng.integers(2, 4))
        P = rng.uniform(60, 240)
        t = np.linspace(0, nc * P, n)
        return t, T0 * np.sin(2 * np.pi * t / P), P, "constant-amplitude sine +-T0"
    if key in ("random-amplitude", "two-rate"):
        if key == "random-amplitude":
            k = int(rng.integers(4, 8))
            amps = rng.uniform(0.15, 0.95, k)
            peaks = [1.0, -1.0] + [a * (1 if i % 2 == 0 else -1) for i, a in enumerate(amps)]
            peaks += [1.0, -1.0, 0.0] if peaks[-1] < 0 else [-1.0, 1.0, 0.0]
            rates = np.ones(len(peaks))
            desc = "reversals at random amplitudes (0.15-0.95 T0) between full +-T0 loops"
        else:
            peaks = [1.0, -1.0, 1.0, -1.0, 1.0, -1.0, 0.0]
            f2 = rng.uniform(2.5, 4.0)
            rates = np.array([1, 1, 1, f2, f2, f2, f2], float)
            desc = f"triangular +-T0, last cycles {f2:.1f}x faster"
        P = rng.uniform(60, 240)
        r = 4 * T0 / P
        pts = np.array([0.0] + peaks) * T0
        durs = np.abs(np.diff(pts)) / (r * rates)
        tk = np.concatenate([[0], np.cumsum(durs)])
        t = np.linspace(0, tk[-1], n)
        return t, np.interp(t, tk, pts), P, desc
    raise KeyError(key)


# ---- gear effects ---------------------------------------------------------------------------
def _h_zener(t, T, tau):
    """Standard linear solid: delayed compliance c*T reached through tau; catalog = relaxed curve.
    Returns the contribution per unit delayed compliance (rad per N m)."""
    return _foh_lag(T, t, tau, y0=T[0]) - T


def _play_var(T, r):
    p = np.empty_like(T)
    p[0] = T[0]
    for k in range(1, len(T)):
        p[k] = min(max(p[k - 1], T[k] - r[k]), T[k] + r[k])
    return p


def _menegotto_pinto(x, hy, E0, R0, cR1=0.925, cR2=0.15):
    """Giuffre-Menegotto-Pinto reversal curves (b = 0), Filippou's R update; y in [-hy, hy]."""
    n = len(x)
    y = np.zeros(n)
    d = 1.0
    for k in range(1, n):
        if x[k] != x[0]:
            d = 1.0 if x[k] > x[0] else -1.0
            break
    xr, yr = x[0], 0.0
    x0 = xr + (d * hy - yr) / E0
    R = R0
    xy = hy / E0
    for k in range(1, n):
        dx = x[k] - x[k - 1]
        if dx * d < 0:
            xi = max(0.0, d * (x[k - 1] - x0)) / xy
            xr, yr = x[k - 1], y[k - 1]
            d = -d
            x0 = xr + (d * hy - yr) / E0
            R = R0 * (1 - cR1 * xi / (cR2 + xi))
        if dx == 0:
            y[k] = y[k - 1]
            continue
        xs = max((x[k] - xr) / (x0 - xr), 0.0)
        y[k] = yr + (d * hy - yr) * xs / (1 + xs ** R) ** (1 / R)
    return y


def _center_loop(c, T, T0):
    """Remove the best odd-quintic function of T from a loop contribution, so the loop is drawn about
    the catalog curve (the hysteresis changes no mean stiffness; that is the stiffness-scale nuisance)."""
    x = T / T0
    B = np.column_stack([x, x ** 3, x ** 5])
    coef, *_ = np.linalg.lstsq(B, c, rcond=None)
    return c - B @ coef


def _zero_cross_width(c, T):
    """Loop width at zero torque: mean contribution on falling minus rising zero crossings."""
    up, dn = [], []
    for k in range(1, len(T)):
        if T[k - 1] < 0 <= T[k] or T[k - 1] > 0 >= T[k]:
            if T[k] == T[k - 1]:
                continue
            w = -T[k - 1] / (T[k] - T[k - 1])
            v = c[k - 1] + w * (c[k] - c[k - 1])
            (up if T[k] > T[k - 1] else dn).append(v)
    if not up or not dn:
        return 0.0
    return float(np.mean(dn) - np.mean(up))


def _torsion_effect(rng, name, form, t, T, m, s, T0, P):
    """Returns (make(amp) -> contribution, amp_phys, description)."""
    Ksec = T0 / _twist_cat(np.array([T0]), m, s)[0]
    HL = m.get("hyst") or 2.9e-4
    if name == "hysteresis":
        target_w = HL * rng.uniform(0.5, 1.4)  # loss B-B' about the catalog value
        if form == "zener":
            tau = P / (2 * np.pi) * math.exp(rng.uniform(math.log(0.3), math.log(3.0)))
            base = _center_loop(_h_zener(t, T, tau), T, T0)
            w1 = abs(_zero_cross_width(base, T)) or _rms(base)
            return (lambda a: a * base), target_w / w1, f"standard-linear-solid (Zener) creep, tau={tau:.0f}s"
        if form == "flank":
            rho = rng.uniform(1.0, 4.0)  # mu*T0 / r0
            def make(a):
                r = a + (rho * a / T0) * np.abs(T)
                return _center_loop(_twist_cat(_play_var(T, r), m, s) - _twist_cat(T, m, s), T, T0)
            r0 = target_w * m["K1"] * s / 2
            return make, r0, f"flank-friction play, threshold r0+mu|T| (mu*T0/r0={rho:.1f})"
        if form == "mp":
            fy = rng.uniform(0.15, 0.45)  # yield span of the reversal curve, fraction of T0
            xy = fy * T0
            R0 = rng.uniform(6, 20)
            make = lambda a: -_center_loop(_menegotto_pinto(T, a, a / xy, R0), T, T0)
            kloc = 1.0 / (_twist_cat(np.array([T0 * 1.0001]), m, s)[0] - _twist_cat(np.array([T0]), m, s)[0]) * T0 * 1e-4
            make.check = lambda a: (a / xy) * kloc < 0.85  # twist must keep rising after a reversal
            return make, target_w / 2, f"Menegotto-Pinto reversal curves (R0={R0:.0f}, yield span {fy:.2f} T0)"
    if name == "backlash":
        b_cat = m.get("backlash") or rng.uniform(3e-5, 8e-5)
        b = b_cat * rng.uniform(1.0, 3.0)
        if form == "ramp":
            gfrac = rng.uniform(0.4, 0.8)
            Tg = rng.uniform(0.002, 0.01) * T0
            Te = rng.uniform(0.05, 0.2) * T0
            a_ = np.abs(T)
            shape = gfrac * np.minimum(a_ / Tg, 1) + (1 - gfrac) * (1 - (1 - np.minimum(a_ / Te, 1)) ** 3)
            shape = np.sign(T) * shape
            return (lambda a: a / 2 * shape), b, \
                f"Oldham gap + edge-to-face engagement ramp (gap {gfrac:.0%}, ramp to {Te / T0:.2f} T0)"
        if form == "traverse":
            fc = rng.uniform(0.02, 0.08)
            rate = max(np.percentile(np.abs(np.gradient(T, t)), 75), 1e-9)
            def make(a):
                cv = (fc * T0) ** 2 / (2 * a * rate)
                z = np.zeros_like(T)
                dt = np.diff(t)
                for k in range(1, len(T)):
                    z[k] = min(max(z[k - 1] + 0.5 * (T[k] + T[k - 1]) * dt[k - 1] / cv, -a / 2), a / 2)
                return z
            return make, b, f"viscously damped gap traverse (closes at ~{fc:.2f} T0)"
    if name == "housing_compliance":
        u = rng.uniform(0.15, 0.35)
        if form == "bredt":
            return (lambda a: a * T), u / Ksec, f"thin-walled housing tube (Bredt), {u:.0%} of gear compliance"
        if form == "spline":
            q = rng.uniform(0.2, 0.5)
            shape = (1 - q) * T + q * np.sign(T) * np.abs(T) ** 0.9 * T0 ** 0.1
            return (lambda a: a * shape), u / Ksec, \
                f"shaft + spline line contact (Lundberg d~F^0.9, {q:.0%}), {u:.0%} of gear compliance"
    raise KeyError((name, form))


# ---- measurement decoys ---------------------------------------------------------------------
def _torsion_decoy(rng, form, t, T, m, s, T0, P):
    """Returns (make(amp) -> (T_meas, theta_meas) noiseless, amp_phys, meas_effects, equiv, desc)."""
    th = _twist_cat(T, m, s)
    Ksec = T0 / _twist_cat(np.array([T0]), m, s)[0]
    if form == "torque-offset":
        return (lambda a: (T + a, th)), rng.uniform(0.01, 0.04) * T0, ("torque_offset",), (), \
            "torque-sensor zero offset"
    if form == "interp":
        nl = rng.integers(9000, 36000)
        p = 2 * np.pi / nl
        ph = rng.uniform(0, 2 * np.pi)
        return (lambda a: (T, th + a * np.sin(2 * np.pi * th / p + ph))), p * rng.uniform(0.01, 0.04), \
            ("encoder_interpolation_error",), (), f"twist-encoder interpolation error ({nl} lines/rev)"
    if form == "hvac":
        dur = t[-1]
        Ph = dur * rng.uniform(1.5, 4.0)
        ph = rng.uniform(0, 2 * np.pi)
        drift = np.sin(2 * np.pi * t / Ph + ph) - np.sin(ph)
        return (lambda a: (T, th + a * drift)), rng.uniform(2e-6, 1e-5), ("thermal_drift",), (), \
            f"fixture temperature (HVAC) cycle, period {Ph / 60:.0f} min"
    if form == "crosstalk":
        u = rng.uniform(0.15, 0.3)
        return (lambda a: (T, th + a * T)), u / Ksec, ("channel_crosstalk",), ("housing_compliance",), \
            f"torque->angle channel crosstalk ({u:.0%} of gear compliance)"
    if form == "aa-lag":
        tau0 = P / (2 * np.pi) * rng.uniform(0.01, 0.04)
        return (lambda a: (T, _foh_lag(th, t, a, y0=th[0]))), tau0, ("filter_lag",), ("hysteresis",), \
            "anti-alias filter lag in the twist channel (first order)"
    if form == "sensor-hyst":
        ef = rng.uniform(0.3, 0.7)
        R0 = rng.uniform(4, 12)
        # torque-sensor flexure hysteresis: loop of measured torque vs true torque
        make = lambda a: (T - _center_loop(_menegotto_pinto(T, a, ef, R0), T, T0), th)
        return make, T0 * rng.uniform(0.003, 0.01), ("sensor_hysteresis",), ("hysteresis",), \
            "torque-transducer hysteresis (Menegotto-Pinto loop in the torque channel)"
    raise KeyError(form)


def _torsion_models(cat):
    pool = [dict(m) for m in cat.gh]
    cs = cat.cs.get("CSF-25-100-2A-GR")
    return pool, cs


def _gen_torsion(rng, cat, cell, idx):
    pool, cs = _torsion_models(cat)
    if cs is not None and rng.uniform() < 0.15:
        m = dict(cs)
        T0 = rng.uniform(28, 45)
        m["hyst"], m["backlash"] = None, None
    else:
        m = pool[rng.integers(len(pool))]
        T0 = m["rated"] * rng.uniform(0.7, 1.0)
    s = 1 + float(np.clip(rng.normal(0, 0.035), -0.07, 0.07))
    n = int(rng.integers(400, 3001))
    prot = cell["protocol"] if "protocol" in cell else \
        rng.choice(["sine-swept", "random-amplitude", "two-rate", "sine"])
    t, T, P, pdesc = _prot_torsion(rng, prot, T0, n)
    th0 = _twist_cat(T, m, s)
    # noise floor: disagreement between the continuous and the printed-theta reading of the curve
    disc = _rms(_twist_cat(T, m, s, table=True) - th0)
    floor = max(0.6 * disc, 2e-4 * np.max(np.abs(th0)), 1e-6)
    nkind = cell.get("noise") or _pick_noise(rng)
    shape, ndesc = _noise(rng, n, nkind)
    cat_ = cell["category"]
    ks = []
    gear, meas, equiv = (), (), ()
    descs = [pdesc]
    Tm, thm = T.copy(), th0.copy()
    contrib = np.zeros(n)
    if cat_ == "clean":
        sigma = max(rng.uniform(0.003, 0.015) * np.max(np.abs(th0)), floor)
    elif cat_ in ("single", "pair"):
        effs = list(cell["effects"])
        forms = list(cell["forms"])
        if "housing_compliance" in effs:  # housing sets the scale (must exceed the stiffness spread)
            j = effs.index("housing_compliance")
            effs.insert(0, effs.pop(j))
            forms.insert(0, forms.pop(j))
        sigma = None
        for e, f in zip(effs, forms):
            make, a0, d = _torsion_effect(rng, e, f, t, T, m, s, T0, P)
            k = rng.uniform(4, 12)
            if sigma is None:
                sigma = max(_rms(make(a0)) / k, floor)
            a = _solve_amp(make, _rms, k * sigma, a0)
            if hasattr(make, "check") and not make.check(a):
                raise _Retry("hysteresis loop too wide for a monotone twist curve")
            contrib = contrib + make(a)
            ks.append(k)
            descs.append(d)
        thm = th0 + contrib
        gear = tuple(cell["effects"])
    else:
        make, a0, meas, equiv, d = _torsion_decoy(rng, cell["forms"][0], t, T, m, s, T0, P)
        disc_of = lambda tt: _rms(tt[1] - _twist_cat(tt[0], m, s))
        k = rng.uniform(4, 12)
        sigma = max(disc_of(make(a0)) / k, floor)
        a = _solve_amp(make, disc_of, k * sigma, a0)
        Tm, thm = make(a)
        contrib = thm - _twist_cat(Tm, m, s)
        descs.append(d)
    idx_map = np.arange(n)
    if cell.get("repeat"):
        idx_map = _repeat_map(rng, n, 0.004)
        descs.append("stale repeated samples")
    noise = shape[idx_map]
    noise = noise / _rms(noise) * sigma
    cols = {"torque_Nm": Tm[idx_map], "twist_rad": thm[idx_map] + noise, "time_s": t[idx_map]}
    descs.append(ndesc)
    snr = _rms(contrib[idx_map]) / sigma if cat_ != "clean" else 0.0
    descs.insert(0, f"T0={T0:.4g} N m")
    return cols, m["code"], dict(stiffness_scale=s), gear, meas, equiv, sigma, "; ".join(descs), snr, None


# ==============================================================================================
# TRANSMISSION
# ==============================================================================================
def _te_shape(rng, name, form, phi, phis, rng_R=100):
    """Unit-amplitude TE shapes as functions of the (true) input angle."""
    b = rng.uniform(0, 2 * np.pi)
    if name == "te_1x":
        if form == "eccentric":
            eps = rng.uniform(0.02, 0.06)
            psi = phi + b
            return np.arctan2(eps * np.sin(psi), 1 + eps * np.cos(psi)) / eps, \
                f"te_1x: eccentric WG plug, exact kinematics (e/r={eps:.3f})"
        if form == "vonmises":
            kap = rng.uniform(0.8, 1.6)
            psi = phi + b
            g = np.exp(kap * np.cos(psi)) - np.exp(kap * np.cos(psi + np.pi))
            return g / (4 * special.iv(1, kap)), f"te_1x: unequal two-lobe engagement, von Mises depth (kappa={kap:.2f})"
        if form == "toothstep":
            R = float(rng_R)
            zc = int(round(2 * R + 2))  # circular-spline teeth for a 2-tooth difference
            knots = np.arange(np.floor(phi.min() * zc / (2 * np.pi)) - 1, np.ceil(phi.max() * zc / (2 * np.pi)) + 2)
            pk = knots * 2 * np.pi / zc
            return np.interp(phi, pk, np.sin(pk + b)), f"te_1x: eccentricity sampled tooth by tooth (z_c={zc}, first-order hold)"
    if name == "te_2x":
        if form == "ballpass":
            nb = int(rng.integers(12, 25))
            dD = rng.uniform(0.08, 0.15)
            q = nb * 0.5 * (1 - dD * math.cos(math.radians(rng.uniform(0, 15))))
            rb = rng.uniform(0.08, 0.2)
            return np.sin(2 * phi + b) + rb * np.sin(q * phi + rng.uniform(0, 2 * np.pi)), \
                f"te_2x: elliptic WG + ball-pass ripple (order {q:.2f}, {rb:.0%})"
        if form == "runin":
            br = rng.uniform(0.3, 0.8)
            mr = rng.uniform(1.0, 3.0)
            return (1 + br * np.exp(-(phi - phis) / (2 * np.pi * mr))) * np.sin(2 * phi + b), \
                f"te_2x: run-in amplitude decay (+{br:.0%}, {mr:.1f} rev)"
    raise KeyError((name, form))


def _trans_models(cat):
    return list(cat.gh), list(cat.cs.values()), list(cat.fd)


def _pick_trans_model(rng, cat):
    gh, cs, fd = _trans_models(cat)
    r = rng.uniform()
    if r < 0.5:
        return gh[rng.integers(len(gh))]
    if r < 0.7:
        return cs[rng.integers(len(cs))]
    return fd[rng.integers(len(fd))]


def _gen_transmission(rng, cat, cell, idx):
    m = _pick_trans_model(rng, cat)
    R = float(m["ratio"])
    nrev = rng.uniform(2.5, 12)
    extra = 0
    need = 50 * nrev
    if cell["category"] == "decoy_separable" and cell["forms"][0] == "interp":
        nl_order = rng.uniform(8.3, 29.7)
        need = 7 * nl_order * nrev
    n = int(max(rng.integers(400, 3001), need))
    phis = rng.uniform(0, 2 * np.pi)
    phi = phis + np.linspace(0, 2 * np.pi * nrev, n)
    descs = [f"{nrev:.1f} WG revolutions"]
    if cell.get("nonuniform"):
        step = 2 * np.pi * nrev / (n - 1)
        phi = phi + rng.uniform(-0.4, 0.4, n) * step
        phi[0], phi = phis, np.sort(phi)
        descs.append("non-uniform sampling (speed jitter)")
    c0 = rng.uniform(-0.5, 0.5)
    out0 = phi / R + c0
    acc = m.get("accuracy") or 2.9e-4
    nkind = cell.get("noise") or _pick_noise(rng)
    shape, ndesc = _noise(rng, n, nkind)
    cat_ = cell["category"]
    phim, out = phi.copy(), out0.copy()
    contrib = np.zeros(n)
    gear, meas, equiv = (), (), ()
    floor = 4e-7  # ~0.08 arc-sec: a very good output encoder
    if cat_ == "clean":
        sigma = max(acc * rng.uniform(0.005, 0.04), floor)
    elif cat_ in ("single", "pair"):
        sigma = None
        for e, f in zip(cell["effects"], cell["forms"]):
            sh, d = _te_shape(rng, e, f, phi, phis, R)
            k = rng.uniform(4, 12)
            if sigma is None:
                sigma = max(acc * rng.uniform(0.1, 0.4) * _std(sh) / k, floor)
            contrib = contrib + sh * (k * sigma / _std(sh))
            descs.append(d)
        out = out0 + contrib
        gear = tuple(cell["effects"])
    else:
        form = cell["forms"][0]
        b = rng.uniform(0, 2 * np.pi)
        psi_out = phi / R
        if form == "interp":
            nl = nl_order * R
            sh = np.sin(nl * psi_out + b)
            a_phys, meas = 2 * np.pi / nl * rng.uniform(0.01, 0.03), ("encoder_interpolation_error",)
            descs.append(f"output-encoder interpolation error ({nl:.0f} periods/rev)")
            kind_ = "out"
        elif form == "hvac":
            Ph = rng.uniform(1.5, 4.0)
            sh = np.sin(2 * np.pi * (phi - phis) / (2 * np.pi * nrev * Ph) + b) - np.sin(b)
            a_phys, meas, kind_ = rng.uniform(3e-6, 2e-5), ("thermal_drift",), "out"
            descs.append(f"HVAC thermal drift of the output angle (period {Ph:.1f} records)")
        elif form == "linecount":
            sh = phi - phis
            a_phys, meas, kind_ = rng.uniform(2e-5, 2e-4), ("sensor_gain",), "in"
            descs.append("input-encoder line-count (scale) error")
        elif form == "out-ecc":
            r2 = rng.uniform(0.1, 0.3)
            sh = np.sin(psi_out + b) + r2 * np.sin(2 * psi_out + rng.uniform(0, 2 * np.pi))
            a_phys, meas, kind_ = rng.uniform(1e-5, 6e-5), ("encoder_eccentricity",), "out"
            descs.append("eccentric + tilted output encoder disc (1x, 2x per output rev)")
        elif form == "stator-runout":
            sh = np.sin(phi + b)
            a_phys, meas, kind_ = R * acc * rng.uniform(0.1, 0.3), ("input_encoder_runout",), "in"
            equiv = ("te_1x",)
            descs.append("input-encoder stator-mount runout (1x per input rev)")
        elif form == "disc-tilt":
            sh = np.sin(2 * phi + b)
            a_phys, meas, kind_ = R * acc * rng.uniform(0.1, 0.3), ("input_encoder_tilt",), "in"
            equiv = ("te_2x",)
            descs.append("input-encoder disc tilt (2x per input rev)")
        else:
            raise KeyError(form)
        k = rng.uniform(4, 12)
        scale = 1.0 / R if kind_ == "in" else 1.0
        sigma = max(a_phys * scale * _std(sh) / k, floor)
        amp = k * sigma / (scale * _std(sh))
        if kind_ == "in":
            phim = phi + amp * sh
        else:
            out = out0 + amp * sh
        contrib = out - (phim / R + c0)
    idx_map = np.arange(n)
    if cell.get("repeat"):
        idx_map = _repeat_map(rng, n, 0.004)
        descs.append("stale repeated samples")
    noise = shape[idx_map]
    noise = noise / _rms(noise) * sigma
    cols = {"input_angle_rad": phim[idx_map], "output_angle_rad": out[idx_map] + noise}
    descs.append(ndesc)
    snr = _std(contrib[idx_map]) / sigma if cat_ != "clean" else 0.0
    return cols, m["code"], dict(offset_rad=float(c0)), gear, meas, equiv, sigma, "; ".join(descs), snr, None


# ==============================================================================================
# EFFICIENCY
# ==============================================================================================
def _doolittle(rng):
    """Doolittle free-volume viscosity ratio nu(theta)/nu(20 C); nu(20)/nu(40) drawn in [2.2, 4]."""
    f20 = rng.uniform(0.08, 0.12)
    r = rng.uniform(2.2, 4.0)
    af = (1.0 / (1.0 / f20 - math.log(r)) - f20) / 20.0
    return (lambda th: np.exp(1.0 / (f20 + af * (np.asarray(th) - 20.0)) - 1.0 / f20)), \
        f"Doolittle free volume (f20={f20:.3f}, nu20/nu40={r:.1f})"


def _eff_models(cat):
    gh = [m for m in cat.gh]
    cs = [m for m in cat.cs.values() if m.get("rated")]
    return gh, cs, list(cat.fd)


def _eff_grid(rng, m, ntemps, warmup=False):
    fam = m["family"]
    if fam == "FD":
        lub_oil = rng.uniform() < 0.6
        nmax = m["nmax_oil"] if lub_oil else m["nmax_grease"]
        speeds_all = [s for s in (500, 750, 960, 1150, 1450, 1750, 2850, 3500) if s <= nmax]
    else:
        nmax = m.get("navg") or m.get("nmax") or 3500
        speeds_all = [s for s in (500, 1000, 1500, 2000, 2500, 3000, 3500) if s <= nmax]
    k = int(min(len(speeds_all), rng.integers(3, 6) if ntemps == 1 else rng.integers(2, 6)))
    speeds = sorted(rng.choice(speeds_all, k, replace=False).tolist())
    alph_all = [0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]
    ka = int(rng.integers(7, 11) if ntemps == 1 else rng.integers(5, 10))
    al = set(rng.choice(alph_all, ka, replace=False).tolist()) | {1.0, float(rng.choice([0.1, 0.15, 0.2]))}
    alphas = sorted(al)
    if warmup:
        combos = [(n_, a_) for n_ in speeds for a_ in alphas]
        reps = int(rng.integers(2, 4))
        seq = []
        for _ in range(reps):
            seq += [combos[i] for i in rng.permutation(len(combos))]
        nr = len(seq)
        dt = rng.uniform(60, 180)
        tt = np.arange(nr) * dt
        tamb = rng.uniform(12, 25)
        dT = rng.uniform(30, 50)
        tau = tt[-1] * rng.uniform(0.25, 0.5)
        temp = tamb + dT * (1 - np.exp(-tt / tau))
        n = np.array([c[0] for c in seq], float)
        a = np.array([c[1] for c in seq], float)
        return n, a, np.round(temp, 1), "warm-up sequence (temperature rising along the test)"
    temps_all = [0, 10, 20, 30, 40, 50, 60, 70]
    if ntemps == 1:
        temps = [float(rng.choice([20, 25, 40]))]
    else:
        lo = int(rng.integers(0, 3))
        temps = temps_all[lo: lo + ntemps + int(rng.integers(0, 2))]
    rows = []
    for th in temps:  # the oven temperature is the slow variable: one block per temperature
        blk = [(n_, a_, th) for n_ in speeds for a_ in alphas]
        rows += [blk[i] for i in rng.permutation(len(blk))]
    rows = np.array(rows, float)
    desc = f"grid {len(speeds)} speeds x {len(alphas)} loads x {len(temps)} temperatures"
    if len(rows) < 40:  # small grid: every point measured twice (second pass in a new random order)
        rows = np.concatenate([rows, rows[rng.permutation(len(rows))]])
        rows = rows[np.argsort(rows[:, 2], kind="stable")]
        desc += ", each point measured twice"
    if rng.uniform() < 0.45 and len(rows) >= 60:
        keep = rng.uniform(0.5, 0.8)
        sel = np.sort(rng.choice(len(rows), max(12, int(keep * len(rows))), replace=False))
        rows = rows[sel]
        desc += f", sparse ({keep:.0%} kept)"
    return rows[:, 0], rows[:, 1], rows[:, 2], desc


def _eff_factor(rng, effs, form, n, a, th):
    """Multiplicative efficiency factor F(alpha, n, theta) (any constant is absorbed by the level).
    Returns make(amp)->F and the physical amplitude, plus (make_alpha_only, make_temp_only) for pairs."""
    nref = 1000.0
    if form == "fs-bending":  # load-independent no-load loss ~ speed^gamma
        g = rng.uniform(0.2, 0.6)
        p0 = lambda A: A * (n / nref) ** g
        return (lambda A: (1 + p0(A)) * a / (a + p0(A))), rng.uniform(0.06, 0.2), \
            f"flexspline bending + churning no-load loss p0~n^{g:.2f}", None
    if form == "stribeck":
        Hs = rng.uniform(0.3, 0.8)
        mh = rng.uniform(0.25, 0.5)
        mu = lambda H: np.exp(-H / Hs) + mh * np.sqrt(H)
        H = (n / nref) / np.sqrt(a)
        H1 = 1.0
        return (lambda A: (1 - np.minimum(A * mu(H) / mu(H1), 0.6))), rng.uniform(0.05, 0.12), \
            f"Stribeck mu(Hersey) = boundary exp(-H/Hs) + film m*sqrt(H), Hs={Hs:.2f}", None
    if form == "skf":
        ms, mr, ml = rng.uniform(0.01, 0.05), rng.uniform(0.02, 0.08), rng.uniform(0.003, 0.015)
        def F(A):
            r = A * (ms + mr * a ** 0.54 * (n / nref) ** 0.6 + ml * a ** (5 / 3)) / a
            return 1.0 / (1.0 + r)
        return F, 1.0, "SKF four-component WG-bearing loss (Grr~F^0.54 (nu n)^0.6, Gsl~F^5/3, seal)", None
    if form == "gw-ehl":  # Greenwood-Williamson asperity share of an EHL line contact
        lam_ref = rng.uniform(0.6, 1.5)
        lam = lam_ref * (n / nref) ** 0.7 * a ** (-0.13)  # Dowson-Higginson: h ~ U^0.7 W^-0.13
        sg = np.linspace(-6, 8, 1401)
        phi_s = np.exp(-0.5 * sg ** 2) / math.sqrt(2 * math.pi)
        F32 = lambda h: np.trapezoid(np.clip(sg[None, :] - np.asarray(h)[:, None], 0, None) ** 1.5 * phi_s, sg, axis=1)
        fa = F32(lam) / F32(np.array([0.0]))[0]
        mub, muf0 = rng.uniform(0.08, 0.12), rng.uniform(0.02, 0.04)
        muf = muf0 * np.sqrt(n / nref) / np.sqrt(a)  # film shear stress ~ const, Hertz pressure ~ sqrt(W)
        mu = fa * mub + (1 - fa) * muf
        return (lambda A: 1 - np.minimum(A * mu, 0.7)), rng.uniform(0.8, 1.6), \
            f"Greenwood-Williamson asperity share (Lambda_ref={lam_ref:.2f}) + EHL film shear", None
    if form == "doolittle":
        nu, d = _doolittle(rng)
        mexp = rng.uniform(0.3, 0.6)
        return (lambda A: 1 - np.minimum(A * nu(th) ** mexp, 0.8)), rng.uniform(0.05, 0.15), \
            f"churning loss ~ nu^{mexp:.2f}, {d}", None
    if form == "channel":
        tch = rng.uniform(np.min(th) + 0.25 * np.ptp(th), np.max(th) - 0.25 * np.ptp(th))
        w = rng.uniform(3, 8)
        S = 1.0 / (1.0 + np.exp((th - tch) / w))
        return (lambda A: 1 - A * S), rng.uniform(0.05, 0.15), \
            f"grease channelling, logistic at {tch:.0f} C (w={w:.1f} K)", None
    if form == "warmup-film":
        nu, d = _doolittle(rng)
        lam = rng.uniform(2.0, 4.0)
        av, ab = rng.uniform(0.5, 1.0), rng.uniform(0.5, 1.0)
        shp = av * 0.1 * nu(th) ** 0.5 + ab * 0.1 * np.exp(-lam * nu(th) ** 0.7)
        return (lambda A: 1 - np.minimum(A * shp, 0.8)), rng.uniform(0.6, 1.2), \
            f"viscous churning + film-thinning boundary loss (h~nu^0.7), {d}", None
    # ---- coupled pairs: make(A, B); A scales the loss, B the temperature coupling ----
    if form == "stribeck-doolittle":
        nu, d = _doolittle(rng)
        Hs, mh = rng.uniform(0.3, 0.8), rng.uniform(0.25, 0.5)
        mu = lambda H: np.exp(-H / Hs) + mh * np.sqrt(H)
        mk = lambda A, B, aa, tt: 1 - np.minimum(A * mu(nu(tt) ** B * (n / nref) / np.sqrt(aa)) / mu(1.0), 0.6)
        desc = f"Stribeck mu(Hersey eta*n/p) with {d}"
        A0 = rng.uniform(0.03, 0.07)
    elif form == "fs-channel":
        g = rng.uniform(0.2, 0.6)
        tch = rng.uniform(np.min(th) + 0.25 * np.ptp(th), np.max(th) - 0.25 * np.ptp(th))
        w = rng.uniform(3, 8)
        cg = rng.uniform(0.8, 2.0)
        def mk(A, B, aa, tt):
            S = 1.0 / (1.0 + np.exp((tt - tch) / w))
            p0 = A * (n / nref) ** g * (1 + B * cg * S)
            return aa / (aa + p0)
        desc = f"no-load loss p0~n^{g:.2f} raised below grease channelling ({tch:.0f} C, w={w:.1f} K)"
        A0 = rng.uniform(0.05, 0.14)
    elif form == "skf-doolittle":
        nu, d = _doolittle(rng)
        ms, mr, ml = rng.uniform(0.01, 0.05), rng.uniform(0.04, 0.1), rng.uniform(0.003, 0.015)
        def mk(A, B, aa, tt):
            r = A * (ms + mr * aa ** 0.54 * (nu(tt) ** B * n / nref) ** 0.6 + ml * aa ** (5 / 3)) / aa
            return 1.0 / (1.0 + r)
        desc = f"SKF four-component loss with {d}"
        A0 = 1.0
    else:
        raise KeyError(form)
    tref = (20.0 if form != "fs-channel" else float(np.max(th))) + 0 * th
    one = 1.0 + 0 * a
    return (lambda A, B: mk(A, B, a, th)), A0, desc, \
        (lambda A, B: mk(A, B, a, tref), lambda A, B: mk(A, B, one, th))
    raise KeyError(form)


def _gen_efficiency(rng, cat, cell, idx):
    gh, cs, fd = _eff_models(cat)
    r = rng.uniform()
    if r < 0.5:
        m = gh[rng.integers(len(gh))]
    elif r < 0.65:
        m = cs[rng.integers(len(cs))]
    else:
        m = fd[rng.integers(len(fd))]
    cat_ = cell["category"]
    effs = tuple(cell.get("effects", ()))
    form = cell["forms"][0]
    warm = form == "warmup-film" or cell.get("warmup")
    if cat_ == "decoy_equivalent" and form == "rig-bearing":
        ntemps = int(rng.integers(3, 6))
    elif cat_ == "single" and effs == ("low_load_efficiency",):
        ntemps = 1 if rng.uniform() < 0.5 else int(rng.integers(2, 4))
    else:
        ntemps = int(rng.integers(3, 6))
    n, a, th, gdesc = _eff_grid(rng, m, ntemps, warmup=warm)
    if m["family"] == "FD":
        Tr = np.array([cat.fd_rated_at(m, v) for v in n])
        L = rng.uniform(70, 88)
    elif m.get("eta"):
        Tr = np.full(len(n), m["rated"])
        L = m["eta"] * rng.uniform(0.96, 1.04)
    else:
        Tr = np.full(len(n), m["rated"])
        L = rng.uniform(62, 85)
    load = a * Tr
    descs = [gdesc]
    nkind = cell.get("noise") or _pick_noise(rng)
    N = len(n)
    shape, ndesc = _noise(rng, N, nkind)
    gear, meas, equiv = (), (), ()
    eta0 = np.full(N, L)
    eta = eta0.copy()
    floor = 0.15  # percentage points: realistic repeatability of an efficiency rig
    if cat_ == "clean":
        sigma = rng.uniform(0.1, 0.6)
    elif cat_ in ("single", "pair"):
        make, A0, d, parts = _eff_factor(rng, effs, form, n, a, th)
        descs.append(d)
        k = rng.uniform(4, 12)
        meas_fn = lambda F: _std(L * F / np.max(F))
        if parts is None:
            sigma = max(meas_fn(make(A0)) / k, floor)
            A = _solve_amp(make, meas_fn, k * sigma, A0)
        else:  # coupled pair: load main effect k1*sigma (amplitude A), temperature main effect k2*sigma (B)
            k2 = rng.uniform(4, 12)
            sigma = max(meas_fn(parts[0](A0, 1.0)) / k, floor)
            A, B = A0, 1.0
            for _ in range(3):
                A = _solve_amp(lambda x: parts[0](x, B), meas_fn, k * sigma, A)
                B = _solve_amp(lambda y: parts[1](A, y), meas_fn, k2 * sigma, B)
            if not (0.05 < B < 4.0):
                raise _Retry("temperature coupling out of range")
            d += f"; temperature coupling x{B:.2f}"
            descs[-1] = d
            make_ = make
            make = lambda x: make_(x, B)
        F = make(A)
        F = F / np.max(F)
        eta = L * F
        gear = effs
    else:
        k = rng.uniform(4, 12)
        if form == "block-drift":  # sensor warm-up drift after re-zeroing at each temperature block
            tau = rng.uniform(3, 8)
            pos = np.zeros(N)
            blk = np.concatenate([[0], np.flatnonzero(np.diff(th)) + 1, [N]])
            for i0, i1 in zip(blk[:-1], blk[1:]):
                pos[i0:i1] = np.arange(i1 - i0)
            sh = 1 - np.exp(-pos / tau)
            meas = ("thermal_drift",)
            a_phys = rng.uniform(0.01, 0.03)
            mk = lambda A: eta0 * (1 - A * sh)
            descs.append("torque-sensor warm-up drift after re-zeroing each temperature block (random load order)")
        elif form == "tach-gain":
            sh = (n - n.mean()) / max(n.mean(), 1)
            meas = ("sensor_gain",)
            a_phys = rng.uniform(0.02, 0.06)
            mk = lambda A: eta0 * (1 + A * sh)
            descs.append("speed-dependent tachogenerator gain error")
        elif form == "input-offset":
            meas, equiv = ("torque_offset",), ("low_load_efficiency",)
            a_phys = rng.uniform(0.02, 0.08)  # q = delta*R*eta/Tr
            mk = lambda A: eta0 / (1 + A / a)
            descs.append("input-torque-sensor zero offset (reads as a load-dependent efficiency)")
        elif form == "rig-bearing":
            nu, d = _doolittle(rng)
            meas, equiv = ("rig_drag",), ("temperature_dependence",)
            a_phys = rng.uniform(0.02, 0.06)
            mk = lambda A: eta0 * (1 - np.minimum(A * nu(th) ** 0.5, 0.7))
            descs.append(f"rig output-bearing drag in the same oven ({d})")
        else:
            raise KeyError(form)
        if np.ptp(mk(a_phys)) == 0:
            raise ValueError("decoy invisible")
        sigma = max(_std(mk(a_phys)) / k, floor)
        A = _solve_amp(mk, _std, k * sigma, a_phys)
        eta = mk(A)
    noise = shape / _rms(shape) * sigma
    cols = {"input_speed_rpm": n, "load_torque_Nm": load, "temperature_C": th, "efficiency_pct": eta + noise}
    descs.append(ndesc)
    snr = _std(eta) / sigma if cat_ != "clean" else 0.0
    return cols, m["code"], dict(efficiency_level_pct=float(L)), gear, meas, equiv, sigma, "; ".join(descs), snr, None


# ==============================================================================================
# VIBRATION
# ==============================================================================================
def _vib_models(cat):
    pool = [m for m in cat.gh]
    cs = cat.cs.get("CSF-25-100-2A-GR")
    return pool, cs


def _speed_profile(rng, key, fn, T, tf):
    lo, hi = 15 * fn * rng.uniform(0.9, 1.1), 78 * fn * rng.uniform(0.95, 1.1)
    if key == "run-up":
        return lo + (hi - lo) * tf / T, f"linear run-up {lo:.0f}->{hi:.0f} r/min"
    if key == "coast-down":
        tau = T / math.log(hi / lo)
        return hi * np.exp(-tf / tau), f"exponential coast-down {hi:.0f}->{lo:.0f} r/min"
    if key == "dwell":
        ns = int(rng.integers(25, 46))
        lev = np.linspace(lo, hi, ns)
        if rng.uniform() < 0.4:
            lev = lev[::-1]
        seg = T / ns
        i = np.minimum((tf / seg).astype(int), ns - 1)
        frac = tf / seg - i
        prev = lev[np.maximum(i - 1, 0)]
        ramp = np.clip(frac / 0.15, 0, 1)
        return prev + (lev[i] - prev) * ramp, f"stepped dwell, {ns} speed levels"
    raise KeyError(key)


def _zener_ss(J, Kt, zeta, wn):
    tau = 1.0 / wn
    K2 = 4 * zeta * Kt
    K0 = Kt * (1 - 2 * zeta)
    A = np.array([[0, 1, 0], [-K0 / J, 0, -1 / J], [0, K2, -1 / tau]])
    B = np.array([[0, 0], [K0 / J, 0], [0, -K2]])
    C = np.array([[1.0, 0, 0]])
    D = np.zeros((1, 2))
    return signal.StateSpace(A, B, C, D)


def _gen_vibration(rng, cat, cell, idx):
    pool, cs = _vib_models(cat)
    if cs is not None and rng.uniform() < 0.15:
        m = dict(cs)
        m["nmax"] = m.get("nmax") or 5000
    else:
        m = pool[rng.integers(len(pool))]
    s = 1 + float(np.clip(rng.normal(0, 0.035), -0.07, 0.07))
    Kt = m["K1"] * s
    nmax = m.get("nmax") or 3500
    fn = rng.uniform(6, min(25, nmax / 85))
    wn = 2 * np.pi * fn
    J = Kt / wn ** 2
    zeta = rng.uniform(0.02, 0.08)
    rows = int(rng.integers(3000, 8001))
    fs = 25 * fn * rng.uniform(0.9, 1.2)
    T = rows / fs
    ts = np.arange(rows) / fs
    form = cell["forms"][0]
    method, prot = cell["method"], cell["protocol"]
    descs = []
    if cell.get("jitter"):
        ts = np.sort(ts + rng.uniform(-0.35, 0.35, rows) / fs)
        ts[0] = max(ts[0], 0.0)
        descs.append("jittered time stamps")
    # fine grid for the integration
    nf = int(T * fn * 90) + 1
    tf = np.linspace(0, max(T, ts[-1]) , nf)
    nrpm_f, pdesc = _speed_profile(rng, prot, fn, tf[-1], tf)
    descs.insert(0, pdesc)
    om_f = 2 * np.pi * nrpm_f / 60.0
    phi_f = np.concatenate([[0], np.cumsum(0.5 * (om_f[1:] + om_f[:-1]) * np.diff(tf))]) + rng.uniform(0, 2 * np.pi)
    R = float(m["ratio"])
    acc = m.get("accuracy") or 2.9e-4
    sys_z = _zener_ss(J, Kt, zeta, wn) if method == "zener" else None
    if method == "frac":
        al = rng.uniform(0.3, 0.7)
        aa = 2 * zeta / (math.sin(al * math.pi / 2) - 2 * zeta * math.cos(al * math.pi / 2))
        Ks = Kt / (1 + aa * math.cos(al * math.pi / 2))
        Kstar = lambda w: Ks * (1 + aa * (1j * w / wn) ** al)
        H = lambda w: Kstar(w) / (Kstar(w) - J * w ** 2)
        mdesc = f"quasi-steady FRF, fractional-derivative (Bagley-Torvik) spring alpha={al:.2f}"
    else:
        mdesc = "Zener (standard linear solid) spring, state space, exact FOH (lsim)"
    descs.insert(0, mdesc)

    def respond(order, amp, b):
        """Load response to a kinematic error amp*sin(order*phi + b) at the gear output."""
        if method == "frac":
            w = order * om_f
            x = np.imag(amp * H(w) * np.exp(1j * (order * phi_f + b)))
        else:
            e = amp * np.sin(order * phi_f + b)
            ed = amp * order * om_f * np.cos(order * phi_f + b)
            _, x, _ = signal.lsim(sys_z, np.column_stack([e, ed]), tf, X0=[e[0], ed[0], 0.0], interp=True)
        return np.interp(ts, tf, x)

    nrpm = np.interp(ts, tf, nrpm_f)
    phis = np.interp(ts, tf, phi_f)
    nkind = cell.get("noise") or _pick_noise(rng)
    shape, ndesc = _noise(rng, rows, nkind)
    cat_ = cell["category"]
    gear, meas, equiv = (), (), ()
    x = np.zeros(rows)
    floor = 5e-7
    if cat_ == "clean":
        sigma = max(acc * rng.uniform(0.005, 0.05), floor)
    elif cat_ in ("single", "pair"):
        sigma = None
        for e in cell["effects"]:
            order = 1 if e == "te_1x" else 2
            b = rng.uniform(0, 2 * np.pi)
            unit = respond(order, 1.0, b)
            k = rng.uniform(4, 12)
            if sigma is None:
                sigma = max(acc * rng.uniform(0.1, 0.35) * _rms(unit) / k, floor)
            x = x + unit * (k * sigma / _rms(unit))
        gear = tuple(cell["effects"])
        descs.append("excitation " + "+".join(cell["effects"]))
    else:
        b = rng.uniform(0, 2 * np.pi)
        if form == "ambient":
            wn_ = rng.standard_normal(nf)
            lo_, hi_ = 0.4 * fn, min(3.0 * fn, 0.45 * nf / tf[-1])
            sos = signal.butter(2, [lo_, hi_], btype="bandpass", fs=nf / tf[-1], output="sos")
            eb = signal.sosfilt(sos, wn_)
            eb /= _rms(eb)
            if method == "frac":  # ambient response computed with the Zener model in every case
                sysa = _zener_ss(J, Kt, zeta, wn)
            else:
                sysa = sys_z
            ebd = np.gradient(eb, tf)
            _, xa, _ = signal.lsim(sysa, np.column_stack([eb, ebd]), tf, interp=True)
            unit = np.interp(ts, tf, xa)
            a_phys, meas = acc * rng.uniform(0.02, 0.1), ("ambient_vibration",)
            descs.append("ambient floor vibration (band-limited base excitation), speed-independent")
        elif form == "out-ecc":
            unit = np.sin(phis / R + b) - np.sin(phis[0] / R + b)
            a_phys, meas = rng.uniform(1e-5, 6e-5), ("encoder_eccentricity",)
            descs.append("output-encoder eccentricity (once per output rev)")
        elif form == "drift":
            tau = T * rng.uniform(0.3, 1.0)
            unit = 1 - np.exp(-ts / tau)
            unit = unit - unit.mean()
            a_phys, meas = rng.uniform(5e-6, 3e-5), ("thermal_drift",)
            descs.append("thermal drift of the output angle")
        elif form == "bellows":
            # 2x input velocity fluctuation of a misaligned bellows coupling, seen through 1/R
            unit = respond(2, 1.0, b)
            a_phys, meas, equiv = rng.uniform(0.5e-3, 4e-3) / R, ("coupling_misalignment",), ("te_2x",)
            descs.append("misaligned bellows coupling, 2x input angle fluctuation")
        elif form == "tacho":
            unit = respond(1, 1.0, b)
            a_phys, meas, equiv = rng.uniform(0.5e-3, 4e-3) / R, ("speed_ripple",), ("te_1x",)
            descs.append("tachogenerator speed loop, 1x per input rev speed ripple")
        else:
            raise KeyError(form)
        k = rng.uniform(4, 12)
        sigma = max(a_phys * _rms(unit) / k, floor)
        x = unit * (k * sigma / _rms(unit))
    noise = shape / _rms(shape) * sigma
    cols = {"time_s": ts, "input_speed_rpm": nrpm, "output_vibration_rad": x + noise}
    descs.append(ndesc)
    snr = _rms(x) / sigma if cat_ != "clean" else 0.0
    descs.insert(0, f"f_n={fn:.2f} Hz")
    return cols, m["code"], dict(stiffness_scale=s, damping_ratio=zeta), gear, meas, equiv, sigma, \
        "; ".join(descs), snr, J


# ==============================================================================================
# the cells
# ==============================================================================================
def _cells():
    C = []
    add = lambda kind, category, effects, forms, **kw: C.append(
        dict(kind=kind, category=category, effects=tuple(effects), forms=tuple(forms), **kw))
    # ---- torsion ----
    add("torsion", "clean", (), ("sine-swept-white",), protocol="sine-swept", noise="white")
    add("torsion", "clean", (), ("randamp-ar1-outl",), protocol="random-amplitude", noise="ar1+outl")
    add("torsion", "clean", (), ("tworate-white-repeat",), protocol="two-rate", noise="white", repeat=True)
    add("torsion", "clean", (), ("sine-ar1",), protocol="sine", noise="ar1")
    for f in ("zener", "flank", "mp"):
        add("torsion", "single", ("hysteresis",), (f,))
    for f in ("ramp", "traverse"):
        add("torsion", "single", ("backlash",), (f,))
    for f in ("bredt", "spline"):
        add("torsion", "single", ("housing_compliance",), (f,))
    add("torsion", "pair", ("hysteresis", "backlash"), ("zener", "ramp"))
    add("torsion", "pair", ("hysteresis", "backlash"), ("flank", "traverse"))
    add("torsion", "pair", ("hysteresis", "housing_compliance"), ("mp", "bredt"))
    add("torsion", "pair", ("hysteresis", "housing_compliance"), ("zener", "spline"))
    add("torsion", "pair", ("backlash", "housing_compliance"), ("ramp", "spline"))
    add("torsion", "pair", ("backlash", "housing_compliance"), ("traverse", "bredt"))
    for f in ("torque-offset", "interp", "hvac"):
        add("torsion", "decoy_separable", (), (f,))
    add("torsion", "decoy_equivalent", (), ("crosstalk",))
    add("torsion", "decoy_equivalent", (), ("aa-lag",), protocol="sine")
    add("torsion", "decoy_equivalent", (), ("sensor-hyst",))
    # ---- transmission ----
    add("transmission", "clean", (), ("white",), noise="white")
    add("transmission", "clean", (), ("ar1-nonuniform",), noise="ar1", nonuniform=True)
    add("transmission", "clean", (), ("outl-repeat",), noise="white+outl", repeat=True)
    for f in ("eccentric", "vonmises", "toothstep"):
        add("transmission", "single", ("te_1x",), (f,))
    for f in ("ballpass", "runin"):
        add("transmission", "single", ("te_2x",), (f,))
    add("transmission", "pair", ("te_1x", "te_2x"), ("eccentric", "ballpass"))
    add("transmission", "pair", ("te_1x", "te_2x"), ("vonmises", "runin"), nonuniform=True)
    add("transmission", "pair", ("te_1x", "te_2x"), ("eccentric", "runin"))
    for f in ("interp", "hvac", "linecount", "out-ecc"):
        add("transmission", "decoy_separable", (), (f,))
    add("transmission", "decoy_equivalent", (), ("stator-runout",))
    add("transmission", "decoy_equivalent", (), ("disc-tilt",))
    # ---- efficiency ----
    add("efficiency", "clean", (), ("grid-white",), noise="white")
    add("efficiency", "clean", (), ("grid-ar1",), noise="ar1")
    add("efficiency", "clean", (), ("warmup-white",), noise="white", warmup=True)
    for f in ("fs-bending", "stribeck", "skf", "gw-ehl"):
        add("efficiency", "single", ("low_load_efficiency",), (f,))
    for f in ("doolittle", "channel", "warmup-film"):
        add("efficiency", "single", ("temperature_dependence",), (f,))
    for f in ("stribeck-doolittle", "fs-channel", "skf-doolittle"):
        add("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"), (f,))
    for f in ("block-drift", "tach-gain"):
        add("efficiency", "decoy_separable", (), (f,))
    add("efficiency", "decoy_equivalent", (), ("input-offset",))
    add("efficiency", "decoy_equivalent", (), ("rig-bearing",))
    # ---- vibration ----
    add("vibration", "clean", (), ("runup-white",), method="zener", protocol="run-up", noise="white")
    add("vibration", "clean", (), ("coast-ar1",), method="zener", protocol="coast-down", noise="ar1")
    add("vibration", "clean", (), ("dwell-jitter-outl",), method="zener", protocol="dwell", noise="white+outl",
        jitter=True)
    for e in ("te_1x", "te_2x"):
        add("vibration", "single", (e,), ("zener-runup",), method="zener", protocol="run-up")
        add("vibration", "single", (e,), ("frac-coast",), method="frac", protocol="coast-down")
        add("vibration", "single", (e,), ("zener-dwell-jitter",), method="zener", protocol="dwell", jitter=True)
    add("vibration", "pair", ("te_1x", "te_2x"), ("zener-coast",), method="zener", protocol="coast-down")
    add("vibration", "pair", ("te_1x", "te_2x"), ("frac-runup",), method="frac", protocol="run-up")
    add("vibration", "pair", ("te_1x", "te_2x"), ("frac-dwell",), method="frac", protocol="dwell")
    add("vibration", "decoy_separable", (), ("ambient",), method="zener", protocol="run-up")
    add("vibration", "decoy_separable", (), ("out-ecc",), method="zener", protocol="coast-down")
    add("vibration", "decoy_separable", (), ("drift",), method="frac", protocol="run-up")
    add("vibration", "decoy_equivalent", (), ("bellows",), method="zener", protocol="run-up")
    add("vibration", "decoy_equivalent", (), ("tacho",), method="frac", protocol="coast-down")
    return C


_GEN = {"torsion": _gen_torsion, "transmission": _gen_transmission,
        "efficiency": _gen_efficiency, "vibration": _gen_vibration}


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    rng = np.random.default_rng(seed)
    cat = _Catalog(catalog_dir)
    out = []
    counter = {}
    for cell in _cells():
        for _ in range(per_cell):
            for attempt in range(50):
                try:
                    res = _GEN[cell["kind"]](rng, cat, cell, attempt)
                    break
                except _Retry:
                    continue
            else:
                raise RuntimeError(f"cannot draw a case for {cell}")
            cols, model, nuis, gear, meas, equiv, sigma, fdesc, snr, J = res
            eff = "-".join(cell["effects"]) if cell["effects"] else "none"
            fkey = "+".join(cell["forms"])
            key = (cell["kind"], cell["category"], eff, fkey)
            counter[key] = counter.get(key, 0) + 1
            eff_short = eff.replace("housing_compliance", "housing").replace("low_load_efficiency", "lowload") \
                .replace("temperature_dependence", "temperature")
            name = f"{SUITE}-{cell['kind']}-{cell['category']}-{eff_short}-{fkey}-{counter[key]:03d}"
            out.append(TruthCase(
                name=name, kind=cell["kind"], model=model,
                columns={k: np.asarray(v, float) for k, v in cols.items()},
                load_inertia_kgm2=None if J is None else float(J),
                gear_effects=tuple(gear), measurement_effects=tuple(meas),
                nuisance={k: float(v) for k, v in nuis.items()}, category=cell["category"],
                equivalent_effects=tuple(equiv), noise_rms=float(sigma),
                formulation=f"{fkey}: {fdesc}", snr=float(snr)))
    return out


# ==============================================================================================
if __name__ == "__main__":
    import sys
    import tempfile
    import time
    from collections import Counter

    catdir = sys.argv[1] if len(sys.argv) > 1 else "/work/main/catalog"
    t0 = time.time()
    cases = generate_cases(11, catdir, per_cell=2)
    dt = time.time() - t0
    print(f"{len(cases)} cases in {dt:.1f} s")
    cnt = Counter((c.kind, c.category) for c in cases)
    cats = ["clean", "single", "pair", "decoy_separable", "decoy_equivalent"]
    print(f"{'kind':14s}" + "".join(f"{c:>18s}" for c in cats))
    for k in ("torsion", "transmission", "efficiency", "vibration"):
        print(f"{k:14s}" + "".join(f"{cnt[(k, c)]:>18d}" for c in cats))
    bad = 0
    names = set()
    req = {"torsion": ["torque_Nm", "twist_rad"], "transmission": ["input_angle_rad", "output_angle_rad"],
           "efficiency": ["input_speed_rpm", "load_torque_Nm", "temperature_C", "efficiency_pct"],
           "vibration": ["time_s", "input_speed_rpm", "output_vibration_rad"]}
    for c in cases:
        assert c.name not in names, c.name
        names.add(c.name)
        for col in req[c.kind]:
            assert col in c.columns, (c.name, col)
        for k_, v in c.columns.items():
            if not np.all(np.isfinite(v)):
                bad += 1
                print("non-finite", c.name, k_)
        if c.category in ("single", "pair", "decoy_separable", "decoy_equivalent") and not (3.5 <= c.snr):
            print("low snr", c.name, c.snr)
        assert np.isfinite(c.noise_rms) and c.noise_rms > 0
        if c.category in ("clean", "decoy_separable", "decoy_equivalent"):
            assert c.gear_effects == ()
        if c.category == "decoy_equivalent":
            assert c.equivalent_effects
    print("all columns finite" if bad == 0 else f"{bad} non-finite columns")
    pairs = Counter((c.kind, c.gear_effects) for c in cases if c.category == "pair")
    print("pair kinds:", sorted(pairs))
    again = generate_cases(11, catdir, per_cell=2)
    same = all(a.name == b.name and all(np.array_equal(a.columns[k], b.columns[k]) for k in a.columns)
               for a, b in zip(cases, again))
    print("deterministic:", same)
    out = Path(tempfile.mkdtemp(prefix="truth_h_"))
    for kind in req:
        c = next(c for c in cases if c.kind == kind and c.category != "clean")
        c.write_csv(out / f"{c.name}.csv")
    print("wrote", sorted(p.name for p in out.iterdir()), "to", out)
