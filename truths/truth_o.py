"""Independent truth suite "o" for strain-wave-gear (Harmonic Drive) model identification.

Generates synthetic "measured" data sets with known hidden effects for the four test kinds of
CONTRACT.md (torsion, transmission, efficiency, vibration).  numpy + scipy only; nothing from
hdcad is imported.  Every random draw comes from one numpy.random.default_rng(seed), walked
through the cells in a fixed order, so the same seed gives the same cases.

The formulations (laws, protocols, noise models, decoys) and the catalog interpretation are
documented in NOTES_o.md; the short version is in the docstrings below.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy import signal, special

SUITE = "o"

KIND_EFFECTS = {
    "torsion": ("hysteresis", "backlash", "housing_compliance"),
    "transmission": ("te_1x", "te_2x"),
    "efficiency": ("low_load_efficiency", "temperature_dependence"),
    "vibration": ("te_1x", "te_2x"),
}
MEASURED_COLUMN = {
    "torsion": "twist_rad",
    "transmission": "output_angle_rad",
    "efficiency": "efficiency_pct",
    "vibration": "output_vibration_rad",
}
K_MIN, K_MAX = 4.0, 12.0
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
        names = list(self.columns)
        cols = [np.asarray(self.columns[c], dtype=float) for c in names]
        n = len(cols[0])
        assert all(len(c) == n for c in cols), "columns of unequal length"
        with open(path, "w", encoding="utf-8", newline="") as fh:
            fh.write(",".join(names) + "\n")
            rows = zip(*[c.tolist() for c in cols])
            fh.write("".join(",".join(repr(v) for v in row) + "\n" for row in rows))


# ----------------------------------------------------------------------------------------------
# catalog
# ----------------------------------------------------------------------------------------------
def _read(path: Path) -> list[dict]:
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _num(x):
    return None if x is None or str(x).strip() == "" else float(x)


def _in_group(ratio, rmin, rmax):
    rmin = _num(rmin)
    rmax = _num(rmax)
    return ratio >= rmin and (rmax is None or ratio <= rmax)


@dataclass
class GearModel:
    code: str
    series: str          # "CSF" | "CSG"
    size: int
    ratio: int
    rated_Nm: float      # rated torque at 2000 r/min input (050-1/058-1)
    avg_speed_max: float
    max_speed: float
    T1: float
    T2: float
    K1: float
    K2: float
    K3: float
    hyst_rad: float
    backlash_rad: float
    th1_printed: float
    th2_printed: float
    accuracy_rad: float | None
    running_Nm: float | None   # no-load running torque at input, 2000 r/min (051-1/059-1)
    greases: tuple             # suitable greases (016-6), (name, rating)


def load_models(catalog_dir) -> list[GearModel]:
    d = Path(catalog_dir)
    ratings = _read(d / "gh_ratings_050-1_058-1.csv")
    stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
    hyst = _read(d / "gh_hysteresis_052_060.csv")
    back = _read(d / "gh_backlash_052-2_060-2.csv")
    perf = _read(d / "gh_performance_051-1_059-1.csv")
    grease = _read(d / "grease_suitability_016-5_016-6.csv")
    models = []
    for r in ratings:
        ser = r["series"]
        size = int(r["size"])
        ratio = int(r["ratio"])
        srow = [s for s in stiff if s["series"] == ser and int(s["size"]) == size
                and _in_group(ratio, s["ratio_min"], s["ratio_max"])]
        hrow = [h for h in hyst if h["series"] == ser and _in_group(ratio, h["ratio_min"], h["ratio_max"])]
        brow = [b for b in back if b["series"] == ser and int(b["size"]) == size and int(b["ratio"]) == ratio]
        prow = [p for p in perf if p["series"] == ser and int(p["size"]) == size and int(p["ratio"]) == ratio]
        if not (srow and hrow and brow):
            continue
        s = srow[0]
        acc = next((_num(p["accuracy_rad"]) for p in prow if _num(p["accuracy_rad"])), None)
        run = next((_num(p["running_torque_cNm"]) for p in prow if _num(p["running_torque_cNm"])), None)
        grp = "30" if ratio == 30 else "50"
        gr = tuple((g["grease"], g["rating"]) for g in grease
                   if g["ratio_min"] == grp and int(g["size"]) == size and g["rating"] != "not_suitable")
        models.append(GearModel(
            code=f"{ser.split('-')[0]}-{size}-{ratio}-GH", series=ser.split("-")[0], size=size, ratio=ratio,
            rated_Nm=float(r["rated_torque_2000_Nm"]), avg_speed_max=float(r["avg_input_speed_max_rpm"]),
            max_speed=float(r["max_input_speed_rpm"]),
            T1=float(s["T1_Nm"]), T2=float(s["T2_Nm"]), K1=float(s["K1_Nm_per_rad"]),
            K2=float(s["K2_Nm_per_rad"]), K3=float(s["K3_Nm_per_rad"]),
            hyst_rad=float(hrow[0]["hysteresis_rad"]), backlash_rad=float(brow[0]["backlash_rad"]),
            th1_printed=float(s["theta1_rad"]), th2_printed=float(s["theta2_rad"]),
            accuracy_rad=acc, running_Nm=None if run is None else run / 100.0, greases=gr))
    return models


def load_lubricants(catalog_dir) -> dict:
    """Lubricant temperature windows: 016-2 ambient use range; the note allows a rise of 40 K."""
    rows = _read(Path(catalog_dir) / "lubricant_temperature_016-2_019.csv")
    out = {}
    for r in rows:
        if r["table"] == "016-2":
            out[r["lubricant"]] = (float(r["use_min_C"]), float(r["use_max_C"]))
    return out


# ----------------------------------------------------------------------------------------------
# small numerical helpers
# ----------------------------------------------------------------------------------------------
def _rms(x) -> float:
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x)))


def _eff_rms(x, mean_free: bool) -> float:
    x = np.asarray(x, dtype=float)
    return _rms(x - x.mean()) if mean_free else _rms(x)


def _solve_monotone(fn, lo, hi, target, iters=60):
    """p in [lo, hi] with fn(p) = target for increasing fn (clipped to the ends)."""
    flo, fhi = fn(lo), fn(hi)
    if target <= flo:
        return lo
    if target >= fhi:
        return hi
    a, b = lo, hi
    for _ in range(iters):
        m = 0.5 * (a + b)
        if fn(m) < target:
            a = m
        else:
            b = m
    return 0.5 * (a + b)


def _logit_normal_scale(rng, half_width=0.10, sd=0.8):
    """Stiffness scale 1 + w*(2*sigmoid(N(0, sd)) - 1): logit-normal on (1-w, 1+w)."""
    g = rng.normal(0.0, sd)
    return 1.0 + half_width * (2.0 / (1.0 + math.exp(-g)) - 1.0)


def _ramp_lag(u, lam):
    """First-order lag responding to a ramp input (Newtonian warm-up under constant heating),
    normalised to 1 at u = 1: (u/lam - (1 - exp(-u/lam))) / (same at 1)."""
    f = lambda v: v / lam - (1.0 - np.exp(-v / lam))
    return f(np.asarray(u, float)) / f(1.0)


# ----------------------------------------------------------------------------------------------
# noise models
# ----------------------------------------------------------------------------------------------
def _noise(rng, n, sigma, model):
    """Noise vector whose RMS is exactly sigma (outliers included).

    white      : N(0,1)
    ar1        : x_t = phi x_{t-1} + w_t, phi ~ U(0.3, 0.8), stationary start
    *-outliers : 0.5 % of rows (>= 1) get +-U(8, 15) x the base sigma added
    telegraph  : random telegraph (Machlup 1954) two-level switching noise, Poisson switching,
                 mean dwell 4-30 samples, plus white noise (Lorentzian + flat spectrum)
    ma2        : MA(2) moving average w_t + t1 w_{t-1} + t2 w_{t-2} (3-tap sensor filter)
    """
    info = {"model": model}
    base = model.replace("-outliers", "")
    if base == "white":
        v = rng.standard_normal(n)
    elif base == "ar1":
        phi = float(rng.uniform(0.3, 0.8))
        w = rng.standard_normal(n)
        x0 = rng.standard_normal() / math.sqrt(1 - phi * phi)
        v, _ = signal.lfilter([1.0], [1.0, -phi], w, zi=[phi * x0])
        info["phi"] = phi
    elif base == "telegraph":
        dwell = float(rng.uniform(4, 30))
        flips = rng.random(n) < 1.0 / dwell
        state = np.where(np.cumsum(flips) % 2 == 0, 1.0, -1.0) * (1 if rng.random() < 0.5 else -1)
        amp = float(rng.uniform(0.8, 1.6))
        v = amp * (state - state.mean()) + rng.standard_normal(n)
        info.update(dwell=dwell, rtn_amp=amp)
    elif base == "ma2":
        t1, t2 = float(rng.uniform(0.4, 0.9)), float(rng.uniform(0.1, 0.5))
        w = rng.standard_normal(n + 2)
        v = w[2:] + t1 * w[1:-1] + t2 * w[:-2]
        info.update(theta1=t1, theta2=t2)
    else:
        raise ValueError(model)
    if model.endswith("-outliers"):
        sb = _rms(v)
        k = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, size=k, replace=False)
        v = v.copy()
        v[idx] += rng.choice([-1.0, 1.0], size=k) * rng.uniform(8, 15, size=k) * sb
        info["outliers"] = int(k)
    v = np.asarray(v, float) * (sigma / _rms(v))
    return v, info


def _effect_noise_model(rng):
    return "white" if rng.random() < 0.5 else "ar1"


# ----------------------------------------------------------------------------------------------
# effect sizing: k x noise in [4, 12]
# ----------------------------------------------------------------------------------------------
class _Eff:
    """A hidden effect: contribution(p) on the measured column, p in [lo, hi] (physical range)."""

    def __init__(self, name, fn, lo, hi, linear=True):
        self.name, self.fn, self.lo, self.hi, self.linear = name, fn, float(lo), float(hi), linear
        self._u = fn(1.0) if linear else None

    def contrib(self, p):
        return p * self._u if self.linear else self.fn(p)


ID_MIN = 3.0       # the part of a single effect no in-spread nuisance can absorb: >= 3 x noise
ID_MIN_PAIR = 2.0  # the same for each effect of a pair (and >= 3 x noise for the pair together)


def _allocate(rng, effs, combine, mean_free, tries=60, ident=None, sigma_min=0.0):
    """Draw noise sigma and effect strengths so every effect alone and the combination have
    RMS / sigma in [4, 12] (the contract's k, by the RMS actually added).  With `ident` (the RMS
    left after the baseline's in-spread nuisances absorb what they can) each effect alone and
    the combination must also keep ident / sigma >= ID_MIN, so every case is detectable in
    principle.  Returns (sigma, [p...], combined contribution, [k...]) or None."""
    r = lambda e, p: _eff_rms(e.contrib(p), mean_free)
    idf = ident or (lambda c: _eff_rms(c, mean_free))
    if len(effs) == 1:
        e = effs[0]
        for _ in range(tries):
            p = float(rng.uniform(e.lo, e.hi))
            c = e.contrib(p)
            rr = _eff_rms(c, mean_free)
            if not np.isfinite(rr) or rr <= 0:
                continue
            rho = idf(c) / rr
            k_lo = max(K_MIN, ID_MIN / rho) if rho > 0 else np.inf
            k_hi = min(K_MAX, rr / sigma_min) if sigma_min > 0 else K_MAX
            if k_lo > k_hi:
                continue
            k = float(rng.uniform(k_lo, k_hi))
            return rr / k, [p], c, [k]
        return None
    rlo = [r(e, e.lo) for e in effs]
    rhi = [r(e, e.hi) for e in effs]
    s_lo = max([a / K_MAX for a in rlo] + [sigma_min])
    s_hi = min(b / K_MIN for b in rhi)
    if not (s_lo < s_hi):
        return None
    for _ in range(tries):
        sig = math.exp(rng.uniform(math.log(s_lo), math.log(s_hi)))
        ps, ks = [], []
        for e, a, b in zip(effs, rlo, rhi):
            tlo, thi = max(K_MIN * sig, a), min(K_MAX * sig, b)
            if tlo > thi:
                break
            tgt = float(rng.uniform(tlo, thi))
            if e.linear:
                p = min(max(tgt / r(e, 1.0), e.lo), e.hi)
            else:
                p = _solve_monotone(lambda q: r(e, q), e.lo, e.hi, tgt)
            ps.append(p)
            ks.append(r(e, p) / sig)
        else:
            if all(K_MIN <= k <= K_MAX for k in ks):
                cs = [e.contrib(p) for e, p in zip(effs, ps)]
                if min(idf(x) for x in cs) / sig < ID_MIN_PAIR:
                    continue
                c = combine(cs, ps)
                kc = _eff_rms(c, mean_free) / sig
                if K_MIN <= kc <= K_MAX and idf(c) / sig >= ID_MIN:
                    return sig, ps, c, ks
    return None


def _torsion_ident(theta_unit, s_true):
    """RMS an effect keeps after the best stiffness scale inside the +-10 % spread is fitted:
    data = theta_cat/s_true + eff is fitted by theta_cat/s', s' in [0.9, 1.1]."""
    tt = float(np.dot(theta_unit, theta_unit))
    a_lo, a_hi = 1 / 1.1 - 1 / s_true, 1 / 0.9 - 1 / s_true

    def f(c):
        a = min(max(float(np.dot(c, theta_unit)) / tt, a_lo), a_hi)
        return _rms(c - a * theta_unit)
    return f


def _size_decoy(rng, fn, lo, hi, sigma0, mean_free, linear=True):
    """Measurement-chain / decoy effect sized so its RMS is k x noise (k in [4, 12]); the noise
    starts at a clean-like sigma0 and is re-set when the physical range clips the strength."""
    k = float(rng.uniform(K_MIN, K_MAX))
    rr = lambda p: _eff_rms(fn(p), mean_free)
    if linear:
        u = rr(1.0)
        p = min(max(k * sigma0 / u, lo), hi)
    else:
        p = _solve_monotone(rr, lo, hi, k * sigma0)
    c = fn(p)
    return p, c, _eff_rms(c, mean_free) / k


# ----------------------------------------------------------------------------------------------
# torsion
# ----------------------------------------------------------------------------------------------
def theta_catalog(T, m: GearModel, scale=1.0):
    """Three-segment catalog twist (P046 / seed 000 p.020), continuous: theta1 = T1/K1,
    theta2 = theta1 + (T2-T1)/K2; odd in T; every spring constant times `scale`."""
    a = np.abs(np.asarray(T, float))
    th1 = m.T1 / m.K1
    th2 = th1 + (m.T2 - m.T1) / m.K2
    th = np.where(a <= m.T1, a / m.K1,
                  np.where(a <= m.T2, th1 + (a - m.T1) / m.K2, th2 + (a - m.T2) / m.K3))
    return np.sign(T) * th / scale


def _theta_printed(T, m: GearModel, th1, th2, scale=1.0):
    """The other reading of the contract's curve: the printed theta1/theta2 as segment anchors."""
    a = np.abs(np.asarray(T, float))
    th = np.where(a <= m.T1, a / m.K1, np.where(a <= m.T2, th1 + (a - m.T1) / m.K2, th2 + (a - m.T2) / m.K3))
    return np.sign(T) * th / scale


def _torsion_noise_floor(T, m: GearModel):
    """Noise floor for torsion: 2 urad (0.4 arcsec, an autocollimator-class twist measurement) and
    at least half the RMS by which the two readings of the catalog curve (theta1 = T1/K1 derived,
    or the printed theta1/theta2) differ after a stiffness-scale fit, so the choice of reading can
    never look like a hidden effect of more than ~0.5 noise RMS."""
    th = theta_catalog(T, m)
    d = _theta_printed(T, m, m.th1_printed, m.th2_printed) - th
    a = float(np.dot(d, th) / np.dot(th, th))
    return max(2e-6, 0.5 * _rms(d - a * th))


class _TorsionPath:
    """Quasi-static torque cycles 0 -> +P1 -> -P2 -> ... -> 0 between about +-T0.

    asym    : constant sample rate, loading legs (|T| rising) 2-3x slower than unloading legs, so
              loading legs are sampled 2-3x more densely (a servo-hydraulic rig that creeps up
              to each peak and releases quickly); peaks overshoot T0 by 0-2 %.
    poisson : the same path at one rate, sampled at Poisson (uniform-order-statistics) instants.
    The models run on the dense path (samples plus every vertex) so reversals are never missed.
    """

    def __init__(self, rng, T0, proto):
        ncyc = int(rng.integers(2, 4))
        peaks = [T0 * (1 + rng.uniform(0, 0.02)) * (1 if i % 2 == 0 else -1) for i in range(2 * ncyc)]
        V = [0.0]
        for p in peaks:
            if V[-1] * p < 0:
                V.append(0.0)
            V.append(p)
        V.append(0.0)
        V = np.array(V)
        rate = T0 / rng.uniform(15, 40)
        fac = rng.uniform(2.0, 3.0) if proto == "asym" else 1.0
        dt = []
        for a, b in zip(V[:-1], V[1:]):
            loading = abs(b) > abs(a)
            dt.append(abs(b - a) / (rate if loading else rate * fac))
        tv = np.concatenate([[0.0], np.cumsum(dt)])
        total = tv[-1]
        N = int(rng.integers(450, 800))
        if proto == "asym":
            ts = np.linspace(0.0, total, N)
        else:
            ts = np.sort(np.concatenate([[0.0, total], rng.uniform(0, total, N - 2)]))
        dense = np.unique(np.concatenate([ts, tv]))
        self.t_dense = dense
        self.T_dense = np.interp(dense, tv, V)
        self.idx = np.searchsorted(dense, ts)
        self.t = ts
        self.T = self.T_dense[self.idx]
        self.tv, self.V, self.total, self.T0 = tv, V, total, T0
        self.proto, self.ncyc = proto, ncyc

    def torque_at(self, t):
        return np.interp(t, self.tv, self.V)


def _legs(t):
    """Split a path into monotone legs; returns list of (i0, i1, direction)."""
    d = np.sign(np.diff(t))
    # carry direction across flat steps
    for i in range(len(d)):
        if d[i] == 0:
            d[i] = d[i - 1] if i > 0 else 1.0
    legs, i0 = [], 0
    for i in range(1, len(d)):
        if d[i] != d[i - 1]:
            legs.append((i0, i, d[i - 1]))
            i0 = i
    legs.append((i0, len(t) - 1, d[-1]))
    return legs


def _ivshin_pence(t, c, w):
    """Ivshin-Pence (1994) hysteresis: phase-fraction xi on major branches
    Phi_up = Phi((t-c)/w), Phi_dn = Phi((t+c)/w) (Gaussian CDFs), inner branches by scaling the
    major branch through the last reversal point:
        rising : xi = 1 - (1 - xi_r) (1 - Phi_up(t)) / (1 - Phi_up(t_r))
        falling: xi = xi_r Phi_dn(t) / Phi_dn(t_r)."""
    t = np.asarray(t, float)
    xi = np.empty_like(t)
    xi[0] = 0.5 * (special.ndtr((t[0] - c) / w) + special.ndtr((t[0] + c) / w))
    for i0, i1, d in _legs(t):
        seg = t[i0:i1 + 1]
        xr, tr = xi[i0], t[i0]
        if d > 0:
            q = special.ndtr(-(seg - c) / w) / special.ndtr(-(tr - c) / w)
            xi[i0:i1 + 1] = 1.0 - (1.0 - xr) * q
        else:
            xi[i0:i1 + 1] = xr * special.ndtr((seg + c) / w) / special.ndtr((tr + c) / w)
    return xi


def _two_surface(t, sB, E0, h, step=0.004):
    """1-D Dafalias-Popov (1975) two-surface plasticity with a vanishing yield surface, torque
    driven: internal twist z grows with dz = dT / H, plastic modulus
        H = E0 + h * delta / (delta_in - delta),  delta = sB + d*E0*z - d*t  (distance to the
    bounding line in the loading direction d; delta_in its value at the last reversal), so every
    reversal starts elastically (H -> inf) and the branch approaches the bound with slope E0."""
    t = np.asarray(t, float)
    z = np.zeros_like(t)
    zc = 0.0
    d_prev = 0.0
    din = sB
    for i in range(1, len(t)):
        dT = t[i] - t[i - 1]
        if dT == 0.0:
            z[i] = zc
            continue
        d = 1.0 if dT > 0 else -1.0
        if d != d_prev:
            din = max(sB + d * E0 * zc - d * t[i - 1], 1e-9)
            d_prev = d
        n = max(1, int(math.ceil(abs(dT) / step)))
        hs = dT / n
        tc = t[i - 1]
        for _ in range(n):
            tm = tc + 0.5 * hs
            dl = sB + d * E0 * zc - d * tm
            if dl <= 0:
                H = E0
            else:
                gap = din - dl
                H = E0 + h * dl / gap if gap > 1e-12 else 1e12
            zc += hs / H
            tc += hs
        z[i] = zc
    return z


def _conditioning(a, ncyc, g=0.004):
    """0 -> +a, then ncyc x (+a -> -a -> +a), then +a -> -a: exercise cycles before the record.
    Returns the path and the index ranges of the last rising and the last falling leg."""
    n = int(round(2 * a / g))
    segs = [np.linspace(0, a, int(round(a / g)) + 1)]
    for _ in range(ncyc):
        segs.append(np.linspace(a, -a, n + 1)[1:])
        segs.append(np.linspace(-a, a, n + 1)[1:])
    segs.append(np.linspace(a, -a, n + 1)[1:])
    p = np.concatenate(segs)
    L = len(p)
    dsc = np.arange(L - n - 1, L)             # last falling leg +a -> -a (includes its start)
    asc = np.arange(L - 2 * n - 1, L - n)     # the rising leg before it  -a -> +a
    return p, asc, dsc


def _loop_unit(model_fn, t_path, t0, ncyc=25):
    """Hysteresis contribution per unit loss, (z - c(t)) / loss_ref.

    The gear is exercised with ncyc cycles at +-t0 before the record (the loop has shaken down;
    the record starts at B', zero torque after the last negative peak).  loss_ref is B - B', the
    width of the steady loop at zero torque after cycling to the rated torque (t = 1, seed 000
    p.020); c(t) is the centre line of the steady loop at the test amplitude t0, so the catalog
    curve stays the mean of the two branches (the catalog's 'average values')."""
    p1, a1, d1 = _conditioning(1.0, ncyc)
    z1 = model_fn(p1)
    za0 = np.interp(0.0, p1[a1], z1[a1])
    zd0 = np.interp(0.0, p1[d1][::-1], z1[d1][::-1])
    loss = zd0 - za0
    pc, ac, dc = _conditioning(t0, ncyc)
    bridge = np.linspace(-t0, 0.0, int(round(t0 / 0.004)) + 1)[1:-1]
    full = np.concatenate([pc, bridge, t_path])
    zf = model_fn(full)
    grid = np.linspace(-t0, t0, 401)
    cz = 0.5 * (np.interp(grid, pc[ac], zf[ac]) + np.interp(grid, pc[dc][::-1], zf[dc][::-1]))
    zt = zf[len(pc) + len(bridge):]
    c = np.interp(t_path, grid, cz)
    sl_hi = (cz[-1] - cz[-6]) / (grid[-1] - grid[-6])
    sl_lo = (cz[5] - cz[0]) / (grid[5] - grid[0])
    c = np.where(t_path > t0, cz[-1] + sl_hi * (t_path - t0), c)
    c = np.where(t_path < -t0, cz[0] + sl_lo * (t_path + t0), c)
    return (zt - c) / loss, loss


def _hysteresis_eff(rng, form, path, m):
    t_dense = path.T_dense / m.rated_Nm
    t0 = path.T0 / m.rated_Nm
    if form == "dafalias-popov":
        sB, E0, h = rng.uniform(1.15, 1.6), rng.uniform(0.3, 2.0), rng.uniform(0.3, 3.0)
        fn = lambda tt: _two_surface(tt, sB, E0, h)
        par = {"sB": sB, "E0": E0, "h": h}
    else:
        c, w = rng.uniform(0.10, 0.35), rng.uniform(0.15, 0.40)
        fn = lambda tt: _ivshin_pence(tt, c, w)
        par = {"c": c, "w": w}
    u, _ = _loop_unit(fn, t_dense, t0)
    u = u[path.idx]
    h_cat = m.hyst_rad
    return _Eff("hysteresis", lambda p: p * u, 0.5 * h_cat, 1.3 * h_cat), par


def _backlash_eff(rng, form, path, m):
    T = path.T
    if form == "beta-smoothstep":
        # Beta(2,2)-distributed engagement torques over |T| < Tc: (3u - u^3)/2, exact +-1 outside
        Tc = rng.uniform(0.02, 0.08) * m.rated_Nm
        u = np.clip(T / Tc, -1, 1)
        shape = 0.5 * (3 * u - u ** 3)
        par = {"Tc": Tc}
    else:
        # Hill-function take-up sign(T) |T|^n / (|T|^n + Tc^n)
        n = rng.uniform(1.5, 3.0)
        Tc = rng.uniform(0.01, 0.05) * m.rated_Nm
        a = np.abs(T) ** n
        shape = np.sign(T) * a / (a + Tc ** n)
        par = {"n": n, "Tc": Tc}
    b = m.backlash_rad
    return _Eff("backlash", lambda p: 0.5 * p * shape, 0.35 * b, 1.0 * b), par


def _housing_eff(rng, form, path, m, scale):
    """Series spring linear in T with a compliance from a physical estimate.

    ker-wilson  : output shaft of two diameters in series up to the twist-measuring point,
                  Saint-Venant G*J/L per section, the shoulder counted by an equivalent-length
                  allowance L_eq = L1 + alpha*d1 (alpha 0.05-0.15, Ker Wilson's equivalent-length
                  practice for shaft steps).
    polymer-pad : the housing seated on a vibration-damping polymer pad (filled polyurethane /
                  epoxy-rubber shim, G 50-300 MPa, 3-8 mm): an annular elastic layer in torsion,
                  K = G pi (a^4 - a_i^4) / (2 t), in series with the machine base as an elastic
                  half-space under a rigid disc (Reissner & Sagoci 1944, K = 16 G a^3 / 3).
    The strength range is 0.6-1.5x the estimate, kept within 5-55 % of the gear's compliance."""
    k_gear = m.K1 * scale
    if form == "ker-wilson":
        G = 79.3e9
        d1 = m.size * rng.uniform(1.0, 1.4) * 1e-3
        L1 = d1 * rng.uniform(1.0, 2.5)
        d2 = d1 * rng.uniform(1.3, 1.8)
        L2 = d1 * rng.uniform(0.5, 1.5)
        alpha = rng.uniform(0.05, 0.15)
        J1, J2 = math.pi * d1 ** 4 / 32, math.pi * d2 ** 4 / 32
        c = (L1 + alpha * d1) / (G * J1) + L2 / (G * J2)
        par = {"d1_m": d1, "L1_m": L1, "d2_m": d2, "L2_m": L2, "alpha": alpha}
    else:
        Gp = rng.uniform(50e6, 300e6)
        a = m.size * rng.uniform(1.5, 1.9) * 1e-3         # flange outer radius
        ai = a * rng.uniform(0.45, 0.65)
        tl = rng.uniform(0.003, 0.008)
        Gf = rng.uniform(38e9, 45e9)                      # cast-iron base
        c = 2 * tl / (Gp * math.pi * (a ** 4 - ai ** 4)) + 3.0 / (16 * Gf * a ** 3)
        par = {"G_pad_Pa": Gp, "a_m": a, "a_i_m": ai, "t_m": tl}
    par["compliance_estimate"] = c
    par["fraction_estimate"] = c * k_gear
    lo = min(max(0.6 * c, 0.05 / k_gear), 0.45 / k_gear)
    hi = max(min(1.5 * c, 0.55 / k_gear), lo * 1.2)
    T = path.T
    return _Eff("housing_compliance", lambda p: p * T, lo, hi), par


# ----------------------------------------------------------------------------------------------
# TE waveforms (transmission and vibration); fundamental amplitude 1
# ----------------------------------------------------------------------------------------------
def _wave_wcauchy_odd(x, rho):
    """Antiperiodic difference of two wrapped-Cauchy (Poisson-kernel) pulses half a period apart:
    sum over odd n of rho^(n-1) cos(n x) -> odd harmonics only, geometric decay rho^2 per step."""
    P = lambda y: (1 - rho ** 2) / (1 - 2 * rho * np.cos(y) + rho ** 2)
    return (P(x) - P(x + np.pi)) / (4 * rho)


def _wave_trapezoid(x, r):
    """Half-wave-symmetric trapezoid (flat tops +-1, linear flanks; each flank takes r of a half
    period), cosine-phased and normalised to a unit fundamental. Only odd harmonics."""
    def raw(v):
        v = np.mod(v, 2 * np.pi)
        v = np.where(v > np.pi, v - 2 * np.pi, v)       # (-pi, pi]
        return np.clip((np.pi / 2 - np.abs(v)) / (r * np.pi / 2), -1, 1)
    g = np.linspace(0, 2 * np.pi, 4096, endpoint=False)
    b1 = 2 * np.mean(raw(g) * np.cos(g))
    return raw(x) / b1


def _te_wave(form, x, par):
    if form == "wcauchy":
        return _wave_wcauchy_odd(x, par["rho"])
    if form == "trapezoid":
        return _wave_trapezoid(x, par["r"])
    return np.cos(x)


# ----------------------------------------------------------------------------------------------
# efficiency laws
# ----------------------------------------------------------------------------------------------
def _ke_inclined(alpha, gamma, mu_inf, dmu, ac):
    """Coulomb wedge (inclined-plane / screw) efficiency tan g / tan(g + rho), rho = atan mu,
    with a load-dependent flank friction mu = mu_inf + dmu * ac / (alpha + ac); Ke = eta/eta(1),
    Ke = 1 at alpha >= 1 (seed 000 p.023 note)."""
    f = lambda a: math.tan(gamma) / np.tan(gamma + np.arctan(mu_inf + dmu * ac / (a + ac)))
    a = np.minimum(np.asarray(alpha, float), 1.0)
    return f(a) / f(1.0)


def _ke_lognormal(alpha, xb, a50, s):
    """Share of tooth-pair contacts in the efficient (full-film) regime is a lognormal CDF of the
    load, the rest run at relative efficiency xb: G = xb + (1-xb) Phi((ln a - ln a50)/s);
    Ke = G(a)/G(1), 1 at a >= 1."""
    G = lambda a: xb + (1 - xb) * special.ndtr((np.log(a) - math.log(a50)) / s)
    a = np.minimum(np.asarray(alpha, float), 1.0)
    return G(a) / G(1.0)


def _visc_fit(kind, nu40, nu100, log_inf=-1.5):
    """Fit a two-parameter viscosity law (T in K, nu in mm^2/s) through nu(40 C) and nu(100 C).
    myega   : log10 nu = L + (K/T) exp(C/T)        (Mauro, Yue, Ellison, Gupta, Allan 2009)
    avramov : log10 nu = L + (tau/T)^a              (Avramov & Milchev 1988)"""
    T1, T2 = 313.15, 373.15
    y1, y2 = math.log10(nu40) - log_inf, math.log10(nu100) - log_inf
    if kind == "myega":
        C = math.log((y1 / y2) * (T1 / T2)) / (1 / T1 - 1 / T2)
        K = y1 * T1 / math.exp(C / T1)
        return lambda TC: 10 ** (log_inf + K / (TC + 273.15) * np.exp(C / (TC + 273.15)))
    a = math.log(y1 / y2) / math.log(T2 / T1)
    tau = T1 * y1 ** (1 / a)
    return lambda TC: 10 ** (log_inf + (tau / (TC + 273.15)) ** a)


# ----------------------------------------------------------------------------------------------
# vibration: linear base-excited oscillator y'' + 2 z w y' + w^2 y = 2 z w e' + w^2 e
# ----------------------------------------------------------------------------------------------
def _tustin_coeffs(wn, zeta, h):
    """Bilinear (Tustin) transform prewarped at wn: s = c (1 - q)/(1 + q), c = wn / tan(wn h/2)."""
    c = wn / math.tan(wn * h / 2)
    b = np.array([2 * zeta * wn * c + wn ** 2, 2 * wn ** 2, wn ** 2 - 2 * zeta * wn * c])
    a = np.array([c * c + 2 * zeta * wn * c + wn ** 2, 2 * wn ** 2 - 2 * c * c,
                  c * c - 2 * zeta * wn * c + wn ** 2])
    return b / a[0], a / a[0]


def _park_coeffs(wn, zeta, h):
    """Park's (1975) stiffly-stable three-step method: velocity and acceleration both by
    D x_{n+1} = (10 x_{n+1} - 15 x_n + 6 x_{n-1} - x_{n-2}) / (6 h). For the linear oscillator the
    scheme is the recursion (D^2 + 2 z w D + w^2) y = (2 z w D + w^2) e, run with lfilter."""
    P = np.array([10.0, -15.0, 6.0, -1.0]) / (6 * h)
    den = np.convolve(P, P)
    den[:4] += 2 * zeta * wn * P
    den[0] += wn ** 2
    num = np.zeros(7)
    num[:4] += 2 * zeta * wn * P
    num[0] += wn ** 2
    return num / den[0], den / den[0]


class _RunUp:
    """Input-speed run-up through both TE resonances (k*f_in = f_n, k = 2 and 1).

    servo : a linear speed reference n_lo -> n_hi followed through a second-order servo lag
            (f_s 0.3-1 Hz, critically damped): smooth start, then a constant-lag ramp.
    sinh  : resonance-centred hyperbolic-sine sweep n = n_c + w sinh((t - t_c)/tau): slowest at
            the expected 2x resonance speed n_c, faster towards both ends.
    Sweep rate kept below a fraction c_s (0.5-1.0) of Ewins' quasi-stationary limit
    54 f_n^2 zeta^2 Hz/min at each resonance crossing.  A constant-speed pre-roll of >= 8 decay
    times at n_lo precedes the record and is discarded (steady running before the run-up).
    """

    def __init__(self, rng, form, n_lo, n_hi, fn, zeta, orders=(1, 2)):
        L = rng.uniform(0.5, 1.0) * 54.0 / 60.0 * fn ** 2 * zeta ** 2      # Hz/s
        kmax = max(orders)
        self.form = form
        if form == "servo":
            rate = 60.0 * L / kmax                                         # rpm/s
            self.T_ramp = (n_hi - n_lo) / rate
            self.ws = 2 * math.pi * rng.uniform(0.3, 1.0)
            self.zs = 1.0          # critically damped: the speed never overshoots (monotone)
            self.T = self.T_ramp + 4.0 / (self.zs * self.ws)
        else:
            nc = 30.0 * fn if 2 in orders else 60.0 * fn / kmax
            nc = min(max(nc, n_lo * 1.05), n_hi * 0.95)
            w = rng.uniform(0.10, 0.20) * nc
            tau = 0.0
            for k in orders:
                nk = 60.0 * fn / k
                if n_lo < nk < n_hi:
                    tau = max(tau, k * math.sqrt(w * w + (nk - nc) ** 2) / (60.0 * L))
            tau = max(tau, 2 * w / (60.0 * L))
            self.nc, self.w, self.tau = nc, w, tau
            self.tc = tau * math.asinh((nc - n_lo) / w)
            self.T = self.tc + tau * math.asinh((n_hi - nc) / w)
        self.n_lo, self.n_hi = n_lo, n_hi

    def speed(self, t):
        t = np.asarray(t, float)
        if self.form == "servo":
            ramp = np.clip(t / self.T_ramp, 0, 1) * (self.n_hi - self.n_lo)
            ramp = np.where(t < 0, 0.0, ramp)
            h = t[1] - t[0]
            b, a = signal.bilinear([self.ws ** 2], [1, 2 * self.zs * self.ws, self.ws ** 2], fs=1 / h)
            return self.n_lo + signal.lfilter(b, a, ramp)
        n = self.nc + self.w * np.sinh((t - self.tc) / self.tau)
        return np.where(t < 0, self.n_lo, np.minimum(n, self.n_hi))


def _vib_response(e, wn, zeta, h, integ):
    b, a = (_tustin_coeffs if integ == "tustin" else _park_coeffs)(wn, zeta, h)
    return signal.lfilter(b, a, e)


# ----------------------------------------------------------------------------------------------
# case assembly helpers
# ----------------------------------------------------------------------------------------------
def _finish(name, kind, model, cols, meas_clean, noise, effect, *, mean_free, J=None,
            gear=(), meas=(), nuis=None, cat="clean", equiv=(), form="", units=None,
            snr_exempt=False, extra=None):
    """Add the noise to the measured column, apply unit errors, build the TruthCase."""
    mc = MEASURED_COLUMN[kind]
    cols = dict(cols)
    cols[mc] = meas_clean + noise
    units = dict(units or {})
    for c, f in units.items():
        cols[c] = cols[c] * f
    nr = _rms(noise)
    if effect is None:
        snr = 0.0
    else:
        snr = _eff_rms(effect, mean_free) / nr
    case = TruthCase(name=name, kind=kind, model=model.code, columns={k: np.asarray(v, float) for k, v in cols.items()},
                     load_inertia_kgm2=J, gear_effects=tuple(gear), measurement_effects=tuple(meas),
                     nuisance=dict(nuis or {}), category=cat, equivalent_effects=tuple(equiv),
                     noise_rms=nr, formulation=form, snr=float(snr))
    case._diag = {"meas_col": mc, "clean": np.asarray(meas_clean, float), "noise": noise,
                  "effect": None if effect is None else np.asarray(effect, float),
                  "mean_free": mean_free, "snr_exempt": snr_exempt, "units": units,
                  "extra": extra or {}}
    return case


def _order_pair(names, contribs, mean_free, metric=None):
    """Pair order as hdcad reports it: the effect that alone explains more comes first, measured
    by the RMS it keeps after the baseline's nuisances absorbed what they can."""
    r = [(metric(c) if metric else _eff_rms(c, mean_free)) for c in contribs]
    order = np.argsort(r)[::-1]
    return tuple(names[i] for i in order)


# ----------------------------------------------------------------------------------------------
# TORSION builder
# ----------------------------------------------------------------------------------------------
def _torsion(rng, models, cell, idx):
    cat, effs, form, slug = cell["category"], cell["effects"], cell["form"], cell["slug"]
    proto = "asym" if idx % 2 == 0 else "poisson"
    pool, tries = models, 200
    if set(effs) == {"backlash", "housing_compliance"}:
        # a housing spring large enough to leave the stiffness spread is ~3x the play's RMS
        # unless the play is large against the twist: only those gears can balance the pair
        pool = [m for m in models if m.backlash_rad / float(theta_catalog(m.rated_Nm, m)) >= 0.06]
        tries = 4000
    elif set(effs) == {"hysteresis", "backlash"}:
        # the play's RMS must come within ~3x of the loop's: catalog backlash >= 13 % of the loss
        pool = [m for m in models if m.backlash_rad / m.hyst_rad >= 0.13]
        tries = 600
    for attempt in range(tries):
        m = pool[int(rng.integers(len(pool)))]
        s = _logit_normal_scale(rng)
        T0 = m.rated_Nm * rng.uniform(0.85, 1.05)
        path = _TorsionPath(rng, T0, proto)
        T = path.T
        nuis = {"stiffness_scale": s}
        base = theta_catalog(T, m, s)
        thmax = float(np.max(np.abs(base)))
        floor = _torsion_noise_floor(T, m)
        extra = {"protocol": proto, "T0_Nm": T0, "noise_floor": floor}
        if cat in ("single", "pair"):
            objs = []
            forms = form.split("+")
            for e, f in zip(effs, forms):
                if e == "hysteresis":
                    o, par = _hysteresis_eff(rng, f, path, m)
                elif e == "backlash":
                    o, par = _backlash_eff(rng, f, path, m)
                else:
                    o, par = _housing_eff(rng, f, path, m, s)
                extra[e] = par
                objs.append(o)
            ident = _torsion_ident(theta_catalog(T, m, 1.0), s)
            al = _allocate(rng, objs, lambda cs, ps: sum(cs), mean_free=False, ident=ident, sigma_min=floor)
            if al is None:
                continue
            sig, ps, eff, ks = al
            extra["ident_k"] = ident(eff) / sig
            nm = _effect_noise_model(rng)
            noise, ninfo = _noise(rng, len(T), sig, nm)
            extra.update(noise=ninfo, k_per_effect=dict(zip(effs, ks)), strengths=dict(zip(effs, ps)))
            gear = _order_pair(list(effs), [o.contrib(p) for o, p in zip(objs, ps)], False, ident) \
                if len(effs) == 2 else effs
            return _finish(f"o-torsion-{cat}-{'+'.join(effs)}-{slug}-{proto}-{idx:03d}", "torsion", m,
                           {"torque_Nm": T}, base + eff, noise, eff, mean_free=False, gear=gear, nuis=nuis,
                           cat=cat, form=form, extra=extra)
        sigma0 = max(thmax * rng.uniform(0.004, 0.02), floor)
        if cat == "clean":
            noise, ninfo = _noise(rng, len(T), sigma0, form)
            extra["noise"] = ninfo
            return _finish(f"o-torsion-clean-{slug}-{proto}-{idx:03d}", "torsion", m, {"torque_Nm": T}, base,
                           noise, None, mean_free=False, nuis=nuis, cat="clean", form=form, extra=extra)
        # ---- decoys ----
        meas, units, equiv, snr_exempt = (), {}, (), False
        Tcol = T.copy()
        u_time = path.t / path.total
        if slug == "torque-gain":
            sgn = rng.choice([-1.0, 1.0])
            fn = lambda p: theta_catalog(T, m, s) - theta_catalog((1 + sgn * p) * T, m, s)
            p, eff, sig = _size_decoy(rng, fn, 0.02, 0.12, sigma0, False, linear=False)
            Tcol = (1 + sgn * p) * T
            meas_clean = base
            meas = ("sensor_gain",)
            extra["torque_gain"] = 1 + sgn * p
        elif slug == "twist-gain":
            sgn = rng.choice([-1.0, 1.0])
            p, eff, sig = _size_decoy(rng, lambda p: sgn * p * base, 0.02, 0.12, sigma0, False)
            meas_clean = base + eff
            meas = ("sensor_gain",)
            extra["twist_gain"] = 1 + sgn * p
        elif slug == "offset-steps":
            c0 = rng.uniform(-1, 1)
            nstep = int(rng.integers(1, 3))
            tst = np.sort(rng.uniform(0.25, 0.85, nstep))
            amps = rng.uniform(0.5, 1.5, nstep) * rng.choice([-1.0, 1.0], nstep)
            shape = c0 + sum(a * (u_time >= ts) for a, ts in zip(amps, tst))
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 1e-7, 0.05, sigma0, False)
            meas_clean = base + eff
            meas = ("angle_offset",)
        elif slug == "drift-ramplag":
            lam = rng.uniform(0.1, 0.5)
            shape = _ramp_lag(u_time, lam) * rng.choice([-1.0, 1.0])
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 1e-7, 0.05, sigma0, False)
            meas_clean = base + eff
            meas = ("thermal_drift",)
        elif slug == "drift-travel":
            # self-heating drift proportional to the cumulative torque travel (loop energy heats
            # the fixture and the autocollimator base): d = D * L(t) / L(end), L = int |dT|
            Ld = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(path.T_dense)))])
            shape = (Ld / Ld[-1])[path.idx] * rng.choice([-1.0, 1.0])
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 1e-7, 0.05, sigma0, False)
            meas_clean = base + eff
            meas = ("thermal_drift",)
        elif slug in ("units-deg", "units-mrad", "units-kNm"):
            sig = sigma0
            eff = None
            meas_clean = base
            meas = ("wrong_units",)
            snr_exempt = True
            if slug == "units-deg":
                units = {"twist_rad": DEG}
            elif slug == "units-mrad":
                units = {"twist_rad": 1e3}
            else:
                units = {"torque_Nm": 1e-3}
        elif slug == "stiff-out":
            s_out = rng.uniform(1.15, 1.30)
            nuis = {"stiffness_scale": s_out}
            base = theta_catalog(T, m, s_out)
            eff = base - theta_catalog(T, m, 1.10)
            sig = _rms(eff) / rng.uniform(K_MIN, K_MAX)
            meas_clean = base
        elif slug == "emi-pickup":
            P = path.total * rng.uniform(0.01, 0.05)
            ph = rng.uniform(0, 2 * np.pi)
            shape = np.sin(2 * np.pi * path.t / P + ph)
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 1e-8, 0.01, sigma0, False)
            meas_clean = base + eff
            meas = ("emi_pickup",)
            extra["period_s"] = P
        elif slug == "soft-gear":
            s_soft = rng.uniform(0.65, 0.82)
            nuis = {"stiffness_scale": s_soft}
            base = theta_catalog(T, m, s_soft)
            eff = base - theta_catalog(T, m, 0.90)
            sig = _rms(eff) / rng.uniform(K_MIN, K_MAX)
            meas_clean = base
            equiv = ("housing_compliance",)
        elif slug == "sampling-skew":
            # scanning DMM reads the twist channel tau after the torque channel
            def fn(tau):
                return theta_catalog(path.torque_at(path.t + tau), m, s) - base
            leg = path.total / (4 * path.ncyc + 2)
            tau, eff, sig = _size_decoy(rng, fn, 1e-4 * leg, 0.05 * leg, sigma0, False, linear=False)
            meas_clean = base + eff
            meas = ("sampling_skew",)
            equiv = ("hysteresis",)
            extra["skew_s"] = tau
        elif slug == "mirror-seat":
            # the autocollimator mirror rocks between two seats of its kinematic mount when the
            # torque passes +-Tf (a relay with thresholds, i.e. play held by friction)
            Tf = rng.uniform(0.03, 0.12) * T0
            st = np.zeros_like(path.T_dense)
            cur = 0.0
            for i, tq in enumerate(path.T_dense):
                if tq >= Tf:
                    cur = 1.0
                elif tq <= -Tf:
                    cur = -1.0
                st[i] = cur
            shape = 0.5 * st[path.idx]
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 0.3 * m.backlash_rad, 3.0 * m.backlash_rad,
                                      sigma0, False)
            meas_clean = base + eff
            meas = ("mirror_seat_rocking",)
            equiv = ("backlash",)
        else:
            raise ValueError(slug)
        if sig < floor:                       # keep the noise floor; k must stay in [4, 12]
            sig = floor
            if eff is not None and _rms(eff) / sig < K_MIN:
                continue
        noise, ninfo = _noise(rng, len(T), sig, _effect_noise_model(rng))
        extra["noise"] = ninfo
        return _finish(f"o-torsion-{cat}-{slug}-{proto}-{idx:03d}", "torsion", m, {"torque_Nm": Tcol},
                       meas_clean, noise, eff, mean_free=False, meas=meas, nuis=nuis, cat=cat, equiv=equiv,
                       form=form, units=units, snr_exempt=snr_exempt, extra=extra)
    raise RuntimeError(f"torsion cell {cell} could not be generated")


# ----------------------------------------------------------------------------------------------
# TRANSMISSION builder
# ----------------------------------------------------------------------------------------------
def _te_params(rng, form, vib=False):
    if form == "wcauchy":
        return {"rho": float(rng.uniform(0.15, 0.25) if vib else rng.uniform(0.2, 0.4))}
    if form == "trapezoid":
        return {"r": float(rng.uniform(0.35, 0.8))}
    return {}


def _transmission(rng, models, cell, idx):
    cat, effs, form, slug = cell["category"], cell["effects"], cell["form"], cell["slug"]
    pool = [m for m in models if m.accuracy_rad]
    for attempt in range(200):
        m = pool[int(rng.integers(len(pool)))]
        R = m.ratio
        acc = m.accuracy_rad
        nrev = int(rng.integers(3, 9))
        spr = int(rng.choice([360, 400, 512, 720]))
        N = nrev * spr + 1
        th0 = rng.uniform(0, 2 * np.pi)
        th_in = th0 + np.linspace(0, 2 * np.pi * nrev, N)
        off = rng.uniform(-np.pi, np.pi)
        nuis = {"output_offset_rad": off}
        base = th_in / R + off
        cols = {"input_angle_rad": th_in}
        extra = {"revolutions": nrev, "samples_per_rev": spr}
        if cat in ("single", "pair"):
            objs = []
            for e in effs:
                k = 1 if e == "te_1x" else 2
                par = _te_params(rng, form)
                ph = rng.uniform(0, 2 * np.pi)
                shape = _te_wave(form, k * th_in + ph, par)
                lo, hi = (0.06, 0.25) if k == 1 else (0.12, 0.35)
                objs.append(_Eff(e, (lambda sh: (lambda p: p * sh))(shape), lo * acc, hi * acc))
                extra[e] = dict(par, phase=ph)
            al = _allocate(rng, objs, lambda cs, ps: sum(cs), mean_free=True)
            if al is None:
                continue
            sig, ps, eff, ks = al
            if np.ptp(eff) > acc:            # catalog accuracy is the maximum error
                continue
            noise, ninfo = _noise(rng, N, sig, _effect_noise_model(rng))
            extra.update(noise=ninfo, k_per_effect=dict(zip(effs, ks)), amplitudes=dict(zip(effs, ps)))
            gear = _order_pair(list(effs), [o.contrib(p) for o, p in zip(objs, ps)], True) if len(effs) == 2 else effs
            return _finish(f"o-transmission-{cat}-{'+'.join(effs)}-{slug}-{idx:03d}", "transmission", m, cols,
                           base + eff, noise, eff, mean_free=True, gear=gear, nuis=nuis, cat=cat, form=form,
                           extra=extra)
        sigma0 = acc * rng.uniform(0.01, 0.05)
        if cat == "clean":
            noise, ninfo = _noise(rng, N, sigma0, form)
            extra["noise"] = ninfo
            return _finish(f"o-transmission-clean-{slug}-{idx:03d}", "transmission", m, cols, base, noise, None,
                           mean_free=True, nuis=nuis, form=form, extra=extra)
        meas, units, equiv, exempt = (), {}, (), False
        th_out = base
        u = np.linspace(0, 1, N)
        if slug == "encoder-oval":
            # eccentric and oval output-encoder disc: 1x and 2x per OUTPUT revolution
            r2 = rng.uniform(0.2, 0.6)
            p1, p2 = rng.uniform(0, 2 * np.pi, 2)
            shape = np.sin(th_out + p1) + r2 * np.sin(2 * th_out + p2)
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 1e-6, 2e-3, sigma0, True)
            meas_clean = base + eff
            meas = ("encoder_eccentricity",)
        elif slug == "offset-step":
            ts = rng.uniform(0.3, 0.7)
            shape = (u >= ts).astype(float) * rng.choice([-1.0, 1.0])
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 1e-7, 1e-2, sigma0, True)
            meas_clean = base + eff
            meas = ("angle_offset",)
        elif slug == "output-gain":
            sgn = rng.choice([-1.0, 1.0])
            p, eff, sig = _size_decoy(rng, lambda p: sgn * p * th_out, 1e-5, 2e-2, sigma0, True)
            meas_clean = base + eff
            meas = ("sensor_gain",)
            extra["output_gain"] = 1 + sgn * p
        elif slug == "drift-ramplag":
            shape = _ramp_lag(u, rng.uniform(0.1, 0.5)) * rng.choice([-1.0, 1.0])
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 1e-7, 1e-2, sigma0, True)
            meas_clean = base + eff
            meas = ("thermal_drift",)
        elif slug in ("units-deg-out", "units-deg-in"):
            sig, eff, meas_clean = sigma0, None, base
            meas, exempt = ("wrong_units",), True
            units = {"output_angle_rad": DEG} if slug == "units-deg-out" else {"input_angle_rad": DEG}
        elif slug == "interp-heydemann":
            # sub-divisional error of the output encoder's quadrature interpolation (Heydemann
            # 1981): signal offsets -> 1x per grating pitch, gain imbalance/quadrature -> 2x
            Nl = int(rng.choice([512, 1024, 2048]))
            while Nl > spr * R / 20 and Nl > 128:
                Nl //= 2
            a1, a2 = rng.uniform(0.01, 0.05), rng.uniform(0.005, 0.03)
            q1, q2 = rng.uniform(0, 2 * np.pi, 2)
            Phi = Nl * th_out
            shape = (a1 * np.sin(Phi + q1) + a2 * np.sin(2 * Phi + q2)) / Nl
            eff = shape
            sig = _eff_rms(eff, True) / rng.uniform(K_MIN, K_MAX)
            meas_clean = base + eff
            meas = ("interpolation_error",)
            extra["lines"] = Nl
        elif slug in ("magnetic-1x", "magnetic-2x"):
            # input read by a magnetic (diametric-magnet) encoder: an off-axis magnet gives a 1x,
            # a tilted / non-uniform magnet a 2x error per INPUT revolution on the input column
            k = 1 if slug == "magnetic-1x" else 2
            ph = rng.uniform(0, 2 * np.pi)
            shape_in = np.sin(k * th_in + ph)
            eps_max = min(math.radians(1.2), 0.4 * acc * R)
            fn = lambda p: -p * shape_in / R
            p, eff, sig = _size_decoy(rng, fn, math.radians(0.05), eps_max, sigma0, True)
            cols = {"input_angle_rad": th_in + p * shape_in}
            meas_clean = base
            eff = -p * shape_in / R          # apparent TE w.r.t. the recorded input angle
            meas = ("input_encoder_error",)
            equiv = ("te_1x",) if k == 1 else ("te_2x",)
            extra["encoder_error_rad"] = p
        else:
            raise ValueError(slug)
        noise, ninfo = _noise(rng, N, sig, _effect_noise_model(rng))
        extra["noise"] = ninfo
        return _finish(f"o-transmission-{cat}-{slug}-{idx:03d}", "transmission", m, cols, meas_clean, noise, eff,
                       mean_free=True, meas=meas, nuis=nuis, cat=cat, equiv=equiv, form=form, units=units,
                       snr_exempt=exempt, extra=extra)
    raise RuntimeError(f"transmission cell {cell} could not be generated")


# ----------------------------------------------------------------------------------------------
# EFFICIENCY builder
# ----------------------------------------------------------------------------------------------
_LEVEL_SPREAD = (70.0, 85.0)


def _eff_grid(rng, m, lub_window, proto):
    """Test grid. factorial: 3-4 input speeds x 8-10 load ratios x 4-5 lubricant set-points,
    the recorded lubricant temperature is the set-point plus a self-heating rise that grows with
    speed and load (0.5-4 K at full speed and load).  random: 150-250 points, speed uniform,
    load ratio log-uniform, temperature uniform, rows in (randomised) run order."""
    tlo, thi = lub_window
    nmax = min(m.avg_speed_max, 3000.0)
    if proto == "factorial":
        speeds = np.array([s for s in (500, 1000, 1500, 2000, 2500, 3000) if s <= nmax])
        speeds = np.sort(rng.choice(speeds, size=min(len(speeds), int(rng.integers(3, 5))), replace=False))
        alphas = np.array([0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1])
        alphas = np.sort(rng.choice(alphas, size=int(rng.integers(8, 11)), replace=False))
        temps = np.linspace(tlo, thi, int(rng.integers(4, 6)))
        S, A, Tm = np.meshgrid(speeds, alphas, temps, indexing="ij")
        S, A, Tm = S.ravel(), A.ravel(), Tm.ravel()
        rise = rng.uniform(0.5, 4.0)
        Tm = Tm + rise * (S / nmax) * (0.3 + 0.7 * np.minimum(A, 1.2)) + rng.normal(0, 0.1, S.size)
        order = np.lexsort((A, S, np.round(Tm, -1)))
        S, A, Tm = S[order], A[order], Tm[order]
    else:
        n = int(rng.integers(150, 251))
        S = np.round(rng.uniform(300, nmax, n), -1)
        A = np.exp(rng.uniform(math.log(0.08), math.log(1.15), n))
        Tm = rng.uniform(tlo, thi, n)
    return S.astype(float), A.astype(float), Tm.astype(float)


def _lub_choice(rng, m, lubs):
    names = [g for g, r in m.greases if g in lubs]
    g = names[int(rng.integers(len(names)))] if names else "SK-1A"
    lo, hi = lubs.get(g, (0.0, 40.0))
    return g, (max(lo, -10.0), min(hi + 30.0, 80.0))


def _efficiency(rng, models, lubs, cell, idx):
    cat, effs, form, slug = cell["category"], cell["effects"], cell["form"], cell["slug"]
    needs_csf = "low_load_efficiency" in effs or slug in ("bearing-drag", "seal-drag")
    pool = [m for m in models if m.series == "CSF"] if needs_csf else models
    proto = "factorial" if idx % 2 == 0 else "random"
    for attempt in range(200):
        m = pool[int(rng.integers(len(pool)))]
        g, win = _lub_choice(rng, m, lubs)
        S, A, Tm = _eff_grid(rng, m, win, proto)
        Tload = A * m.rated_Nm
        eta0 = rng.uniform(*_LEVEL_SPREAD)
        nuis = {"efficiency_level_pct": eta0}
        Tref = round(0.5 * (win[0] + win[1]))
        extra = {"protocol": proto, "lubricant": g, "T_ref_C": Tref}
        cols = {"input_speed_rpm": S, "load_torque_Nm": Tload, "temperature_C": Tm}
        base = np.full(S.size, eta0)
        nu40 = rng.uniform(60, 160)
        nu100 = nu40 / rng.uniform(6.5, 10.0)
        if cat in ("single", "pair"):
            ke_fn = None
            tf = None
            forms = form.split("+")
            for e, f in zip(effs, forms):
                if e == "low_load_efficiency":
                    if f == "inclined-plane":
                        gam, mui, ac = rng.uniform(math.radians(20), math.radians(40)), rng.uniform(0.03, 0.08), rng.uniform(0.05, 0.3)
                        def ke_of_d(d, gam=gam, mui=mui, ac=ac):
                            dmu_max = 0.9 * (1 - mui) * (0.08 + ac) / ac     # keep g + rho < 90 deg
                            dmu = _solve_monotone(lambda q: 1 - float(_ke_inclined(0.58, gam, mui, q, ac)),
                                                  0.0, dmu_max, d)
                            return _ke_inclined(A, gam, mui, dmu, ac)
                        extra[e] = {"gamma_rad": gam, "mu_inf": mui, "alpha_c": ac}
                    else:
                        a50, sd = rng.uniform(0.1, 0.45), rng.uniform(0.5, 1.2)
                        def ke_of_d(d, a50=a50, sd=sd):
                            xb = 1 - _solve_monotone(lambda q: 1 - float(_ke_lognormal(0.58, 1 - q, a50, sd)), 0.0, 0.85, d)
                            return _ke_lognormal(A, xb, a50, sd)
                        extra[e] = {"alpha50": a50, "s": sd}
                    ke_fn = ke_of_d
                else:
                    if f == "myega-additive":
                        nu = _visc_fit("myega", nu40, nu100)
                        pexp = rng.uniform(0.25, 0.5)
                        ratio = (nu(Tm) / nu(Tref)) ** pexp - 1.0
                        tf = ("add", lambda Aamp, ratio=ratio: -Aamp * ratio)
                        extra[e] = {"nu40": nu40, "nu100": nu100, "p": pexp}
                        trange = (1.5, 10.0)
                    else:
                        nu = _visc_fit("avramov", nu40, nu100)
                        mm, epsr, lg = rng.uniform(0.5, 0.9), rng.uniform(0.05, 0.2), rng.uniform(0.5, 3.0)
                        def mu_app(TC, n):
                            lam = lg * nu(TC) / nu(Tref)
                            return nu(TC) * (epsr + (1 - epsr) / (1 + (lam * n / 1000.0) ** mm))
                        lr = np.log(mu_app(Tm, S) / mu_app(Tref, S))
                        tf = ("mul", lambda beta, lr=lr: np.exp(-beta * lr))
                        extra[e] = {"nu40": nu40, "nu100": nu100, "cross_m": mm, "eps": epsr, "lam_gdot": lg}
                        trange = (0.01, 0.10)

            def model_eta(d=None, q=None):
                ke = ke_fn(d) if (ke_fn is not None and d is not None) else 1.0
                eta = eta0 * ke
                if tf is not None and q is not None:
                    eta = eta + tf[1](q) if tf[0] == "add" else eta * tf[1](q)
                return eta * np.ones(S.size)

            objs = []
            for e in effs:
                if e == "low_load_efficiency":
                    objs.append(_Eff(e, lambda d: model_eta(d=d) - base, 0.035, 0.12, linear=False))
                else:
                    objs.append(_Eff(e, lambda q: model_eta(q=q) - base, trange[0], trange[1], linear=False))
            if len(effs) == 2:
                comb = lambda cs, ps: model_eta(d=ps[0], q=ps[1]) - base
            else:
                comb = lambda cs, ps: cs[0]
            al = _allocate(rng, objs, comb, mean_free=True)
            if al is None:
                continue
            sig, ps, eff, ks = al
            full = base + eff
            if full.max() > 97 or full.min() < 5:
                continue
            noise, ninfo = _noise(rng, S.size, sig, _effect_noise_model(rng))
            extra.update(noise=ninfo, k_per_effect=dict(zip(effs, ks)), strengths=dict(zip(effs, ps)))
            gear = _order_pair(list(effs), [o.contrib(p) for o, p in zip(objs, ps)], True) if len(effs) == 2 else effs
            return _finish(f"o-efficiency-{cat}-{'+'.join(effs)}-{slug}-{proto}-{idx:03d}", "efficiency", m, cols,
                           full, noise, eff, mean_free=True, gear=gear, nuis=nuis, cat=cat, form=form, extra=extra)
        sigma0 = rng.uniform(0.3, 1.5)
        if cat == "clean":
            noise, ninfo = _noise(rng, S.size, sigma0, form)
            extra["noise"] = ninfo
            return _finish(f"o-efficiency-clean-{slug}-{proto}-{idx:03d}", "efficiency", m, cols, base, noise, None,
                           mean_free=True, nuis=nuis, form=form, extra=extra)
        meas, units, equiv, exempt, mean_free = (), {}, (), False, True
        n_rows = S.size
        if slug in ("units-fraction", "units-kNm"):
            sig, eff, meas_clean = sigma0, None, base
            meas, exempt = ("wrong_units",), True
            units = {"efficiency_pct": 0.01} if slug == "units-fraction" else {"load_torque_Nm": 1e-3}
        elif slug == "torque-gain":
            # output torque meter gain g: the load column and the computed efficiency both scale
            sgn = rng.choice([-1.0, 1.0])
            lo_g = 0.02
            hi_g = min(0.08, (_LEVEL_SPREAD[1] + 5) / eta0 - 1 if sgn > 0 else 0.08)
            hi_g = max(hi_g, lo_g * 1.01)
            p, eff, sig = _size_decoy(rng, lambda p: sgn * p * base, lo_g, hi_g, sigma0, False)
            cols["load_torque_Nm"] = Tload * (1 + sgn * p)
            meas_clean = base + eff
            meas, mean_free = ("sensor_gain",), False
            extra["torque_gain"] = 1 + sgn * p
        elif slug == "level-out":
            if rng.random() < 0.5:
                eta_out, edge = rng.uniform(52.0, 63.0), _LEVEL_SPREAD[0]
            else:
                eta_out, edge = rng.uniform(88.0, 93.0), _LEVEL_SPREAD[1]
            nuis = {"efficiency_level_pct": eta_out}
            base = np.full(n_rows, eta_out)
            eff = base - edge
            sig = _rms(eff) / rng.uniform(K_MIN, K_MAX)
            meas_clean, mean_free = base, False
        elif slug == "drift-runorder":
            # rows are in run order; the input torque flange zero drifts as the rig warms up
            if proto == "factorial":
                perm = rng.permutation(n_rows)          # randomised run order for this decoy
                for c in cols:
                    cols[c] = cols[c][perm]
            u = np.linspace(0, 1, n_rows)
            shape = _ramp_lag(u, rng.uniform(0.1, 0.5)) * rng.choice([-1.0, 1.0])
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 0.05, 15.0, sigma0, True)
            meas_clean = base + eff
            meas = ("thermal_drift",)
        elif slug == "belt-slip":
            # output speed from a belt-driven pickup that slips in proportion to speed
            shape = -base * cols["input_speed_rpm"] / m.avg_speed_max
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 0.002, 0.08, sigma0, True)
            meas_clean = base + eff
            meas = ("speed_pickup_slip",)
        elif slug == "bearing-drag":
            # unsubtracted drag of the input torque flange's support bearings (input side):
            # eta_m = 1 / (1/eta + R T_d / T_out); T_d tied to the catalog no-load running torque
            run = m.running_Nm or 0.1
            R = m.ratio
            def fn(td):
                return 100.0 / (100.0 / base + R * td / Tload) - base
            p, eff, sig = _size_decoy(rng, fn, 0.02 * run, 1.0 * run, sigma0, True, linear=False)
            meas_clean = base + eff
            meas, equiv = ("input_bearing_drag",), ("low_load_efficiency",)
            extra["drag_input_Nm"] = p
        elif slug == "span-comp":
            # the rig software's span compensation of the torque flange uses a wrong temperature
            # coefficient: eta_m = eta (1 + kappa (T - T_ref))
            sgn = rng.choice([-1.0, 1.0])
            shape = base * (cols["temperature_C"] - Tref)
            p, eff, sig = _size_decoy(rng, lambda p: sgn * p * shape, 5e-4, 4e-3, sigma0, True)
            meas_clean = base + eff
            meas, equiv = ("span_compensation_error",), ("temperature_dependence",)
            extra["kappa_per_K"] = sgn * p
        elif slug == "seal-drag":
            # adaptor lip seal (ISO 6194) on the input side; elastomer friction rises in the cold:
            # T_s = T_s0 exp(-(T - T_ref)/theta_s)
            run = m.running_Nm or 0.1
            R = m.ratio
            th_s = rng.uniform(15.0, 35.0)
            sh = np.exp(-(cols["temperature_C"] - Tref) / th_s)
            def fn(ts0):
                return 100.0 / (100.0 / base + R * ts0 * sh / Tload) - base
            p, eff, sig = _size_decoy(rng, fn, 0.01 * run, 0.6 * run, sigma0, True, linear=False)
            meas_clean = base + eff
            meas, equiv = ("seal_drag",), ("low_load_efficiency", "temperature_dependence")
            extra["seal_drag_ref_Nm"] = p
        else:
            raise ValueError(slug)
        if meas_clean.min() < 5 or meas_clean.max() > 97:
            continue
        noise, ninfo = _noise(rng, n_rows, sig, _effect_noise_model(rng))
        extra["noise"] = ninfo
        return _finish(f"o-efficiency-{cat}-{slug}-{proto}-{idx:03d}", "efficiency", m, cols, meas_clean, noise,
                       eff, mean_free=mean_free, meas=meas, nuis=nuis, cat=cat, equiv=equiv, form=form,
                       units=units, snr_exempt=exempt, extra=extra)
    raise RuntimeError(f"efficiency cell {cell} could not be generated")


# ----------------------------------------------------------------------------------------------
# VIBRATION builder
# ----------------------------------------------------------------------------------------------
def _vibration(rng, models, cell, idx):
    cat, effs, form, slug = cell["category"], cell["effects"], cell["form"], cell["slug"]
    pool = [m for m in models if m.accuracy_rad]
    if form in ("tustin-servo", "park-sinh"):
        integ, ru, wave = ("tustin", "servo", "cos") if form == "tustin-servo" else ("park", "sinh", "wcauchy")
    else:
        integ, ru, wave = ("tustin", "servo", "cos") if idx % 2 == 0 else ("park", "sinh", "cos")
    for attempt in range(200):
        m = pool[int(rng.integers(len(pool)))]
        R, acc = m.ratio, m.accuracy_rad
        fmax = min(60.0, m.max_speed / 78.0)
        if fmax < 20:
            continue
        fn_cat = rng.uniform(15.0, fmax)                      # design f_n from catalog K1 and J
        J = m.K1 / (2 * math.pi * fn_cat) ** 2
        s = _logit_normal_scale(rng)
        zeta = rng.uniform(0.05, 0.15)
        fn = fn_cat * math.sqrt(s)
        wn = 2 * math.pi * fn
        nuis = {"stiffness_scale": s, "damping_ratio": zeta}
        orders = (1, 2)
        cog_q = None
        if slug in ("cogging", "units-deg-cogging"):
            cog_q = int(rng.choice([6, 8, 10, 12]))
            n_lo = 0.6 * 60.0 * fn_cat / cog_q
            orders = (1, 2, cog_q)
        else:
            n_lo = 0.6 * 30.0 * fn_cat
        n_hi = 1.3 * 60.0 * fn_cat
        run = _RunUp(rng, ru, n_lo, n_hi, fn_cat, zeta, orders=(1, 2))
        f_out = 10.0 * 2 * n_hi / 60.0
        if cog_q:
            f_out = max(f_out, 5.0 * cog_q * n_hi / 60.0)
        f_out = max(f_out, 200.0)
        mfine = 2 if integ == "tustin" else max(2, int(math.ceil(wn / (0.06 * f_out))))
        h = 1.0 / (f_out * mfine)
        T_pre = 8.0 / (zeta * wn)
        t = np.arange(-T_pre, run.T, h)
        n_rpm = run.speed(t)
        th_in = np.concatenate([[0.0], np.cumsum(0.5 * (n_rpm[1:] + n_rpm[:-1]) * h)]) * 2 * math.pi / 60.0
        th_in += rng.uniform(0, 2 * np.pi)
        win = np.clip((t + T_pre) / (0.5 * T_pre), 0, 1)
        win = 0.5 - 0.5 * np.cos(np.pi * win)                     # soft start in the pre-roll
        keep = np.nonzero(t >= 0)[0][::mfine]
        t_out = t[keep] - t[keep][0]
        if t_out.size > 90000:
            continue
        cols = {"time_s": t_out, "input_speed_rpm": n_rpm[keep]}
        extra = {"integrator": integ, "runup": ru, "f_n_Hz": fn, "J": J, "sample_rate_Hz": f_out}

        def resp(e_shape):
            return _vib_response(win * e_shape, wn, zeta, h, integ)[keep]

        if cat in ("single", "pair"):
            objs, shapes = [], []
            for e in effs:
                k = 1 if e == "te_1x" else 2
                par = _te_params(rng, wave, vib=True)
                ph = rng.uniform(0, 2 * np.pi)
                sh = _te_wave(wave, k * th_in + ph, par)
                y = resp(sh)
                shapes.append(sh[keep])
                lo, hi = (0.06, 0.25) if k == 1 else (0.12, 0.35)
                objs.append(_Eff(e, (lambda yy: (lambda p: p * yy))(y), lo * acc, hi * acc))
                extra[e] = dict(par, phase=ph)
            al = _allocate(rng, objs, lambda cs, ps: sum(cs), mean_free=False)
            if al is None:
                continue
            sig, ps, eff, ks = al
            if np.ptp(sum(p * sh for p, sh in zip(ps, shapes))) > acc:   # TE within the accuracy
                continue
            noise, ninfo = _noise(rng, t_out.size, sig, _effect_noise_model(rng))
            extra.update(noise=ninfo, k_per_effect=dict(zip(effs, ks)), amplitudes=dict(zip(effs, ps)))
            gear = _order_pair(list(effs), [o.contrib(p) for o, p in zip(objs, ps)], False) if len(effs) == 2 else effs
            return _finish(f"o-vibration-{cat}-{'+'.join(effs)}-{slug}-{idx:03d}", "vibration", m, cols, eff, noise,
                           eff, mean_free=False, J=J, gear=gear, nuis=nuis, cat=cat, form=form, extra=extra)
        sigma0 = acc * rng.uniform(0.005, 0.03)
        zero = np.zeros(t_out.size)
        if cat == "clean":
            noise, ninfo = _noise(rng, t_out.size, sigma0, cell["noise"])
            extra["noise"] = ninfo
            return _finish(f"o-vibration-clean-{slug}-{idx:03d}", "vibration", m, cols, zero, noise, None,
                           mean_free=False, J=J, nuis=nuis, form=form, extra=extra)
        meas, units, equiv, exempt = (), {}, (), False
        u = t_out / t_out[-1]
        if slug in ("cogging", "units-deg-cogging"):
            # servo-motor cogging / torque ripple at order q per input revolution, seen at the
            # output as a kinematic excitation through the same spring (resonance at q f_in = f_n)
            ph = rng.uniform(0, 2 * np.pi)
            y = resp(np.sin(cog_q * th_in + ph))
            p, eff, sig = _size_decoy(rng, lambda p: p * y, 1e-3 * acc, 0.3 * acc, sigma0, False)
            meas_clean = eff
            meas = ("motor_cogging",)
            extra["cogging_order"] = cog_q
            if slug == "units-deg-cogging":
                meas, units, exempt = ("motor_cogging", "wrong_units"), {"output_vibration_rad": DEG}, True
        elif slug == "drift-ramplag":
            shape = _ramp_lag(u, rng.uniform(0.1, 0.5)) * rng.choice([-1.0, 1.0])
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 1e-8, 1e-2, sigma0, False)
            meas_clean = eff
            meas = ("thermal_drift",)
        elif slug == "offset-step":
            c0 = rng.uniform(-1, 1)
            shape = c0 + (u >= rng.uniform(0.3, 0.7)) * rng.choice([-1.0, 1.0])
            p, eff, sig = _size_decoy(rng, lambda p: p * shape, 1e-8, 1e-2, sigma0, False)
            meas_clean = eff
            meas = ("angle_offset",)
        elif slug in ("inloop-magnetic-1x", "inloop-magnetic-2x"):
            # the servo closes its position loop on a magnetic input encoder with a 1x (off-axis
            # magnet) or 2x (tilted magnet) error: the true input carries -eps, the output -eps/R
            k = 1 if slug.endswith("1x") else 2
            ph = rng.uniform(0, 2 * np.pi)
            y = resp(-np.sin(k * th_in + ph) / R)
            eps_max = min(math.radians(1.2), 0.35 * acc * R)
            p, eff, sig = _size_decoy(rng, lambda p: p * y, math.radians(0.05), eps_max, sigma0, False)
            meas_clean = eff
            meas = ("input_encoder_error",)
            equiv = ("te_1x",) if k == 1 else ("te_2x",)
            extra["encoder_error_rad"] = p
        else:
            raise ValueError(slug)
        noise, ninfo = _noise(rng, t_out.size, sig, _effect_noise_model(rng))
        extra["noise"] = ninfo
        return _finish(f"o-vibration-{cat}-{slug}-{idx:03d}", "vibration", m, cols, meas_clean, noise, eff,
                       mean_free=False, J=J, meas=meas, nuis=nuis, cat=cat, equiv=equiv, form=form, units=units,
                       snr_exempt=exempt, extra=extra)
    raise RuntimeError(f"vibration cell {cell} could not be generated")


# ----------------------------------------------------------------------------------------------
# the cell list
# ----------------------------------------------------------------------------------------------
CLEAN_NOISES = ("white", "ar1", "white-outliers", "ar1-outliers", "telegraph", "ma2")


def _cells():
    cells = []

    def add(kind, cat, effects, form, slug, **kw):
        cells.append(dict(kind=kind, category=cat, effects=tuple(effects), form=form, slug=slug, **kw))

    # torsion
    for nz in CLEAN_NOISES:
        add("torsion", "clean", (), nz, nz)
    for f in ("dafalias-popov", "ivshin-pence"):
        add("torsion", "single", ("hysteresis",), f, f)
    for f in ("beta-smoothstep", "hill"):
        add("torsion", "single", ("backlash",), f, f)
    for f in ("ker-wilson", "polymer-pad"):
        add("torsion", "single", ("housing_compliance",), f, f)
    for a, b in (("dafalias-popov", "beta-smoothstep"), ("ivshin-pence", "hill")):
        add("torsion", "pair", ("hysteresis", "backlash"), f"{a}+{b}", f"{a}+{b}")
    for a, b in (("dafalias-popov", "polymer-pad"), ("ivshin-pence", "ker-wilson")):
        add("torsion", "pair", ("hysteresis", "housing_compliance"), f"{a}+{b}", f"{a}+{b}")
    for a, b in (("beta-smoothstep", "ker-wilson"), ("hill", "polymer-pad")):
        add("torsion", "pair", ("backlash", "housing_compliance"), f"{a}+{b}", f"{a}+{b}")
    for slug, form in (("torque-gain", "torque-sensor gain"), ("twist-gain", "twist-channel gain"),
                       ("offset-steps", "angle offset with re-zero steps"),
                       ("drift-ramplag", "ramp-lag thermal drift"),
                       ("drift-travel", "drift proportional to cumulative torque travel"),
                       ("units-deg", "twist in degrees"), ("units-mrad", "twist in milliradians"),
                       ("units-kNm", "torque in kN*m"), ("stiff-out", "stiffness scale above the spread"),
                       ("emi-pickup", "periodic EMI pickup on the twist channel")):
        add("torsion", "decoy_separable", (), form, slug)
    for slug, form in (("soft-gear", "gear softer than the spread"),
                       ("sampling-skew", "scanning-DMM channel skew"),
                       ("mirror-seat", "autocollimator mirror rocking in its kinematic seat")):
        add("torsion", "decoy_equivalent", (), form, slug)

    # transmission
    for nz in ("white", "ar1", "white-outliers", "telegraph", "ma2"):
        add("transmission", "clean", (), nz, nz)
    for e in ("te_1x", "te_2x"):
        for f in ("wcauchy", "trapezoid"):
            add("transmission", "single", (e,), f, f)
    for f in ("wcauchy", "trapezoid"):
        add("transmission", "pair", ("te_1x", "te_2x"), f, f)
    for slug, form in (("encoder-oval", "eccentric + oval output encoder disc"),
                       ("offset-step", "output encoder re-latch step"),
                       ("output-gain", "output encoder scale error"),
                       ("drift-ramplag", "ramp-lag thermal drift"),
                       ("units-deg-out", "output angle in degrees"), ("units-deg-in", "input angle in degrees"),
                       ("interp-heydemann", "Heydemann interpolation error of the output encoder")):
        add("transmission", "decoy_separable", (), form, slug)
    for slug, form in (("magnetic-1x", "magnetic input encoder, off-axis magnet (1x)"),
                       ("magnetic-2x", "magnetic input encoder, tilted magnet (2x)")):
        add("transmission", "decoy_equivalent", (), form, slug)

    # efficiency
    for nz in ("white", "ar1", "white-outliers", "telegraph", "ma2"):
        add("efficiency", "clean", (), nz, nz)
    for f in ("inclined-plane", "lognormal-share"):
        add("efficiency", "single", ("low_load_efficiency",), f, f)
    for f in ("myega-additive", "avramov-cross"):
        add("efficiency", "single", ("temperature_dependence",), f, f)
    for a, b in (("inclined-plane", "myega-additive"), ("lognormal-share", "avramov-cross")):
        add("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"), f"{a}+{b}", f"{a}+{b}")
    for slug, form in (("units-fraction", "efficiency as a fraction"), ("units-kNm", "load torque in kN*m"),
                       ("torque-gain", "output torque-meter gain"), ("level-out", "efficiency level outside spread"),
                       ("drift-runorder", "run-order drift of the input torque zero"),
                       ("belt-slip", "speed pickup slip proportional to speed")):
        add("efficiency", "decoy_separable", (), form, slug)
    for slug, form in (("bearing-drag", "unsubtracted input support-bearing drag"),
                       ("span-comp", "wrong span temperature compensation"),
                       ("seal-drag", "adaptor lip-seal drag stiffening in the cold")):
        add("efficiency", "decoy_equivalent", (), form, slug)

    # vibration
    for nz in ("white", "ar1", "white-outliers", "telegraph", "ma2"):
        add("vibration", "clean", (), nz, nz, noise=nz)
    for e in ("te_1x", "te_2x"):
        for f in ("tustin-servo", "park-sinh"):
            add("vibration", "single", (e,), f, f)
    for f in ("tustin-servo", "park-sinh"):
        add("vibration", "pair", ("te_1x", "te_2x"), f, f)
    for slug, form in (("cogging", "motor cogging at order 6-12"), ("drift-ramplag", "ramp-lag thermal drift"),
                       ("offset-step", "vibration channel offset and re-zero step"),
                       ("units-deg-cogging", "vibration in degrees (with motor cogging)")):
        add("vibration", "decoy_separable", (), form, slug)
    for slug, form in (("inloop-magnetic-1x", "in-loop magnetic input encoder, 1x"),
                       ("inloop-magnetic-2x", "in-loop magnetic input encoder, 2x")):
        add("vibration", "decoy_equivalent", (), form, slug)
    return cells


LABELS = {
    "dafalias-popov": "Dafalias-Popov two-surface (bounding-line) loop",
    "ivshin-pence": "Ivshin-Pence phase-fraction loop, Gaussian-CDF branches",
    "beta-smoothstep": "Beta(2,2) engagement dead zone (cubic smoothstep)",
    "hill": "Hill-function take-up",
    "ker-wilson": "stepped output shaft, Ker Wilson equivalent length",
    "polymer-pad": "housing on a polymer pad + Reissner-Sagoci half-space",
    "wcauchy": "odd-harmonic wrapped-Cauchy waveform",
    "trapezoid": "half-wave-symmetric trapezoid waveform",
    "inclined-plane": "Coulomb-wedge efficiency, load-dependent flank friction",
    "lognormal-share": "lognormal full-film share of tooth contacts",
    "myega-additive": "MYEGA viscosity, additive loss-fraction law",
    "avramov-cross": "Avramov-Milchev viscosity with Cross shear thinning, multiplicative",
    "tustin-servo": "Tustin (prewarped) integration, servo-lag run-up, sinusoidal TE",
    "park-sinh": "Park stiffly-stable integration, sinh sweep, odd-harmonic wrapped-Cauchy TE",
    "white": "white Gaussian", "ar1": "AR(1)", "white-outliers": "white + 0.5 % outliers",
    "ar1-outliers": "AR(1) + 0.5 % outliers", "telegraph": "random telegraph + white",
    "ma2": "MA(2) moving average",
}


def _label(cell):
    f = cell["form"]
    if cell["category"] in ("single", "pair", "clean"):
        return " + ".join(LABELS.get(x, x) for x in f.split("+"))
    return f


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    rng = np.random.default_rng(seed)
    models = load_models(catalog_dir)
    lubs = load_lubricants(catalog_dir)
    out = []
    for cell in _cells():
        for i in range(per_cell):
            k = cell["kind"]
            if k == "torsion":
                c = _torsion(rng, models, cell, i)
            elif k == "transmission":
                c = _transmission(rng, models, cell, i)
            elif k == "efficiency":
                c = _efficiency(rng, models, lubs, cell, i)
            else:
                c = _vibration(rng, models, cell, i)
            c.formulation = _label(cell)
            out.append(c)
    return out


def cell_list():
    """(kind, category, effects, formulation) of every cell, in generation order."""
    return [(c["kind"], c["category"], c["effects"], _label(c)) for c in _cells()]
