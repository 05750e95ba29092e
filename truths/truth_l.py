"""Independent truth suite "l" for ``hdcad reconcile``.

Written from /work/main/truths/CONTRACT.md, the catalog tables (catalog/*.csv), the seeds
(seed 000 p.020-023, seed 003 p.046-060) and the physics literature only.  numpy + scipy only;
nothing is imported from hdcad.  Every case is drawn from ``numpy.random.default_rng(seed)``.

The formulations are chosen to differ from those of suites B-K (see NOTES_l.md):
  torsion      sinh-spaced reversal legs, a lost-motion (small-then-full amplitude) protocol and a
               two-lock-angle protocol; hysteresis as Masing branches on a Hardin-Drnevich
               hyperbolic backbone (extended Masing rules: loop closure, skeleton rejoin) and as a Bliman-Sorine
               second-order path-length friction element in parallel with the gear spring (solved
               implicitly); backlash as an exponential take-up or a lock-angle dependent algebraic
               engagement; housing compliance from a bolted flange joint (Yoshimura/Ito joint
               stiffness) or a stepped keyed output shaft; decoys: bridge-excitation torque gain,
               preload zero offset, Joule-heating drift, degrees, kN.m, stiffness scale; equivalent:
               torque-flange windup, hydraulic-actuator seal friction, holding-brake spline play.
  transmission output-triggered sampling, time sampling with speed-loop ripple and full-output-
               revolution records; te_1x from hub-fit eccentricity / runout, te_2x as a circular-
               spline local pitch-error sector met by both lobes (von Mises pulse) or a soft-clipped
               2x; decoys: output-encoder eccentricity, coupling-slip step, degrees; equivalent:
               magnetic-tape input encoder, 2-pole-pair resolver channel offset.
  efficiency   Lazan flexspline damping law, PTFE lip-seal Coulomb drag, EP-additive tribofilm
               activation, housing/CS thermal-expansion mismatch; decoys: level, output-torque gain,
               fraction; equivalent: dynamometer Steinmetz core loss, calorimetric c_p (Cragoe).
  vibration    base (kinematic) excitation of the load through the gear spring, hyperbolic
               (constant-Q) and two-rate run-ups, Wilson-theta and Bathe-composite integration,
               Jacobsen equivalent damping from the catalog hysteresis loss; decoys: output-encoder
               eccentricity, motor-heating drift, index re-homing step; equivalent: resolver DC
               offset / amplitude imbalance inside the position loop.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import optimize

SUITE = "l"

DEG = 180.0 / math.pi


# --------------------------------------------------------------------------------------------
# the contract's dataclass
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
        names = list(self.columns)
        cols = [np.asarray(self.columns[n], dtype=float) for n in names]
        n = len(cols[0])
        lines = [",".join(names)]
        for i in range(n):
            lines.append(",".join(repr(float(c[i])) for c in cols))
        Path(path).write_text("\n".join(lines) + "\n")


# --------------------------------------------------------------------------------------------
# catalog
# --------------------------------------------------------------------------------------------
@dataclass
class Gear:
    code: str
    series: str
    size: int
    ratio: int
    T1: float
    T2: float
    K1: float
    K2: float
    K3: float
    rated: float            # rated torque at 2000 r/min input (050-1 / 058-1)
    hysteresis: float       # rad, 052 / 060 text
    backlash: float         # rad, 052-2 / 060-2 (maximum)
    accuracy: float | None  # rad, 051-1 / 059-1 (maximum)
    max_in_rpm: float
    avg_in_rpm: float
    running_torque: float   # N.m input, no load, 2000 r/min (051-1 / 059-1)


def _rows(catalog_dir, name):
    with open(Path(catalog_dir) / name, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _ratio_row(rows, series, ratio, size=None):
    for r in rows:
        if r["series"] != series or (size is not None and int(r["size"]) != size):
            continue
        lo = int(r["ratio_min"])
        hi = r["ratio_max"]
        if (hi and lo <= ratio <= int(hi)) or (not hi and ratio >= lo):
            return r
    return None


def load_gears(catalog_dir) -> list[Gear]:
    rat = _rows(catalog_dir, "gh_ratings_050-1_058-1.csv")
    stf = _rows(catalog_dir, "gh_stiffness_052-1_060-1.csv")
    hys = _rows(catalog_dir, "gh_hysteresis_052_060.csv")
    bkl = _rows(catalog_dir, "gh_backlash_052-2_060-2.csv")
    prf = _rows(catalog_dir, "gh_performance_051-1_059-1.csv")
    gears = []
    for r in rat:
        series, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
        s = _ratio_row(stf, series, ratio, size)
        h = _ratio_row(hys, series, ratio)
        b = [x for x in bkl if x["series"] == series and int(x["size"]) == size and int(x["ratio"]) == ratio]
        p = [x for x in prf if x["series"] == series and int(x["size"]) == size and int(x["ratio"]) == ratio]
        if s is None or h is None or not b or not p:
            continue
        acc = [float(x["accuracy_rad"]) for x in p if x["accuracy_rad"]]
        gears.append(Gear(
            code=f"{series.split('-')[0]}-{size}-{ratio}-GH", series=series, size=size, ratio=ratio,
            T1=float(s["T1_Nm"]), T2=float(s["T2_Nm"]), K1=float(s["K1_Nm_per_rad"]),
            K2=float(s["K2_Nm_per_rad"]), K3=float(s["K3_Nm_per_rad"]),
            rated=float(r["rated_torque_2000_Nm"]), hysteresis=float(h["hysteresis_rad"]),
            backlash=float(b[0]["backlash_rad"]), accuracy=acc[0] if acc else None,
            max_in_rpm=float(r["max_input_speed_rpm"]), avg_in_rpm=float(r["avg_input_speed_max_rpm"]),
            running_torque=float(p[0]["running_torque_cNm"]) / 100.0))
    gears.sort(key=lambda g: (g.series, g.size, g.ratio))
    return gears


def _seal_d1(catalog_dir):
    return np.array([float(r["d1_mm"]) for r in _rows(catalog_dir, "shaft_seal_iso6194.csv")])


def _hub_fit(catalog_dir):
    hub = {int(r["size"]): float(r["standard_H7_mm"]) for r in _rows(catalog_dir, "wg_hub_bore_027-1.csv")}
    fits = [(float(r["over_mm"]), float(r["upto_mm"]), float(r["IT7_um"]), float(r["IT6_um"]),
             float(r["g_es_below_zero_um"])) for r in _rows(catalog_dir, "iso286_h7_g6.csv")]
    return hub, fits


# --------------------------------------------------------------------------------------------
# small helpers
# --------------------------------------------------------------------------------------------
_CENTRED = {"on": False}


def _rms(x):
    """RMS of an effect.  Torsion and vibration: plain RMS (their baselines have no free offset).
    Transmission and efficiency: RMS about the mean (a constant is absorbed by the baseline's
    offset / level nuisance).  Switched by the kind being generated."""
    x = np.asarray(x, dtype=float)
    if _CENTRED["on"]:
        x = x - x.mean()
    return float(np.sqrt(np.mean(x ** 2)))


def _u(rng, a, b):
    return float(rng.uniform(a, b))


def _stiffness_scale(rng):
    """Catalog stiffness is an average value (003 p.052/060 '本表の値は、平均値です'); no spread
    is printed, so the contract's +-10 % is used, drawn as 1 + 0.1 tanh(N(0, 0.6))."""
    return 1.0 + 0.1 * math.tanh(0.6 * rng.standard_normal())


def _noise(rng, n, sigma, kind):
    """white or AR(1) (phi in [0.3, 0.8]); the realised sample RMS is exactly sigma.
    kind 'outliers' = white + 0.5 % of rows at 8-15 sigma (encoder/ADC glitches)."""
    info = {}
    if kind == "ar1":
        phi = _u(rng, 0.3, 0.8)
        w = rng.standard_normal(n)
        x = np.empty(n)
        x[0] = w[0] / math.sqrt(1 - phi * phi)
        for i in range(1, n):
            x[i] = phi * x[i - 1] + w[i]
        info["ar1_phi"] = phi
    else:
        x = rng.standard_normal(n)
    x = x - x.mean()
    x *= sigma / math.sqrt(np.mean(x * x))
    out = x.copy()
    if kind == "outliers":
        m = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, size=m, replace=False)
        out[idx] += rng.choice([-1.0, 1.0], size=m) * rng.uniform(8, 15, size=m) * sigma
        info["outlier_count"] = float(m)
    return out, info


def _sigma_single(rng, effect):
    k = _u(rng, 4.0, 12.0)
    return _rms(effect) / k


def _sigma_multi(rng, parts, total):
    """sigma such that every part and the total have RMS/sigma in [4, 12]; None if impossible."""
    rr = [_rms(p) for p in parts] + [_rms(total)]
    lo, hi = max(rr) / 12.0, min(rr) / 4.0
    if lo > hi:
        return None
    return math.exp(_u(rng, math.log(lo), math.log(hi)))


def _balance(ev1, ev2, maxratio=2.4):
    """amplitude multipliers (a1, a2) that bring two effects to an RMS ratio <= maxratio."""
    r1, r2 = _rms(ev1(1.0)), _rms(ev2(1.0))
    rho = r1 / r2
    if rho > maxratio:
        f = math.sqrt(rho / maxratio)
        return 1.0 / f, f
    if rho < 1.0 / maxratio:
        f = math.sqrt(1.0 / (rho * maxratio))
        return f, 1.0 / f
    return 1.0, 1.0


# --------------------------------------------------------------------------------------------
# TORSION
# --------------------------------------------------------------------------------------------
def catalog_twist(T, g: Gear, s=1.0):
    """Contract curve: theta = T/K1 up to T1, theta1 + (T-T1)/K2 up to T2, theta2 + (T-T2)/K3
    beyond; odd in T; theta1, theta2 continuous (computed from T1, K1, K2); stiffness x s."""
    K1, K2, K3 = g.K1 * s, g.K2 * s, g.K3 * s
    a = np.abs(np.asarray(T, dtype=float))
    th1 = g.T1 / K1
    th2 = th1 + (g.T2 - g.T1) / K2
    th = np.where(a <= g.T1, a / K1, np.where(a <= g.T2, th1 + (a - g.T1) / K2, th2 + (a - g.T2) / K3))
    return np.sign(T) * th


def _legs(points, n_leg, spacing=None):
    out = [np.array([points[0]])]
    for a, b in zip(points[:-1], points[1:]):
        s = np.linspace(0.0, 1.0, n_leg + 1)[1:]
        if spacing is not None:
            s = spacing(s)
        out.append(a + (b - a) * s)
    return np.concatenate(out)


def proto_sinh(rng, T0):
    """0 -> +T0, then 1-2 full cycles; each leg sampled densely near zero torque
    (u = sinh(beta x)/sinh(beta) on a uniform x), so the reversal region is well resolved."""
    beta = _u(rng, 1.5, 3.0)
    ncyc = int(rng.integers(1, 3))
    pts = [0.0, T0] + [-T0, T0] * ncyc
    n_leg = int(rng.integers(160, 300))
    segs = [np.array([0.0])]
    for a, b in zip(pts[:-1], pts[1:]):
        x = np.linspace(-1.0, 1.0, 2 * n_leg + 1)[1:] if a != 0.0 else np.linspace(0.0, 1.0, n_leg + 1)[1:]
        u = np.sinh(beta * x) / math.sinh(beta)
        if a == 0.0:
            segs.append(b * u)
        else:
            segs.append(0.5 * (a + b) + 0.5 * (b - a) * u)
    T = np.concatenate(segs)
    return T, {"protocol_beta": beta, "protocol_cycles": float(ncyc)}


def proto_lostmotion(rng, T0):
    """lost-motion protocol: two small cycles at +-lam*T0 (lam 4-10 %), back to zero, then the
    full 0 -> +T0 -> -T0 -> +T0 loop (seed loop 0-A-B-A'-B'-A); uniform torque steps."""
    lam = _u(rng, 0.04, 0.10)
    n_full = int(rng.integers(120, 220))
    dT = T0 / n_full
    pts = [0.0, lam * T0, -lam * T0, lam * T0, -lam * T0, 0.0, T0, -T0, T0]
    segs = [np.array([0.0])]
    for a, b in zip(pts[:-1], pts[1:]):
        m = max(8, int(round(abs(b - a) / dT)))
        segs.append(np.linspace(a, b, m + 1)[1:])
    return np.concatenate(segs), {"lost_motion_fraction": lam}


def proto_triangle(rng, T0):
    """plain triangle 0 -> +T0 -> -T0 -> +T0 -> -T0 -> 0, uniform steps."""
    n = int(rng.integers(150, 260))
    return _legs([0.0, T0, -T0, T0, -T0, 0.0], n), {}


def proto_twolock(rng, T0):
    """two full loops with the input locked at WG angle 0 deg, re-lock at 90 deg, two more
    (the Oldham clearance seen at the output depends on the lock orientation)."""
    n = int(rng.integers(110, 170))
    a = _legs([0.0, T0, -T0, T0, -T0, 0.0], n)
    b = _legs([0.0, T0, -T0, T0, -T0, 0.0], n)[1:]
    lock = np.concatenate([np.zeros(a.size), np.full(b.size, 90.0)])
    return np.concatenate([a, b]), {"lock": lock}


PROTOCOLS = {"sinh": proto_sinh, "lostmotion": proto_lostmotion, "triangle": proto_triangle,
             "twolock": proto_twolock}


def _time_from_torque(T, rate):
    dt = np.abs(np.diff(T, prepend=T[0])) / rate
    return np.cumsum(dt)


def _reversal_dir(T):
    d = np.sign(np.diff(T, prepend=T[0]))
    for i in range(1, d.size):
        if d[i] == 0:
            d[i] = d[i - 1]
    if d.size > 1 and d[0] == 0:
        d[0] = d[1]
    return d


# ---- hysteresis H1: extended Masing rules on a Hardin-Drnevich hyperbolic backbone ----------
def masing(T, gfun):
    """Extended Masing: skeleton h = g(T); a branch from reversal (Tr, hr) is
    h = hr + 2 g((T - Tr)/2); a branch that passes the previous reversal point closes the loop
    and resumes the earlier branch; passing the skeleton's extreme rejoins the skeleton."""
    h = np.empty(T.size)
    stack = []
    vmax = 0.0
    direction = 0.0
    prev = T[0]
    for i, t in enumerate(T):
        d = np.sign(t - prev) if i else 0.0
        if d != 0 and direction != 0 and d != direction:
            stack.append((prev, h[i - 1]))
        if d != 0:
            direction = d
        while len(stack) >= 2 and direction * (t - stack[-2][0]) >= 0:
            stack.pop()
            stack.pop()
        if len(stack) == 1 and abs(t) >= vmax and np.sign(t) == direction:
            stack.pop()
        if not stack:
            h[i] = gfun(t)
            vmax = max(vmax, abs(t))
        else:
            Tr, hr = stack[-1]
            h[i] = hr + 2.0 * gfun((t - Tr) / 2.0)
        prev = t
    return h


def eff_hyst_masing_hd(rng, g, s, T0, T):
    rho = _u(rng, 0.55, 0.85)          # T0 / tau_max of the hyperbolic backbone
    tau = T0 / rho
    delta = g.hysteresis * _u(rng, 0.6, 1.3)

    def gb(x, c=1.0):
        return c * x / (1.0 - np.abs(x) / tau)

    # loss at zero torque of the +-T0 major loop: 2 g(T0) - 4 g(T0/2) (per unit c)
    unit = 2 * gb(T0) - 4 * gb(T0 / 2)
    c = delta / unit

    def ev(amp):
        gg = lambda x: gb(x, c * amp)
        h = masing(T, gg)
        centre = gg((T0 + T) / 2.0) - gg((T0 - T) / 2.0)
        return h - centre
    return ev, {"hyst_loss_rad": delta, "hd_T0_over_taumax": rho}


# ---- hysteresis H2: Bliman-Sorine 2nd-order friction in parallel with the gear spring -------
def eff_hyst_bliman_sorine(rng, g, s, T0, T):
    delta = g.hysteresis * _u(rng, 0.6, 1.3)
    Fss = 0.5 * delta * g.K1 * s                       # residual twist at zero = 2 Fss / K1
    p = _u(rng, 0.1, 0.4)                              # f2 / Fss (stiction overshoot)
    eta = _u(rng, 0.2, 0.5)
    eps = _u(rng, 0.06, 0.18) * float(catalog_twist(T0, g, s))   # presliding path length
    base = catalog_twist(T, g, s)
    K1, K2, K3 = g.K1 * s, g.K2 * s, g.K3 * s
    th1 = g.T1 / K1
    th2 = th1 + (g.T2 - g.T1) / K2

    def tw(x):
        a = abs(x)
        v = a / K1 if a <= g.T1 else (th1 + (a - g.T1) / K2 if a <= g.T2 else th2 + (a - g.T2) / K3)
        return v if x >= 0 else -v

    def ev(amp):
        f1, f2 = (1 + p) * Fss * amp, p * Fss * amp
        x1 = x2 = 0.0
        th_prev = 0.0
        out = np.empty(T.size)
        fmax = f1 + f2
        for i, t in enumerate(T):
            def upd(th):
                dth = th - th_prev
                ds = abs(dth)
                sg = math.copysign(1.0, dth) if ds > 0 else 0.0
                e1 = math.exp(-ds / (eta * eps))
                e2 = math.exp(-ds / eps)
                return x1 * e1 + f1 * sg * (1 - e1), x2 * e2 - f2 * sg * (1 - e2)

            def gfun(th):
                a, b = upd(th)
                return th - tw(t - (a + b))
            lo = tw(t - fmax) - 1e-12
            hi = tw(t + fmax) + 1e-12
            th = optimize.brentq(gfun, lo, hi, xtol=1e-15, rtol=1e-12)
            x1, x2 = upd(th)
            th_prev = th
            out[i] = th
        return out - base
    return ev, {"hyst_loss_rad": delta, "bs_steady_friction_Nm": Fss, "bs_overshoot": p,
                "bs_eta": eta, "bs_presliding_rad": eps}


# ---- backlash ----------------------------------------------------------------------------
def eff_backlash_exp(rng, g, s, T0, T, extra=None):
    """exponential take-up of the Oldham clearance: e = sgn(T) b/2 (1 - exp(-|T|/Te))."""
    b = g.backlash * _u(rng, 0.6, 1.5)
    Te = _u(rng, 0.004, 0.02) * T0

    def ev(amp):
        return np.sign(T) * 0.5 * b * amp * (1.0 - np.exp(-np.abs(T) / Te))
    return ev, {"backlash_rad": b, "takeup_torque_Nm": Te}


def eff_backlash_twolock(rng, g, s, T0, T, extra=None):
    """algebraic engagement e = b/2 x/sqrt(1+x^2), x = T/Tw, with the clearance seen at the output
    depending on the input lock angle phi: b(phi) = b0 sqrt(cos^2 phi + r^2 sin^2 phi)."""
    b0 = g.backlash * _u(rng, 0.6, 1.4)
    r = _u(rng, 0.55, 0.95)
    Tw = _u(rng, 0.002, 0.008) * T0
    lock = np.radians(extra["lock"]) if extra and "lock" in extra else np.zeros(T.size)
    b = b0 * np.sqrt(np.cos(lock) ** 2 + (r * np.sin(lock)) ** 2)

    def ev(amp):
        x = T / Tw
        return 0.5 * b * amp * x / np.sqrt(1.0 + x * x)
    return ev, {"backlash_rad": b0, "backlash_ratio_90deg": r, "engage_torque_Nm": Tw}


# ---- housing compliance (linear series spring) ---------------------------------------------
def eff_housing_joint(rng, g, s, T0, T, extra=None):
    """bolted output-flange interface: tangential joint stiffness per unit area
    k_t = alpha p^m (Yoshimura / Ito), rotational stiffness k_t * I_p(annulus); expressed as a
    fraction r of the gear's secant compliance theta(T0)/T0."""
    r = _u(rng, 0.08, 0.35)
    c = r * float(catalog_twist(T0, g, s)) / T0

    def ev(amp):
        return c * amp * T
    return ev, {"housing_compliance_rad_per_Nm": c, "housing_fraction": r}


def eff_housing_shaft(rng, g, s, T0, T, extra=None):
    """shaft-output gear head: stepped output shaft L_i/(G J_i) with a keyway factor (J of the
    keyed section x 0.75-0.85), pickup at the shaft end; fraction r of the gear compliance."""
    r = _u(rng, 0.05, 0.30)
    kw = _u(rng, 0.75, 0.85)
    c = r * float(catalog_twist(T0, g, s)) / T0

    def ev(amp):
        return c * amp * T
    return ev, {"housing_compliance_rad_per_Nm": c, "housing_fraction": r, "keyway_factor": kw}


TORSION_EFFECTS = {
    ("hysteresis", "masing-hardin-drnevich"): eff_hyst_masing_hd,
    ("hysteresis", "bliman-sorine"): eff_hyst_bliman_sorine,
    ("backlash", "exp-takeup"): eff_backlash_exp,
    ("backlash", "two-lock-algebraic"): eff_backlash_twolock,
    ("housing_compliance", "flange-joint"): eff_housing_joint,
    ("housing_compliance", "keyed-shaft"): eff_housing_shaft,
}


def _torsion_base(rng, gears, protocol):
    g = gears[int(rng.integers(len(gears)))]
    s = _stiffness_scale(rng)
    T0 = g.rated
    T, extra = PROTOCOLS[protocol](rng, T0)
    rate = T0 / _u(rng, 20.0, 60.0)      # N.m/s, quasi-static
    t = _time_from_torque(T, rate)
    nuis = {"stiffness_scale": s, "T0_Nm": T0}
    for k, v in extra.items():
        if not isinstance(v, np.ndarray):
            nuis[k] = float(v)
    return g, s, T0, T, t, extra, nuis


def _torsion_cols(T, th, t, extra):
    cols = {"torque_Nm": T, "twist_rad": th, "time_s": t}
    if "lock" in extra:
        cols["lock_angle_deg"] = extra["lock"]
    return cols


def torsion_effect_case(rng, gears, protocol, combo, category="single"):
    """combo: list of (effect, formulation) keys of TORSION_EFFECTS (one or two)."""
    g, s, T0, T, t, extra, nuis = _torsion_base(rng, gears, protocol)
    base = catalog_twist(T, g, s)
    for attempt in range(30):
        evs = []
        for key in combo:
            ev, par = TORSION_EFFECTS[key](rng, g, s, T0, T, extra) if key[0] != "hysteresis" \
                else TORSION_EFFECTS[key](rng, g, s, T0, T)
            evs.append(ev)
            nuis.update(par)
        if len(evs) == 1:
            eff = [evs[0](1.0)]
            sigma = _sigma_single(rng, eff[0])
            break
        a1, a2 = _balance(evs[0], evs[1], maxratio=1.8)   # odd effects add nearly coherently
        eff = [evs[0](a1), evs[1](a2)]
        sigma = _sigma_multi(rng, eff, eff[0] + eff[1])
        if sigma is not None:
            nuis["amp_factor_" + combo[0][0]] = a1
            nuis["amp_factor_" + combo[1][0]] = a2
            break
    if sigma is None:
        sigma = _rms(eff[0] + eff[1]) / 8.0
    total = np.sum(eff, axis=0)
    kind = "ar1" if rng.random() < 0.5 else "white"
    nz, ninfo = _noise(rng, T.size, sigma, kind)
    nuis.update(ninfo)
    for (name, _), e in zip(combo, eff):
        nuis["snr_" + name] = _rms(e) / sigma
    th = base + total + nz
    return dict(kind="torsion", model=g.code, columns=_torsion_cols(T, th, t, extra), load_inertia_kgm2=None,
                gear_effects=tuple(k[0] for k in combo), measurement_effects=(), nuisance=nuis,
                category=category, noise_rms=sigma,
                formulation=" + ".join(f"{k[1]}" for k in combo) + f"; protocol {protocol}; noise {kind}",
                snr=_rms(total) / sigma)


def torsion_clean_case(rng, gears, protocol, noise_kind):
    g, s, T0, T, t, extra, nuis = _torsion_base(rng, gears, protocol)
    base = catalog_twist(T, g, s)
    sigma = _u(rng, 0.002, 0.008) * float(catalog_twist(T0, g, s))
    nz, ninfo = _noise(rng, T.size, sigma, noise_kind)
    nuis.update(ninfo)
    return dict(kind="torsion", model=g.code, columns=_torsion_cols(T, base + nz, t, extra),
                load_inertia_kgm2=None, gear_effects=(), measurement_effects=(), nuisance=nuis,
                category="clean", noise_rms=sigma,
                formulation=f"catalog curve x tanh-normal stiffness scale; protocol {protocol}; noise {noise_kind}",
                snr=0.0)


def torsion_decoy_case(rng, gears, decoy):
    protocol = {"torque_gain": "sinh", "preload_offset": "lostmotion", "joule_drift": "triangle",
                "degrees": "sinh", "kNm": "triangle", "scale": "sinh",
                "torque_flange": "lostmotion", "seal_friction": "sinh", "brake_play": "triangle"}[decoy]
    g, s, T0, T, t, extra, nuis = _torsion_base(rng, gears, protocol)
    base = catalog_twist(T, g, s)
    Tcol = T.copy()
    meas, cat, equiv = (), "decoy_separable", ()
    wrong_units = False
    if decoy == "torque_gain":
        # strain-gauge bridge excitation sagging (lead resistance / supply): gain 3-8 % off
        gain = 1.0 + rng.choice([-1.0, 1.0]) * _u(rng, 0.03, 0.08)
        Tcol = gain * T
        eff = base - catalog_twist(Tcol, g, s)   # what the catalog curve mis-predicts from the column
        th_clean = base
        meas = ("sensor_gain",)
        nuis["torque_gain"] = gain
        form = "torque-bridge excitation sag (gain on the torque channel)"
    elif decoy == "preload_offset":
        # twist zeroed while the loading arm's dead weight preloaded the gear: constant offset
        off = rng.choice([-1.0, 1.0]) * _u(rng, 0.05, 0.25) * float(catalog_twist(T0, g, s))
        eff = np.full(T.size, off)
        th_clean = base + off
        meas = ("angle_offset",)
        nuis["twist_offset_rad"] = off
        form = "constant twist offset (zero taken under the arm's dead-weight preload)"
    elif decoy == "joule_drift":
        # loading motor Joule heat ~ T^2 -> fixture temperature first-order lag (tau >> test)
        tau = _u(rng, 2.0, 6.0) * t[-1]
        q = (T / T0) ** 2
        dt = np.diff(t, prepend=t[0])
        Th = np.zeros(T.size)
        for i in range(1, T.size):
            a = math.exp(-dt[i] / tau)
            Th[i] = Th[i - 1] * a + q[i] * (1 - a)
        beta = rng.choice([-1.0, 1.0]) * _u(rng, 0.05, 0.2) * float(catalog_twist(T0, g, s)) / max(Th.max(), 1e-12)
        eff = beta * Th
        th_clean = base + eff
        meas = ("thermal_drift",)
        nuis["drift_tau_s"] = tau
        form = "Joule-heating drift (first-order lag of T^2 heating)"
    elif decoy == "degrees":
        th_clean = base * DEG
        eff = base * (DEG - 1)
        meas, wrong_units = ("wrong_units",), True
        form = "twist column in degrees"
    elif decoy == "kNm":
        Tcol = T * 1e-3
        th_clean = base
        eff = base - catalog_twist(Tcol, g, s)
        meas, wrong_units = ("wrong_units",), True
        form = "torque column in kN.m"
    elif decoy == "scale":
        s2 = 1.0 + rng.choice([-1.0, 1.0]) * _u(rng, 0.04, 0.10)
        nuis["stiffness_scale"] = s2
        th_clean = catalog_twist(T, g, s2)
        eff = th_clean - catalog_twist(T, g, 1.0)
        form = "stiffness scale within +-10 % (nuisance only)"
    elif decoy == "torque_flange":
        # in-line torque flange between the gear output and the angle pickup: its torsional
        # stiffness (1e5-1e7 N.m/rad class) is a linear series spring -> c*T exactly
        r = _u(rng, 0.08, 0.35)
        c = r * float(catalog_twist(T0, g, s)) / T0
        eff = c * T
        th_clean = base + eff
        cat, equiv = "decoy_equivalent", ("housing_compliance",)
        meas = ()
        nuis["flange_stiffness_Nm_per_rad"] = 1.0 / c
        form = "torque-flange windup in series (angle pickup beyond the torque flange)"
    elif decoy == "seal_friction":
        # hydraulic rotary actuator; torque taken from chamber pressure; vane-seal Coulomb
        # friction Fs: gear torque = play operator of the indicated torque with half-width Fs
        delta = g.hysteresis * _u(rng, 0.6, 1.3)
        Fs = 0.5 * delta * g.K1 * s
        Tg = np.empty(T.size)
        tg = 0.0
        for i, ti in enumerate(T):
            tg = min(max(tg, ti - Fs), ti + Fs)
            Tg[i] = tg
        th_clean = catalog_twist(Tg, g, s)
        eff = th_clean - base
        cat, equiv = "decoy_equivalent", ("hysteresis",)
        nuis["seal_friction_Nm"] = Fs
        form = "hydraulic-actuator seal friction (torque from pressure): play operator on torque"
    elif decoy == "brake_play":
        # input held by a spring-applied holding brake; friction disc on a splined hub with
        # circumferential clearance c_in (input rad) -> output jump c_in / R at zero torque,
        # contact taken up over a finite torque window (smoothstep)
        b = g.backlash * _u(rng, 0.5, 1.2)
        Tw = _u(rng, 0.003, 0.012) * T0
        x = np.clip(T / Tw, -1, 1)
        eff = 0.5 * b * x * (3 - x * x) / 2.0
        th_clean = base + eff
        cat, equiv = "decoy_equivalent", ("backlash",)
        nuis["brake_clearance_input_rad"] = b * g.ratio
        form = "holding-brake spline clearance at the locked input (smoothstep engagement)"
    else:
        raise ValueError(decoy)
    if wrong_units:
        k = _u(rng, 4.0, 12.0)
        sigma = _u(rng, 0.002, 0.008) * float(catalog_twist(T0, g, s)) * (DEG if decoy == "degrees" else 1.0)
    else:
        sigma = _sigma_single(rng, eff)
    kind = "ar1" if rng.random() < 0.5 else "white"
    nz, ninfo = _noise(rng, T.size, sigma, kind)
    nuis.update(ninfo)
    nuis["snr_" + (meas[0] if meas else (equiv[0] if equiv else "stiffness_scale"))] = _rms(eff) / sigma
    return dict(kind="torsion", model=g.code, columns=_torsion_cols(Tcol, th_clean + nz, t, extra),
                load_inertia_kgm2=None, gear_effects=(), measurement_effects=meas, nuisance=nuis,
                category=cat, equivalent_effects=equiv, noise_rms=sigma,
                formulation=f"{form}; protocol {protocol}; noise {kind}", snr=_rms(eff) / sigma)


# --------------------------------------------------------------------------------------------
# TRANSMISSION
# --------------------------------------------------------------------------------------------
def _te_gears(gears):
    return [g for g in gears if g.accuracy]


def te1_hubfit(rng, g, catalog_dir):
    """te_1x from the WG hub running eccentric on the input shaft inside its H7/g6 clearance
    (table 027-1 standard H7 bore, ISO 286 IT7 / g6 limits): 1x sinusoid, amplitude bounded by
    the catalog transmission accuracy (051-1 / 059-1)."""
    hub, fits = _hub_fit(catalog_dir)
    d = hub.get(g.size, 10.0)
    row = [f for f in fits if f[0] < d <= f[1]][0]
    clearance_um = row[2] + row[4] + row[3]          # H7 upper (+IT7) .. g6 lower (-(es+IT6))
    e = _u(rng, 0.3, 1.0) * 0.5 * clearance_um * 1e-6
    a = g.accuracy * _u(rng, 0.12, 0.35)
    beta = _u(rng, 0, 2 * math.pi)
    return (lambda phi, amp=1.0: amp * a * np.sin(phi + beta),
            lambda phi, amp=1.0: amp * a * np.cos(phi + beta),
            {"te1_amp_rad": a, "hub_eccentricity_m": e})


def te1_runout(rng, g, catalog_dir):
    """te_1x as the vector sum of WG-cam runout and input-shaft bend (two 1x phasors)."""
    a1, a2 = g.accuracy * _u(rng, 0.05, 0.25), g.accuracy * _u(rng, 0.05, 0.2)
    b1, b2 = _u(rng, 0, 2 * math.pi), _u(rng, 0, 2 * math.pi)
    z = a1 * np.exp(1j * b1) + a2 * np.exp(1j * b2)
    a, beta = abs(z), float(np.angle(z))
    return (lambda phi, amp=1.0: amp * a * np.sin(phi + beta),
            lambda phi, amp=1.0: amp * a * np.cos(phi + beta),
            {"te1_amp_rad": a})


def te2_vonmises(rng, g, catalog_dir):
    """te_2x from a local circular-spline pitch-error sector met by each of the two lobes once per
    WG revolution: periodic von Mises pulse exp(k cos 2(phi-phi0)), mean removed."""
    kap = _u(rng, 0.8, 2.5)
    a = g.accuracy * _u(rng, 0.12, 0.35)
    p0 = _u(rng, 0, math.pi)
    z = np.linspace(0, math.pi, 4001)[:-1]
    w = np.exp(kap * np.cos(2 * z))
    m, sd = w.mean(), w.std()

    def f(phi, amp=1.0):
        return amp * a * (np.exp(kap * np.cos(2 * (phi - p0))) - m) / sd / math.sqrt(2) * 1.0

    def fd(phi, amp=1.0):
        return amp * a * (-2 * kap * np.sin(2 * (phi - p0)) * np.exp(kap * np.cos(2 * (phi - p0)))) / sd / math.sqrt(2)
    return f, fd, {"te2_rms_rad": a / math.sqrt(2), "vonmises_kappa": kap}


def te2_softclip(rng, g, catalog_dir):
    """te_2x soft-clipped at the lobe extremes (partial tooth disengagement):
    a tanh(gam sin(2 phi + b)) / tanh(gam)."""
    gam = _u(rng, 0.8, 2.0)
    a = g.accuracy * _u(rng, 0.12, 0.35)
    b = _u(rng, 0, 2 * math.pi)
    tg = math.tanh(gam)

    def f(phi, amp=1.0):
        return amp * a * np.tanh(gam * np.sin(2 * phi + b)) / tg

    def fd(phi, amp=1.0):
        return amp * a * gam * 2 * np.cos(2 * phi + b) / np.cosh(gam * np.sin(2 * phi + b)) ** 2 / tg
    return f, fd, {"te2_amp_rad": a, "clip_gamma": gam}


TE_FORMS = {("te_1x", "hubfit"): te1_hubfit, ("te_1x", "runout-phasor"): te1_runout,
            ("te_2x", "cs-sector-vonmises"): te2_vonmises, ("te_2x", "soft-clip"): te2_softclip}


def _input_angles(rng, protocol, R, te_total):
    """returns measured input angle phi (rad) for a protocol; te_total(phi) used by
    'output-triggered' to place samples at equal OUTPUT angle increments."""
    info = {}
    phi0 = _u(rng, 0, 2 * math.pi)
    if protocol == "fullrev":
        n_per = max(18, int(2900 // R))
        n = int(R * n_per)
        phi = phi0 + 2 * math.pi * np.arange(n) / n_per
        info["samples_per_rev"] = float(n_per)
    elif protocol == "output-triggered":
        n_rev = int(rng.integers(8, 20))
        n_per = int(rng.integers(72, min(180, 2900 // n_rev)))
        n = n_rev * n_per
        out = phi0 / R + (2 * math.pi / R) * np.arange(n) / n_per
        phi = out * R
        for _ in range(6):
            phi = R * (out - te_total(phi))
        info["samples_per_rev"] = float(n_per)
    elif protocol == "time-ripple":
        n_rev = int(rng.integers(8, 20))
        n_per = int(rng.integers(72, min(180, 2900 // n_rev)))
        n = n_rev * n_per
        x = np.arange(n) / n_per                     # nominal revolutions
        r = _u(rng, 0.005, 0.03)
        fr = _u(rng, 0.11, 0.43)                     # ripple per nominal revolution (not 1x/2x)
        ps = _u(rng, 0, 2 * math.pi)
        phi = phi0 + 2 * math.pi * x - r / fr * (np.cos(2 * math.pi * fr * x + ps) - math.cos(ps))
        info.update({"speed_ripple": r, "ripple_per_rev": fr})
    else:  # equal-angle
        n_rev = int(rng.integers(8, 20))
        n_per = int(rng.integers(64, min(180, 2900 // n_rev)))
        n = n_rev * n_per
        phi = phi0 + 2 * math.pi * np.arange(n) / n_per
        info["samples_per_rev"] = float(n_per)
    return phi, info


def transmission_case(rng, gears, catalog_dir, combo, protocol, category="single", noise_kind=None):
    gl = _te_gears(gears)
    g = gl[int(rng.integers(len(gl)))]
    R = g.ratio
    off = _u(rng, -math.pi, math.pi)
    nuis = {"output_offset_rad": off}
    forms = []
    for key in combo:
        f, fd, par = TE_FORMS[key](rng, g, catalog_dir)
        forms.append(f)
        nuis.update(par)
    amps = [1.0] * len(forms)
    if len(forms) == 2:
        phi_t = np.linspace(0, 2 * math.pi, 720)
        a1, a2 = _balance(lambda a: forms[0](phi_t, a), lambda a: forms[1](phi_t, a))
        amps = [a1, a2]
    te_total = lambda p: sum(f(p, a) for f, a in zip(forms, amps)) if forms else 0.0 * p
    phi, info = _input_angles(rng, protocol, R, te_total)
    nuis.update(info)
    parts = [f(phi, a) for f, a in zip(forms, amps)]
    total = np.sum(parts, axis=0) if parts else np.zeros(phi.size)
    if category == "clean":
        sigma = _u(rng, 2e-6, 1e-5)
    elif len(parts) == 1:
        sigma = _sigma_single(rng, parts[0])
    else:
        sigma = _sigma_multi(rng, parts, total)
        if sigma is None:
            sigma = _rms(total) / 8.0
    nk = noise_kind or ("ar1" if rng.random() < 0.5 else "white")
    nz, ninfo = _noise(rng, phi.size, sigma, nk)
    nuis.update(ninfo)
    for key, p in zip(combo, parts):
        nuis["snr_" + key[0]] = _rms(p) / sigma
    out = phi / R + off + total + nz
    return dict(kind="transmission", model=g.code,
                columns={"input_angle_rad": phi, "output_angle_rad": out}, load_inertia_kgm2=None,
                gear_effects=tuple(k[0] for k in combo), measurement_effects=(), nuisance=nuis,
                category=category, noise_rms=sigma,
                formulation=(" + ".join(k[1] for k in combo) or "output = input/R + offset")
                + f"; sampling {protocol}; noise {nk}",
                snr=_rms(total) / sigma if parts else 0.0)


def transmission_decoy_case(rng, gears, catalog_dir, decoy):
    gl = _te_gears(gears)
    g = gl[int(rng.integers(len(gl)))]
    R = g.ratio
    off = _u(rng, -math.pi, math.pi)
    nuis = {"output_offset_rad": off}
    protocol = {"out_ecc": "fullrev", "slip_step": "equal-angle", "out_deg": "time-ripple",
                "in_deg": "equal-angle", "tape": "equal-angle", "resolver2p": "time-ripple"}[decoy]
    phi, info = _input_angles(rng, protocol, R, lambda p: 0.0 * p)
    nuis.update(info)
    out = phi / R + off
    phim = phi.copy()
    meas, cat, equiv, wrong = (), "decoy_separable", (), False
    if decoy == "out_ecc":
        # output encoder disc eccentric by e on read radius r: error (e/r) sin(theta_out + b)
        e_r = _u(rng, 2e-5, 1.5e-4)
        b = _u(rng, 0, 2 * math.pi)
        eff = e_r * np.sin(phi / R + b)
        out = out + eff
        meas = ("encoder_eccentricity",)
        nuis["encoder_ecc_rad"] = e_r
        form = "output-encoder eccentricity, once per output revolution, full output revolution recorded"
    elif decoy == "slip_step":
        # output-encoder coupling set-screw slips once during the run: a step
        n = phi.size
        i0 = int(rng.integers(int(0.3 * n), int(0.7 * n)))
        st = rng.choice([-1.0, 1.0]) * g.accuracy * _u(rng, 0.1, 0.4)
        eff = np.where(np.arange(n) >= i0, st, 0.0)
        out = out + eff
        meas = ("angle_offset",)
        nuis["step_rad"] = st
        form = "output-encoder coupling slip (single step)"
    elif decoy == "out_deg":
        eff = (out) * (DEG - 1)
        out = out * DEG
        meas, wrong = ("wrong_units",), True
        form = "output angle in degrees"
    elif decoy == "in_deg":
        eff = phi * (DEG - 1) / R
        phim = phi * DEG
        meas, wrong = ("wrong_units",), True
        form = "input angle in degrees"
    elif decoy == "tape":
        # magnetic-tape input encoder tensioned unevenly: once-per-rev scale error in the
        # measured input angle -> output - input_meas/R shows a 1x error of amplitude a/R
        a_in = g.accuracy * R * _u(rng, 0.12, 0.35)
        b = _u(rng, 0, 2 * math.pi)
        phim = phi + a_in * np.sin(phi + b)
        eff = -(a_in / R) * np.sin(phi + b)
        cat, equiv = "decoy_equivalent", ("te_1x",)
        nuis["tape_error_input_rad"] = a_in
        form = "magnetic-tape input encoder, once-per-rev scale error"
    elif decoy == "resolver2p":
        # 2-pole-pair resolver with a DC offset o on the sine channel: electrical error
        # ~ o cos(theta_e), theta_e = 2 phi -> twice per input revolution
        o = g.accuracy * R * 2 * _u(rng, 0.12, 0.35)
        b = _u(rng, 0, 2 * math.pi)
        te = 2 * phi + b
        tem = np.unwrap(np.arctan2(np.sin(te) + o, np.cos(te)))
        tem += 2 * math.pi * np.round((te[0] - tem[0]) / (2 * math.pi))
        phim = (tem - b) / 2
        eff = (phi - phim) / R
        cat, equiv = "decoy_equivalent", ("te_2x",)
        nuis["resolver_offset"] = o
        form = "2-pole-pair resolver sine-channel offset (2x per input revolution)"
    else:
        raise ValueError(decoy)
    if wrong:
        sigma = _u(rng, 2e-6, 1e-5) * (DEG if decoy == "out_deg" else 1.0)
    else:
        sigma = _sigma_single(rng, eff)
    nk = "ar1" if rng.random() < 0.5 else "white"
    nz, ninfo = _noise(rng, phi.size, sigma, nk)
    nuis.update(ninfo)
    snr = _rms(eff) / sigma
    nuis["snr_" + (meas[0] if meas else equiv[0])] = snr
    return dict(kind="transmission", model=g.code,
                columns={"input_angle_rad": phim, "output_angle_rad": out + nz}, load_inertia_kgm2=None,
                gear_effects=(), measurement_effects=meas, nuisance=nuis, category=cat,
                equivalent_effects=equiv, noise_rms=sigma,
                formulation=f"{form}; sampling {protocol}; noise {nk}", snr=snr)


# --------------------------------------------------------------------------------------------
# EFFICIENCY
# --------------------------------------------------------------------------------------------
GREASES = {"SK-1A": (0.0, 40.0), "SK-2": (0.0, 40.0), "4B No.2": (-10.0, 70.0)}   # 016-2 ambient


def _eff_grid(rng, g):
    speeds = [n for n in (500, 1000, 1500, 2000, 2500, 3000, 3500) if n <= g.avg_in_rpm]
    k = int(rng.integers(3, min(5, len(speeds)) + 1))
    speeds = sorted(rng.choice(speeds, size=k, replace=False).tolist())
    alphas = np.round(np.linspace(0.2, 1.0, int(rng.integers(6, 10))), 4)
    gname = list(GREASES)[int(rng.integers(3))]
    lo, hi = GREASES[gname]
    # lubricant (lubricated part) temperature: ambient range + up to 40 K rise (016-2 note)
    temps = np.round(np.linspace(lo + 5, hi + 30, int(rng.integers(4, 7))), 1)
    S, A, Tm = np.meshgrid(speeds, alphas, temps, indexing="ij")
    S, A, Tm = S.ravel().astype(float), A.ravel(), Tm.ravel()
    if rng.random() < 0.5:   # randomised run order within temperature blocks is NOT used; full shuffle
        p = rng.permutation(S.size)
        S, A, Tm = S[p], A[p], Tm[p]
    return S, A * g.rated, Tm, {"grease": gname}


def lowload_lazan(rng, g, catalog_dir):
    """Lazan's damping law for the flexspline (loss per stress cycle ~ sigma_eq^n, n 2-3), two
    bending cycles per WG revolution, sigma_eq^2 = sigma_b^2 + 3 tau(T)^2 -> input-referred loss
    torque T_L(T) = T_L0 (1 + beta (T/Tr)^2)^(n/2); eta = 1/(1/eta_m + R T_L / T).  T_L0 is
    set so that Ke(0.58) = 0.93 +- 0.02 (seed 000 p.023)."""
    n = _u(rng, 2.0, 3.0)
    beta = _u(rng, 0.1, 0.6)
    ke = _u(rng, 0.91, 0.95)
    R, Tr = g.ratio, g.rated

    def loss(T, TL0):
        return TL0 * (1 + beta * (T / Tr) ** 2) ** (n / 2)

    def eta_fn(T, eta_m, TL0):
        return 1.0 / (1.0 / eta_m + R * loss(T, TL0) / T)

    def ke_of(TL0, eta_m=0.8):
        return eta_fn(0.58 * Tr, eta_m, TL0) / eta_fn(Tr, eta_m, TL0)
    TL0 = optimize.brentq(lambda x: ke_of(x) - ke, 1e-9 * Tr, 1.0 * Tr / R)
    return eta_fn, TL0, {"lazan_n": n, "lazan_beta": beta, "Ke058_target": ke, "TL0_input_Nm": TL0}


def lowload_seal(rng, g, catalog_dir):
    """PTFE lip seals, Coulomb drag: T = mu * (pi d f_r) * d/2 with the lip radial load per length
    f_r and an ISO 6194 seal size; input seal (input shaft) and output seal; temperature- and
    speed-insensitive; eta = eta_m T/(T + R T_in_seal + T_out_seal) (drags referred to output)."""
    d1 = _seal_d1(catalog_dir)
    din = float(d1[min(int(np.searchsorted(d1, 0.8 * g.size)), d1.size - 1)])
    dout = float(d1[min(int(np.searchsorted(d1, 2.0 * g.size)), d1.size - 1)])
    mu = _u(rng, 0.15, 0.35)
    fr = _u(rng, 0.10, 0.25)                       # N/mm
    Tin = mu * math.pi * din * fr * din / 2 / 1000.0   # N.m
    Tout = mu * math.pi * dout * fr * dout / 2 / 1000.0
    # also the grease-packed WG bearing's constant drag, a fraction of the catalog running torque
    kr = _u(rng, 0.1, 0.35)
    Tin_tot = Tin + kr * g.running_torque
    R = g.ratio

    def eta_fn(T, eta_m, scale):
        return eta_m * T / (T + scale * (R * Tin_tot + Tout))
    return eta_fn, 1.0, {"seal_d_in_mm": din, "seal_d_out_mm": dout, "seal_mu": mu,
                         "lip_load_N_per_mm": fr, "running_torque_fraction": kr,
                         "drag_output_Nm": R * Tin_tot + Tout}


def temp_ep_film(rng, temps_range):
    """EP-additive tribofilm (industrial gear oil class 2 EP / EP greases): above an activation
    temperature the boundary friction of the tooth flanks falls; logistic in T with an
    Arrhenius-like width: loss factor phi(T) = 1 - D / (1 + exp(-(T - Ta)/w))."""
    lo, hi = temps_range
    Ta = _u(rng, lo + 0.3 * (hi - lo), lo + 0.7 * (hi - lo))
    w = _u(rng, 4.0, 10.0)
    D = _u(rng, 0.15, 0.35)
    return (lambda T, amp=1.0: 1.0 - amp * D / (1.0 + np.exp(-(T - Ta) / w)),
            {"ep_activation_C": Ta, "ep_width_K": w, "ep_loss_drop": D})


def temp_expansion(rng, temps_range):
    """aluminium housing vs steel circular spline: radial fit changes with (alpha_Al - alpha_st)
    D dT, the tooth engagement depth and the sliding loss change linearly with temperature:
    loss factor phi(T) = 1 - gam (T - Tref)."""
    lo, hi = temps_range
    Tref = 20.0
    gam = _u(rng, 0.002, 0.005)          # 1/K on the loss fraction
    return (lambda T, amp=1.0: 1.0 - amp * gam * (T - Tref), {"expansion_loss_coeff_per_K": gam})


def efficiency_case(rng, gears, catalog_dir, low=None, temp=None, category="single", noise_kind=None):
    g = gears[int(rng.integers(len(gears)))]
    S, T, Tm, ginfo = _eff_grid(rng, g)
    nuis = {"efficiency_level_pct": 0.0}
    nuis.update({"grease_" + ginfo["grease"]: 1.0})
    level = _u(rng, 65.0, 85.0)
    nuis["efficiency_level_pct"] = level
    eta_m = level / 100.0
    trange = (float(Tm.min()), float(Tm.max()))
    base = np.full(S.size, level)
    if low == "lazan":
        eta_fn, p0, par = lowload_lazan(rng, g, catalog_dir)
    elif low == "seal":
        eta_fn, p0, par = lowload_seal(rng, g, catalog_dir)
    if low:
        nuis.update(par)
    if temp == "ep":
        phi, par = temp_ep_film(rng, trange)
    elif temp == "expansion":
        phi, par = temp_expansion(rng, trange)
    if temp:
        nuis.update(par)

    if low == "lazan":
        Ke = eta_fn(T, eta_m, p0) / eta_fn(g.rated, eta_m, p0)
    elif low == "seal":
        Ke = eta_fn(T, eta_m, 1.0) / eta_fn(g.rated, eta_m, 1.0)

    def model(la, ta):
        """catalog form eta = Ke(alpha) * eta_R (seed 000 p.023); eta_R = level at rated torque,
        its loss fraction scaled by the temperature factor phi(T); amplitudes la, ta."""
        etaR = 1 - (1 - eta_m) * phi(Tm, ta) if temp else np.full(S.size, eta_m)
        ke = 1 - la * (1 - Ke) if low else 1.0
        return 100 * etaR * ke

    parts = []
    if low:
        parts.append(model(1.0, 0.0) - base)
    if temp:
        parts.append(model(0.0, 1.0) - base)
    total = model(1.0 if low else 0.0, 1.0 if temp else 0.0) - base
    if category == "clean":
        sigma = _u(rng, 0.15, 0.6)
    elif len(parts) == 1:
        sigma = _sigma_single(rng, parts[0])
    else:
        sigma = _sigma_multi(rng, parts, total)
        amp = 1.0
        while sigma is None:
            # keep both visible: shrink the larger one
            r0, r1 = _rms(parts[0]), _rms(parts[1])
            amp *= 0.8
            la, ta = (amp, 1.0) if r0 > r1 else (1.0, amp)
            parts = [model(la, 0.0) - base, model(0.0, ta) - base]
            total = model(la, ta) - base
            nuis["amp_factor"] = amp
            sigma = _sigma_multi(rng, parts, total)
    nk = noise_kind or ("ar1" if rng.random() < 0.5 else "white")
    nz, ninfo = _noise(rng, S.size, sigma, nk)
    nuis.update(ninfo)
    names = ([("low_load_efficiency")] if low else []) + (["temperature_dependence"] if temp else [])
    for nmx, p in zip(names, parts):
        nuis["snr_" + nmx] = _rms(p) / sigma
    form = " + ".join([x for x in (low and f"low-load {low}", temp and f"temperature {temp}") if x]) \
        or "constant level"
    return dict(kind="efficiency", model=g.code,
                columns={"input_speed_rpm": S, "load_torque_Nm": T, "temperature_C": Tm,
                         "efficiency_pct": base + total + nz},
                load_inertia_kgm2=None, gear_effects=tuple(names), measurement_effects=(),
                nuisance=nuis, category=category, noise_rms=sigma,
                formulation=form + f"; grid {ginfo['grease']}; noise {nk}",
                snr=_rms(total) / sigma if parts else 0.0)


def efficiency_decoy_case(rng, gears, catalog_dir, decoy):
    g = gears[int(rng.integers(len(gears)))]
    S, T, Tm, ginfo = _eff_grid(rng, g)
    level = _u(rng, 65.0, 85.0)
    nuis = {"efficiency_level_pct": level, "grease_" + ginfo["grease"]: 1.0}
    meas, cat, equiv, wrong = (), "decoy_separable", (), False
    eta = np.full(S.size, level)
    if decoy == "level":
        sigma = _u(rng, 0.5, 1.5)
        k = _u(rng, 4.0, 12.0)
        level = 78.0 - k * sigma          # seed example CSF-20-80: 78 % at rated torque
        nuis["efficiency_level_pct"] = level
        eta = np.full(S.size, level)
        eff_rms = abs(level - 78.0)
        form = "efficiency level away from the seed's 78 % (nuisance only)"
    elif decoy == "gain":
        gain = 1.0 + rng.choice([-1.0, 1.0]) * _u(rng, 0.03, 0.08)
        eta = eta * gain
        eff_rms = abs(gain - 1) * level
        sigma = eff_rms / _u(rng, 4.0, 12.0)
        meas = ("sensor_gain",)
        nuis["output_torque_gain"] = gain
        form = "output torque transducer gain (efficiency x gain)"
    elif decoy == "fraction":
        eta = eta / 100.0
        sigma = _u(rng, 0.15, 0.6) / 100.0
        eff_rms = level * 0.99
        meas, wrong = ("wrong_units",), True
        form = "efficiency as a fraction"
    elif decoy == "steinmetz":
        # output power from a PM load generator's electrical output; its core hysteresis
        # (Steinmetz P_h = k_h f B^1.6, f ~ speed) is a constant drag torque T_h not subtracted:
        # eta_meas = eta (1 - T_h / T)  == a gear with a constant output drag (low-load effect)
        ke = _u(rng, 0.94, 0.98)                  # apparent Ke at alpha = 0.58
        Th = optimize.brentq(lambda x: (1 - x / (0.58 * g.rated)) / (1 - x / g.rated) - ke, 0, 0.5 * g.rated)
        eta = level * (1 - Th / T)
        eff = eta - level * (1 - Th / g.rated)
        eff_rms = _rms(eff)
        sigma = eff_rms / _u(rng, 4.0, 12.0)
        cat, equiv = "decoy_equivalent", ("low_load_efficiency",)
        nuis["generator_hysteresis_torque_Nm"] = Th
        form = "dynamometer core (Steinmetz hysteresis) loss not subtracted"
    elif decoy == "cragoe":
        # calorimetric efficiency: loss = m_dot c_p dT with c_p taken at 40 C; Cragoe's
        # c_p = (1.684 + 0.003389 T)/sqrt(SG) kJ/(kg K) -> eta_meas = 1 - (1-eta) c_ref / c_p(T)
        cref = 1.684 + 0.003389 * 40.0
        loss = (1 - level / 100.0) * cref / (1.684 + 0.003389 * Tm)
        eta = 100 * (1 - loss)
        eff_rms = _rms(eta)
        sigma = eff_rms / _u(rng, 4.0, 12.0)
        cat, equiv = "decoy_equivalent", ("temperature_dependence",)
        nuis["cp_reference_C"] = 40.0
        form = "calorimetric loss with c_p fixed at 40 C (Cragoe c_p(T))"
    else:
        raise ValueError(decoy)
    nk = "ar1" if rng.random() < 0.5 else "white"
    nz, ninfo = _noise(rng, S.size, sigma, nk)
    nuis.update(ninfo)
    snr = eff_rms / sigma
    nuis["snr_" + (meas[0] if meas else (equiv[0] if equiv else "efficiency_level"))] = snr
    return dict(kind="efficiency", model=g.code,
                columns={"input_speed_rpm": S, "load_torque_Nm": T, "temperature_C": Tm,
                         "efficiency_pct": eta + nz},
                load_inertia_kgm2=None, gear_effects=(), measurement_effects=meas, nuisance=nuis,
                category=cat, equivalent_effects=equiv, noise_rms=sigma,
                formulation=f"{form}; grid {ginfo['grease']}; noise {nk}", snr=snr)


# --------------------------------------------------------------------------------------------
# VIBRATION
# --------------------------------------------------------------------------------------------
def wilson_theta(m, c, k, p, h, u0, v0, theta=1.4):
    n = p.size
    u = np.empty(n)
    u[0] = u0
    v, a = v0, (p[0] - c * v0 - k * u0) / m
    tau = theta * h
    kh = k + 6 * m / tau ** 2 + 3 * c / tau
    for i in range(n - 1):
        ph = p[i] + theta * (p[i + 1] - p[i]) + m * (6 * u[i] / tau ** 2 + 6 * v / tau + 2 * a) \
            + c * (3 * u[i] / tau + 2 * v + tau * a / 2)
        ut = ph / kh
        at = 6 * (ut - u[i]) / tau ** 2 - 6 * v / tau - 2 * a
        an = a + (at - a) / theta
        vn = v + h * (a + an) / 2
        u[i + 1] = u[i] + h * v + h * h * (an + 2 * a) / 6
        v, a = vn, an
    return u


def bathe_composite(m, c, k, p, h, u0, v0):
    """Bathe (2005) composite scheme: trapezoidal rule over the first half step, 3-point Euler
    backward over the second; step 2h uses p at the fine grid points (half steps)."""
    n = p.size
    u = np.full(n, np.nan)
    u[0] = u0
    v, a = v0, (p[0] - c * v0 - k * u0) / m
    dt = 2 * h
    kt = k + 4 * m / h ** 2 + 2 * c / h            # trapezoid over h
    kb = k + 9 * m / dt ** 2 + 3 * c / dt
    i = 0
    while i + 2 <= n - 1:
        # stage 1: trapezoidal over h
        ph = p[i + 1] + m * (4 * u[i] / h ** 2 + 4 * v / h + a) + c * (2 * u[i] / h + v)
        uh = ph / kt
        vh = 2 * (uh - u[i]) / h - v
        # stage 2: 3-point backward Euler over dt
        A = (u[i] - 4 * uh) / dt
        B = (v - 4 * vh) / dt
        un = (p[i + 2] - m * (B + 3 * A / dt) - c * A) / kb
        vn = A + 3 * un / dt
        an = B + 3 * vn / dt
        u[i + 1], u[i + 2] = uh, un
        v, a = vn, an
        i += 2
    if i == n - 2:   # odd number of intervals: finish with one trapezoidal step of h
        ph = p[i + 1] + m * (4 * u[i] / h ** 2 + 4 * v / h + a) + c * (2 * u[i] / h + v)
        u[i + 1] = ph / kt
    return u


def _runup(rng, kind, f_lo, f_hi, f_res, n_rows, fs):
    """input frequency (Hz) on the sample grid. 'hyperbolic': f = f_lo/(1 - t/tau) (constant-Q
    sweep, df/dt ~ f^2). 'tworate': piecewise linear, 4x slower in +-20 % of the expected
    resonant input frequency f_res."""
    Tr = n_rows / fs
    t = np.arange(n_rows) / fs
    if kind == "hyperbolic":
        tau = Tr / (1 - f_lo / f_hi)
        f = f_lo / (1 - t / tau)
    else:
        a, b = 0.8 * f_res, 1.2 * f_res
        w = np.array([a - f_lo, 4 * (b - a), f_hi - b])   # time weights (slow band x4)
        tb = np.cumsum(np.concatenate([[0], w])) / w.sum() * Tr
        f = np.interp(t, tb, [f_lo, a, b, f_hi])
    return t, f


def vibration_case(rng, gears, catalog_dir, combo=(), runup="hyperbolic", solver="wilson",
                   category="single", noise_kind=None, decoy=None):
    gl = _te_gears(gears)
    g = gl[int(rng.integers(len(gl)))]
    R = g.ratio
    s = _stiffness_scale(rng)
    K = g.K1 * s
    fn = _u(rng, 8.0, 20.0)
    J = K / (2 * math.pi * fn) ** 2
    # Jacobsen equivalent viscous damping from the catalog hysteresis loop at rated torque:
    # zeta = kappa delta / (pi theta(T0)), kappa = loop-shape factor 0.5-0.9
    kap = _u(rng, 0.5, 0.9)
    zeta = float(np.clip(kap * g.hysteresis / (math.pi * float(catalog_twist(g.rated, g, s))), 0.015, 0.12))
    rel = _u(rng, 0.6, 1.0)               # share of the damping across the spring (rest: load bearing)
    c_tot = 2 * zeta * math.sqrt(K * J)
    c_r, c_a = rel * c_tot, (1 - rel) * c_tot
    nuis = {"stiffness_scale": s, "damping_ratio": zeta, "damping_relative_share": rel,
            "f_n_Hz": math.sqrt(K / J) / (2 * math.pi)}
    effs = [e for e, _ in combo]
    orders = [1 if e == "te_1x" else 2 for e in effs]
    dkind = decoy
    if dkind in ("res_offset",):
        orders = [1]
    if dkind in ("res_imbalance",):
        orders = [2]
    if not orders:
        orders = [int(rng.integers(1, 3))]   # clean / separable decoys: a run-up for a nominal order
    # input sweep covering the resonances of the orders present
    f_lo = fn / max(orders) * _u(rng, 0.45, 0.6)
    f_hi = fn / min(orders) * _u(rng, 1.35, 1.6)
    f_hi = min(f_hi, g.max_in_rpm / 60.0)
    fs = 10.0 * max(orders) * f_hi
    n_rows = int(rng.integers(2400, 3000))
    t, f = _runup(rng, runup, f_lo, f_hi, fn / orders[0], n_rows, fs)
    nsub = 24
    h = 1.0 / (fs * nsub)
    tf = np.arange((n_rows - 1) * nsub + 1) * h
    ff = np.interp(tf, t, f)
    phif = 2 * math.pi * np.concatenate([[0], np.cumsum(0.5 * (ff[1:] + ff[:-1]) * h)]) + _u(rng, 0, 2 * math.pi)
    omf = 2 * math.pi * ff
    nuis.update({"runup_f_lo_Hz": f_lo, "runup_f_hi_Hz": f_hi})

    # excitation shapes: kinematic error e(phi) at the gear output, 1x or 2x per input rev
    shapes = []
    names = []
    if combo:
        for (eff, form) in combo:
            a = g.accuracy * _u(rng, 0.1, 0.3)
            b = _u(rng, 0, 2 * math.pi)
            o = 1 if eff == "te_1x" else 2
            shapes.append((o, a, b))
            names.append(eff)
            nuis[f"{eff}_amp_rad"] = a
    elif dkind == "res_offset":
        # 1X resolver, DC offset o on the sine channel, inside the position loop: the real
        # shaft follows phi_real = phi_cmd - o cos(phi) -> output base motion -(o/R) cos(phi)
        o_in = g.accuracy * R * _u(rng, 0.1, 0.3)
        shapes.append((1, o_in / R, _u(rng, 0, 2 * math.pi)))
        nuis["resolver_offset_input_rad"] = o_in
    elif dkind == "res_imbalance":
        # 1X resolver amplitude imbalance m: angle error (m/2) sin(2 phi) -> real 2x shaft motion
        m_in = g.accuracy * R * 2 * _u(rng, 0.1, 0.3)
        shapes.append((2, m_in / 2 / R, _u(rng, 0, 2 * math.pi)))
        nuis["resolver_imbalance"] = m_in

    def response(shp):
        e = np.zeros(tf.size)
        ed = np.zeros(tf.size)
        for (o, a, b) in shp:
            e += a * np.sin(o * phif + b)
            ed += a * o * omf * np.cos(o * phif + b)
        if not shp:
            return np.zeros(n_rows)
        p = K * e + c_r * ed
        if solver == "wilson":
            u = wilson_theta(J, c_tot, K, p, h, e[0], ed[0])
        else:
            u = bathe_composite(J, c_tot, K, p, h, e[0], ed[0])
        return u[::nsub][:n_rows]

    parts = []
    if len(shapes) == 2:
        # balance: both resonant responses visible
        r1, r2 = _rms(response([shapes[0]])), _rms(response([shapes[1]]))
        rho = r1 / r2
        if rho > 2.4 or rho < 1 / 2.4:
            fct = math.sqrt(rho / 2.4) if rho > 2.4 else math.sqrt(1 / (rho * 2.4))
            if rho > 2.4:
                shapes = [(shapes[0][0], shapes[0][1] / fct, shapes[0][2]), (shapes[1][0], shapes[1][1] * fct, shapes[1][2])]
            else:
                shapes = [(shapes[0][0], shapes[0][1] * fct, shapes[0][2]), (shapes[1][0], shapes[1][1] / fct, shapes[1][2])]
            nuis["amp_balance_factor"] = fct
    for shp in shapes:
        parts.append(response([shp]))
    total = np.sum(parts, axis=0) if parts else np.zeros(n_rows)
    meas, equiv = (), ()
    eff_meas = None
    if dkind == "out_ecc":
        er = _u(rng, 2e-5, 1e-4)
        eff_meas = er * np.sin(phif[::nsub][:n_rows] / R + _u(rng, 0, 2 * math.pi))
        meas = ("encoder_eccentricity",)
        nuis["encoder_ecc_rad"] = er
    elif dkind == "motor_drift":
        tau = _u(rng, 1.0, 4.0) * t[-1]
        q = (f / f.max()) ** 2
        th = np.zeros(n_rows)
        al = math.exp(-1.0 / (fs * tau))
        for i in range(1, n_rows):
            th[i] = th[i - 1] * al + q[i] * (1 - al)
        eff_meas = rng.choice([-1.0, 1.0]) * _u(rng, 2e-5, 1e-4) * th / th.max()
        meas = ("thermal_drift",)
        nuis["drift_tau_s"] = tau
    elif dkind == "rehome_step":
        i0 = int(rng.integers(int(0.3 * n_rows), int(0.7 * n_rows)))
        st = rng.choice([-1.0, 1.0]) * _u(rng, 1e-5, 6e-5)
        eff_meas = np.where(np.arange(n_rows) >= i0, st, 0.0)
        meas = ("angle_offset",)
        nuis["step_rad"] = st
    elif dkind in ("res_offset", "res_imbalance"):
        equiv = ("te_1x",) if dkind == "res_offset" else ("te_2x",)
    signal = total + (eff_meas if eff_meas is not None else 0.0)
    if category == "clean":
        sigma = _u(rng, 1e-6, 5e-6)
    elif eff_meas is not None:
        sigma = _sigma_single(rng, eff_meas)
    elif len(parts) == 1:
        sigma = _sigma_single(rng, parts[0])
    else:
        sigma = _sigma_multi(rng, parts, total)
        if sigma is None:
            sigma = _rms(total) / 8.0
    nk = noise_kind or ("ar1" if rng.random() < 0.5 else "white")
    nz, ninfo = _noise(rng, n_rows, sigma, nk)
    nuis.update(ninfo)
    for nmx, p in zip(names, parts):
        nuis["snr_" + nmx] = _rms(p) / sigma
    if meas:
        nuis["snr_" + meas[0]] = _rms(eff_meas) / sigma
    if equiv:
        nuis["snr_" + equiv[0]] = _rms(total) / sigma
    snr = _rms(signal) / sigma if (parts or eff_meas is not None) else 0.0
    form = {"": "no excitation"}.get("+".join(f for _, f in combo), " + ".join(f"{e} {f}" for e, f in combo))
    if dkind:
        form = {"out_ecc": "output-encoder eccentricity (1/output rev)",
                "motor_drift": "motor-heating drift (lag of speed^2)",
                "rehome_step": "output-encoder index re-homing step",
                "res_offset": "1X resolver sine-channel offset in the position loop (real 1x input motion)",
                "res_imbalance": "1X resolver amplitude imbalance in the position loop (real 2x input motion)"}[dkind]
    return dict(kind="vibration", model=g.code,
                columns={"time_s": t, "input_speed_rpm": 60.0 * f, "output_vibration_rad": signal + nz},
                load_inertia_kgm2=J, gear_effects=tuple(names), measurement_effects=meas,
                nuisance=nuis, category=category, equivalent_effects=equiv, noise_rms=sigma,
                formulation=f"{form}; base excitation; run-up {runup}; solver {solver}; "
                            f"Jacobsen damping; noise {nk}", snr=snr)


# --------------------------------------------------------------------------------------------
# the cell list
# --------------------------------------------------------------------------------------------
H1 = ("hysteresis", "masing-hardin-drnevich")
H2 = ("hysteresis", "bliman-sorine")
B1 = ("backlash", "exp-takeup")
B2 = ("backlash", "two-lock-algebraic")
C1 = ("housing_compliance", "flange-joint")
C2 = ("housing_compliance", "keyed-shaft")


def _cells(gears, cat_dir):
    C = []

    def add(tag, fn):
        C.append((tag, fn))
    # ---- torsion (22)
    add("torsion-clean-white-sinh", lambda r: torsion_clean_case(r, gears, "sinh", "white"))
    add("torsion-clean-ar1-lostmotion", lambda r: torsion_clean_case(r, gears, "lostmotion", "ar1"))
    add("torsion-clean-outliers-triangle", lambda r: torsion_clean_case(r, gears, "triangle", "outliers"))
    add("torsion-single-hysteresis-masinghd", lambda r: torsion_effect_case(r, gears, "lostmotion", [H1]))
    add("torsion-single-hysteresis-masinghd-sinh", lambda r: torsion_effect_case(r, gears, "sinh", [H1]))
    add("torsion-single-hysteresis-bliman", lambda r: torsion_effect_case(r, gears, "sinh", [H2]))
    add("torsion-single-backlash-exp", lambda r: torsion_effect_case(r, gears, "sinh", [B1]))
    add("torsion-single-backlash-twolock", lambda r: torsion_effect_case(r, gears, "twolock", [B2]))
    add("torsion-single-housing-joint", lambda r: torsion_effect_case(r, gears, "sinh", [C1]))
    add("torsion-single-housing-shaft", lambda r: torsion_effect_case(r, gears, "lostmotion", [C2]))
    add("torsion-pair-hysteresis-backlash", lambda r: torsion_effect_case(r, gears, "sinh", [H1, B1], "pair"))
    add("torsion-pair-hysteresis-housing", lambda r: torsion_effect_case(r, gears, "triangle", [H2, C1], "pair"))
    add("torsion-pair-backlash-housing", lambda r: torsion_effect_case(r, gears, "twolock", [B2, C2], "pair"))
    for d in ("torque_gain", "preload_offset", "joule_drift", "degrees", "kNm", "scale"):
        add(f"torsion-decoy-{d.replace('_', '')}", (lambda dd: lambda r: torsion_decoy_case(r, gears, dd))(d))
    for d in ("torque_flange", "seal_friction", "brake_play"):
        add(f"torsion-equiv-{d.replace('_', '')}", (lambda dd: lambda r: torsion_decoy_case(r, gears, dd))(d))
    # ---- transmission (15)
    add("transmission-clean-white", lambda r: transmission_case(r, gears, cat_dir, [], "equal-angle", "clean", "white"))
    add("transmission-clean-ar1", lambda r: transmission_case(r, gears, cat_dir, [], "time-ripple", "clean", "ar1"))
    add("transmission-clean-outliers", lambda r: transmission_case(r, gears, cat_dir, [], "output-triggered", "clean", "outliers"))
    add("transmission-single-te1x-hubfit", lambda r: transmission_case(r, gears, cat_dir, [("te_1x", "hubfit")], "output-triggered"))
    add("transmission-single-te1x-runout", lambda r: transmission_case(r, gears, cat_dir, [("te_1x", "runout-phasor")], "time-ripple"))
    add("transmission-single-te2x-vonmises", lambda r: transmission_case(r, gears, cat_dir, [("te_2x", "cs-sector-vonmises")], "equal-angle"))
    add("transmission-single-te2x-softclip", lambda r: transmission_case(r, gears, cat_dir, [("te_2x", "soft-clip")], "output-triggered"))
    add("transmission-pair-hubfit-vonmises", lambda r: transmission_case(r, gears, cat_dir, [("te_1x", "hubfit"), ("te_2x", "cs-sector-vonmises")], "output-triggered", "pair"))
    add("transmission-pair-runout-softclip", lambda r: transmission_case(r, gears, cat_dir, [("te_1x", "runout-phasor"), ("te_2x", "soft-clip")], "time-ripple", "pair"))
    for d in ("out_ecc", "slip_step", "out_deg", "in_deg"):
        add(f"transmission-decoy-{d.replace('_', '')}", (lambda dd: lambda r: transmission_decoy_case(r, gears, cat_dir, dd))(d))
    for d in ("tape", "resolver2p"):
        add(f"transmission-equiv-{d}", (lambda dd: lambda r: transmission_decoy_case(r, gears, cat_dir, dd))(d))
    # ---- efficiency (14)
    add("efficiency-clean-white", lambda r: efficiency_case(r, gears, cat_dir, category="clean", noise_kind="white"))
    add("efficiency-clean-ar1", lambda r: efficiency_case(r, gears, cat_dir, category="clean", noise_kind="ar1"))
    add("efficiency-clean-outliers", lambda r: efficiency_case(r, gears, cat_dir, category="clean", noise_kind="outliers"))
    add("efficiency-single-lowload-lazan", lambda r: efficiency_case(r, gears, cat_dir, low="lazan"))
    add("efficiency-single-lowload-seal", lambda r: efficiency_case(r, gears, cat_dir, low="seal"))
    add("efficiency-single-temp-ep", lambda r: efficiency_case(r, gears, cat_dir, temp="ep"))
    add("efficiency-single-temp-expansion", lambda r: efficiency_case(r, gears, cat_dir, temp="expansion"))
    add("efficiency-pair-lazan-ep", lambda r: efficiency_case(r, gears, cat_dir, low="lazan", temp="ep", category="pair"))
    add("efficiency-pair-seal-expansion", lambda r: efficiency_case(r, gears, cat_dir, low="seal", temp="expansion", category="pair"))
    for d in ("level", "gain", "fraction"):
        add(f"efficiency-decoy-{d}", (lambda dd: lambda r: efficiency_decoy_case(r, gears, cat_dir, dd))(d))
    for d in ("steinmetz", "cragoe"):
        add(f"efficiency-equiv-{d}", (lambda dd: lambda r: efficiency_decoy_case(r, gears, cat_dir, dd))(d))
    # ---- vibration (14)
    add("vibration-clean-white", lambda r: vibration_case(r, gears, cat_dir, category="clean", noise_kind="white"))
    add("vibration-clean-ar1", lambda r: vibration_case(r, gears, cat_dir, runup="tworate", category="clean", noise_kind="ar1"))
    add("vibration-clean-outliers", lambda r: vibration_case(r, gears, cat_dir, solver="bathe", category="clean", noise_kind="outliers"))
    add("vibration-single-te1x-hyper-wilson", lambda r: vibration_case(r, gears, cat_dir, [("te_1x", "sinusoid")], "hyperbolic", "wilson"))
    add("vibration-single-te1x-tworate-bathe", lambda r: vibration_case(r, gears, cat_dir, [("te_1x", "sinusoid")], "tworate", "bathe"))
    add("vibration-single-te2x-hyper-bathe", lambda r: vibration_case(r, gears, cat_dir, [("te_2x", "sinusoid")], "hyperbolic", "bathe"))
    add("vibration-single-te2x-tworate-wilson", lambda r: vibration_case(r, gears, cat_dir, [("te_2x", "sinusoid")], "tworate", "wilson"))
    add("vibration-pair-hyper-wilson", lambda r: vibration_case(r, gears, cat_dir, [("te_1x", "sinusoid"), ("te_2x", "sinusoid")], "hyperbolic", "wilson", "pair"))
    add("vibration-pair-tworate-bathe", lambda r: vibration_case(r, gears, cat_dir, [("te_1x", "sinusoid"), ("te_2x", "sinusoid")], "tworate", "bathe", "pair"))
    for d, ru in (("out_ecc", "hyperbolic"), ("motor_drift", "tworate"), ("rehome_step", "hyperbolic")):
        add(f"vibration-decoy-{d.replace('_', '')}", (lambda dd, rr: lambda r: vibration_case(r, gears, cat_dir, (), rr, "wilson", "decoy_separable", decoy=dd))(d, ru))
    for d, ru in (("res_offset", "hyperbolic"), ("res_imbalance", "tworate")):
        add(f"vibration-equiv-{d.replace('_', '')}", (lambda dd, rr: lambda r: vibration_case(r, gears, cat_dir, (), rr, "bathe", "decoy_equivalent", decoy=dd))(d, ru))
    return C


def cell_tags(catalog_dir):
    return [t for t, _ in _cells(load_gears(catalog_dir), str(catalog_dir))]


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    rng = np.random.default_rng(seed)
    gears = load_gears(catalog_dir)
    cases = []
    for tag, fn in _cells(gears, str(catalog_dir)):
        _CENTRED["on"] = tag.split("-")[0] in ("transmission", "efficiency")
        for i in range(per_cell):
            d = fn(rng)
            d["nuisance"] = {k: float(v) for k, v in d["nuisance"].items()}
            d["columns"] = {k: np.asarray(v, dtype=float) for k, v in d["columns"].items()}
            cases.append(TruthCase(name=f"l-{tag}-{i:03d}", **d))
    return cases
