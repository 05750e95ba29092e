"""Truth suite "m" for `hdcad reconcile` (strain-wave-gear test-data reconciliation).

Written from CONTRACT.md, the catalog tables and the seeds only (see NOTES_m.md for the
formulations and their literature sources).  numpy + scipy only.

generate_cases(seed, catalog_dir, per_cell=4) -> list[TruthCase]
"""
from __future__ import annotations

import csv
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import signal as _sig
from scipy.special import jv as _besselj

SUITE = "m"
K_RANGE = (4.0, 12.0)
DEG = 180.0 / np.pi


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
        cols = [np.asarray(self.columns[n], dtype=float) for n in names]
        with open(path, "w", newline="") as fh:
            fh.write(",".join(names) + "\n")
            for row in zip(*cols):
                fh.write(",".join(repr(float(v)) for v in row) + "\n")


HEADERS = {
    "torsion": ("torque_Nm", "twist_rad"),
    "transmission": ("input_angle_rad", "output_angle_rad"),
    "efficiency": ("input_speed_rpm", "load_torque_Nm", "temperature_C", "efficiency_pct"),
    "vibration": ("time_s", "input_speed_rpm", "output_vibration_rad"),
}
MEASURED = {"torsion": "twist_rad", "transmission": "output_angle_rad",
            "efficiency": "efficiency_pct", "vibration": "output_vibration_rad"}


# ----------------------------------------------------------------------------------------------
# catalog
def _num(s):
    s = (s or "").strip()
    return float(s) if s else None


def _read(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def load_catalog(catalog_dir):
    d = Path(catalog_dir)
    stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
    hyst = _read(d / "gh_hysteresis_052_060.csv")
    back = _read(d / "gh_backlash_052-2_060-2.csv")
    rat = _read(d / "gh_ratings_050-1_058-1.csv")
    perf = _read(d / "gh_performance_051-1_059-1.csv")
    ke = _read(d / "ke_curve_023-1.csv")
    lub = _read(d / "lubricant_temperature_016-2_019.csv")
    keys = _read(d / "parallel_key_jisb1301.csv")
    fit = _read(d / "iso286_h7_g6.csv")

    def group(rows, series, size, ratio):
        for r in rows:
            if r["series"] != series or (size is not None and int(r["size"]) != size):
                continue
            lo, hi = _num(r["ratio_min"]), _num(r["ratio_max"])
            if ratio >= lo and (hi is None or ratio <= hi):
                return r
        return None

    models = []
    for b in back:
        series, size, ratio = b["series"], int(b["size"]), int(b["ratio"])
        st = group(stiff, series, size, ratio)
        hy = group(hyst, series, None, ratio)
        ra = next((r for r in rat if r["series"] == series and int(r["size"]) == size
                   and int(r["ratio"]) == ratio), None)
        if st is None or hy is None or ra is None:
            continue
        acc = None
        for p in perf:
            if p["series"] == series and int(p["size"]) == size and int(p["ratio"]) == ratio \
                    and _num(p["accuracy_rad"]):
                acc = _num(p["accuracy_rad"])
                break
        m = dict(code=f"{series.split('-')[0]}-{size}-{ratio}-GH", series=series, size=size,
                 ratio=ratio, T1=_num(st["T1_Nm"]), T2=_num(st["T2_Nm"]),
                 K1=_num(st["K1_Nm_per_rad"]), K2=_num(st["K2_Nm_per_rad"]),
                 K3=_num(st["K3_Nm_per_rad"]), hyst=_num(hy["hysteresis_rad"]),
                 backlash=_num(b["backlash_rad"]), Tr=_num(ra["rated_torque_2000_Nm"]),
                 nmax=_num(ra["max_input_speed_rpm"]), navg=_num(ra["avg_input_speed_max_rpm"]),
                 accuracy=acc)
        models.append(m)
    kec = sorted((_num(r["alpha"]), _num(r["Ke"])) for r in ke)
    sk = next(r for r in lub if r["lubricant"] == "SK-1A")
    return dict(models=models, ke=kec, lub_sk1a=(_num(sk["use_min_C"]), _num(sk["use_max_C"])),
                keys=keys, fit=fit)


def twist_catalog(T, m, scale=1.0):
    """Three-segment catalog curve (odd in T), continuous: theta1 = T1/K1, theta2 = theta1+(T2-T1)/K2."""
    K1, K2, K3 = m["K1"] * scale, m["K2"] * scale, m["K3"] * scale
    a = np.abs(T)
    th1 = m["T1"] / K1
    th2 = th1 + (m["T2"] - m["T1"]) / K2
    th = np.where(a <= m["T1"], a / K1, np.where(a <= m["T2"], th1 + (a - m["T1"]) / K2,
                                                   th2 + (a - m["T2"]) / K3))
    return np.sign(T) * th


# ----------------------------------------------------------------------------------------------
# noise
def _rms(x):
    x = np.asarray(x, float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def make_noise(rng, n, sigma, kind):
    """Noise with sample RMS exactly sigma. kinds: white, ar1, arma11, butter (band-limited)."""
    e = rng.standard_normal(n + 200)
    info = {}
    if kind == "white":
        x = e
    elif kind == "ar1":
        phi = rng.uniform(0.3, 0.8)
        x = _sig.lfilter([1.0], [1.0, -phi], e)
        info["ar1_phi"] = phi
    elif kind == "arma11":            # ARMA(1,1): Box & Jenkins (1970)
        phi, th = rng.uniform(0.3, 0.8), rng.uniform(0.2, 0.6)
        x = _sig.lfilter([1.0, th], [1.0, -phi], e)
        info.update(arma_phi=phi, arma_theta=th)
    elif kind == "butter":            # anti-alias-filtered sensor noise, 2nd-order Butterworth
        wc = rng.uniform(0.25, 0.5)
        b, a = _sig.butter(2, wc)
        x = _sig.lfilter(b, a, e)
        info["butter_wc"] = wc
    else:
        raise ValueError(kind)
    x = x[200:]
    x = x - x.mean()
    x *= sigma / _rms(x)
    return x, info


def make_outliers(rng, n, sigma):
    m = max(1, int(round(0.005 * n)))
    idx = rng.choice(n, size=m, replace=False)
    o = np.zeros(n)
    o[idx] = rng.choice([-1.0, 1.0], size=m) * rng.uniform(8, 15, size=m) * sigma
    return o


def raised_cosine(rng, half):
    """Stiffness-scale deviation from a raised-cosine (von Hann) density on [-half, half]."""
    while True:
        x = rng.uniform(-half, half)
        if rng.uniform() <= 0.5 * (1 + np.cos(np.pi * x / half)):
            return x


def size_pair(rng, contribs, combine):
    """size_effects, then shrink the larger effect until the combined RMS/sigma is <= 12 too
    (each effect keeps k >= 4). combine(scaled dict) -> combined hidden contribution."""
    sigma, scales, ks = size_effects(rng, contribs)
    names = list(contribs)
    for _ in range(200):
        hid = combine({n: contribs[n] * scales[n] for n in names})
        kc = _rms(hid) / sigma
        if kc <= K_RANGE[1] or len(names) == 1:
            break
        big = max(names, key=lambda n: ks[n])
        if ks[big] <= K_RANGE[0] * 1.0001:
            break
        new = max(K_RANGE[0], ks[big] * 0.97)
        scales[big] *= new / ks[big]
        ks[big] = new
    return sigma, scales, ks


def size_effects(rng, contribs):
    """contribs: dict name -> unscaled contribution (linear in its amplitude).
    Returns (noise_sigma, scales, ks). Each effect gets RMS = k*sigma, k ~ U(4,12)."""
    names = list(contribs)
    ks = {n: rng.uniform(*K_RANGE) for n in names}
    rs = {n: _rms(contribs[n]) for n in names}
    if len(names) == 1:
        n = names[0]
        sigma = rs[n] / ks[n]
        return sigma, {n: 1.0}, ks
    # balance: sigma from the geometric mean of the drawn targets; each k then stays as close to
    # the effect's natural (physically sized) value as [4, 12] allows, jittered by U(0.8, 1.25)
    sigma = float(np.exp(np.mean([np.log(rs[n] / ks[n]) for n in names])))
    for n in names:
        ks[n] = float(np.clip(rs[n] / sigma * rng.uniform(0.8, 1.25), *K_RANGE))
    scales = {n: ks[n] * sigma / rs[n] for n in names}
    return sigma, scales, ks


# ----------------------------------------------------------------------------------------------
# torsion
def protocol_forc(rng, T0):
    """Major loops then first-order reversal curves (Mayergoyz-style FORC), torque-controlled."""
    r1, r2 = rng.uniform(0.2, 0.5), rng.uniform(-0.6, -0.1)
    tp = [0.0, T0, -T0, T0, r1 * T0, T0, r2 * T0, T0, -T0, T0]
    dT = T0 / rng.integers(50, 80)
    T, t = [tp[0]], [0.0]
    for a, b in zip(tp[:-1], tp[1:]):
        m = max(3, int(np.ceil(abs(b - a) / dT)))
        seg = np.linspace(a, b, m + 1)[1:]
        T.extend(seg)
        t.extend(t[-1] + np.abs(np.diff(np.concatenate([[a], seg]))).cumsum() / T0)
    return np.array(T), np.array(t), tp


def protocol_cheb(rng, T0):
    """Three triangle cycles at constant torque rate, samples Chebyshev-Lobatto clustered
    near the reversals (dense where the loop turns). A full leg (-T0 -> T0) takes 1 time unit."""
    m = int(rng.integers(70, 110))
    legs = [(0.0, T0), (T0, -T0), (-T0, T0), (T0, -T0), (-T0, T0), (T0, -T0), (-T0, 0.0)]
    T, t = [0.0], [0.0]
    for a, b in legs:
        mm = m if abs(b - a) > 1.5 * T0 else m // 2
        j = np.arange(1, mm + 1)
        if abs(b - a) > 1.5 * T0:
            u = 0.5 * (1 - np.cos(np.pi * j / mm))
        elif a == 0.0:
            u = np.sin(0.5 * np.pi * j / mm)
        else:
            u = 1 - np.cos(0.5 * np.pi * j / mm)
        seg = a + (b - a) * u
        T.extend(seg)
    T = np.array(T)
    # time at constant torque rate: one full leg (-T0 -> T0) takes 1 time unit
    tt, cur = [0.0], 0.0
    for i in range(1, len(T)):
        cur += abs(T[i] - T[i - 1]) / (2 * T0)
        tt.append(cur)
    return T, np.array(tt), legs


def _masing(T, branch, backbone):
    """Masing branches with Madelung memory (reversal stack). branch(D)>=0 for D=|T-Tr|."""
    out = np.zeros_like(T)
    stack = []               # reversal points (T_r, x_r)
    d = 0
    Tr, xr = 0.0, 0.0
    virgin = True
    for i in range(1, len(T)):
        dT = T[i] - T[i - 1]
        if dT == 0:
            out[i] = out[i - 1]
            continue
        nd = 1 if dT > 0 else -1
        if d != 0 and nd != d:       # reversal
            stack.append((Tr, xr, virgin))
            Tr, xr, virgin = T[i - 1], out[i - 1], False
        d = nd
        # Madelung: close inner loops when the path passes an earlier reversal
        while len(stack) >= 2 and not virgin:
            T_prev = stack[-1][0]
            if (d > 0 and T[i] >= T_prev) or (d < 0 and T[i] <= T_prev):
                stack.pop()
                Tr, xr, virgin = stack.pop()
            else:
                break
        if virgin:
            out[i] = backbone(T[i])
        else:
            out[i] = xr + d * branch(abs(T[i] - Tr))
    return out


def hyst_davidenkov(T, T0, n, width0, Tref):
    """Davidenkov (1938) power-law Masing branches; loop width at T=0 for a +-Tref cycle = width0.
    Centre line of the +-T0 major loop removed (catalog curve = loop centre)."""
    eps = width0 / (2 * Tref ** n * (2 ** (n - 1) - 1))
    x = _masing(T, lambda D: eps * D ** n, lambda t: np.sign(t) * eps * 2 ** (n - 1) * abs(t) ** n)
    centre = 0.5 * eps * ((T0 + T) ** n - (T0 - T) ** n)
    return x - centre


def hyst_hilbert(T, t, T0, width_target):
    """Reid's linear hysteretic damping in the time domain (Hilbert transform, Inaudi & Kelly 1995):
    extra twist = c * H[T](t), periodic steady state; c set so the loop width at T=0 = target.
    Protocol time: a cycle T0 -> -T0 -> T0 takes 2 time units (protocol_cheb)."""
    period = 2.0
    nu = int(round(t[-1] / period * 2048))
    tu = np.linspace(0, t[-1], nu, endpoint=False)
    tri = np.interp((tu / period) % 1.0, [0, 0.25, 0.75, 1.0], [0, 1, -1, 0])
    h = np.imag(_sig.hilbert(tri * T0))
    H = np.interp(t, tu, h, period=t[-1])
    desc = np.interp(np.arange(1.0, t[-1], period), tu, h)
    asc = np.interp(np.arange(period, t[-1], period), tu, h)
    w = float(np.mean(desc) - np.mean(asc))
    return H * width_target / w


def backlash_lostmotion(T, b, Tg):
    """Lost motion with a centring spring: twist b/2*clip(T/Tg) (cf. FD table 314-1 'lost motion'
    then 'spring constant')."""
    return 0.5 * b * np.clip(T / Tg, -1, 1)


def backlash_cauchy(T, b, Tc):
    """Oldham-clearance take-up with a Cauchy (Lorentzian) spread of engagement torques."""
    return 0.5 * b * (2 / np.pi) * np.arctan(T / Tc)


def play_operator(x, w):
    """Play (backlash) operator of half-width w (may vary per sample)."""
    y = np.empty_like(x)
    y[0] = x[0]
    w = np.broadcast_to(w, x.shape)
    for i in range(1, len(x)):
        y[i] = min(max(y[i - 1], x[i] - w[i]), x[i] + w[i])
    return y


def housing_spoked(rng, m):
    """Castigliano: output hub with n radial spokes (cantilevers) carrying the torque."""
    E = 206e9
    n = int(rng.integers(4, 7))
    Rm = m["size"] * 1.2e-3            # ~ pitch radius of the output hub (mm per size unit)
    L = Rm * rng.uniform(0.25, 0.45)
    bsec = Rm * rng.uniform(0.25, 0.4)
    hsec = Rm * rng.uniform(0.25, 0.4)
    I = bsec * hsec ** 3 / 12
    c = L ** 3 / (3 * E * I * n * Rm ** 2)
    return c, dict(spokes=n, spoke_len_m=L, spoke_I_m4=I, hub_radius_m=Rm)


def housing_keyed(rng, m, keys):
    """Keyed output shaft hub: key flank stiffness c' = phi*E*L (DIN 6892 style), torsional
    stiffness k_t = c'*(d/2)^2; key section from JIS B 1301 (catalog)."""
    d = m["size"] * rng.uniform(0.9, 1.3)         # output shaft diameter ~ size (mm)
    row = next((r for r in keys if float(r["shaft_min_mm"]) < d <= float(r["shaft_max_mm"])),
               keys[-1])
    L = 1.5 * d * 1e-3
    phi = rng.uniform(0.1, 0.3)
    kt = phi * 206e9 * L * (0.5 * d * 1e-3) ** 2 * float(row["h_mm"]) / 10.0
    return 1.0 / kt, dict(shaft_d_mm=d, key_b_mm=float(row["b_mm"]), key_h_mm=float(row["h_mm"]),
                          key_len_m=L, flank_phi=phi)


def gen_torsion(rng, cat, cell):
    cat_models = cat["models"]
    eff = cell["effects"]
    # models: backlash cases prefer small sizes / high ratio (backlash comparable to noise)
    pool = cat_models
    if "backlash" in eff or cell.get("rig") == "dowel_fit_clearance":
        pool = [m for m in cat_models if m["backlash"] >= 5e-5]   # backlash >= ~10 arc-sec
    m = pool[rng.integers(len(pool))]
    nu = {}
    s = 1.0 + raised_cosine(rng, 0.09)
    T0 = m["Tr"] * rng.uniform(0.9, 1.15)
    form = cell["formulation"]
    prot = cell.get("protocol") or ("forc" if rng.uniform() < 0.5 else "cheb")
    if prot == "forc":
        T, t, _ = protocol_forc(rng, T0)
    else:
        T, t, _ = protocol_cheb(rng, T0)
    nu.update(stiffness_scale=s, T0_Nm=T0, protocol_forc=float(prot == "forc"))
    base_true = twist_catalog(T, m, s)
    contribs = {}
    for e in eff:
        f = cell["forms"][e]
        if e == "hysteresis":
            w = m["hyst"] * rng.uniform(0.7, 1.3)
            nu["hysteresis_width_rad"] = w
            if f == "davidenkov":
                n = rng.uniform(1.6, 2.6)
                nu["davidenkov_n"] = n
                contribs[e] = hyst_davidenkov(T, T0, n, w, m["Tr"])
            else:
                contribs[e] = hyst_hilbert(T, t, T0, w * T0 / m["Tr"])
        elif e == "backlash":
            b = m["backlash"] * rng.uniform(0.6, 1.0)
            nu["backlash_rad"] = b
            if f == "lostmotion":
                Tg = m["Tr"] * rng.uniform(0.02, 0.06)
                nu["lostmotion_torque_Nm"] = Tg
                contribs[e] = backlash_lostmotion(T, b, Tg)
            else:
                Tc = m["Tr"] * rng.uniform(0.004, 0.015)
                nu["cauchy_torque_Nm"] = Tc
                contribs[e] = backlash_cauchy(T, b, Tc)
        elif e == "housing_compliance":
            if f == "spoked":
                c, g = housing_spoked(rng, m)
            else:
                c, g = housing_keyed(rng, m, cat["keys"])
            frac = c * m["K1"]
            lo, hi = (0.03, 0.12) if "backlash" in eff else (0.05, 0.4)
            if not lo <= frac <= hi:          # keep within a physical share of the gear's compliance
                c = rng.uniform(lo, hi) / m["K1"]
            nu.update({f"housing_{k}": v for k, v in g.items()})
            nu["housing_compliance_rad_per_Nm"] = c
            contribs[e] = c * T
    rig = cell.get("rig")
    meas = ()
    col_T = T.copy()
    rig_contrib = None
    if rig == "sensor_gain":
        g = 1 + rng.choice([-1, 1]) * rng.uniform(0.03, 0.08)
        nu["torque_gain"] = g
        col_T = g * T                                  # recorded torque
        rig_contrib = base_true - twist_catalog(col_T, m, s)
        meas = ("sensor_gain",)
    elif rig == "angle_offset":
        off = rng.choice([-1, 1]) * rng.uniform(0.5, 1.5) * m["hyst"]
        i0 = int(len(T) * rng.uniform(0.3, 0.7))
        rig_contrib = np.where(np.arange(len(T)) >= i0, off, 0.0)
        nu.update(offset_step_rad=off, offset_step_index=float(i0))
        meas = ("angle_offset",)
    elif rig == "thermal_drift":
        D = rng.choice([-1, 1]) * rng.uniform(0.3, 1.0) * m["hyst"]
        tau = t[-1] * rng.uniform(0.08, 0.2)
        tc = t[-1] * rng.uniform(0.3, 0.6)
        lg = 1 / (1 + np.exp(-(t - tc) / tau))
        rig_contrib = D * (lg - lg[0])
        nu.update(drift_rad=D, drift_tau=tau)
        meas = ("thermal_drift",)
    elif rig in ("wrong_units_deg", "wrong_units_kNm"):
        meas = ("wrong_units",)
    elif rig == "stiffness_scale":
        s2 = 1 + rng.choice([-1, 1]) * rng.uniform(0.05, 0.095)
        rig_contrib = twist_catalog(T, m, s2) - twist_catalog(T, m, 1.0)
        base_true = twist_catalog(T, m, 1.0)
        nu["stiffness_scale"] = s2
    elif rig == "soft_gear":
        s2 = rng.uniform(0.68, 0.84)
        rig_contrib = twist_catalog(T, m, s2) - twist_catalog(T, m, 1.0)
        base_true = twist_catalog(T, m, 1.0)
        nu["stiffness_scale"] = s2
    elif rig == "fixture_base_rotation":
        c = rng.uniform(0.05, 0.3) / m["K1"]
        rig_contrib = c * T
        nu["base_rotation_rad_per_Nm"] = c
        meas = ("fixture_base_rotation",)
    elif rig == "lever_pivot_friction":
        beta = rng.uniform(0.01, 0.03)     # mu * r_pivot / L_lever
        f0 = m["Tr"] * rng.uniform(0.005, 0.02)   # lever dead-weight share
        Tg = play_operator(T, beta * np.abs(T) + f0)
        rig_contrib = twist_catalog(Tg, m, s) - base_true
        nu.update(pivot_beta=beta, pivot_f0_Nm=f0)
        meas = ("lever_pivot_friction",)
    elif rig == "dowel_fit_clearance":
        fit = cat["fit"]
        dp = rng.choice([6.0, 8.0, 10.0])
        row = next(r for r in fit if float(r["over_mm"]) < dp <= float(r["upto_mm"]))
        clr = (float(row["IT7_um"]) / 2 + float(row["g_es_below_zero_um"]) + float(row["IT6_um"]) / 2) * 1e-6
        pc = m["size"] * 4e-3 * rng.uniform(0.8, 1.2)     # dowel pitch circle (m)
        ang = 2 * clr / pc
        Ts = m["Tr"] * rng.uniform(0.005, 0.02)
        rig_contrib = 0.5 * ang * np.tanh(T / Ts)
        nu.update(dowel_d_mm=dp, dowel_clearance_m=clr, dowel_circle_m=pc, dowel_angle_rad=ang)
        meas = ("dowel_fit_clearance",)
    # sizing
    if eff:
        sigma, scales, ks = size_pair(rng, contribs, lambda d: sum(d.values()))
        for e in eff:
            contribs[e] = contribs[e] * scales[e]
            nu[f"snr_{e}"] = ks[e]
            nu[f"scale_{e}"] = scales[e]
        hidden = sum(contribs.values())
    elif rig_contrib is not None:
        k = rng.uniform(*K_RANGE)
        sigma = _rms(rig_contrib) / k
        hidden = rig_contrib
        nu[f"snr_{meas[0] if meas else rig}"] = k
    else:
        hidden = np.zeros_like(T)
        sigma = m["hyst"] * rng.uniform(0.03, 0.1)
    clean = base_true + hidden
    return m, T, col_T, clean, hidden, sigma, nu, meas, rig


# ----------------------------------------------------------------------------------------------
# transmission error waveforms (only odd multiples of the base order -> te_1x has no 2x content)
def te_components(form, amp, rng, nu, tag):
    """Return list of (order_multiple k, sine amplitude, phase) of the waveform w(x) so that
    te = sum a_k sin(k*x + ph_k); x = n*phi + psi. Amplitude = peak of the fundamental-normalised wave."""
    if form == "triangle":         # linear index taper within each lobe period
        comps = []
        for k in (1, 3, 5, 7, 9, 11):
            comps.append((k, amp * 8 / np.pi ** 2 * (-1) ** ((k - 1) // 2) / k ** 2, 0.0))
        return comps
    if form == "oddwarp":          # asymmetric tooth entry/exit: sin(x + beta sin 2x)
        beta = rng.uniform(0.3, 0.7)
        nu[f"{tag}_warp_beta"] = beta
        comps = []
        for j in range(-4, 5):
            k = 1 + 2 * j
            a = amp * _besselj(j, beta)
            if k < 0:
                comps.append((-k, -a, 0.0))
            else:
                comps.append((k, a, 0.0))
        # merge
        dd = {}
        for k, a, p in comps:
            dd[k] = dd.get(k, 0.0) + a
        return [(k, a, 0.0) for k, a in sorted(dd.items()) if abs(a) > 1e-6 * amp]
    raise ValueError(form)


def te_eval(comps, x):
    return sum(a * np.sin(k * x + p) for k, a, p in comps)


def gen_transmission(rng, cat, cell):
    pool = [m for m in cat["models"] if m["accuracy"]]
    m = pool[rng.integers(len(pool))]
    R = m["ratio"]
    nu = {}
    eff = cell["effects"]
    rig = cell.get("rig")
    spr = int(rng.integers(64, 129))
    if rig == "encoder_eccentricity":
        nrev = R * rng.uniform(0.6, 1.1)
    else:
        nrev = rng.uniform(8, 24)
    n = int(nrev * spr)
    phi0 = rng.uniform(0, 2 * np.pi)
    phi = phi0 + np.arange(n) * 2 * np.pi / spr
    off = rng.uniform(-np.pi, np.pi)
    base = phi / R + off
    nu.update(output_offset_rad=off, input_revs=nrev, samples_per_rev=float(spr))
    contribs = {}
    for e in eff:
        order = 1 if e == "te_1x" else 2
        f = cell["forms"][e]
        amp = 0.5 * m["accuracy"] * rng.uniform(0.3, 0.8)
        psi = rng.uniform(0, 2 * np.pi)
        comps = te_components(f, amp, rng, nu, e)
        contribs[e] = te_eval(comps, order * phi + psi)
        nu[f"{e}_amp_rad"] = amp
        nu[f"{e}_phase"] = psi
    meas = ()
    rig_contrib = None
    th_out = phi / R
    if rig == "encoder_eccentricity":
        e_r = rng.uniform(0.5, 3.0) * m["accuracy"]     # eccentricity / read radius
        ps = rng.uniform(0, 2 * np.pi)
        rig_contrib = np.arctan2(e_r * np.sin(th_out + ps), 1 + e_r * np.cos(th_out + ps))
        nu["ecc_ratio"] = e_r
        meas = ("encoder_eccentricity",)
    elif rig == "angle_offset":
        i0 = int(n * rng.uniform(0.3, 0.7))
        o = rng.choice([-1, 1]) * rng.uniform(0.5, 2) * m["accuracy"]
        rig_contrib = np.where(np.arange(n) >= i0, o, 0.0)
        nu.update(offset_step_rad=o, offset_step_index=float(i0))
        meas = ("angle_offset",)
    elif rig == "sensor_gain":
        g = 1 + rng.choice([-1, 1]) * rng.uniform(1e-4, 2e-3)
        rig_contrib = (g - 1) * (th_out - th_out[0])
        nu["angle_gain"] = g
        meas = ("sensor_gain",)
    elif rig == "thermal_drift":
        D = rng.choice([-1, 1]) * rng.uniform(0.5, 2) * m["accuracy"]
        tt = np.linspace(0, 1, n)
        tc, tau = rng.uniform(0.3, 0.7), rng.uniform(0.08, 0.25)
        lg = 1 / (1 + np.exp(-(tt - tc) / tau))
        rig_contrib = D * (lg - lg[0])
        nu["drift_rad"] = D
        meas = ("thermal_drift",)
    elif rig == "wrong_units_deg":
        meas = ("wrong_units",)
    elif rig == "stray_field_pickup":        # magnetic output encoder sees the motor's rotating field
        pp = 1
        A = 0.5 * m["accuracy"] * rng.uniform(0.3, 0.8)
        rig_contrib = A * np.sin(pp * phi + rng.uniform(0, 2 * np.pi))
        nu.update(pickup_pole_pairs=float(pp), pickup_amp_rad=A)
        meas = ("stray_field_pickup",)
    elif rig == "readhead_mount_flexing":    # WG's rotating elliptical load bends the read-head mount
        A = 0.5 * m["accuracy"] * rng.uniform(0.3, 0.8)
        ps = rng.uniform(0, 2 * np.pi)
        rig_contrib = A * (np.sin(2 * phi + ps) + rng.uniform(0, 0.1) * np.sin(6 * phi + 3 * ps))
        nu["readhead_amp_rad"] = A
        meas = ("readhead_mount_flexing",)
    if eff:
        sigma, scales, ks = size_pair(rng, contribs, lambda d: sum(d.values()))
        for e in eff:
            contribs[e] = contribs[e] * scales[e]
            nu[f"snr_{e}"] = ks[e]
            nu[f"scale_{e}"] = scales[e]
        hidden = sum(contribs.values())
    elif rig_contrib is not None:
        k = rng.uniform(*K_RANGE)
        sigma = _rms(rig_contrib) / k
        hidden = rig_contrib
        nu[f"snr_{meas[0]}"] = k
    else:
        hidden = np.zeros(n)
        sigma = m["accuracy"] * rng.uniform(0.01, 0.05)
    clean = base + hidden
    return m, phi, clean, hidden, sigma, nu, meas, rig


# ----------------------------------------------------------------------------------------------
# efficiency
def _calib(fun, target, lo, hi):
    from scipy.optimize import brentq
    return brentq(lambda p: fun(p) - target, lo, hi)


def ke_anderson_loewenthal(rng, alpha, n, nu, ke_pt):
    """Part-load efficiency (Anderson & Loewenthal, NASA TP-1622, 1980): sliding loss ~ load,
    rolling (EHL film) loss ~ v^0.67 h W^-0.067 nearly load-independent, windage ~ v^2.8."""
    a58, k58 = ke_pt
    k_target = k58 + rng.uniform(-0.02, 0.02)
    m_sl = rng.uniform(0.05, 0.15)
    share_w = rng.uniform(0.05, 0.2)
    nref = 1500.0

    def L(a, nn, c):
        v = nn / nref
        return c * ((1 - share_w) * v ** 0.67 * a ** -1.067 + share_w * v ** 1.8 / a)

    def eta(a, nn, c):
        return 1.0 / (1 + m_sl + L(a, nn, c))

    c = _calib(lambda c: eta(a58, nref, c) / eta(1.0, nref, c), k_target, 1e-6, 5.0)
    Ke = np.where(alpha >= 1, 1.0, eta(np.minimum(alpha, 1), n, c) / eta(1.0, n, c))
    nu.update(al_sliding=m_sl, al_windage_share=share_w, al_c=c, ke_at_058=k_target)
    return Ke


def ke_misharin(rng, alpha, n, nu, ke_pt):
    """Mesh friction from Misharin's (1958) logarithmic law mu ~ mu_r (1 + beta ln alpha) plus a
    load-independent no-load drag T_nl (catalog 'running torque' idea) growing as n^0.3."""
    a58, k58 = ke_pt
    k_target = k58 + rng.uniform(-0.02, 0.02)
    mu_r = rng.uniform(0.06, 0.14)
    beta = rng.uniform(0.05, 0.2)

    def eta(a, nn, L0):
        mu = mu_r * (1 + beta * np.log(a))
        return 1.0 / (1 + mu + L0 * (nn / 2000.0) ** 0.3 / a)

    L0 = _calib(lambda L0: eta(a58, 2000.0, L0) / eta(1.0, 2000.0, L0), k_target, 1e-6, 5.0)
    Ke = np.where(alpha >= 1, 1.0, eta(np.minimum(alpha, 1), n, L0) / eta(1.0, n, L0))
    nu.update(mish_mu=mu_r, mish_beta=beta, mish_L0=L0, ke_at_058=k_target)
    return Ke


def _nu_litovitz(TC):
    """Litovitz (1952) viscosity law ln nu = A + B/T^3 through ISO VG68 (68 cSt at 40 C, 8.6 cSt at 100 C)."""
    T1, T2 = 313.15, 373.15
    B = (np.log(68.0) - np.log(8.6)) / (T1 ** -3 - T2 ** -3)
    A = np.log(68.0) - B * T1 ** -3
    return np.exp(A + B / (np.asarray(TC) + 273.15) ** 3)


def _nu_poling(TC):
    """Reid-Prausnitz-Poling liquid form ln nu = A + B/T + C T, through 68 cSt @40, 8.6 @100,
    ~700 cSt @0 C (typical VI~95 gear oil)."""
    Ts = np.array([273.15, 313.15, 373.15])
    y = np.log([700.0, 68.0, 8.6])
    M = np.column_stack([np.ones(3), 1 / Ts, Ts])
    A, B, C = np.linalg.solve(M, y)
    T = np.asarray(TC) + 273.15
    return np.exp(A + B / T + C * T)


def kt_petroff(rng, TC, n, nu):
    """Petroff (1883) viscous film drag, loss fraction ~ nu(T) * omega, viscosity by Litovitz."""
    Tref = 20.0
    c = rng.uniform(0.02, 0.06)
    p = rng.uniform(0.4, 0.8)
    v = _nu_litovitz(TC) / _nu_litovitz(Tref)
    Lr = c * (n / 1000.0) ** p
    K = (1 + Lr) / (1 + Lr * v)
    nu.update(petroff_c=c, petroff_speed_exp=p)
    return K


def kt_changenet(rng, TC, n, nu):
    """Changenet & Velex (2007) churning: C_m ~ Re^-0.21 (P ~ nu^0.21 omega^2.79),
    viscosity by the Reid-Prausnitz-Poling form."""
    Tref = 20.0
    c = rng.uniform(0.04, 0.12)
    v = (_nu_poling(TC) / _nu_poling(Tref)) ** 0.21
    Lr = c * (n / 1000.0) ** 1.79
    K = (1 + Lr) / (1 + Lr * v)
    nu["churn_c"] = c
    return K


def gen_efficiency(rng, cat, cell):
    pool = cat["models"]
    m = pool[rng.integers(len(pool))]
    nu = {}
    eff = cell["effects"]
    rig = cell.get("rig")
    speeds = [s for s in (500, 1000, 1500, 2000, 3000) if s <= m["navg"]]
    if rng.uniform() < 0.5:
        speeds = speeds[::2] if len(speeds) > 3 else speeds
    alphas = np.array(sorted(set(np.round(np.geomspace(0.12, 1.2, int(rng.integers(7, 10))), 3))))
    tlo, thi = cat["lub_sk1a"]
    temps = np.linspace(tlo, thi + 20, int(rng.integers(4, 6)))   # lubricant temperature 0..60 C
    # run order: temperature blocks (oven) in shuffled order, random order within each block
    rows = []
    for Tb in rng.permutation(temps):
        blk = [(s, a, Tb) for s in speeds for a in alphas]
        for i in rng.permutation(len(blk)):
            rows.append(blk[i])
    rows = np.array(rows, float)
    ns, al, TC = rows[:, 0], rows[:, 1], rows[:, 2]
    load = al * m["Tr"]
    level = rng.uniform(68, 86)
    nu["efficiency_level_pct"] = level
    ke_pt = next(p for p in cat["ke"] if p[0] < 1.0)
    contribs = {}
    for e in eff:
        f = cell["forms"][e]
        if e == "low_load_efficiency":
            Ke = (ke_anderson_loewenthal if f == "anderson-loewenthal" else ke_misharin)(
                rng, al, ns, nu, ke_pt)
            contribs[e] = level * (Ke - 1)
        else:
            Kt = (kt_petroff if f == "petroff-litovitz" else kt_changenet)(rng, TC, ns, nu)
            contribs[e] = level * (Kt - 1)
    meas = ()
    rig_contrib = None
    if rig == "sensor_gain":
        g = 1 + rng.choice([-1, 1]) * rng.uniform(0.01, 0.04)
        rig_contrib = level * (g - 1) * np.ones(len(rows))
        load = load * g
        nu["torque_gain"] = g
        meas = ("sensor_gain",)
    elif rig == "thermal_drift":
        tt = np.linspace(0, 1, len(rows))
        D = rng.choice([-1, 1]) * rng.uniform(0.5, 2.0)
        tc, tau = rng.uniform(0.2, 0.6), rng.uniform(0.1, 0.3)
        lg = 1 / (1 + np.exp(-(tt - tc) / tau))
        rig_contrib = D * (lg - lg[0]) + 0.3 * D * tt
        nu["drift_pct"] = D
        meas = ("thermal_drift",)
    elif rig == "wrong_units_fraction":
        meas = ("wrong_units",)
    elif rig == "motor_noload_current":
        t0 = rng.uniform(0.004, 0.015)      # unremoved no-load torque share of rated input torque
        r = t0 * (level / 100.0) / al      # input-torque error / true input torque
        rig_contrib = level * (1 / (1 + r) - 1)
        nu["noload_share"] = t0
        meas = ("motor_noload_current",)
    elif rig == "copper_resistance_uncorrected":
        a_cu = 0.00393
        cu = rng.uniform(0.03, 0.08)       # copper loss share of input power at rated load, 20 C
        err = cu * a_cu * (TC - 20.0) * (al ** 0.3)
        rig_contrib = level * (1 / (1 + err) - 1)
        nu["copper_share"] = cu
        meas = ("copper_resistance_uncorrected",)
    if eff:
        def _comb(d):
            mm = np.ones(len(rows))
            for v in d.values():
                mm = mm * (1 + v / level)
            return level * mm - level
        sigma, scales, ks = size_pair(rng, contribs, _comb)
        mult = np.ones(len(rows))
        for e in eff:
            contribs[e] = contribs[e] * scales[e]
            nu[f"snr_{e}"] = ks[e]
            nu[f"scale_{e}"] = scales[e]
            mult = mult * (1 + contribs[e] / level)
        eta = level * mult
        hidden = eta - level
    elif rig_contrib is not None:
        k = rng.uniform(*K_RANGE)
        sigma = _rms(rig_contrib) / k
        hidden = rig_contrib
        eta = level + hidden
        nu[f"snr_{meas[0]}"] = k
    else:
        hidden = np.zeros(len(rows))
        sigma = rng.uniform(0.15, 0.6)
        eta = level + hidden
    return m, ns, load, TC, eta, hidden, sigma, nu, meas, rig


# ----------------------------------------------------------------------------------------------
# vibration
def runup_cycloidal(t, n0, n1):
    tau = t / t[-1]
    return n0 + (n1 - n0) * (tau - np.sin(2 * np.pi * tau) / (2 * np.pi))


def runup_kloss(t, n0, n1, rng, nu):
    """Induction-motor run-up, Kloss torque 2Tk/(s/sk + sk/s), load torque ~ n^2; speed scaled to [n0, n1]."""
    sk = rng.uniform(0.15, 0.3)
    ns = n1 / 0.97
    TL = rng.uniform(0.1, 0.3)
    s_end = 0.03
    # integrate ds/dt' = -(Tm - TL*(1-s)^2) in normalised time, then map to duration
    s = 1 - n0 / ns
    ss = [s]
    h = 1e-3
    while s > s_end and len(ss) < 200000:
        Tm = 2 / (s / sk + sk / s)
        s -= h * max(Tm - TL * (1 - s) ** 2, 0.02)
        ss.append(s)
    ss = np.array(ss)
    tn = np.linspace(0, 1, len(ss))
    n = ns * (1 - np.interp(t / t[-1], tn, ss))
    nu.update(kloss_sk=sk, kloss_TL=TL)
    return n


def resp_envelope_etd(t, phi, comps_by_order, wn, zeta):
    """Exact exponential (ETD) integration of y' = lam*y + f with y = x' - conj(lam) x, per Fourier
    component in a slowly varying complex envelope (Lewis 1932 sweep-through-resonance form)."""
    lam = -zeta * wn + 1j * wn * np.sqrt(1 - zeta ** 2)
    wd = wn * np.sqrt(1 - zeta ** 2)
    h = np.diff(t)
    om = np.gradient(phi, t)
    y = np.zeros(len(t), complex)
    for q, a, ph in comps_by_order:     # forcing wn^2 * a sin(q phi + ph)
        G = wn ** 2 * a * np.exp(1j * (ph - np.pi / 2))   # a sin(x) = Re(a e^{i(x - pi/2)})
        for sgn in (1, -1):
            Gs = G / 2 if sgn > 0 else np.conj(G) / 2
            av = lam - 1j * sgn * q * 0.5 * (om[:-1] + om[1:])
            g = np.exp(av * h)
            bb = (g - 1) / av * Gs
            u = _linrec(g, bb)
            y += u * np.exp(1j * sgn * q * phi)
    return np.imag(y) / wd


def _linrec(g, b, block=256):
    """u_0=0, u_{k+1} = g_k u_k + b_k, vectorised in blocks (cumulative products)."""
    n = len(g) + 1
    u = np.zeros(n, complex)
    cur = 0.0 + 0j
    for s in range(0, len(g), block):
        gg, bbk = g[s:s + block], b[s:s + block]
        P = np.cumprod(gg)
        acc = np.cumsum(bbk / P)
        u[s + 1:s + 1 + len(gg)] = P * (cur + acc)
        cur = u[s + len(gg)]
    return u


def resp_verlet(t, f, wn, zeta, sub=4):
    """Stormer-Verlet (velocity Verlet) with the damping term implicit in the velocity half-step."""
    x = np.zeros(len(t))
    xv, vv = 0.0, 0.0
    w2, c = wn * wn, 2 * zeta * wn
    for i in range(len(t) - 1):
        h = (t[i + 1] - t[i]) / sub
        for j in range(sub):
            fa = f[i] + (f[i + 1] - f[i]) * j / sub
            fb = f[i] + (f[i + 1] - f[i]) * (j + 1) / sub
            a = fa - w2 * xv - c * vv
            vh = vv + 0.5 * h * a
            xv = xv + h * vh
            vv = (vh + 0.5 * h * (fb - w2 * xv)) / (1 + 0.5 * h * c)
        x[i + 1] = xv
    return x


def gen_vibration(rng, cat, cell):
    pool = [m for m in cat["models"] if m["accuracy"]]
    m = pool[rng.integers(len(pool))]
    nu = {}
    eff = cell["effects"]
    rig = cell.get("rig")
    s = 1.0 + raised_cosine(rng, 0.09)
    K = m["K1"] * s
    N1_max = min(0.75 * m["nmax"], 3000.0)
    fn = rng.uniform(6.0, N1_max / 60.0 / 1.4)
    J = K / (2 * np.pi * fn) ** 2
    zeta = rng.uniform(0.03, 0.12)
    nu.update(stiffness_scale=s, damping_ratio=zeta, f_n_Hz=fn)
    N1 = 60 * fn
    n0, n1 = 0.25 * N1, 1.4 * N1
    dur = rng.uniform(40, 70)
    fs = max(30 * fn, 200.0)
    nsamp = int(dur * fs)
    if nsamp > 24000:
        fs = 24000 / dur
        nsamp = 24000
    t = np.arange(nsamp) / fs
    integ, prof = cell["integrator"]
    if prof == "cycloidal":
        n_rpm = runup_cycloidal(t, n0, n1)
    else:
        n_rpm = runup_kloss(t, n0, n1, rng, nu)
    om = n_rpm * 2 * np.pi / 60
    phi = np.concatenate([[0.0], np.cumsum(0.5 * (om[1:] + om[:-1]) * np.diff(t))])
    phi += rng.uniform(0, 2 * np.pi)
    wn = 2 * np.pi * fn
    fmax = 0.45 * fs
    sources = {}
    for e in eff:
        order = 1 if e == "te_1x" else 2
        amp = 0.5 * m["accuracy"] * rng.uniform(0.3, 0.8)
        comps = te_components(cell["forms"][e], amp, rng, nu, e)
        psi = rng.uniform(0, 2 * np.pi)
        cc = [(order * k, a, k * psi) for k, a, _ in comps if order * k * n1 / 60 < fmax]
        sources[e] = cc
        nu[f"{e}_amp_rad"] = amp
    meas = ()
    rig_contrib = None
    if rig in ("rotor_eccentricity_ripple", "oldham_coupling_friction"):
        q = 1 if rig == "rotor_eccentricity_ripple" else 2
        A = 0.5 * m["accuracy"] * rng.uniform(0.3, 0.8)
        ps = rng.uniform(0, 2 * np.pi)
        sources[rig] = [(q, A, ps)]
        meas = (rig,)
    contribs = {}
    for key, cc in sources.items():
        if integ == "etd":
            contribs[key] = resp_envelope_etd(t, phi, cc, wn, zeta)
        else:
            fsig = wn ** 2 * sum(a * np.sin(q * phi + p) for q, a, p in cc)
            contribs[key] = resp_verlet(t, fsig, wn, zeta)
    th_out = phi / m["ratio"]
    if rig == "encoder_eccentricity":
        A = m["accuracy"] * rng.uniform(0.5, 2)
        rig_contrib = A * np.sin(th_out + rng.uniform(0, 2 * np.pi))
        nu["ecc_amp_rad"] = A
        meas = ("encoder_eccentricity",)
    elif rig == "angle_offset":
        o = rng.choice([-1, 1]) * m["accuracy"] * rng.uniform(0.2, 1)
        i0 = int(nsamp * rng.uniform(0.3, 0.7))
        rig_contrib = np.where(np.arange(nsamp) >= i0, o, 0.0)
        nu["offset_step_rad"] = o
        meas = ("angle_offset",)
    elif rig == "thermal_drift":
        D = rng.choice([-1, 1]) * m["accuracy"] * rng.uniform(0.2, 1)
        tc, tau = rng.uniform(0.3, 0.7) * dur, rng.uniform(0.08, 0.2) * dur
        lg = 1 / (1 + np.exp(-(t - tc) / tau))
        rig_contrib = D * (lg - lg[0])
        nu["drift_rad"] = D
        meas = ("thermal_drift",)
    elif rig == "wrong_units_deg":
        meas = ("wrong_units",)
    elif rig in ("rotor_eccentricity_ripple", "oldham_coupling_friction"):
        rig_contrib = contribs.pop(rig)
    if eff:
        sigma, scales, ks = size_pair(rng, contribs, lambda d: sum(d.values()))
        for e in eff:
            contribs[e] = contribs[e] * scales[e]
            nu[f"snr_{e}"] = ks[e]
            nu[f"scale_{e}"] = scales[e]
        hidden = sum(contribs.values())
    elif rig_contrib is not None:
        k = rng.uniform(*K_RANGE)
        sigma = _rms(rig_contrib) / k
        hidden = rig_contrib
        nu[f"snr_{meas[0]}"] = k
    else:
        hidden = np.zeros(nsamp)
        sigma = m["accuracy"] * rng.uniform(0.005, 0.03)
    return m, t, n_rpm, hidden, sigma, nu, meas, rig, J


# ----------------------------------------------------------------------------------------------
# cells
def _cells():
    C = []

    def add(kind, cat, effects, formulation, forms=None, rig=None, equiv=(), noise=None, **kw):
        C.append(dict(kind=kind, category=cat, effects=tuple(effects), formulation=formulation,
                      forms=forms or {}, rig=rig, equiv=tuple(equiv), noise=noise, **kw))

    # torsion
    for nz in ("white-outliers", "ar1", "arma11"):
        add("torsion", "clean", (), nz, noise=nz)
    for e, fs in (("hysteresis", (("davidenkov", "forc"), ("hilbert", "cheb"))),
                  ("backlash", (("lostmotion", None), ("cauchy", None))),
                  ("housing_compliance", (("spoked", None), ("keyed", None)))):
        for f, prot in fs:
            add("torsion", "single", (e,), f, forms={e: f}, protocol=prot)
    pairs = [
        (("hysteresis", "backlash"), [("davidenkov", "cauchy", "forc"), ("hilbert", "lostmotion", "cheb")]),
        (("hysteresis", "housing_compliance"), [("davidenkov", "keyed", "forc"), ("hilbert", "spoked", "cheb")]),
        (("backlash", "housing_compliance"), [("lostmotion", "keyed", None), ("cauchy", "spoked", None)]),
    ]
    for (a, b), fl in pairs:
        for fa, fb, prot in fl:
            add("torsion", "pair", (a, b), f"{fa}+{fb}", forms={a: fa, b: fb}, protocol=prot)
    for rig, f in (("sensor_gain", "torque-gain"), ("angle_offset", "rezero-step"),
                   ("thermal_drift", "logistic-soak"), ("wrong_units_deg", "degrees"),
                   ("wrong_units_kNm", "kNm"), ("stiffness_scale", "in-spread")):
        add("torsion", "decoy_separable", (), f, rig=rig)
    for rig, f, eq in (("soft_gear", "scale-0.68-0.84", ("housing_compliance",)),
                       ("fixture_base_rotation", "linear-base-tilt", ("housing_compliance",)),
                       ("lever_pivot_friction", "pivot-play-operator", ("hysteresis",)),
                       ("dowel_fit_clearance", "h7g6-dowel", ("backlash",))):
        add("torsion", "decoy_equivalent", (), f, rig=rig, equiv=eq)
    # transmission
    for nz in ("white-outliers", "ar1", "butter"):
        add("transmission", "clean", (), nz, noise=nz)
    for e in ("te_1x", "te_2x"):
        for f in ("triangle", "oddwarp"):
            add("transmission", "single", (e,), f, forms={e: f})
    for fa, fb in (("triangle", "oddwarp"), ("oddwarp", "triangle")):
        add("transmission", "pair", ("te_1x", "te_2x"), f"{fa}+{fb}", forms={"te_1x": fa, "te_2x": fb})
    for rig, f in (("encoder_eccentricity", "exact-readhead"), ("angle_offset", "rezero-step"),
                   ("sensor_gain", "angle-gain"), ("thermal_drift", "logistic-soak"),
                   ("wrong_units_deg", "degrees")):
        add("transmission", "decoy_separable", (), f, rig=rig)
    add("transmission", "decoy_equivalent", (), "hall-pickup-1pp", rig="stray_field_pickup", equiv=("te_1x",))
    add("transmission", "decoy_equivalent", (), "mount-flex-2x", rig="readhead_mount_flexing", equiv=("te_2x",))
    # efficiency
    for nz in ("white-outliers", "ar1", "arma11"):
        add("efficiency", "clean", (), nz, noise=nz)
    for f in ("anderson-loewenthal", "misharin"):
        add("efficiency", "single", ("low_load_efficiency",), f, forms={"low_load_efficiency": f})
    for f in ("petroff-litovitz", "changenet-poling"):
        add("efficiency", "single", ("temperature_dependence",), f, forms={"temperature_dependence": f})
    for fa, fb in (("anderson-loewenthal", "changenet-poling"), ("misharin", "petroff-litovitz")):
        add("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"), f"{fa}+{fb}",
            forms={"low_load_efficiency": fa, "temperature_dependence": fb})
    for rig, f in (("sensor_gain", "torque-gain"), ("thermal_drift", "logistic-soak+ramp"),
                   ("wrong_units_fraction", "fraction")):
        add("efficiency", "decoy_separable", (), f, rig=rig)
    add("efficiency", "decoy_equivalent", (), "motor-I0", rig="motor_noload_current", equiv=("low_load_efficiency",))
    add("efficiency", "decoy_equivalent", (), "cu-resistance", rig="copper_resistance_uncorrected",
        equiv=("temperature_dependence",))
    # vibration
    for nz in ("white-outliers", "ar1", "butter"):
        add("vibration", "clean", (), nz, noise=nz, integrator=("etd", "cycloidal"))
    for e in ("te_1x", "te_2x"):
        add("vibration", "single", (e,), "etd-cycloidal-triangle", forms={e: "triangle"}, integrator=("etd", "cycloidal"))
        add("vibration", "single", (e,), "verlet-kloss-oddwarp", forms={e: "oddwarp"}, integrator=("verlet", "kloss"))
    add("vibration", "pair", ("te_1x", "te_2x"), "etd-kloss-triangle+oddwarp",
        forms={"te_1x": "triangle", "te_2x": "oddwarp"}, integrator=("etd", "kloss"))
    add("vibration", "pair", ("te_1x", "te_2x"), "verlet-cycloidal-oddwarp+triangle",
        forms={"te_1x": "oddwarp", "te_2x": "triangle"}, integrator=("verlet", "cycloidal"))
    for rig, f in (("encoder_eccentricity", "output-1x"), ("angle_offset", "rezero-step"),
                   ("thermal_drift", "logistic-soak"), ("wrong_units_deg", "degrees")):
        add("vibration", "decoy_separable", (), f, rig=rig, integrator=("etd", "cycloidal"))
    add("vibration", "decoy_equivalent", (), "rotor-ecc-1x-etd", rig="rotor_eccentricity_ripple",
        equiv=("te_1x",), integrator=("etd", "kloss"))
    add("vibration", "decoy_equivalent", (), "oldham-2x-verlet", rig="oldham_coupling_friction",
        equiv=("te_2x",), integrator=("verlet", "cycloidal"))
    return C


CELLS = _cells()


def _slug(s):
    return s.replace("_", "").replace("+", "+").replace(" ", "")


def _case_name(cell, idx):
    eff = "+".join(cell["effects"]) if cell["effects"] else (cell["rig"] or "none")
    eff = eff.replace("_", "")
    form = cell["formulation"].replace("_", "").replace(" ", "")
    return f"m-{cell['kind']}-{cell['category']}-{eff}-{form}-{idx:03d}"


def _noise_kind(rng, cell):
    if cell.get("noise"):
        nk = cell["noise"]
    else:
        nk = "white" if rng.uniform() < 0.5 else "ar1"
    base = nk.replace("-outliers", "")
    outl = nk.endswith("-outliers") or (cell["category"] != "clean" and rng.uniform() < 0.1)
    return base, outl


def _finish(rng, cell, n, sigma):
    kind_n, outl = _noise_kind(rng, cell)
    noise, info = make_noise(rng, n, sigma, kind_n)
    out = make_outliers(rng, n, sigma) if outl else np.zeros(n)
    return noise, out, kind_n, outl, info


def generate_cases(seed: int, catalog_dir, per_cell: int = 4, keep_parts: bool = False):
    cat = load_catalog(catalog_dir)
    master = np.random.default_rng(seed)
    cases = []
    for cell in CELLS:
        for rep in range(per_cell):
            rng = np.random.default_rng(master.integers(2 ** 63))
            kind = cell["kind"]
            J = None
            if kind == "torsion":
                m, T, col_T, clean, hidden, sigma, nu, meas, rig = gen_torsion(rng, cat, cell)
                noise, out, nk, outl, info = _finish(rng, cell, len(T), sigma)
                meas_col = clean + noise + out
                unit = 1.0
                if rig == "wrong_units_deg":
                    unit = DEG
                if rig == "wrong_units_kNm":
                    col_T = col_T * 1e-3
                cols = {"torque_Nm": col_T, "twist_rad": meas_col * unit}
            elif kind == "transmission":
                m, phi, clean, hidden, sigma, nu, meas, rig = gen_transmission(rng, cat, cell)
                noise, out, nk, outl, info = _finish(rng, cell, len(phi), sigma)
                unit = DEG if rig == "wrong_units_deg" else 1.0
                cols = {"input_angle_rad": phi, "output_angle_rad": (clean + noise + out) * unit}
            elif kind == "efficiency":
                m, ns, load, TC, clean, hidden, sigma, nu, meas, rig = gen_efficiency(rng, cat, cell)
                noise, out, nk, outl, info = _finish(rng, cell, len(ns), sigma)
                unit = 0.01 if rig == "wrong_units_fraction" else 1.0
                cols = {"input_speed_rpm": ns, "load_torque_Nm": load, "temperature_C": TC,
                        "efficiency_pct": (clean + noise + out) * unit}
            else:
                m, t, n_rpm, hidden, sigma, nu, meas, rig, J = gen_vibration(rng, cat, cell)
                clean = hidden
                noise, out, nk, outl, info = _finish(rng, cell, len(t), sigma)
                unit = DEG if rig == "wrong_units_deg" else 1.0
                cols = {"time_s": t, "input_speed_rpm": n_rpm,
                        "output_vibration_rad": (clean + noise + out) * unit}
            nu = dict(nu)
            nu.update({f"noise_{k}": float(v) for k, v in info.items()})
            nu["noise_white"] = float(nk == "white")
            nu["outlier_count"] = float(np.count_nonzero(out))
            nu["units_factor"] = float(unit)
            nu = {k: float(v) for k, v in nu.items()}
            if cell["effects"]:
                snr = _rms(hidden) / sigma
            elif cell["category"] == "clean" or rig and rig.startswith("wrong_units"):
                snr = 0.0
            else:
                snr = _rms(hidden) / sigma
            nform = cell["formulation"] + ("" if cell["category"] == "clean" else f" [{nk}{'+outliers' if outl else ''}]")
            c = TruthCase(name=_case_name(cell, rep), kind=kind, model=m["code"], columns=cols,
                          load_inertia_kgm2=(float(J) if kind == "vibration" else None),
                          gear_effects=tuple(cell["effects"]), measurement_effects=tuple(meas),
                          nuisance=nu, category=cell["category"],
                          equivalent_effects=tuple(cell["equiv"]), noise_rms=float(sigma * unit),
                          formulation=nform, snr=float(snr))
            if keep_parts:
                c._parts = dict(clean=clean * unit, noise=noise * unit, outliers=out * unit,
                                hidden=hidden * unit)
            cases.append(c)
    return cases
