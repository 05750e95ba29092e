"""Truth suite "n" for `hdcad reconcile` (strain-wave-gear test-data reconciliation).

Independent generator of synthetic "measured" test data with known hidden effects.
Written from CONTRACT.md, the catalog tables and the physics literature only
(formulations and citations: NOTES_n.md).  numpy + scipy only.

    SUITE = "n"
    generate_cases(seed, catalog_dir, per_cell=4) -> list[TruthCase]
"""
from __future__ import annotations

import csv
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import signal, special, stats
from scipy.optimize import brentq

SUITE = "n"

# noise arrays actually added, by case name (filled by generate_cases; used by selfcheck)
ADDED_NOISE: dict[str, np.ndarray] = {}

HEADERS = {
    "torsion": ("torque_Nm", "twist_rad"),
    "transmission": ("input_angle_rad", "output_angle_rad"),
    "efficiency": ("input_speed_rpm", "load_torque_Nm", "temperature_C", "efficiency_pct"),
    "vibration": ("time_s", "input_speed_rpm", "output_vibration_rad"),
}
MEASURED = {"torsion": "twist_rad", "transmission": "output_angle_rad",
            "efficiency": "efficiency_pct", "vibration": "output_vibration_rad"}


@dataclass
class TruthCase:
    name: str
    kind: str
    model: str
    columns: dict[str, np.ndarray]
    load_inertia_kgm2: float | None
    gear_effects: tuple[str, ...]
    measurement_effects: tuple[str, ...]
    nuisance: dict[str, float]
    category: str
    equivalent_effects: tuple[str, ...] = ()
    noise_rms: float = 0.0
    formulation: str = ""
    snr: float = 0.0

    def write_csv(self, path) -> None:
        names = list(self.columns)
        cols = [np.asarray(self.columns[c], dtype=float) for c in names]
        n = len(cols[0])
        with open(path, "w", newline="") as fh:
            fh.write(",".join(names) + "\n")
            for i in range(n):
                fh.write(",".join(repr(float(c[i])) for c in cols) + "\n")


# ----------------------------------------------------------------------------------------
# catalog
# ----------------------------------------------------------------------------------------
def _f(s):
    s = (s or "").strip()
    return float(s) if s else None


class Catalog:
    """GH gear heads (CSF-GH, CSG-GH) with every table a kind needs."""

    def __init__(self, catalog_dir):
        d = Path(catalog_dir)
        rd = lambda n: list(csv.DictReader(open(d / n, newline="", encoding="utf-8")))
        stiff = rd("gh_stiffness_052-1_060-1.csv")
        hyst = rd("gh_hysteresis_052_060.csv")
        back = rd("gh_backlash_052-2_060-2.csv")
        perf = rd("gh_performance_051-1_059-1.csv")
        rate = rd("gh_ratings_050-1_058-1.csv")
        ke = rd("ke_curve_023-1.csv")
        self.ke_anchor = [(float(r["alpha"]), float(r["Ke"])) for r in ke]
        self.models: dict[str, dict] = {}
        for r in rate:
            ser, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
            st = None
            for s in stiff:
                if s["series"] != ser or int(s["size"]) != size:
                    continue
                lo, hi = float(s["ratio_min"]), _f(s["ratio_max"])
                if ratio >= lo and (hi is None or ratio <= hi):
                    st = s
            hy = None
            for h in hyst:
                lo, hi = float(h["ratio_min"]), _f(h["ratio_max"])
                if h["series"] == ser and ratio >= lo and (hi is None or ratio <= hi):
                    hy = float(h["hysteresis_rad"])
            bl = None
            for b in back:
                if b["series"] == ser and int(b["size"]) == size and int(b["ratio"]) == ratio:
                    bl = float(b["backlash_rad"])
            acc = None
            for p in perf:
                if p["series"] == ser and int(p["size"]) == size and int(p["ratio"]) == ratio:
                    if _f(p["accuracy_rad"]) is not None:
                        acc = float(p["accuracy_rad"])
            code = f"{ser.split('-')[0]}-{size}-{ratio}-GH"
            m = dict(code=code, series=ser, size=size, ratio=ratio,
                     rated=float(r["rated_torque_2000_Nm"]),
                     n_avg_max=float(r["avg_input_speed_max_rpm"]),
                     n_max=float(r["max_input_speed_rpm"]),
                     hysteresis=hy, backlash=bl, accuracy=acc)
            if st is not None:
                m.update(T1=float(st["T1_Nm"]), T2=float(st["T2_Nm"]),
                         K1=float(st["K1_Nm_per_rad"]), K2=float(st["K2_Nm_per_rad"]),
                         K3=float(st["K3_Nm_per_rad"]))
            self.models[code] = m
        ms = self.models.values()
        self.torsion = sorted(m["code"] for m in ms if "K1" in m and m["hysteresis"] and m["backlash"])
        self.transmission = sorted(m["code"] for m in ms if m["accuracy"])
        self.vibration = sorted(m["code"] for m in ms if m["accuracy"] and "K1" in m)
        self.efficiency = sorted(m["code"] for m in ms)


# ----------------------------------------------------------------------------------------
# helpers: noise, rms
# ----------------------------------------------------------------------------------------
def rms(x):
    x = np.asarray(x, float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def crms(x):
    x = np.asarray(x, float)
    return rms(x - x.mean())


def unit_noise(rng, n, model, outliers=False):
    """Unit-RMS noise shape (RMS exactly 1 before outliers) and its metadata."""
    meta = {}
    if model == "white":
        w = rng.standard_normal(n)
        meta["noise_model_id"] = 0.0
    elif model == "ar1":
        phi = rng.uniform(0.3, 0.8)
        w = signal.lfilter([1.0], [1.0, -phi], rng.standard_normal(n))
        meta["noise_model_id"] = 1.0
        meta["ar1_phi"] = float(phi)
    elif model == "ggd":  # generalised Gaussian (Subbotin / Box-Tiao exponential power)
        beta = rng.uniform(1.2, 1.8)
        w = stats.gennorm.rvs(beta, size=n, random_state=rng)
        meta["noise_model_id"] = 2.0
        meta["ggd_beta"] = float(beta)
    else:
        raise ValueError(model)
    w = w - w.mean()
    w = w / rms(w)
    if outliers:
        m = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, size=m, replace=False)
        w[idx] += rng.choice([-1.0, 1.0], size=m) * rng.uniform(8, 15, size=m)
        meta["outlier_count"] = float(m)
    return w, meta


def pick_noise(rng, clean_formulation=None):
    if clean_formulation is not None:
        return {"white": ("white", False), "ar1": ("ar1", False),
                "ggd-outliers": ("ggd", True)}[clean_formulation]
    model = "white" if rng.random() < 0.5 else "ar1"
    return model, bool(rng.random() < 0.15)


def kumaraswamy_scale(rng, half=0.10, a=2.0, b=2.5):
    """Catalog stiffness spread: Kumaraswamy(a, b) on [1-half, 1+half]."""
    u = rng.random()
    x = (1 - (1 - u) ** (1 / b)) ** (1 / a)
    return 1 - half + 2 * half * x


# ----------------------------------------------------------------------------------------
# torsion
# ----------------------------------------------------------------------------------------
def twist_curve(T, m):
    """Catalog three-segment curve, theta1 = T1/K1, theta2 = theta1 + (T2-T1)/K2 (continuous), odd."""
    a = np.abs(T)
    th1 = m["T1"] / m["K1"]
    th2 = th1 + (m["T2"] - m["T1"]) / m["K2"]
    th = np.where(a <= m["T1"], a / m["K1"],
                  np.where(a <= m["T2"], th1 + (a - m["T1"]) / m["K2"], th2 + (a - m["T2"]) / m["K3"]))
    return np.sign(T) * th


def torsion_protocol(rng, T0):
    """Quasi-static cycles 0 -> +T0 -> -T0 ... -> 0 (specimen pre-cycled to -T0 before logging).

    'step': torque follows a first-order (pneumatic/servo-valve) step response towards +-T0,
            logged at a fixed rate.  'poisson': linear ramps logged at Poisson (event-driven)
            instants.  Returns t, T, protocol id."""
    ncyc = int(rng.integers(2, 5))
    if rng.random() < 0.5:
        tau = rng.uniform(2.0, 5.0)
        fs = rng.uniform(8.0, 20.0)
        dur = 6.0 * tau
        tt = np.arange(0, dur, 1 / fs)
        T, t = [], []
        cur, t0 = 0.0, 0.0
        targets = []
        for _ in range(ncyc):
            targets += [T0, -T0]
        targets += [0.0]
        for tg in targets:
            seg = tg + (cur - tg) * np.exp(-tt / tau)
            T.append(seg)
            t.append(t0 + tt)
            cur = tg + (cur - tg) * np.exp(-dur / tau)  # value when the next set-point is issued
            t0 += dur
        return np.concatenate(t), np.concatenate(T), 0.0
    rate = T0 / rng.uniform(8.0, 20.0)  # N m / s
    path = [0.0] + [T0, -T0] * ncyc + [0.0]
    knots_t = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(path)) / rate)])
    lam = rng.uniform(8.0, 20.0)
    n_exp = int(knots_t[-1] * lam * 1.3) + 10
    t = np.cumsum(rng.exponential(1 / lam, size=n_exp))
    t = t[t < knots_t[-1]]
    T = np.interp(t, knots_t, path)
    return t, T, 1.0


def _segments(T):
    """Monotone segments of T (start index, end index, direction)."""
    d = np.sign(np.diff(T))
    for i in range(1, len(d)):
        if d[i] == 0:
            d[i] = d[i - 1]
    if d[0] == 0:
        d[0] = 1.0
    cut = np.where(np.diff(d) != 0)[0] + 1
    starts = np.concatenate([[0], cut])
    ends = np.concatenate([cut, [len(T) - 1]])
    return [(s, e, d[min(s, len(d) - 1)]) for s, e in zip(starts, ends)]


def hyst_takacs(T, T0, Tr, loss, rng, nz):
    """Takacs T(x) hysteresis (tanh branches), centre line removed; loss = loop width at T=0
    after cycling to rated torque."""
    a = rng.uniform(0.25, 0.6)
    w = rng.uniform(0.3, 0.6) * Tr
    D = lambda x: np.tanh(x + a) - np.tanh(x - a)
    A = loss / (D(0.0) - D(Tr / w))
    nz.update(takacs_a=float(a), takacs_w_Nm=float(w))
    h = np.zeros_like(T)
    # virtual previous reversal: (-T0, 0) on the ascending branch (pre-cycled specimen)
    Tr_prev, h_prev = -T0, 0.0
    for s, e, d in _segments(T):
        x = T[s:e + 1] / w
        shape = -d * A * D(x) / 2.0
        c = h_prev - (-d * A * D(Tr_prev / w) / 2.0)
        h[s:e + 1] = shape + c
        Tr_prev, h_prev = T[e], h[e]
    return h


def hyst_lapshin(T, T0, Tr, loss, rng, nz):
    """Lapshin (1995) harmonic loop: split +-a*(1-(T/T_end)^2)^(m/2) about the centre line,
    amplitude law a ~ (T0/Tr)^p (almost no loss at very small torque)."""
    m = float(rng.choice([1.0, 3.0]))
    p = rng.uniform(1.5, 2.5)
    a = 0.5 * loss * (T0 / Tr) ** p
    nz.update(lapshin_m=m, lapshin_p=float(p))
    h = np.zeros_like(T)
    for i, (s, e, d) in enumerate(_segments(T)):
        Ts = T[s:e + 1]
        t_start = T[s] if i > 0 else -T0  # pre-cycled: the first branch comes from -T0
        t_end = T[e]
        pos = abs(t_end) if d > 0 else abs(t_start)
        neg = abs(t_start) if d > 0 else abs(t_end)
        norm = np.maximum(np.where(Ts >= 0, pos, neg), 1e-12)
        u = np.clip(1 - (Ts / norm) ** 2, 0, None)
        h[s:e + 1] = -d * a * u ** (m / 2)
    return h


def backlash_johnson(T, T0, b, rng, nz):
    """Gap of width b crossed at torque reversal; closure follows Johnson's line-contact
    compliance shape u(1 - ln u) up to the engagement torque Tb (Oldham key on its slot)."""
    Tb = rng.uniform(0.005, 0.03) * T0
    nz["backlash_engage_Nm"] = float(Tb)
    u = np.clip(np.abs(T) / Tb, 1e-300, None)
    g = np.where(u < 1, u * (1 - np.log(u)), 1.0)
    return np.sign(T) * 0.5 * b * g


def backlash_rational(T, T0, b, rng, nz):
    """Gap of width b with a rational (softsign) take-up u/(1+|u|), u = T/Tb."""
    Tb = rng.uniform(0.002, 0.01) * T0
    nz["backlash_engage_Nm"] = float(Tb)
    u = T / Tb
    return 0.5 * b * u / (1 + np.abs(u))


def housing_geometry(rng, form):
    if form == "stvenant-rectbar":
        return dict(G=float(rng.choice([79.3e9, 26.0e9])), L=rng.uniform(0.05, 0.3),
                    ar=rng.uniform(1.0, 3.0))
    return dict(R=rng.uniform(0.15, 0.5), bw=rng.uniform(0.02, 0.06))


def housing_rectbar(T, K1, f, geo, nz):
    """Output adaptor bar of rectangular section b x h (b = ar*h) in Saint-Venant torsion:
    J = beta*b*h^3 with the Timoshenko-Goodier series for beta(b/h); c = L/(G J) = f/K1 fixes h."""
    G, L, ar = geo["G"], geo["L"], geo["ar"]
    n = np.arange(1, 20, 2)
    beta = (1 - 192 / np.pi ** 5 / ar * np.sum(np.tanh(n * np.pi * ar / 2) / n ** 5)) / 3
    c = f / K1
    h = (L / (G * beta * ar * c)) ** 0.25
    nz.update(housing_fraction=float(f), bar_length_m=float(L), bar_thickness_m=float(h),
              bar_beta=float(beta), bar_shear_modulus_Pa=float(G))
    return c * T


def housing_arm(T, K1, f, geo, nz):
    """Housing held by a reaction arm (Timoshenko cantilever, bending + shear):
    phi = T*(R/(3EI) + 1/(kappa*G*A*R)); the section height gives c = f/K1."""
    E, G, kap = 206e9, 79.3e9, 5 / 6
    R, bw = geo["R"], geo["bw"]
    c = f / K1
    fun = lambda hh: R / (3 * E * bw * hh ** 3 / 12) + 1 / (kap * G * bw * hh * R) - c
    lo, hi = 1e-4, 2.0
    hh = brentq(fun, lo, hi) if fun(lo) * fun(hi) < 0 else -1.0
    nz.update(housing_fraction=float(f), arm_length_m=float(R), arm_height_m=float(hh))
    return c * T


TORSION_CELLS = []
for _f_ in ("white", "ar1", "ggd-outliers"):
    TORSION_CELLS.append(("clean", (), (), _f_))
for _f_ in ("takacs-tanh", "lapshin-harmonic"):
    TORSION_CELLS.append(("single", ("hysteresis",), (), _f_))
for _f_ in ("johnson-line", "softsign-gap"):
    TORSION_CELLS.append(("single", ("backlash",), (), _f_))
for _f_ in ("stvenant-rectbar", "timoshenko-arm"):
    TORSION_CELLS.append(("single", ("housing_compliance",), (), _f_))
TORSION_CELLS += [
    ("pair", ("hysteresis", "backlash"), (), "takacs-tanh+johnson-line"),
    ("pair", ("hysteresis", "backlash"), (), "lapshin-harmonic+softsign-gap"),
    ("pair", ("hysteresis", "housing_compliance"), (), "takacs-tanh+timoshenko-arm"),
    ("pair", ("hysteresis", "housing_compliance"), (), "lapshin-harmonic+stvenant-rectbar"),
    ("pair", ("backlash", "housing_compliance"), (), "johnson-line+stvenant-rectbar"),
    ("pair", ("backlash", "housing_compliance"), (), "softsign-gap+timoshenko-arm"),
    ("decoy_separable", (), ("sensor_gain",), "adc-reference-gain"),
    ("decoy_separable", (), ("angle_offset",), "autocollimator-zero"),
    ("decoy_separable", (), ("thermal_drift",), "work-heating-lag"),
    ("decoy_separable", (), ("thermal_drift",), "wiener-drift"),
    ("decoy_separable", (), ("wrong_units",), "degrees"),
    ("decoy_separable", (), ("wrong_units",), "kNm"),
    ("decoy_separable", (), (), "stiffness-scale"),
    ("decoy_equivalent", (), ("adaptor_windup",), "mirror-adaptor-windup"),
    ("decoy_equivalent", (), ("eddy_current_drag",), "eddy-current-drag"),
    ("decoy_equivalent", (), ("torque_deadband",), "amplifier-crossover-deadband"),
]
EQUIV = {"adaptor_windup": ("housing_compliance",), "eddy_current_drag": ("hysteresis",),
         "torque_deadband": ("backlash",), "input_gravity_unbalance": ("te_1x",),
         "encoder_drum_ovality": ("te_2x",), "dynamometer_trunnion_friction": ("low_load_efficiency",),
         "coupling_spider_friction": ("temperature_dependence",), "brake_detent_torque": ("te_2x",)}

HYST = {"takacs-tanh": hyst_takacs, "lapshin-harmonic": hyst_lapshin}
BACK = {"johnson-line": backlash_johnson, "softsign-gap": backlash_rational}
HOUS = {"stvenant-rectbar": housing_rectbar, "timoshenko-arm": housing_arm}


def _pair_ks(rng, hi=8.0):
    return rng.uniform(4.0, hi), rng.uniform(4.0, hi)


def torsion_case(rng, cat, cell):
    cat_, gear, meas, form = cell
    forms = form.split("+")
    for _attempt in range(400):
        code = str(rng.choice(cat.torsion))
        m = cat.models[code]
        nz: dict[str, float] = {}
        s = kumaraswamy_scale(rng)
        nz["stiffness_scale"] = float(s)
        Tr = m["rated"]
        lo_T0 = 0.3 if (cat_ == "pair" and "backlash" in gear and "hysteresis" in gear) else 0.9
        T0 = Tr * rng.uniform(lo_T0, 1.1)
        nz["T0_Nm"] = float(T0)
        t, T, pid = torsion_protocol(rng, T0)
        nz["protocol_id"] = pid
        K1s = m["K1"] * s
        base = twist_curve(T, m) / s
        eff: dict[str, np.ndarray] = {}
        hs = rng.uniform(0.8, 1.2)  # "約" (approximately) on the hysteresis value
        geo = None
        for g, fm in zip(gear, forms):
            if g == "hysteresis":
                nz["hysteresis_scale"] = float(hs)
                eff[g] = HYST[fm](T, T0, Tr, m["hysteresis"] * hs, rng, nz)
            elif g == "backlash":
                bf = rng.uniform(0.5, 1.0)  # the table gives the maximum backlash
                nz["backlash_fraction_of_max"] = float(bf)
                eff[g] = BACK[fm](T, T0, m["backlash"] * bf, rng, nz)
            elif g == "housing_compliance":
                geo = housing_geometry(rng, fm)
                hfun = HOUS[fm]
                eff[g] = hfun(T, K1s, rng.uniform(0.05, 0.35), geo, nz)
        noise_model, outl = pick_noise(rng, form if cat_ == "clean" else None)
        w, meta = unit_noise(rng, len(T), noise_model, outl)
        nz.update(meta)
        k = rng.uniform(4, 12)
        T_meas = T.copy()
        twist = base.copy()
        ref = base  # what the decoy/effect is measured against
        noise_rms = (T0 / m["K1"]) * rng.uniform(0.002, 0.012)  # default (clean, drifts, units)
        if cat_ == "single":
            noise_rms = rms(eff[gear[0]]) / k
        elif cat_ == "pair":
            anchor = "backlash" if "backlash" in gear else "hysteresis"
            other = [g for g in gear if g != anchor][0]
            k1, k2 = _pair_ks(rng)
            noise_rms = rms(eff[anchor]) / k1
            sc = k2 * noise_rms / rms(eff[other])
            if other == "hysteresis":
                if not 0.5 <= hs * sc <= 1.5:
                    continue
                eff[other] = eff[other] * sc
                nz["hysteresis_scale"] = float(hs * sc)
            else:
                f_new = nz["housing_fraction"] * sc
                if not 0.01 <= f_new <= 0.5:
                    continue
                eff[other] = hfun(T, K1s, f_new, geo, nz)
        elif form == "adc-reference-gain":
            gg = 1 + rng.choice([-1, 1]) * rng.uniform(0.02, 0.06)
            nz["torque_gain"] = float(gg)
            T_meas = gg * T
            ref = twist_curve(T_meas, m) / s
        elif form in ("autocollimator-zero", "work-heating-lag", "wiener-drift"):
            if form == "autocollimator-zero":
                me = np.ones_like(T) * rng.choice([-1, 1])
            elif form == "work-heating-lag":
                P = np.abs(T * np.gradient(base, t))
                tau = rng.uniform(0.3, 1.0) * t[-1]
                dt = np.diff(t, prepend=t[0])
                me = np.zeros_like(t)
                for i in range(1, len(t)):
                    me[i] = me[i - 1] + dt[i] * (P[i] - me[i - 1] / tau)
                nz["drift_tau_s"] = float(tau)
                me *= rng.choice([-1, 1])
            else:
                me = np.cumsum(rng.standard_normal(len(t)) * np.sqrt(np.diff(t, prepend=t[0]) + 1e-9))
                me -= me[0]
            me = me * k * noise_rms / rms(me)
            if form == "autocollimator-zero":
                nz["angle_offset_rad"] = float(me[0])
            twist = base + me
        elif form == "stiffness-scale":
            s2 = 1 + rng.choice([-1, 1]) * rng.uniform(0.03, 0.095)
            nz["stiffness_scale"] = float(s2)
            twist = twist_curve(T, m) / s2
            ref = twist_curve(T, m)
        elif form == "mirror-adaptor-windup":
            fa = rng.uniform(0.05, 0.3)
            nz["adaptor_fraction"] = float(fa)
            twist = base + fa / K1s * T
        elif form == "eddy-current-drag":
            dth = np.gradient(base, t)
            cv = rng.uniform(0.5, 2.0) * 0.01 * T0 / np.max(np.abs(dth))
            nz["eddy_drag_Nms_per_rad"] = float(cv)
            T_meas = T + cv * dth
            ref = twist_curve(T_meas, m) / s
        elif form == "amplifier-crossover-deadband":
            dlt = rng.uniform(0.003, 0.015) * T0
            nz["deadband_Nm"] = float(dlt)
            T_meas = np.sign(T) * np.maximum(np.abs(T) - dlt, 0.0)
            ref = twist_curve(T_meas, m) / s
        if eff:
            twist = base + sum(eff.values())
        if cat_ in ("decoy_separable", "decoy_equivalent") and form in (
                "adc-reference-gain", "stiffness-scale", "mirror-adaptor-windup",
                "eddy-current-drag", "amplifier-crossover-deadband"):
            noise_rms = rms(twist - ref) / k
        noise = w * (noise_rms / rms(w))
        noise_rms = rms(noise)
        twist_meas = twist + noise
        if form == "degrees":
            twist_meas, noise = np.degrees(twist_meas), np.degrees(noise)
            noise_rms = rms(noise)
        if form == "kNm":
            T_meas = T_meas * 1e-3
        snrs = {}
        if gear:
            for g in gear:
                snrs[f"snr_{g}"] = rms(eff[g]) / noise_rms
            tot = rms(sum(eff.values())) / noise_rms
        elif cat_ == "clean" or form in ("degrees", "kNm"):
            tot = 0.0
        else:
            tot = rms(twist - ref) / noise_rms
            snrs["snr_" + (meas[0] if meas else "stiffness_scale")] = tot
        vals = list(snrs.values()) + ([tot] if snrs else [])
        if any(not (4 - 1e-6 <= v <= 12 + 1e-6) for v in vals):
            continue
        nz.update({a: float(b) for a, b in snrs.items()})
        cols = {"torque_Nm": T_meas, "twist_rad": twist_meas}
        return dict(model=code, columns=cols, gear=gear, meas=meas, nuisance=nz, noise=noise,
                    noise_rms=noise_rms, snr=float(tot), load_inertia=None,
                    equiv=EQUIV.get(meas[0], ()) if cat_ == "decoy_equivalent" else ())
    raise RuntimeError(f"torsion cell {cell} infeasible")


# ----------------------------------------------------------------------------------------
# transmission
# ----------------------------------------------------------------------------------------
def wave_parabolic(x):
    """Unit-peak piecewise-parabolic wave (constant-acceleration cam law), odd harmonics 1/n^3."""
    y = np.mod(x, 2 * np.pi)
    half = np.where(y < np.pi, 1.0, -1.0)
    z = np.mod(y, np.pi)
    return half * 4 / np.pi ** 2 * z * (np.pi - z)


def wave_hertz(x, p):
    """Signed power of a sinusoid, sign(sin)|sin|^p (Hertzian contact mapping), odd harmonics."""
    s = np.sin(x)
    return np.sign(s) * np.abs(s) ** p


TRANS_CELLS = []
for _f_ in ("white", "ar1", "ggd-outliers"):
    TRANS_CELLS.append(("clean", (), (), _f_))
for _g_ in ("te_1x", "te_2x"):
    for _f_ in ("parabolic-cam", "hertz-power"):
        TRANS_CELLS.append(("single", (_g_,), (), _f_))
for _f_ in ("parabolic-cam", "hertz-power"):
    TRANS_CELLS.append(("pair", ("te_1x", "te_2x"), (), _f_))
TRANS_CELLS += [
    ("decoy_separable", (), ("encoder_eccentricity",), "hub-eccentricity-exact"),
    ("decoy_separable", (), ("angle_offset",), "index-relatch-step"),
    ("decoy_separable", (), ("thermal_drift",), "wiener-drift"),
    ("decoy_separable", (), ("sensor_gain",), "interpolator-scale"),
    ("decoy_separable", (), ("wrong_units",), "degrees"),
    ("decoy_equivalent", (), ("input_gravity_unbalance",), "unbalance-input-twist"),
    ("decoy_equivalent", (), ("encoder_drum_ovality",), "oval-tape-drum"),
]


def transmission_case(rng, cat, cell):
    cat_, gear, meas, form = cell
    code = str(rng.choice(cat.transmission))
    m = cat.models[code]
    R = m["ratio"]
    acc = m["accuracy"]
    nz: dict[str, float] = {}
    full = (form in ("hub-eccentricity-exact", "interpolator-scale")) or rng.random() < 0.4
    if full:  # one full output revolution and a little more, encoder-triggered
        nrev = R * rng.uniform(1.02, 1.15)
        npr = int(rng.choice([48, 64, 72, 90]))
    else:
        nrev = rng.uniform(6.0, 16.0)
        npr = int(rng.choice([256, 360, 512, 720]))
    N = int(nrev * npr)
    phi0 = rng.uniform(0, 2 * np.pi)
    phi = phi0 + 2 * np.pi * np.arange(N) / npr
    off = rng.uniform(-np.pi, np.pi)
    nz.update(output_offset_rad=float(off), samples_per_input_rev=float(npr), input_revs=float(nrev))
    out = phi / R + off
    eff = {}
    if cat_ in ("single", "pair"):
        p = rng.uniform(0.6, 0.95)
        shapes = {}
        for g in gear:
            kk = 1 if g == "te_1x" else 2
            ps = rng.uniform(0, 2 * np.pi)
            nz[f"{g}_phase_rad"] = float(ps)
            if form == "parabolic-cam":
                shapes[g] = wave_parabolic(kk * phi + ps)
            else:
                shapes[g] = wave_hertz(kk * phi + ps, p)
                nz["hertz_exponent"] = float(p)
        if cat_ == "single":
            (g,) = gear
            amp = 0.5 * acc * rng.uniform(0.3, 0.9)
            eff[g] = amp * shapes[g]
            nz[f"{g}_amp_rad"] = float(amp)
            k = rng.uniform(4, 12)
            noise_rms = rms(eff[g]) / k
        else:
            while True:
                k1, k2 = _pair_ks(rng)
                r1, r2 = rms(shapes["te_1x"]), rms(shapes["te_2x"])
                a1 = 1.0
                a2 = (k2 / k1) * r1 / r2
                tot = shapes["te_1x"] * a1 + shapes["te_2x"] * a2
                scale = rng.uniform(0.4, 0.95) * acc / np.ptp(tot)
                a1, a2 = a1 * scale, a2 * scale
                eff = {"te_1x": a1 * shapes["te_1x"], "te_2x": a2 * shapes["te_2x"]}
                noise_rms = rms(eff["te_1x"]) / k1
                if rms(eff["te_1x"] + eff["te_2x"]) / noise_rms <= 12:
                    break
            nz.update(te_1x_amp_rad=float(a1), te_2x_amp_rad=float(a2))
    else:
        noise_rms = acc * rng.uniform(0.01, 0.06)
    noise_model, outl = pick_noise(rng, form if cat_ == "clean" else None)
    w, meta = unit_noise(rng, N, noise_model, outl)
    nz.update(meta)
    truth = out + sum(eff.values()) if eff else out.copy()
    inp = phi.copy()
    me = None
    k = rng.uniform(4, 12)
    if form == "hub-eccentricity-exact":
        psi = rng.uniform(0, 2 * np.pi)
        th = phi / R
        shape = np.arctan2(np.sin(th - psi), 1 / 1e-4 + np.cos(th - psi))
        me = shape
    elif form == "index-relatch-step":
        i0 = int(N * rng.uniform(0.3, 0.7))
        me = np.where(np.arange(N) >= i0, 1.0, 0.0)
        nz["step_index"] = float(i0)
    elif form == "wiener-drift":
        me = np.cumsum(rng.standard_normal(N))
        me -= me[0]
    elif form == "interpolator-scale":
        me = (phi / R + off)  # gain acts on the whole output reading
    elif form == "unbalance-input-twist":
        # the WG lags the motor encoder by (m g r / K_shaft) sin(phi + psi): output = (phi - d)/R
        mm, rr, Ks = rng.uniform(0.3, 1.5), rng.uniform(0.01, 0.035), rng.uniform(30, 300)
        psi = rng.uniform(0, 2 * np.pi)
        dphi = mm * 9.81 * rr / Ks
        nz.update(unbalance_kg_m=float(mm * rr), input_shaft_stiffness_Nm_per_rad=float(Ks))
        me = -(dphi / R) * np.sin(phi + psi)
    elif form == "oval-tape-drum":
        eps = rng.uniform(3e-4, 3e-3)  # drum out-of-roundness / radius
        psi = rng.uniform(0, 2 * np.pi)
        nz["drum_ovality"] = float(eps)
        inp = phi + eps * np.sin(2 * phi + psi)  # the input reading is wrong
        me = None
    if cat_ in ("decoy_separable", "decoy_equivalent") and form != "degrees":
        if form == "unbalance-input-twist":
            noise_rms = rms(me) / k
        elif form == "oval-tape-drum":
            noise_rms = rms((inp - phi) / R) / k
        elif form == "interpolator-scale":
            # choose gain so the part not absorbed by the constant offset has RMS k*noise
            gg = k * noise_rms / crms(me)
            nz["output_gain_error"] = float(gg)
            me = gg * me
        elif form == "index-relatch-step":
            me = me - 0.0
            me = me * (k * noise_rms / crms(me)) * rng.choice([-1, 1])
        elif form != "unbalance-input-twist":
            c = me - me.mean() if form in ("wiener-drift", "hub-eccentricity-exact") else me
            me = me * (k * noise_rms / rms(c))
        if me is not None:
            truth = truth + me
    noise = w * (noise_rms / rms(w))
    noise_rms = rms(noise)
    outm = truth + noise
    if form == "degrees":
        outm = np.degrees(outm)
        noise = np.degrees(noise)
        noise_rms = rms(noise)
    snrs = {}
    if cat_ in ("single", "pair"):
        for g in gear:
            snrs[f"snr_{g}"] = rms(eff[g]) / noise_rms
        tot = rms(sum(eff.values())) / noise_rms
    elif cat_ == "clean" or form == "degrees":
        tot = 0.0
    else:
        resid = truth - (inp / R + off)
        tot = crms(resid) / noise_rms
        snrs[f"snr_{meas[0]}"] = tot
    nz.update({a: float(b) for a, b in snrs.items()})
    cols = {"input_angle_rad": inp, "output_angle_rad": outm}
    return dict(model=code, columns=cols, gear=gear, meas=meas, nuisance=nz, noise=noise,
                noise_rms=noise_rms, snr=float(tot), load_inertia=None,
                equiv=EQUIV.get(meas[0], ()) if cat_ == "decoy_equivalent" else ())


# ----------------------------------------------------------------------------------------
# efficiency
# ----------------------------------------------------------------------------------------
def yaws_coeffs(rng):
    """Yaws correlation log10(mu) = A + B/T + C*T (+ D*T^2, D = 0 here), T in K, fitted to a
    grease base oil: nu40 from ISO VG grades, nu0/nu40 and nu40/nu100 in mineral-oil ranges."""
    vg = float(rng.choice([32.0, 68.0, 100.0])) * rng.uniform(0.9, 1.1)
    r0 = rng.uniform(9.0, 16.0)
    r100 = rng.uniform(6.0, 9.0)
    Tk = np.array([273.15, 313.15, 373.15])
    y = np.log10([vg * r0, vg, vg / r100])
    M = np.column_stack([np.ones(3), 1 / Tk, Tk])
    A, B, C = np.linalg.solve(M, y)
    return (A, B, C), vg


def yaws_mu(TC, co):
    A, B, C = co
    Tk = np.asarray(TC) + 273.15
    return 10 ** (A + B / Tk + C * Tk)


def ke_archard(alpha, etaR, ke_anchor):
    """Losses L0 + c*T^(2/3) (Archard: single elastic contact, mu ~ W^(-1/3)), split fixed by
    the catalog point Ke(0.58) = 0.93 and eta(1) = etaR; Ke = 1 for alpha >= 1 (023-1 note)."""
    l1 = 1 / etaR - 1
    a0, k0 = ke_anchor

    def ke(al, l0):
        al = np.asarray(al, float)
        eta = al / (al + l0 + (l1 - l0) * al ** (2 / 3))
        return eta * (1 + l1)
    fz = lambda l0: ke(a0, l0) - k0
    if fz(0.0) * fz(l1) > 0:
        return None, None  # this (etaR, anchor) pair admits no non-negative split
    l0 = brentq(fz, 0.0, l1)
    out = np.where(alpha >= 1, 1.0, ke(np.minimum(alpha, 1), l0))
    return out, l0


def ke_loglaw(alpha, ke_anchor):
    """Ke = 1 + c ln(alpha) (logarithmic part-load law), c from the catalog point."""
    a0, k0 = ke_anchor
    c = (1 - k0) / np.log(1 / a0)
    return np.clip(np.where(alpha >= 1, 1.0, 1 + c * np.log(np.maximum(alpha, 1e-9))), 0.25, 1.0), c


EFF_CELLS = []
for _f_ in ("white", "ar1", "ggd-outliers"):
    EFF_CELLS.append(("clean", (), (), _f_))
for _f_ in ("archard-two-thirds", "log-law"):
    EFF_CELLS.append(("single", ("low_load_efficiency",), (), _f_))
for _f_ in ("yaws-viscous", "sisko-grease"):
    EFF_CELLS.append(("single", ("temperature_dependence",), (), _f_))
EFF_CELLS += [
    ("pair", ("low_load_efficiency", "temperature_dependence"), (), "archard-two-thirds+yaws-viscous"),
    ("pair", ("low_load_efficiency", "temperature_dependence"), (), "log-law+sisko-grease"),
    ("decoy_separable", (), ("sensor_gain",), "output-torque-gain"),
    ("decoy_separable", (), ("wrong_units",), "fraction"),
    ("decoy_separable", (), (), "efficiency-level"),
    ("decoy_equivalent", (), ("dynamometer_trunnion_friction",), "cradled-motor-trunnion"),
    ("decoy_equivalent", (), ("coupling_spider_friction",), "grosch-wlf-spider"),
]
ETA_REF = 78.0  # % : the seed's worked example CSF-20-80 at rated torque (component_examples.csv)


def draw_temp_params(rng, form):
    co, vg = yaws_coeffs(rng)
    p = dict(co=co, vg=vg, q=rng.uniform(0.4, 0.7))
    if form == "sisko-grease":
        p.update(ns=rng.uniform(0.2, 0.5), kr=rng.uniform(2.0, 10.0))
    return p


def temp_factor(p, TC, n, form, lam, nz, Tref=25.0):
    """Multiplicative efficiency factor (1+lam)/(1+lam*r^q); r = lubricant viscosity ratio to the
    catalog's 25 C measuring condition (yaws-viscous) or the Sisko apparent-viscosity ratio at
    the same input speed (sisko-grease)."""
    co, q = p["co"], p["q"]
    nz.update(base_oil_vg=float(p["vg"]), viscous_exponent_q=float(q))
    mu = lambda TT: yaws_mu(TT, co) / yaws_mu(Tref, co)
    if form == "yaws-viscous":
        r = mu(TC)
    else:
        ns, kr = p["ns"], p["kr"]
        gd = 1e4 * np.asarray(n) / 1000.0  # shear rate in the WG/flexspline grease film, 1/s
        app = lambda TT: mu(TT) + kr * mu(TT) ** 0.7 * (gd / 1e4) ** (ns - 1)
        r = app(TC) / app(Tref)
        nz.update(sisko_n=float(ns), sisko_ratio=float(kr))
    return (1 + lam) / (1 + lam * r ** q)


def efficiency_case(rng, cat, cell):
    cat_, gear, meas, form = cell
    for _attempt in range(200):
        code = str(rng.choice(cat.efficiency))
        m = cat.models[code]
        Tr = m["rated"]
        R = m["ratio"]
        nz: dict[str, float] = {}
        lub = int(rng.integers(0, 2))  # 0: SK-1A/SK-2 (0..40 C ambient), 1: 4B No.2 (-10..70 C)
        nz["lubricant_id"] = float(lub)
        tlo, thi = (0.0, 40.0) if lub == 0 else (-10.0, 70.0)
        temps = np.linspace(tlo, thi, 5)
        speeds_all = np.array([500, 1000, 1500, 2000, 2500, 3000, 3500], float)
        speeds_all = speeds_all[speeds_all <= m["n_avg_max"]]
        speeds = np.sort(rng.choice(speeds_all, size=min(4, len(speeds_all)), replace=False))
        alphas = np.array([0.1, 0.2, 0.3, 0.45, 0.6, 0.8, 1.0, 1.15])
        rows = []
        for Tc in temps:  # climatic chamber steps cold -> warm; random order within a step
            block = [(n, a, Tc + rng.normal(0, 0.4)) for n in speeds for a in alphas]
            order = rng.permutation(len(block))
            rows += [block[i] for i in order]
        n = np.array([r[0] for r in rows])
        al = np.array([r[1] for r in rows])
        TC = np.array([r[2] for r in rows])
        Tl = al * Tr
        etaR = rng.uniform(0.62, 0.85)
        nz["efficiency_level_pct"] = float(100 * etaR)
        ka = cat.ke_anchor[0]
        ke_anchor = (ka[0], ka[1] + rng.uniform(-0.01, 0.01))
        Ke = np.ones_like(al)
        F = np.ones_like(al)
        forms = form.split("+")
        for g, fm in zip(gear, forms):
            if g == "low_load_efficiency":
                if fm == "archard-two-thirds":
                    Ke, l0 = ke_archard(al, etaR, ke_anchor)
                    if Ke is None:
                        break
                    nz["archard_constant_loss"] = float(l0)
                else:
                    Ke, c = ke_loglaw(al, ke_anchor)
                    nz["loglaw_c"] = float(c)
                nz["ke_anchor"] = float(ke_anchor[1])
        if Ke is None:
            continue
        eta = 100 * etaR * Ke
        eff = {}
        if "low_load_efficiency" in gear:
            eff["low_load_efficiency"] = eta - 100 * etaR
        if "temperature_dependence" in gear:
            fm = forms[gear.index("temperature_dependence")]
            prm = draw_temp_params(rng, fm)
            lam = rng.uniform(0.1, 0.35)
            d = {}
            Fv = temp_factor(prm, TC, n, fm, lam, d)
            if cat_ == "pair":
                k1, k2 = _pair_ks(rng)
                noise_rms = crms(eff["low_load_efficiency"]) / k1
                target = k2 * noise_rms
                fun = lambda L: crms(eta * (temp_factor(prm, TC, n, fm, L, {}) - 1)) - target
                if fun(0.005) * fun(1.5) > 0:
                    continue
                lam = brentq(fun, 0.005, 1.5)
                Fv = temp_factor(prm, TC, n, fm, lam, d)
            nz.update(d)
            nz["viscous_share_lambda"] = float(lam)
            eff["temperature_dependence"] = eta * (Fv - 1)
            eta = eta * Fv
        noise_model, outl = pick_noise(rng, form if cat_ == "clean" else None)
        w, meta = unit_noise(rng, len(n), noise_model, outl)
        nz.update(meta)
        if cat_ == "single":
            k = rng.uniform(4, 12)
            noise_rms = crms(sum(eff.values())) / k
        elif cat_ == "clean" or form == "fraction":
            noise_rms = rng.uniform(0.2, 1.2)
        Tl_meas = Tl.copy()
        truth = eta.copy()
        k = rng.uniform(4, 12)
        ref = None
        if form == "output-torque-gain":
            gg = 1 + rng.choice([-1, 1]) * rng.uniform(0.02, 0.06)
            nz["torque_gain"] = float(gg)
            Tl_meas = gg * Tl
            truth = eta * gg
            noise_rms = rms(truth - eta) / k
            ref = eta
        elif form == "efficiency-level":
            # the level differs from the reference level 78 % (CSF-20-80 example) within spread
            noise_rms = rng.uniform(0.2, 1.2)
            lvl = ETA_REF + rng.choice([-1, 1]) * k * noise_rms
            if not 55 <= lvl <= 90:
                continue
            truth = np.full_like(eta, lvl)
            nz["efficiency_level_pct"] = float(lvl)
            ref = np.full_like(eta, ETA_REF)
        elif form == "cradled-motor-trunnion":
            Tin_r = Tr / (R * etaR)
            Tin = Tl / (R * eta / 100)
            tf = rng.uniform(0.005, 0.04) * Tin_r
            nz["trunnion_friction_Nm"] = float(tf)
            truth = eta / (1 + tf / Tin)
            noise_rms = crms(truth - eta) / k
            ref = eta
        elif form == "grosch-wlf-spider":
            Tg = rng.uniform(-60, -40)
            Ts = Tg + 50.0
            aT = -8.86 * (TC - Ts) / (101.6 + TC - Ts)  # log10 a_T, WLF universal constants
            v = 0.02 * n / 1000.0  # sliding velocity in the jaws (m/s) from misalignment
            lv = np.log10(v) + aT
            vpk = rng.uniform(-4.0, -1.0)
            sig = rng.uniform(1.0, 2.0)
            epsmax = rng.uniform(0.04, 0.12)
            eps = epsmax * np.exp(-((lv - vpk) ** 2) / (2 * sig ** 2))
            nz.update(spider_Tg_C=float(Tg), spider_log10_vpeak=float(vpk), spider_loss_max=float(epsmax))
            truth = eta * (1 - eps)
            if crms(truth - eta) < 1e-9:
                continue
            noise_rms = crms(truth - eta) / k
            ref = eta
        noise = w * (noise_rms / rms(w))
        noise_rms = rms(noise)
        effm = truth + noise
        if form == "fraction":
            effm = effm / 100.0
            noise = noise / 100.0
            noise_rms = rms(noise)
        snrs = {}
        if cat_ in ("single", "pair"):
            for g in gear:
                snrs[f"snr_{g}"] = crms(eff[g]) / noise_rms
            tot = crms(sum(eff.values())) / noise_rms
            if cat_ == "pair" and not all(4 - 1e-6 <= v <= 12 + 1e-6 for v in snrs.values()):
                continue
            if tot > 12.0 + 1e-9 or tot < 4 - 1e-9:
                continue
        elif cat_ == "clean" or form == "fraction":
            tot = 0.0
        else:
            dd = truth - ref
            tot = (rms(dd) if form == "efficiency-level" else (rms(dd) if form == "output-torque-gain" else crms(dd))) / noise_rms
            snrs["snr_" + (meas[0] if meas else "efficiency_level")] = tot
        nz.update({a: float(b) for a, b in snrs.items()})
        cols = {"input_speed_rpm": n, "load_torque_Nm": Tl_meas, "temperature_C": TC,
                "efficiency_pct": effm}
        return dict(model=code, columns=cols, gear=gear, meas=meas, nuisance=nz, noise=noise,
                    noise_rms=noise_rms, snr=float(tot), load_inertia=None,
                    equiv=EQUIV.get(meas[0], ()) if cat_ == "decoy_equivalent" else ())
    raise RuntimeError(f"efficiency cell {cell} infeasible")


# ----------------------------------------------------------------------------------------
# vibration
# ----------------------------------------------------------------------------------------
VIB_CELLS = []
for _f_ in ("white", "ar1", "ggd-outliers"):
    VIB_CELLS.append(("clean", (), (), _f_))
for _g_ in ("te_1x", "te_2x"):
    for _f_ in ("hok-quasistationary-tanh", "houbolt-quintic"):
        VIB_CELLS.append(("single", (_g_,), (), _f_))
for _f_ in ("hok-quasistationary-tanh", "houbolt-quintic"):
    VIB_CELLS.append(("pair", ("te_1x", "te_2x"), (), _f_))
VIB_CELLS += [
    ("decoy_separable", (), ("thermal_drift",), "speed-squared-heating"),
    ("decoy_separable", (), ("angle_offset",), "unremoved-mean"),
    ("decoy_separable", (), ("encoder_eccentricity",), "output-encoder-once-per-rev"),
    ("decoy_equivalent", (), ("input_gravity_unbalance",), "servo-compliance-unbalance"),
    ("decoy_equivalent", (), ("brake_detent_torque",), "pm-brake-detent"),
]


def runup(rng, kind, n0, n1, Trun, t):
    if kind == "tanh":  # constant drive torque against quadratic (fan-like) drag
        tau = rng.uniform(0.4, 1.0) * Trun
        return n0 + (n1 - n0) * np.tanh(t / tau) / np.tanh(Trun / tau), tau
    s = t / Trun  # 3-4-5 polynomial motion law
    return n0 + (n1 - n0) * (10 * s ** 3 - 15 * s ** 4 + 6 * s ** 5), 0.0


def resp_hok(phi, omega_in, kk, a, psi, K, J, c):
    """Quasi-stationary steady-state response (Hok 1948): TE as base motion through the gear's
    Kelvin element, transmissibility evaluated at the instantaneous excitation frequency."""
    w = kk * omega_in
    H = (K + 1j * c * w) / (K - J * w ** 2 + 1j * c * w)
    return a * np.abs(H) * np.sin(kk * phi + psi + np.angle(H))


def resp_houbolt(phi, dt, kk, a, psi, K, J, c, sub=4):
    """Houbolt (1950) implicit multistep integration of J x'' + c x' + K x = K e(t),
    e = a sin(k phi + psi); run as an IIR filter at dt/sub, then decimated."""
    n = len(phi)
    tf = np.arange((n - 1) * sub + 1) / sub
    ph = np.interp(tf, np.arange(n), phi)
    f = K * a * np.sin(kk * ph + psi)
    h = dt / sub
    a0 = 2 * J / h ** 2 + 11 * c / (6 * h) + K
    a1 = 5 * J / h ** 2 + 3 * c / h
    a2 = -4 * J / h ** 2 - 1.5 * c / h
    a3 = J / h ** 2 + c / (3 * h)
    x = signal.lfilter([1.0], [a0, -a1, -a2, -a3], f)
    return x[::sub]


def vibration_case(rng, cat, cell):
    cat_, gear, meas, form = cell
    code = str(rng.choice(cat.vibration))
    m = cat.models[code]
    R = m["ratio"]
    acc = m["accuracy"]
    nz: dict[str, float] = {}
    s = kumaraswamy_scale(rng)
    K = m["K1"] * s
    fn_target = rng.uniform(8.0, 22.0)
    J = float(f"{m['K1'] / (2 * np.pi * fn_target) ** 2:.3g}")
    fn = np.sqrt(K / J) / (2 * np.pi)
    zeta = rng.uniform(0.03, 0.12)
    c = 2 * zeta * np.sqrt(K * J)
    nz.update(stiffness_scale=float(s), damping_ratio=float(zeta), natural_freq_Hz=float(fn))
    n0 = 0.3 * fn * 60
    n1 = min(1.5 * fn * 60, m["n_max"])
    Trun = rng.uniform(20.0, 45.0)
    fs = float(rng.choice([400.0, 500.0, 800.0]))
    if fs < 25 * fn:
        fs = 1000.0
    t = np.arange(0, Trun, 1 / fs)
    prof = "tanh" if (form.endswith("tanh") or (rng.random() < 0.5 and "houbolt" not in form)) else "quintic"
    nrpm, tau = runup(rng, prof, n0, n1, Trun, t)
    nz.update(runup_id=0.0 if prof == "tanh" else 1.0, run_s=float(Trun), fs_Hz=float(fs))
    om = 2 * np.pi * nrpm / 60
    phi = np.concatenate([[0.0], np.cumsum(0.5 * (om[1:] + om[:-1]) / fs)]) + rng.uniform(0, 2 * np.pi)
    solver = "houbolt" if "houbolt" in form or cat_ == "decoy_equivalent" else "hok"

    def resp(kk, a, psi):
        if solver == "hok":
            return resp_hok(phi, om, kk, a, psi, K, J, c)
        return resp_houbolt(phi, 1 / fs, kk, a, psi, K, J, c)
    eff = {}
    if cat_ in ("single", "pair"):
        unit = {}
        for g in gear:
            kk = 1 if g == "te_1x" else 2
            psi = rng.uniform(0, 2 * np.pi)
            unit[g] = resp(kk, 1.0, psi)
        if cat_ == "single":
            (g,) = gear
            a = 0.5 * acc * rng.uniform(0.2, 0.9)
            eff[g] = a * unit[g]
            nz[f"{g}_amp_rad"] = float(a)
            k = rng.uniform(4, 12)
            noise_rms = rms(eff[g]) / k
        else:
            while True:
                k1, k2 = _pair_ks(rng)
                a1 = 1.0
                a2 = (k2 / k1) * rms(unit["te_1x"]) / rms(unit["te_2x"])
                sc = 0.5 * acc * rng.uniform(0.3, 0.9) / (a1 + a2)
                a1, a2 = a1 * sc, a2 * sc
                eff = {"te_1x": a1 * unit["te_1x"], "te_2x": a2 * unit["te_2x"]}
                noise_rms = rms(eff["te_1x"]) / k1
                if rms(eff["te_1x"] + eff["te_2x"]) / noise_rms <= 12:
                    break
            nz.update(te_1x_amp_rad=float(a1), te_2x_amp_rad=float(a2))
    else:
        noise_rms = rng.uniform(0.5e-6, 5e-6)
    noise_model, outl = pick_noise(rng, form if cat_ == "clean" else None)
    w, meta = unit_noise(rng, len(t), noise_model, outl)
    nz.update(meta)
    truth = sum(eff.values()) if eff else np.zeros_like(t)
    k = rng.uniform(4, 12)
    me = None
    if form == "speed-squared-heating":
        tau_th = rng.uniform(20.0, 150.0)
        P = (nrpm / 1000.0) ** 2
        aa = np.exp(-1 / (fs * tau_th))
        me = signal.lfilter([1 - aa], [1, -aa], P)
        nz["drift_tau_s"] = float(tau_th)
        me = me * k * noise_rms / rms(me)
    elif form == "unremoved-mean":
        me = np.full_like(t, rng.choice([-1, 1]) * k * noise_rms)
        nz["angle_offset_rad"] = float(me[0])
    elif form == "output-encoder-once-per-rev":
        psi = rng.uniform(0, 2 * np.pi)
        me = np.sin(phi / R + psi)
        me = me * k * noise_rms / rms(me)
    elif form in ("servo-compliance-unbalance", "pm-brake-detent"):
        kk = 1 if form.startswith("servo") else 2
        Kserv = rng.uniform(50.0, 400.0)
        if kk == 1:
            tq = rng.uniform(0.3, 1.5) * 9.81 * rng.uniform(0.01, 0.035)
        else:
            tq = rng.uniform(0.1, 0.6)
        a_eq = tq / Kserv / R
        nz.update(input_ripple_torque_Nm=float(tq), servo_stiffness_Nm_per_rad=float(Kserv),
                  equivalent_amp_rad=float(a_eq))
        me = resp(kk, a_eq, rng.uniform(0, 2 * np.pi))
        noise_rms = rms(me) / k
    if me is not None:
        truth = truth + me
    noise = w * (noise_rms / rms(w))
    noise_rms = rms(noise)
    snrs = {}
    if cat_ in ("single", "pair"):
        for g in gear:
            snrs[f"snr_{g}"] = rms(eff[g]) / noise_rms
        tot = rms(sum(eff.values())) / noise_rms
    elif cat_ == "clean":
        tot = 0.0
    else:
        tot = rms(me) / noise_rms
        snrs[f"snr_{meas[0]}"] = tot
    nz.update({a_: float(b) for a_, b in snrs.items()})
    cols = {"time_s": t, "input_speed_rpm": nrpm, "output_vibration_rad": truth + noise}
    return dict(model=code, columns=cols, gear=gear, meas=meas, nuisance=nz, noise=noise,
                noise_rms=noise_rms, snr=float(tot), load_inertia=J,
                equiv=EQUIV.get(meas[0], ()) if cat_ == "decoy_equivalent" else ())


# ----------------------------------------------------------------------------------------
KINDS = (("torsion", TORSION_CELLS, torsion_case),
         ("transmission", TRANS_CELLS, transmission_case),
         ("efficiency", EFF_CELLS, efficiency_case),
         ("vibration", VIB_CELLS, vibration_case))


def all_cells():
    return [(kind, c) for kind, cells, _ in KINDS for c in cells]


def _slug(s):
    return s.replace(" ", "").replace("_", "_")


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    rng = np.random.default_rng(seed)
    cat = Catalog(catalog_dir)
    ADDED_NOISE.clear()
    out: list[TruthCase] = []
    for kind, cells, fn in KINDS:
        for cell in cells:
            cat_, gear, meas, form = cell
            eff_name = "+".join(gear) if gear else ("+".join(meas) if meas else
                                                    ("none" if cat_ == "clean" else "nuisance"))
            for i in range(per_cell):
                d = fn(rng, cat, cell)
                name = f"{SUITE}-{kind}-{cat_}-{eff_name}-{_slug(form)}-{i:03d}"
                cols = {h: np.asarray(d["columns"][h], float) for h in HEADERS[kind]}
                tc = TruthCase(name=name, kind=kind, model=d["model"], columns=cols,
                               load_inertia_kgm2=d["load_inertia"], gear_effects=tuple(d["gear"]),
                               measurement_effects=tuple(d["meas"]), nuisance=d["nuisance"],
                               category=cat_, equivalent_effects=tuple(d["equiv"]),
                               noise_rms=float(d["noise_rms"]), formulation=form, snr=float(d["snr"]))
                ADDED_NOISE[name] = np.asarray(d["noise"], float)
                out.append(tc)
    return out
