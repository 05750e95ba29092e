"""Suite D: independent truth simulator for `hdcad reconcile` (strain-wave-gear test data).

Written from /work/truths/CONTRACT.md, the catalog tables (catalog/*.csv, read-only) and the
seeds (000 p.020 stiffness / hysteresis / backlash, p.021 transmission error and vibration,
p.023 efficiency; 003 tables 050-1/058-1, 051-1/059-1, 052-1/060-1, 052-2/060-2).
numpy + scipy only; nothing from hdcad is imported or read.

Baselines (the catalog model the data are measured against)
------------------------------------------------------------
* torsion: three-segment curve from the stiffness table (T1, T2, K1, K2, K3; theta1 = T1/K1,
  theta2 = theta1 + (T2-T1)/K2, odd in T) with a stiffness-scale nuisance s in [0.9, 1.1]
  (the seeds call the table values averages and give no spread; the contract's +-10 % is used).
  Clean formulation "pchip" rounds the two corners with a monotone piecewise-cubic Hermite
  interpolant (Fritsch & Carlson 1980, SIAM J. Numer. Anal. 17:238) inside +-3..8 % windows;
  the rounding stays below half the noise RMS.  Protocol: virgin loading 0 -> +T0, then two full
  triangular cycles +-T0 (T0 = 0.95..1.2 x rated torque), ending at 0.  Extra column time_s.
* transmission: output = input / R + offset, constant input speed, 8..24 input revolutions.
* efficiency: constant level L (nuisance, 62..86 %) on a grid speed x load x lubricant temperature.
* vibration: 1-DOF load inertia J on the gear spring, input speed run up through resonance;
  with no excitation the vibration is zero (only noise).

Gear-effect formulations (effect = noise-free measurement minus the baseline with the same nuisance)
-----------------------------------------------------------------------------------------------------
hysteresis (torsion)
  "iwan-jenkins"   Iwan parallel-series model: 30 Jenkins elements (spring k_i + Coulomb slider
                   phi_i) in parallel with the catalog spring, log-normal slip-angle distribution
                   (none slips at very small torque).  Torque-controlled, solved per step with Brent's
                   method.  Iwan 1966, J. Appl. Mech. 33:893; Segalman 2005, J. Appl. Mech. 72:752.
  "masing-ro"      Ramberg-Osgood backbone h(T) = c*theta0*|T/T0|^r*sgn T (r 2..3.5) with Masing's
                   branch rule theta = theta_r + 2 h((T - T_r)/2) and the extended (Madelung memory)
                   rules; loop width grows as amplitude^r.  Masing 1926; Ramberg & Osgood 1943 NACA
                   TN-902; Pyke 1979 J. Geotech. Eng. 105:715.  Added in series to the catalog twist,
                   virgin curve = catalog curve.
  "gpi-play"       Generalized Prandtl-Ishlinskii model: 25 generalized play operators with a sinh
                   envelope and slightly different ascending / descending envelopes (asymmetric
                   loops), threshold density r^m exp(-lambda r) (vanishes at r = 0, so no loop at
                   small torque).  Al Janaideh, Rakheja & Su 2009, Smart Mater. Struct. 18:045001;
                   Kuhnen 2003, Eur. J. Control 9:407.
  "lugre"          LuGre bristle friction torque (sigma0 z + sigma1 dz/dt + sigma2 dtheta/dt, Stribeck
                   g(v)) in parallel with the catalog spring; rate dependent, implicit Euler + Brent.
                   Canudas de Wit, Olsson, Astrom & Lischinsky 1995, IEEE TAC 40:419.
backlash (torsion)
  "hertz-asym"     Oldham-coupling clearance with different play on the + and - sides, taken up
                   partly as a jump at torque reversal and partly as Hertzian re-engagement
                   delta ~ T^(2/3) up to an engagement torque.  Johnson 1985 Contact Mechanics ch.4;
                   Nordin & Gutman 2002, Automatica 38:1633 (dead-zone backlash).
  "preloaded-play" play held closed by a preload spring: extra compliance b/(2 T_p) for |T| < T_p,
                   full half-play b/2 beyond (spring-loaded anti-backlash coupling, Nordin & Gutman).
housing_compliance (torsion)
  "shaft-linear"   series output-shaft spring theta = T L / (G J_p), J_p = pi d^4 / 32, G = 79.3 GPa
                   (Young & Budynas, Roark's Formulas, table 10.1); L chosen so K1/K_shaft = 0.1..0.5.
  "bolted-bilinear" series bolted-flange spring whose compliance rises by 1.4..2x once the joint opens
                   above T_open = 0.3..0.6 T0 (joint separation, VDI 2230 part 1 / Shigley ch. 8).
te_1x, te_2x (transmission)
  "rw-modulated"   sinusoids at 1 and/or 2 cycles per input revolution whose amplitude is
                   exp(sigma W(rev)) and phase sigma_p W'(rev), W, W' smoothed Gaussian random walks
                   (slow, several revolutions), plus an unnamed 3x or 4x component of RMS 0.1..0.3 x
                   noise.  Ghorbel, Gandhi & Alpeter 2001 J. Mech. Des. 123:90 (kinematic error);
                   Tuttle & Seering 1996 IEEE TRA 12:368.
  "cam-geometry"   stationary kinematic error from wave-generator geometry: 1x from an eccentric
                   WG, atan2(e sin x, 1 + e cos x)/e (e 0.02..0.06); 2x from a cam-profile error
                   sin(2x)/(1 + b cos(2x + psi)) (b 0.03..0.08); the harmonics this creates stay
                   inside the noise.
low_load_efficiency (efficiency)
  "coulomb-viscous-drag" input-side loss torque T_d = T_c + c_v omega_in; eta = 1/(1/eta_m + R T_d/T),
                   eta_m normalised so eta(rated, n_ref, T_ref) = L.  Taghirad & Belanger 1998,
                   J. Dyn. Syst. Meas. Control 120:439; reproduces Ke(0.58) ~ 0.93 of graph 023-1
                   for R T_d / T_rated ~ 0.12.
  "catalog-running-torque" T_d = (no-load running torque of table 051-1/059-1 at 2000 r/min, 25 C)
                   x 0.7..1.4 (capped so R T_d / T_rated <= 0.25) x (n/2000)^x, x 0.2..0.6.
temperature_dependence (efficiency)
  "walther-ehl"    load-proportional mesh loss ratio l(T) = l_ref (nu(T)/nu_ref)^m, viscosity from
                   Walther's equation (ASTM D341): log log(nu + 0.7) = A - B log T_K fitted to
                   nu40, nu100; eta = L (1 + l_ref)/(1 + l(T)).
  "vogel-speed"    viscosity from Vogel's equation nu = a exp(b/(T + 95 C)) (Vogel 1921, Phys. Z.
                   22:645); l(T, n) = l_ref [1 + ((nu/nu_ref)^m - 1)(n/n_ref)^p]: the temperature
                   effect grows with speed (film shear, Changenet & Velex 2007 J. Mech. Des. 129:128)
                   and vanishes at T_ref.
  pairs            "drag-vogel-coupled": T_d = T_c + c_v (nu(T)/nu_ref)^m_d omega plus Vogel mesh loss;
                   "coulomb-x-walther": eta = L Ke(alpha) F(T), Ke = alpha(1+beta)/(alpha+beta).
te_1x, te_2x (vibration)
  J x'' + damping + T_s(x - e) = 0, e(t) the rw-modulated TE (above) at the input angle phi(t),
  T_s the three-segment (nonlinear, stiffening) catalog spring x stiffness scale; J chosen so the
  resonance f_n = sqrt(s K1/J)/(2 pi) is crossed at k f_in = f_n (k = 1 and/or 2); non-constant
  run-up (exponential, power-law or S-shaped speed profile); fixed-step RK4 (seed 000 p.021;
  Markert & Seidler 2001 Int. J. Solids Struct. 38:1975 for run-up through resonance).
  "kelvin-voigt-zeta"  relative (gear-internal) viscous damping c (x' - e'), c = 2 zeta sqrt(s K1 J).
  "load-drag-loss"     absolute damping on the load c x', c = eta_loss sqrt(s K1 J) (loss factor).

Measurement chain / decoys
--------------------------
Noise (measured column only): white Gaussian, AR(1) phi 0.3..0.8, Student-t nu 3..6 (unit
variance), optionally 0.5 % outliers at 8..15 x sigma, and quantisation of angle channels to
encoder counts 2 pi / 2^N (q/sqrt12 ~ 0.2..0.35 x target noise; Widrow & Kollar 2008).  noise_rms is
the RMS of (measured - noise-free measured), everything included; sigma is iterated so that the
effect RMS / noise_rms equals the drawn k in [4, 12].  For pairs both effects are sized and `snr`
is the smaller of the two ratios (both lie in [4, 12]).
decoy_separable: torque-sensor gain, constant or stepped twist offset, thermal drift (exponential
warm-up), wrong units (deg for rad, kN m for N m, fraction for %), stiffness scale within the spread,
output-encoder eccentricity (once per output revolution), angle-channel gain, efficiency torque
gain (level shift), thermal drift of the efficiency rig in randomised run order.
decoy_equivalent (truly data-equivalent readings):
  torsion "soft-gear-below-T1": gear 25..45 % softer than the catalog, tested only below T1:
          T/(s K1) = T/K1 + c T exactly -> housing_compliance.
  torsion "rig-coulomb-friction": Coulomb friction of the torque-arm bearing between sensor and gear
          (a rigid-plastic element in parallel with the gear spring) = a Coulomb-type internal
          friction loop -> hysteresis.
  torsion "keyed-coupling-play": clearance of the keyed coupling between gear output and the
          loading arm, in series with the gear -> backlash.
  transmission "input-encoder-eccentricity": once-per-input-rev error of the input encoder:
          output - input_meas/R = -(e/R) sin(phi + psi) exactly -> te_1x.
  efficiency "temp-dependent-torque-gain": torque-sensor gain 1 + kappa (T - T_ref) multiplies the
          computed efficiency (and the load column, invisible on a constant level) -> temperature_dependence.
  efficiency "rig-input-drag": Coulomb drag of a rig support bearing between the input torque sensor
          and the gear = a constant input loss torque -> low_load_efficiency.
Rig effects that have no contract measurement-effect name are recorded with measurement_effects = ().

Bookkeeping
-----------
snr = min over the named hidden effects of RMS(effect) / noise_rms, effect in the measured column's
unit (for wrong-unit decoys the literal value, far above 12: a unit factor cannot be sized to
4..12 x noise; their noise is sized like a clean case).  nuisance holds floats only: stiffness_scale,
offset_rad, efficiency_level_pct, damping_ratio, corner_rounding (pchip clean), torque_gain,
angle_gain, torque_gain_per_K (decoys), and the noise description noise_ar1_phi (0 = not AR),
noise_student_t_nu (0 = Gaussian), noise_outlier_frac, noise_quant_step (rad, or 0.01 % for
efficiency).  Extra CSV column time_s (test time) in torsion, transmission and efficiency.
_generate() also returns the noise-free measured column for the self-test.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.interpolate import PchipInterpolator
from scipy.optimize import brentq
from scipy.signal import lfilter

SUITE = "d"

DEG = 180.0 / math.pi
G_STEEL = 79.3e9


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
        with open(path, "w", newline="") as f:
            f.write(",".join(names) + "\n")
            for row in zip(*cols):
                f.write(",".join(repr(float(v)) for v in row) + "\n")


# ----------------------------------------------------------------------------- catalog
def _f(x):
    x = (x or "").strip()
    return float(x) if x else None


def _read(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


MODEL_POOL = [
    ("CSF-GH", 14, 50), ("CSG-GH", 14, 100), ("CSF-GH", 20, 80), ("CSG-GH", 20, 160),
    ("CSF-GH", 32, 100), ("CSG-GH", 32, 50), ("CSF-GH", 45, 120), ("CSG-GH", 45, 80),
    ("CSF-GH", 65, 160), ("CSG-GH", 65, 100),
]


def _load_models(catalog_dir):
    d = Path(catalog_dir)
    stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
    rat = _read(d / "gh_ratings_050-1_058-1.csv")
    hyst = _read(d / "gh_hysteresis_052_060.csv")
    bl = _read(d / "gh_backlash_052-2_060-2.csv")
    perf = _read(d / "gh_performance_051-1_059-1.csv")

    def in_group(row, ratio):
        lo = _f(row["ratio_min"])
        hi = _f(row["ratio_max"])
        return ratio >= lo and (hi is None or ratio <= hi)

    models = []
    for series, size, ratio in MODEL_POOL:
        st = [r for r in stiff if r["series"] == series and int(r["size"]) == size and in_group(r, ratio)][0]
        ra = [r for r in rat if r["series"] == series and int(r["size"]) == size and int(r["ratio"]) == ratio][0]
        hy = [r for r in hyst if r["series"] == series and in_group(r, ratio)][0]
        b = [r for r in bl if r["series"] == series and int(r["size"]) == size and int(r["ratio"]) == ratio][0]
        pf = [r for r in perf if r["series"] == series and int(r["size"]) == size and int(r["ratio"]) == ratio][0]
        acc = _f(pf["accuracy_rad"])
        if acc is None:  # CSG-GH 32..65 blank in 051-1: take the other series' value (only to size the TE)
            other = [r for r in perf if r["series"] != series and int(r["size"]) == size
                     and int(r["ratio"]) == ratio and _f(r["accuracy_rad"])]
            acc = _f(other[0]["accuracy_rad"]) if other else 2.9e-4
        models.append(dict(
            code=f"{series.split('-')[0]}-{size}-{ratio}-GH", series=series, size=size, ratio=ratio,
            T1=_f(st["T1_Nm"]), T2=_f(st["T2_Nm"]), K1=_f(st["K1_Nm_per_rad"]),
            K2=_f(st["K2_Nm_per_rad"]), K3=_f(st["K3_Nm_per_rad"]),
            rated=_f(ra["rated_torque_2000_Nm"]), momentary=_f(ra["momentary_torque_Nm"]),
            avg_speed=_f(ra["avg_input_speed_max_rpm"]), max_speed=_f(ra["max_input_speed_rpm"]),
            hyst=_f(hy["hysteresis_rad"]), backlash=_f(b["backlash_rad"]), accuracy=acc,
            running_torque=_f(pf["running_torque_cNm"]) / 100.0,
        ))
    return models


# ----------------------------------------------------------------------------- helpers
def _rms(x):
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x)))


class Seg3:
    """Catalog three-segment spring, stiffness scale s applied to K1..K3 (T1, T2 fixed)."""

    def __init__(self, m, s=1.0):
        self.T1, self.T2 = m["T1"], m["T2"]
        self.K1, self.K2, self.K3 = m["K1"] * s, m["K2"] * s, m["K3"] * s
        self.th1 = self.T1 / self.K1
        self.th2 = self.th1 + (self.T2 - self.T1) / self.K2

    def theta(self, T):
        T = np.asarray(T, dtype=float)
        a = np.abs(T)
        th = np.where(a <= self.T1, a / self.K1,
                      np.where(a <= self.T2, self.th1 + (a - self.T1) / self.K2,
                               self.th2 + (a - self.T2) / self.K3))
        return np.sign(T) * th

    def torque(self, th):  # scalar inverse
        a = abs(th)
        if a <= self.th1:
            t = self.K1 * a
        elif a <= self.th2:
            t = self.T1 + self.K2 * (a - self.th1)
        else:
            t = self.T2 + self.K3 * (a - self.th2)
        return t if th >= 0 else -t


def _torque_protocol(T0, n_q):
    knots = [0.0, T0, -T0, T0, -T0, 0.0]
    quarters = [1, 2, 2, 2, 1]
    parts = [np.linspace(knots[i], knots[i + 1], q * n_q, endpoint=False) for i, q in enumerate(quarters)]
    return np.concatenate(parts + [np.array([0.0])])


def _slow_walk(rng, x, corr):
    """Smoothed Gaussian random walk over x (knot spacing corr), zero mean, unit RMS."""
    span = float(x.max() - x.min())
    nk = int(span / corr) + 4
    knots = np.linspace(x.min() - corr, x.max() + corr, nk)
    w = np.cumsum(rng.standard_normal(nk))
    w = PchipInterpolator(knots, w)(x)
    w -= w.mean()
    r = _rms(w)
    return w / r if r > 0 else w


# ----------------------------------------------------------------------------- noise
NOISE_KINDS = ("white", "ar1", "student-t")


def _noise_spec(rng, kind=None, outliers=None, quant=True):
    kind = kind or NOISE_KINDS[int(rng.integers(3))]
    spec = dict(kind=kind, phi=0.0, nu=0.0, outliers=bool(rng.random() < 0.25) if outliers is None else outliers,
                quant=quant)
    if kind == "ar1":
        spec["phi"] = float(rng.uniform(0.3, 0.8))
    elif kind == "student-t":
        spec["nu"] = float(rng.uniform(3.0, 6.0))
    return spec


def _unit_noise(rng, n, spec):
    if spec["kind"] == "white":
        u = rng.standard_normal(n)
    elif spec["kind"] == "ar1":
        phi = spec["phi"]
        e = rng.standard_normal(n)
        u = lfilter([math.sqrt(1 - phi * phi)], [1.0, -phi], e, zi=[phi * rng.standard_normal()])[0]
    else:
        nu = spec["nu"]
        u = rng.standard_t(nu, n) * math.sqrt((nu - 2.0) / nu)
    out = np.zeros(n)
    if spec["outliers"]:
        k = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, k, replace=False)
        out[idx] = rng.uniform(8.0, 15.0, k) * rng.choice([-1.0, 1.0], k)
    return u, out


def _quant_step(target_si):
    n = math.ceil(math.log2(2 * math.pi / (0.35 * math.sqrt(12.0) * target_si)))
    return 2 * math.pi / 2 ** n


def _add_noise(rng, y_true_si, target_si, spec, factor=1.0, decimals=None, angle=True):
    """Returns measured column (in measured unit), noise_rms (measured unit), info for nuisance."""
    n = len(y_true_si)
    u, out = _unit_noise(rng, n, spec)
    q = _quant_step(target_si) if (spec["quant"] and angle) else None
    ref = y_true_si * factor
    sigma = target_si
    ym = None
    for _ in range(8):
        y = y_true_si + sigma * (u + out)
        if q is not None:
            y = np.round(y / q) * q
        ym = y * factor
        if decimals is not None:
            ym = np.round(ym, decimals)
        act = _rms(ym - ref) / factor
        if act <= 0:
            break
        if abs(act / target_si - 1) < 1e-6:
            break
        sigma *= target_si / act
    info = {"noise_ar1_phi": spec["phi"], "noise_student_t_nu": spec["nu"],
            "noise_outlier_frac": float(np.count_nonzero(out)) / n,
            "noise_quant_step": float(q) if q is not None else (10.0 ** -decimals if decimals else 0.0)}
    return ym, _rms(ym - ref), info


def _draw_k(rng, rms_list):
    lo, hi = min(rms_list), max(rms_list)
    rho = hi / lo
    kmax = 12.0 / rho
    kmin = 4.0
    if kmax <= kmin:  # cannot fit both in [4, 12]; caller should have balanced
        kmax = kmin
    return float(rng.uniform(kmin + 0.15, max(kmin + 0.15, kmax - 0.15)))


def _balance(rms_a, rms_b, limit=2.6):
    """Factor to apply to effect b so that max/min of the two RMS values is at most 0.9 * limit."""
    if rms_b > limit * rms_a:
        return 0.9 * limit * rms_a / rms_b
    if rms_a > limit * rms_b:
        return rms_a / (0.9 * limit * rms_b)
    return 1.0


# ----------------------------------------------------------------------------- case assembly
CSV_COLUMNS = {
    "torsion": ("torque_Nm", "twist_rad"),
    "transmission": ("input_angle_rad", "output_angle_rad"),
    "efficiency": ("input_speed_rpm", "load_torque_Nm", "temperature_C", "efficiency_pct"),
    "vibration": ("time_s", "input_speed_rpm", "output_vibration_rad"),
}


def _finish(rng, *, kind, category, model, effects_gear, effects_meas, formulation, x_cols, meas_name,
            y_true_si, effect_arrays, nuisance, spec, target_noise_si=None, factor=1.0, decimals=None,
            angle=True, equivalent=(), load_inertia=None, hidden_shape=None, hidden_frac=0.0,
            wrong_units=False):
    """effect_arrays: list of arrays in the measured unit (already including factor effects)."""
    rms_list = [_rms(e) for e in effect_arrays]
    if target_noise_si is None:
        k = _draw_k(rng, rms_list)
        target_noise_si = min(rms_list) / k / factor
    y_true_si = np.asarray(y_true_si, dtype=float).copy()
    if hidden_shape is not None:
        y_true_si = y_true_si + hidden_frac * target_noise_si * hidden_shape / _rms(hidden_shape)
    ym, noise_rms, info = _add_noise(rng, y_true_si, target_noise_si, spec, factor, decimals, angle)
    snr = (min(rms_list) / noise_rms) if rms_list else 0.0
    allc = dict(x_cols)
    allc[meas_name] = ym
    cols = {k: allc[k] for k in CSV_COLUMNS[kind]}  # contract columns first, extras last
    cols.update({k: v for k, v in allc.items() if k not in cols})
    nz = dict(nuisance)
    nz.update(info)
    case = TruthCase(name="", kind=kind, model=model["code"], columns=cols, load_inertia_kgm2=load_inertia,
                     gear_effects=tuple(effects_gear), measurement_effects=tuple(effects_meas), nuisance=nz,
                     category=category, equivalent_effects=tuple(equivalent), noise_rms=float(noise_rms),
                     formulation=formulation, snr=float(snr))
    truth = dict(meas_name=meas_name, y_clean=y_true_si * factor, effect_rms=rms_list, wrong_units=wrong_units,
                 factor=factor)
    return case, truth


# ============================================================================= torsion
def _pchip_baseline(rng, seg, T):
    a = np.abs(T)
    amax = max(a.max(), seg.T2 * 1.5)
    w1 = float(rng.uniform(0.03, 0.08))
    w2 = float(rng.uniform(0.03, 0.08))
    grid = np.linspace(0.0, amax, 400)
    keep = ~((np.abs(grid - seg.T1) < w1 * seg.T1) | (np.abs(grid - seg.T2) < w2 * seg.T2))
    g = grid[keep]
    p = PchipInterpolator(g, seg.theta(g))
    return np.sign(T) * p(a), max(w1, w2)


def _iwan(rng, seg, T, w_target, T0):
    N = 30
    kappa = float(rng.uniform(0.3, 0.8))
    k = np.full(N, kappa * seg.K1 / N)
    theta0 = float(seg.theta(np.array([T0]))[0])
    sig = float(rng.uniform(0.5, 0.9))
    z = rng.standard_normal(N)
    delta = np.exp(sig * (z - z.mean()) / (z.std() + 1e-12))
    # width at zero ~ 2 sum(phi)/K_eff with all sliders slipping
    delta *= w_target * (1 + kappa) / (2 * kappa * delta.mean())
    delta = np.minimum(delta, 0.9 * theta0)
    phi = k * delta
    sl = np.zeros(N)
    th = 0.0
    out = np.empty(len(T))
    Tprev = 0.0
    kmin = seg.K1
    for j, Tj in enumerate(T):
        def f(x):
            return seg.torque(x) + float(np.sum(np.clip(k * (x - sl), -phi, phi))) - Tj
        d = abs(Tj - Tprev) / kmin * 1.05 + 1e-15
        if d > 1e-15 and f(th) != 0.0:
            lo, hi = (th, th + d) if Tj > Tprev else (th - d, th)
            th = brentq(f, lo, hi, xtol=1e-16, rtol=1e-13)
        el = k * (th - sl)
        over = np.abs(el) > phi
        sl[over] = th - np.sign(el[over]) * phi[over] / k[over]
        out[j] = th
        Tprev = Tj
    return out


def _lugre(rng, seg, T, t, w_target, T0):
    theta0 = float(seg.theta(np.array([T0]))[0])
    Fc = 0.5 * w_target * seg.K1 * float(rng.uniform(0.9, 1.2))
    Fs = Fc * float(rng.uniform(1.1, 1.5))
    sigma0 = seg.K1 * float(rng.uniform(1.0, 3.0))
    dt = float(t[1] - t[0])
    vtyp = 4 * theta0 / (t[-1] / 2.0)
    vs = vtyp * float(rng.uniform(0.3, 1.0))
    sigma2 = 0.08 * Fc / vtyp * float(rng.uniform(0.2, 1.0))
    sigma1 = 0.05 * Fc / vtyp * float(rng.uniform(0.2, 1.0))
    th, z = 0.0, 0.0
    out = np.empty(len(T))
    out[0] = 0.0
    for j in range(1, len(T)):
        Tj = T[j]

        def state(x):
            v = (x - th) / dt
            g = Fc + (Fs - Fc) * math.exp(-(v / vs) ** 2)
            zn = (z + v * dt) / (1.0 + sigma0 * abs(v) * dt / g)
            return v, zn

        def f(x):
            v, zn = state(x)
            return seg.torque(x) + sigma0 * zn + sigma1 * (zn - z) / dt + sigma2 * v - Tj

        f0 = f(th)
        if f0 != 0.0:
            d = abs(f0) / seg.K1 * 1.05 + 1e-12
            if f0 < 0:
                lo, hi = th, th + d
                while f(hi) < 0:
                    hi += d
            else:
                lo, hi = th - d, th
                while f(lo) > 0:
                    lo -= d
            x = brentq(f, lo, hi, xtol=1e-16, rtol=1e-13)
        else:
            x = th
        _, z = state(x)
        th = x
        out[j] = th
    return out


def _masing(T, h):
    T = [float(v) for v in T]
    H = np.empty(len(T))
    stack = []
    Tmax = 0.0
    prev = T[0]
    Hc = h(T[0])
    H[0] = Hc
    direction = 0
    for j in range(1, len(T)):
        Tj = T[j]
        d = (Tj > prev) - (Tj < prev)
        if d == 0:
            H[j] = Hc
            continue
        if direction != 0 and d != direction:
            stack.append((prev, Hc))
        direction = d
        if d * Tj > 0 and abs(Tj) >= Tmax:
            stack.clear()
            Tmax = abs(Tj)
            Hc = h(Tj)
        else:
            while len(stack) >= 2 and ((d > 0 and Tj >= stack[-2][0]) or (d < 0 and Tj <= stack[-2][0])):
                stack.pop()
                stack.pop()
            if stack:
                Tr, Hr = stack[-1]
                Hc = Hr + 2.0 * h((Tj - Tr) / 2.0)
            else:
                Hc = h(Tj)
        H[j] = Hc
        prev = Tj
    return H


def _width_at_zero(T, y, n_q):
    # protocol indices: T = +T0 at n_q, 5 n_q; -T0 at 3 n_q, 7 n_q; zero crossings of the
    # second cycle: ascending at 4 n_q, descending at 6 n_q
    i_desc = 6 * n_q
    i_asc = 4 * n_q
    return float(y[i_desc] - y[i_asc])


def _hysteresis(form, rng, seg, T, t, T0, w_target, n_q):
    base = seg.theta(T)
    if form == "iwan-jenkins":
        return _iwan(rng, seg, T, w_target, T0) - base
    if form == "lugre":
        return _lugre(rng, seg, T, t, w_target, T0) - base
    if form == "masing-ro":
        r = float(rng.uniform(2.0, 3.5))
        theta0 = float(seg.theta(np.array([T0]))[0])

        def h(x):
            return theta0 * math.copysign(abs(x / T0) ** r, x)
        H = np.array(_masing(T, h))
        hv = theta0 * np.sign(T) * np.abs(T / T0) ** r
        e = H - hv
    elif form == "gpi-play":
        beta = float(rng.uniform(0.5, 2.0))
        u = T / T0
        gam = np.sinh(beta * u) / np.sinh(beta)
        N = 25
        R = float(rng.uniform(0.6, 1.0))
        r = R * np.arange(1, N + 1) / N
        eps = float(rng.uniform(0.2, 0.9)) * r[0]
        g_up = gam + eps * u * u
        g_dn = gam - eps * u * u
        m_ = float(rng.uniform(1.0, 2.0))
        lam = float(rng.uniform(1.0, 4.0)) / R
        p = r ** m_ * np.exp(-lam * r)
        w = np.zeros(N)
        acc = np.empty(len(T))
        for j in range(len(T)):
            w = np.maximum(g_up[j] - r, np.minimum(g_dn[j] + r, w))
            acc[j] = float(np.dot(p, w - gam[j]))
        e = acc
    else:
        raise ValueError(form)
    wid = _width_at_zero(T, e, n_q)
    return e * (w_target / wid)


def _backlash(form, rng, m, T, T0):
    B = m["backlash"] * float(rng.uniform(1.5, 5.0))
    s = np.sign(T)
    a = np.abs(T)
    if form == "hertz-asym":
        frac = float(rng.uniform(0.3, 0.7))
        bp, bm = B * frac, B * (1 - frac)
        rho = float(rng.uniform(0.3, 0.7))
        Te = T0 * float(rng.uniform(0.03, 0.1))
        shape = rho + (1 - rho) * np.minimum(1.0, a / Te) ** (2.0 / 3.0)
        return np.where(T > 0, bp * shape, np.where(T < 0, -bm * shape, 0.0))
    if form == "preloaded-play":
        Tp = T0 * float(rng.uniform(0.05, 0.15))
        return s * (B / 2) * np.minimum(1.0, a / Tp)
    if form == "keyed-coupling-play":
        return s * (B / 2)
    raise ValueError(form)


def _housing(form, rng, m, seg, T, T0):
    chi = float(rng.uniform(0.1, 0.5))
    c1 = chi / seg.K1
    if form == "shaft-linear":
        return c1 * T
    if form == "bolted-bilinear":
        c2 = c1 * float(rng.uniform(1.4, 2.0))
        To = T0 * float(rng.uniform(0.3, 0.6))
        return c1 * T + (c2 - c1) * np.sign(T) * np.maximum(0.0, np.abs(T) - To)
    raise ValueError(form)


def _torsion_case(rng, m, category, effects, form):
    s = float(rng.uniform(0.9, 1.1))
    T0 = m["rated"] * float(rng.uniform(0.95, 1.2))
    n_q = int(rng.integers(60, 111))
    tq = float(rng.uniform(8.0, 25.0))
    if form == "soft-gear-below-T1":
        T0 = m["T1"] * float(rng.uniform(0.6, 0.95))
    T = _torque_protocol(T0, n_q)
    t = np.arange(len(T)) * (tq / n_q)
    seg = Seg3(m, s)
    base = seg.theta(T)
    x_cols = {"torque_Nm": T.copy(), "time_s": t}
    nuis = {"stiffness_scale": s}
    w_h = m["hyst"] * float(rng.uniform(0.6, 1.5))
    common = dict(kind="torsion", category=category, model=m, meas_name="twist_rad")
    spec = _noise_spec(rng)
    th_rms = _rms(base)

    if category == "clean":
        kind_noise, outl = {"3seg+white": ("white", False), "3seg+ar1+outliers": ("ar1", True),
                            "pchip+student-t": ("student-t", False)}[form]
        spec = _noise_spec(rng, kind_noise, outl)
        target = th_rms * float(rng.uniform(0.003, 0.012))
        y = base
        if form.startswith("pchip"):
            yp, wmax = _pchip_baseline(rng, seg, T)
            dev = _rms(yp - base)
            if dev > 0.5 * target:
                yp = base + (yp - base) * (0.5 * target / dev)
            y = yp
            nuis["corner_rounding"] = wmax
        return _finish(rng, **common, effects_gear=(), effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=y, effect_arrays=[], nuisance=nuis, spec=spec, target_noise_si=target)

    if category in ("single", "pair"):
        forms = dict(zip(effects, form.split("+")))
        parts = {}
        for eff in effects:
            if eff == "hysteresis":
                parts[eff] = _hysteresis(forms[eff], rng, seg, T, t, T0, w_h, n_q)
            elif eff == "backlash":
                parts[eff] = _backlash(forms[eff], rng, m, T, T0)
            else:
                parts[eff] = _housing(forms[eff], rng, m, seg, T, T0)
        if len(effects) == 2:
            a, b = effects  # b is additive (backlash or housing) -> scalable exactly
            fct = _balance(_rms(parts[a]), _rms(parts[b]))
            parts[b] = parts[b] * fct
        y = base + sum(parts.values())
        return _finish(rng, **common, effects_gear=effects, effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=y, effect_arrays=[parts[e] for e in effects], nuisance=nuis, spec=spec)

    if category == "decoy_equivalent":
        if form == "soft-gear-below-T1":
            s_soft = float(rng.uniform(0.55, 0.75))
            y = Seg3(m, s_soft).theta(T)
            eff = y - Seg3(m, 1.0).theta(T)
            nuis = {"stiffness_scale": s_soft}
            return _finish(rng, **common, effects_gear=(), effects_meas=(), formulation=form, x_cols=x_cols,
                           y_true_si=y, effect_arrays=[eff], nuisance=nuis, spec=spec,
                           equivalent=("housing_compliance",))
        if form == "rig-coulomb-friction":
            Tf = 0.5 * w_h * seg.K1
            y = np.empty(len(T))
            th = 0.0
            lo_a = seg.theta(T - Tf)
            hi_a = seg.theta(T + Tf)
            for j in range(len(T)):
                th = min(max(th, lo_a[j]), hi_a[j])
                y[j] = th
            return _finish(rng, **common, effects_gear=(), effects_meas=(), formulation=form, x_cols=x_cols,
                           y_true_si=y, effect_arrays=[y - base], nuisance=nuis, spec=spec,
                           equivalent=("hysteresis",))
        if form == "keyed-coupling-play":
            e = _backlash(form, rng, m, T, T0)
            return _finish(rng, **common, effects_gear=(), effects_meas=(), formulation=form, x_cols=x_cols,
                           y_true_si=base + e, effect_arrays=[e], nuisance=nuis, spec=spec,
                           equivalent=("backlash",))
        raise ValueError(form)

    # decoy_separable
    if form == "stiffness-scale":
        s2 = float(rng.choice([-1, 1]) * rng.uniform(0.04, 0.10) + 1.0)
        y = Seg3(m, s2).theta(T)
        eff = y - Seg3(m, 1.0).theta(T)
        return _finish(rng, **common, effects_gear=(), effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=y, effect_arrays=[eff], nuisance={"stiffness_scale": s2}, spec=spec)
    if form == "torque-sensor-gain":
        g = float(1.0 + rng.choice([-1, 1]) * rng.uniform(0.02, 0.08))
        Tm = g * T
        x_cols["torque_Nm"] = Tm
        eff = base - seg.theta(Tm)
        return _finish(rng, **common, effects_gear=(), effects_meas=("sensor_gain",), formulation=form,
                       x_cols=x_cols, y_true_si=base, effect_arrays=[eff], nuisance=dict(nuis, torque_gain=g),
                       spec=spec)
    if form in ("angle-offset-constant", "angle-offset-step", "thermal-drift-exp"):
        target = th_rms * float(rng.uniform(0.003, 0.012))
        k = float(rng.uniform(4.15, 11.85))
        if form == "angle-offset-constant":
            shape = np.ones(len(T))
        elif form == "angle-offset-step":
            cand = np.nonzero((np.abs(T) > 0.3 * T0) & (np.arange(len(T)) > 0.25 * len(T))
                              & (np.arange(len(T)) < 0.75 * len(T)))[0]
            i0 = int(rng.choice(cand))
            shape = (np.arange(len(T)) >= i0).astype(float)
        else:
            tau = t[-1] * float(rng.uniform(0.4, 2.0))
            shape = 1.0 - np.exp(-t / tau)
        eff = float(rng.choice([-1, 1])) * k * target * shape / _rms(shape)
        meff = ("thermal_drift",) if form.startswith("thermal") else ("angle_offset",)
        return _finish(rng, **common, effects_gear=(), effects_meas=meff, formulation=form, x_cols=x_cols,
                       y_true_si=base + eff, effect_arrays=[eff], nuisance=nuis, spec=spec)
    if form == "wrong-units-deg":
        target = th_rms * float(rng.uniform(0.003, 0.012))
        return _finish(rng, **common, effects_gear=(), effects_meas=("wrong_units",), formulation=form,
                       x_cols=x_cols, y_true_si=base, effect_arrays=[base * DEG - base], nuisance=nuis,
                       spec=spec, target_noise_si=target, factor=DEG, wrong_units=True)
    if form == "wrong-units-kNm":
        target = th_rms * float(rng.uniform(0.003, 0.012))
        x_cols["torque_Nm"] = T * 1e-3
        eff = base - seg.theta(T * 1e-3)
        return _finish(rng, **common, effects_gear=(), effects_meas=("wrong_units",), formulation=form,
                       x_cols=x_cols, y_true_si=base, effect_arrays=[eff], nuisance=nuis, spec=spec,
                       target_noise_si=target, wrong_units=True)
    raise ValueError(form)


# ============================================================================= transmission
def _te_rw(rng, phi, k, amp, corr_revs):
    revs = phi / (2 * math.pi)
    wa = _slow_walk(rng, revs, corr_revs)
    wp = _slow_walk(rng, revs, corr_revs)
    sa = float(rng.uniform(0.1, 0.3))
    sp = float(rng.uniform(0.1, 0.4))
    psi = float(rng.uniform(0, 2 * math.pi))
    mod = np.exp(sa * wa)
    mod /= mod.mean()
    arg = k * phi + psi + sp * wp
    return amp * mod * np.sin(arg), amp * mod * k * np.cos(arg)  # value, d/dphi (slow terms neglected)


def _te_cam(rng, phi, k, amp):
    psi = float(rng.uniform(0, 2 * math.pi))
    if k == 1:
        e = float(rng.uniform(0.02, 0.06))
        x = phi + psi
        return amp * np.arctan2(e * np.sin(x), 1 + e * np.cos(x)) / e
    b = float(rng.uniform(0.03, 0.08))
    psi2 = float(rng.uniform(0, 2 * math.pi))
    return amp * np.sin(2 * phi + psi) / (1 + b * np.cos(2 * phi + psi2))


def _transmission_case(rng, m, category, effects, form):
    R = m["ratio"]
    n_rev = float(rng.uniform(8, 24))
    spr = int(rng.choice([48, 64, 72, 90]))
    if form == "output-encoder-eccentricity":
        n_rev = R * float(rng.uniform(0.5, 1.2))
        spr = int(rng.choice([36, 40, 48]))
    n = int(n_rev * spr) + 1
    phi = np.arange(n) * (2 * math.pi / spr)
    rpm = float(rng.uniform(5.0, 60.0))
    t = phi / (2 * math.pi * rpm / 60.0)
    off = float(rng.uniform(0, 2 * math.pi))
    base = phi / R + off
    x_cols = {"input_angle_rad": phi.copy(), "time_s": t}
    nuis = {"offset_rad": off}
    common = dict(kind="transmission", category=category, model=m, meas_name="output_angle_rad")
    spec = _noise_spec(rng)
    acc = m["accuracy"]

    if category == "clean":
        kind_noise, outl = {"linear+white": ("white", False), "linear+ar1+outliers": ("ar1", True),
                            "linear+student-t": ("student-t", False)}[form]
        spec = _noise_spec(rng, kind_noise, outl)
        target = acc * float(rng.uniform(0.01, 0.05))
        return _finish(rng, **common, effects_gear=(), effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=base, effect_arrays=[], nuisance=nuis, spec=spec, target_noise_si=target)

    if category in ("single", "pair"):
        parts = {}
        for eff in effects:
            k = 1 if eff == "te_1x" else 2
            amp = acc * float(rng.uniform(0.1, 0.4))
            if form == "rw-modulated":
                parts[eff] = _te_rw(rng, phi, k, amp, float(rng.uniform(2.0, 6.0)))[0]
            else:
                parts[eff] = _te_cam(rng, phi, k, amp)
        if len(effects) == 2:
            parts["te_2x"] *= _balance(_rms(parts["te_1x"]), _rms(parts["te_2x"]))
        hidden = None
        if form == "rw-modulated":
            kh = int(rng.choice([3, 4]))
            hidden = np.sin(kh * phi + float(rng.uniform(0, 2 * math.pi)))
        return _finish(rng, **common, effects_gear=effects, effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=base + sum(parts.values()), effect_arrays=[parts[e] for e in effects],
                       nuisance=nuis, spec=spec, hidden_shape=hidden, hidden_frac=float(rng.uniform(0.1, 0.3)))

    target = acc * float(rng.uniform(0.01, 0.05))
    kk = float(rng.uniform(4.15, 11.85))
    sign = float(rng.choice([-1, 1]))
    if form == "input-encoder-eccentricity":
        psi = float(rng.uniform(0, 2 * math.pi))
        e_out = kk * target * math.sqrt(2.0)  # amplitude at the output
        e_in = e_out * R
        phi_m = phi + e_in * np.sin(phi + psi)
        x_cols["input_angle_rad"] = phi_m
        eff = base - (phi_m / R + off)
        return _finish(rng, **common, effects_gear=(), effects_meas=("encoder_eccentricity",), formulation=form,
                       x_cols=x_cols, y_true_si=base, effect_arrays=[eff], nuisance=nuis, spec=spec,
                       target_noise_si=target, equivalent=("te_1x",))
    if form == "wrong-units-deg":
        return _finish(rng, **common, effects_gear=(), effects_meas=("wrong_units",), formulation=form,
                       x_cols=x_cols, y_true_si=base, effect_arrays=[base * DEG - base], nuisance=nuis,
                       spec=spec, target_noise_si=target, factor=DEG, wrong_units=True)
    if form == "output-encoder-eccentricity":
        shape = np.sin(base - off + float(rng.uniform(0, 2 * math.pi)))
        meff = ("encoder_eccentricity",)
    elif form == "angle-offset-step":
        i0 = int(rng.integers(int(0.25 * n), int(0.75 * n)))
        shape = (np.arange(n) >= i0).astype(float)
        meff = ("angle_offset",)
    elif form == "thermal-drift-exp":
        tau = t[-1] * float(rng.uniform(0.4, 2.0))
        shape = 1 - np.exp(-t / tau)
        meff = ("thermal_drift",)
    elif form == "angle-gain":
        shape = phi / R
        meff = ("sensor_gain",)
    else:
        raise ValueError(form)
    eff = sign * kk * target * shape / _rms(shape)
    if form == "angle-gain":
        nuis = dict(nuis, angle_gain=float(1 + sign * kk * target / _rms(shape)))
    return _finish(rng, **common, effects_gear=(), effects_meas=meff, formulation=form, x_cols=x_cols,
                   y_true_si=base + eff, effect_arrays=[eff], nuisance=nuis, spec=spec, target_noise_si=target)


# ============================================================================= efficiency
def _walther(Tc, nu40, nu100):
    T1, T2 = math.log10(40 + 273.15), math.log10(100 + 273.15)
    y1, y2 = math.log10(math.log10(nu40 + 0.7)), math.log10(math.log10(nu100 + 0.7))
    B = (y1 - y2) / (T2 - T1)
    A = y1 + B * T1
    return 10 ** (10 ** (A - B * np.log10(np.asarray(Tc) + 273.15))) - 0.7


def _vogel(Tc, nu40, nu100, C=95.0):
    b = math.log(nu40 / nu100) / (1 / (40 + C) - 1 / (100 + C))
    a = nu40 / math.exp(b / (40 + C))
    return a * np.exp(b / (np.asarray(Tc) + C))


def _eff_case(rng, m, category, effects, form):
    R, Tr = m["ratio"], m["rated"]
    sp_all = [s for s in (500, 1000, 1500, 2000, 2500, 3000, 3500) if s <= m["avg_speed"]]
    ns = int(rng.integers(3, min(5, len(sp_all)) + 1))
    speeds = np.sort(rng.choice(sp_all, ns, replace=False)).astype(float)
    alphas = np.array([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0])
    temps = np.sort(rng.choice([0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0], int(rng.integers(3, 6)), replace=False))
    TT, NN, AA = np.meshgrid(temps, speeds, alphas, indexing="ij")
    Tc, n, alpha = TT.ravel(), NN.ravel(), AA.ravel()
    load = alpha * Tr
    L = float(rng.uniform(62.0, 86.0))
    T_ref = float(np.median(temps))
    n_ref = float(np.median(speeds))
    w_in = 2 * math.pi * n / 60.0
    w_ref = 2 * math.pi * n_ref / 60.0
    nu40 = float(rng.uniform(30, 100))
    nu100 = nu40 * float(rng.uniform(0.11, 0.16))
    base = np.full(len(Tc), L)
    t = np.arange(len(Tc)) * float(rng.uniform(30.0, 90.0))
    x_cols = {"input_speed_rpm": n, "load_torque_Nm": load.copy(), "temperature_C": Tc, "time_s": t}
    nuis = {"efficiency_level_pct": L}
    common = dict(kind="efficiency", category=category, model=m, meas_name="efficiency_pct", angle=False,
                  decimals=2)
    spec = _noise_spec(rng, quant=False)

    def drag_eta(Td_arr, Td_ref, scale_T=None):
        """eta (pct) = 1/(1/eta_m + R Td / T), eta_m such that eta(rated, n_ref) = L."""
        inv_m = 100.0 / L - R * Td_ref / Tr
        return 100.0 / (inv_m + R * Td_arr / load)

    def lratio_walther(l_ref, mexp):
        nu = _walther(Tc, nu40, nu100)
        nur = float(_walther(T_ref, nu40, nu100))
        return l_ref * (nu / nur) ** mexp

    if category == "clean":
        kind_noise, outl = {"constant+white": ("white", False), "constant+ar1+outliers": ("ar1", True),
                            "constant+student-t": ("student-t", False)}[form]
        spec = _noise_spec(rng, kind_noise, outl, quant=False)
        target = float(rng.uniform(0.2, 0.8))
        return _finish(rng, **common, effects_gear=(), effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=base, effect_arrays=[], nuisance=nuis, spec=spec, target_noise_si=target)

    if category == "single" and effects == ("low_load_efficiency",):
        if form == "coulomb-viscous-drag":
            beta = float(rng.uniform(0.04, 0.18))
            Td_ref = beta * Tr / R
            fv = float(rng.uniform(0.2, 0.7))
            Tcoul, cv = (1 - fv) * Td_ref, fv * Td_ref / w_ref
            y = drag_eta(Tcoul + cv * w_in, Td_ref)
        else:  # catalog-running-torque
            sr = float(rng.uniform(0.7, 1.4))
            sr = min(sr, 0.25 * Tr / (R * m["running_torque"]))  # keep R T_d / T_rated <= 0.25
            x = float(rng.uniform(0.2, 0.6))
            Td = m["running_torque"] * sr * (n / 2000.0) ** x
            Td_ref = m["running_torque"] * sr * (n_ref / 2000.0) ** x
            y = drag_eta(Td, Td_ref)
        return _finish(rng, **common, effects_gear=effects, effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=y, effect_arrays=[y - base], nuisance=nuis, spec=spec)

    if category == "single":  # temperature_dependence
        l_ref = float(rng.uniform(0.15, 0.4))
        mexp = float(rng.uniform(0.15, 0.4))
        if form == "walther-ehl":
            lr = lratio_walther(l_ref, mexp)
        else:
            nu = _vogel(Tc, nu40, nu100)
            nur = float(_vogel(T_ref, nu40, nu100))
            p = float(rng.uniform(0.3, 1.0))
            lr = l_ref * (1 + ((nu / nur) ** mexp - 1) * (n / n_ref) ** p)
        y = L * (1 + l_ref) / (1 + lr)
        return _finish(rng, **common, effects_gear=effects, effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=y, effect_arrays=[y - base], nuisance=nuis, spec=spec)

    if category == "pair":
        beta = float(rng.uniform(0.04, 0.18))
        l_ref = float(rng.uniform(0.15, 0.35))
        mexp = float(rng.uniform(0.15, 0.35))
        for _ in range(20):
            if form == "drag-vogel-coupled":
                nu = _vogel(Tc, nu40, nu100)
                nur = float(_vogel(T_ref, nu40, nu100))
                md = float(0.5)
                Td_ref = beta * Tr / R
                fv = 0.5
                Tcoul, cv = (1 - fv) * Td_ref, fv * Td_ref / w_ref

                def model_eta(rel_nu):
                    Td = Tcoul + cv * rel_nu ** md * w_in
                    lr = l_ref * rel_nu ** mexp
                    inv_m = (100.0 / L - R * Td_ref / Tr) * (1 + lr) / (1 + l_ref)
                    return 100.0 / (inv_m + R * Td / load)
                y = model_eta(nu / nur)
                y_tref = model_eta(np.ones_like(nu))
            else:  # coulomb-x-walther
                Ke = alpha * (1 + beta) / (alpha + beta)
                F = (1 + l_ref) / (1 + lratio_walther(l_ref, mexp))
                y = L * Ke * F
                y_tref = L * Ke
            e_low = y_tref - base
            e_temp = y - y_tref
            r1, r2 = _rms(e_low), _rms(e_temp)
            if r1 > 2.4 * r2:
                beta *= max(0.3, 1.8 * r2 / r1)
            elif r2 > 2.4 * r1:
                mexp *= max(0.3, 1.8 * r1 / r2)
            else:
                break
        else:
            raise RuntimeError("efficiency pair could not be balanced")
        return _finish(rng, **common, effects_gear=effects, effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=y, effect_arrays=[e_low, e_temp], nuisance=nuis, spec=spec)

    if category == "decoy_equivalent":
        if form == "temp-dependent-torque-gain":
            target = float(rng.uniform(0.2, 0.8))
            kk = float(rng.uniform(4.15, 11.85))
            dT = Tc - T_ref
            kappa = float(rng.choice([-1, 1])) * kk * target / (L * _rms(dT))
            g = 1 + kappa * dT
            x_cols["load_torque_Nm"] = load * g
            y = L * g
            return _finish(rng, **common, effects_gear=(), effects_meas=("sensor_gain",), formulation=form,
                           x_cols=x_cols, y_true_si=y, effect_arrays=[y - base],
                           nuisance=dict(nuis, torque_gain_per_K=kappa), spec=spec, target_noise_si=target,
                           equivalent=("temperature_dependence",))
        if form == "rig-input-drag":
            beta = float(rng.uniform(0.03, 0.12))
            Tb = beta * Tr / R
            y = 100.0 / (100.0 / L + R * Tb / load)
            return _finish(rng, **common, effects_gear=(), effects_meas=(), formulation=form, x_cols=x_cols,
                           y_true_si=y, effect_arrays=[y - base], nuisance=nuis, spec=spec,
                           equivalent=("low_load_efficiency",))
        raise ValueError(form)

    # decoy_separable
    if form == "wrong-units-fraction":
        target = float(rng.uniform(0.2, 0.8))
        return _finish(rng, **dict(common, decimals=4), effects_gear=(), effects_meas=("wrong_units",),
                       formulation=form, x_cols=x_cols, y_true_si=base, effect_arrays=[base / 100.0 - base],
                       nuisance=nuis, spec=spec, target_noise_si=target, factor=0.01, wrong_units=True)
    if form == "torque-sensor-gain":
        g = float(1.0 + rng.choice([-1, 1]) * rng.uniform(0.02, 0.08))
        x_cols["load_torque_Nm"] = load * g
        y = base * g
        return _finish(rng, **common, effects_gear=(), effects_meas=("sensor_gain",), formulation=form,
                       x_cols=x_cols, y_true_si=y, effect_arrays=[y - base], nuisance=dict(nuis, torque_gain=g),
                       spec=spec)
    if form == "thermal-drift-shuffled":
        perm = rng.permutation(len(Tc))
        for key in ("input_speed_rpm", "load_torque_Nm", "temperature_C"):
            x_cols[key] = x_cols[key][perm]
        target = float(rng.uniform(0.2, 0.8))
        kk = float(rng.uniform(4.15, 11.85))
        tau = t[-1] * float(rng.uniform(0.4, 2.0))
        shape = 1 - np.exp(-t / tau)
        eff = float(rng.choice([-1, 1])) * kk * target * shape / _rms(shape)
        return _finish(rng, **common, effects_gear=(), effects_meas=("thermal_drift",), formulation=form,
                       x_cols=x_cols, y_true_si=base + eff, effect_arrays=[eff], nuisance=nuis, spec=spec,
                       target_noise_si=target)
    raise ValueError(form)


# ============================================================================= vibration
def _simulate(seg, J, c, relative, tgrid_half, e_half, ed_half):
    """RK4 on the half-step grid (values at t, t+dt/2, t+dt); returns x at full steps."""
    K1, K2, K3 = seg.K1, seg.K2, seg.K3
    T1, T2 = seg.T1, seg.T2
    th1, th2 = seg.th1, seg.th2
    E = e_half.tolist()
    ED = ed_half.tolist()
    N = (len(E) - 1) // 2
    dt = float(tgrid_half[2] - tgrid_half[0])
    invJ = 1.0 / J
    rel = 1.0 if relative else 0.0

    def acc(x, v, e, ed):
        d = x - e
        a = d if d >= 0 else -d
        if a <= th1:
            f = K1 * a
        elif a <= th2:
            f = T1 + K2 * (a - th1)
        else:
            f = T2 + K3 * (a - th2)
        if d < 0:
            f = -f
        return -(f + c * (v - rel * ed)) * invJ

    x = E[0]
    v = ED[0]
    out = [x]
    h2 = dt / 2
    for i in range(N):
        e0, e1, e2 = E[2 * i], E[2 * i + 1], E[2 * i + 2]
        d0, d1, d2 = ED[2 * i], ED[2 * i + 1], ED[2 * i + 2]
        k1x, k1v = v, acc(x, v, e0, d0)
        k2x, k2v = v + h2 * k1v, acc(x + h2 * k1x, v + h2 * k1v, e1, d1)
        k3x, k3v = v + h2 * k2v, acc(x + h2 * k2x, v + h2 * k2v, e1, d1)
        k4x, k4v = v + dt * k3v, acc(x + dt * k3x, v + dt * k3v, e2, d2)
        x += dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x)
        v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v)
        out.append(x)
    return np.array(out)


def _vib_case(rng, m, category, effects, form):
    s = float(rng.uniform(0.9, 1.1))
    seg = Seg3(m, s)
    R = m["ratio"]
    vmax = min(m["max_speed"], 3000.0)
    has1 = "te_1x" in effects
    has2 = "te_2x" in effects
    # choose natural frequency so the needed crossings lie inside the speed range
    if has1 and has2:
        fn = float(rng.uniform(6.0, min(25.0, vmax / 84.0)))
        n0, n1 = 0.6 * 30 * fn, 1.4 * 60 * fn
    elif has1:
        fn = float(rng.uniform(8.0, min(30.0, vmax / 84.0)))
        n0, n1 = 0.5 * 60 * fn, 1.4 * 60 * fn
    else:
        fn = float(rng.uniform(8.0, 40.0))
        n0, n1 = 0.5 * 30 * fn, 1.6 * 30 * fn
    J = seg.K1 / (2 * math.pi * fn) ** 2
    zeta = float(rng.uniform(0.02, 0.08))
    relative = form != "load-drag-loss"
    c = 2 * zeta * math.sqrt(seg.K1 * J)
    f_exc = 2 * n1 / 60.0
    fs = max(12.0 * f_exc, 25.0 * fn * math.sqrt(seg.K3 / seg.K1))
    D = float(rng.uniform(15.0, 30.0))
    D = min(D, 24000.0 / fs)
    N = int(D * fs)
    dt = D / N
    th = np.arange(2 * N + 1) * (dt / 2)
    u = th / D
    prof = int(rng.integers(3))
    if prof == 0:
        tau = float(rng.uniform(0.5, 1.5))
        p = (1 - np.exp(-u / tau)) / (1 - math.exp(-1 / tau))
    elif prof == 1:
        p = u ** float(rng.uniform(1.3, 2.0))
    else:
        p = u - np.sin(2 * math.pi * u) / (2 * math.pi) * float(rng.uniform(0.5, 0.9))
    rpm_h = n0 + (n1 - n0) * p
    om = 2 * math.pi * rpm_h / 60.0
    phi_h = np.concatenate([[0.0], np.cumsum(0.5 * (om[1:] + om[:-1]) * np.diff(th))])
    t_full = th[::2]
    x_cols = {"time_s": t_full, "input_speed_rpm": rpm_h[::2].copy()}
    nuis = {"stiffness_scale": s, "damping_ratio": zeta}
    common = dict(kind="vibration", category=category, model=m, meas_name="output_vibration_rad")
    spec = _noise_spec(rng)
    acc_ = m["accuracy"]
    zero = np.zeros(N + 1)
    if category == "clean":
        kind_noise, outl = {"zero+white": ("white", False), "zero+ar1+outliers": ("ar1", True),
                            "zero+student-t": ("student-t", False)}[form]
        spec = _noise_spec(rng, kind_noise, outl)
        target = acc_ * float(rng.uniform(0.01, 0.05))
        return _finish(rng, **common, effects_gear=(), effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=zero, effect_arrays=[], nuisance=nuis, spec=spec, target_noise_si=target,
                       load_inertia=J)
    if category in ("single", "pair"):
        total_revs = phi_h[-1] / (2 * math.pi)
        comps = {}
        for eff in effects:
            k = 1 if eff == "te_1x" else 2
            amp = acc_ * float(rng.uniform(0.1, 0.35))
            comps[eff] = list(_te_rw(rng, phi_h, k, amp, max(5.0, total_revs / float(rng.uniform(4, 10)))))
            comps[eff][1] = comps[eff][1] * om
        def run(which):
            e = sum(comps[w][0] for w in which)
            ed = sum(comps[w][1] for w in which)
            return _simulate(seg, J, c, relative, th, e, ed)
        if len(effects) == 1:
            x = run(effects)
            arrays = [x]
        else:
            for _ in range(8):
                x1, x2 = run(("te_1x",)), run(("te_2x",))
                r1, r2 = _rms(x1), _rms(x2)
                if r1 > 2.4 * r2:
                    f = 1.8 * r2 / r1
                    comps["te_1x"] = [a * f for a in comps["te_1x"]]
                elif r2 > 2.4 * r1:
                    f = 1.8 * r1 / r2
                    comps["te_2x"] = [a * f for a in comps["te_2x"]]
                else:
                    break
            else:
                raise RuntimeError("vibration pair could not be balanced")
            x = run(effects)
            arrays = [x1, x2]
        return _finish(rng, **common, effects_gear=effects, effects_meas=(), formulation=form, x_cols=x_cols,
                       y_true_si=x, effect_arrays=arrays, nuisance=nuis, spec=spec, load_inertia=J)
    # decoy_separable
    target = acc_ * float(rng.uniform(0.01, 0.05))
    kk = float(rng.uniform(4.15, 11.85))
    if form == "thermal-drift-exp":
        tau = D * float(rng.uniform(0.4, 2.0))
        shape = 1 - np.exp(-t_full / tau)
        meff = ("thermal_drift",)
    elif form == "angle-offset-step":
        i0 = int(rng.integers(int(0.25 * N), int(0.75 * N)))
        shape = (np.arange(N + 1) >= i0).astype(float)
        meff = ("angle_offset",)
    elif form == "output-encoder-eccentricity":
        shape = np.sin(phi_h[::2] / R + float(rng.uniform(0, 2 * math.pi)))
        meff = ("encoder_eccentricity",)
    else:
        raise ValueError(form)
    eff = float(rng.choice([-1, 1])) * kk * target * shape / _rms(shape)
    return _finish(rng, **common, effects_gear=(), effects_meas=meff, formulation=form, x_cols=x_cols,
                   y_true_si=eff, effect_arrays=[eff], nuisance=nuis, spec=spec, target_noise_si=target,
                   load_inertia=J)


# ============================================================================= cells
H, B, C = "hysteresis", "backlash", "housing_compliance"
CELLS = [
    # torsion
    ("torsion", "clean", (), "3seg+white"),
    ("torsion", "clean", (), "3seg+ar1+outliers"),
    ("torsion", "clean", (), "pchip+student-t"),
    ("torsion", "single", (H,), "iwan-jenkins"),
    ("torsion", "single", (H,), "masing-ro"),
    ("torsion", "single", (H,), "gpi-play"),
    ("torsion", "single", (H,), "lugre"),
    ("torsion", "single", (B,), "hertz-asym"),
    ("torsion", "single", (B,), "preloaded-play"),
    ("torsion", "single", (C,), "shaft-linear"),
    ("torsion", "single", (C,), "bolted-bilinear"),
    ("torsion", "pair", (H, B), "iwan-jenkins+hertz-asym"),
    ("torsion", "pair", (H, B), "masing-ro+preloaded-play"),
    ("torsion", "pair", (H, C), "gpi-play+shaft-linear"),
    ("torsion", "pair", (H, C), "lugre+bolted-bilinear"),
    ("torsion", "pair", (B, C), "hertz-asym+shaft-linear"),
    ("torsion", "pair", (B, C), "preloaded-play+bolted-bilinear"),
    ("torsion", "decoy_separable", (), "torque-sensor-gain"),
    ("torsion", "decoy_separable", (), "angle-offset-constant"),
    ("torsion", "decoy_separable", (), "angle-offset-step"),
    ("torsion", "decoy_separable", (), "thermal-drift-exp"),
    ("torsion", "decoy_separable", (), "wrong-units-deg"),
    ("torsion", "decoy_separable", (), "wrong-units-kNm"),
    ("torsion", "decoy_separable", (), "stiffness-scale"),
    ("torsion", "decoy_equivalent", (), "soft-gear-below-T1"),
    ("torsion", "decoy_equivalent", (), "rig-coulomb-friction"),
    ("torsion", "decoy_equivalent", (), "keyed-coupling-play"),
    # transmission
    ("transmission", "clean", (), "linear+white"),
    ("transmission", "clean", (), "linear+ar1+outliers"),
    ("transmission", "clean", (), "linear+student-t"),
    ("transmission", "single", ("te_1x",), "rw-modulated"),
    ("transmission", "single", ("te_1x",), "cam-geometry"),
    ("transmission", "single", ("te_2x",), "rw-modulated"),
    ("transmission", "single", ("te_2x",), "cam-geometry"),
    ("transmission", "pair", ("te_1x", "te_2x"), "rw-modulated"),
    ("transmission", "pair", ("te_1x", "te_2x"), "cam-geometry"),
    ("transmission", "decoy_separable", (), "output-encoder-eccentricity"),
    ("transmission", "decoy_separable", (), "angle-offset-step"),
    ("transmission", "decoy_separable", (), "thermal-drift-exp"),
    ("transmission", "decoy_separable", (), "angle-gain"),
    ("transmission", "decoy_separable", (), "wrong-units-deg"),
    ("transmission", "decoy_equivalent", (), "input-encoder-eccentricity"),
    # efficiency
    ("efficiency", "clean", (), "constant+white"),
    ("efficiency", "clean", (), "constant+ar1+outliers"),
    ("efficiency", "clean", (), "constant+student-t"),
    ("efficiency", "single", ("low_load_efficiency",), "coulomb-viscous-drag"),
    ("efficiency", "single", ("low_load_efficiency",), "catalog-running-torque"),
    ("efficiency", "single", ("temperature_dependence",), "walther-ehl"),
    ("efficiency", "single", ("temperature_dependence",), "vogel-speed"),
    ("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"), "drag-vogel-coupled"),
    ("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"), "coulomb-x-walther"),
    ("efficiency", "decoy_separable", (), "wrong-units-fraction"),
    ("efficiency", "decoy_separable", (), "torque-sensor-gain"),
    ("efficiency", "decoy_separable", (), "thermal-drift-shuffled"),
    ("efficiency", "decoy_equivalent", (), "temp-dependent-torque-gain"),
    ("efficiency", "decoy_equivalent", (), "rig-input-drag"),
    # vibration
    ("vibration", "clean", (), "zero+white"),
    ("vibration", "clean", (), "zero+ar1+outliers"),
    ("vibration", "clean", (), "zero+student-t"),
    ("vibration", "single", ("te_1x",), "kelvin-voigt-zeta"),
    ("vibration", "single", ("te_1x",), "load-drag-loss"),
    ("vibration", "single", ("te_2x",), "kelvin-voigt-zeta"),
    ("vibration", "single", ("te_2x",), "load-drag-loss"),
    ("vibration", "pair", ("te_1x", "te_2x"), "kelvin-voigt-zeta"),
    ("vibration", "pair", ("te_1x", "te_2x"), "load-drag-loss"),
    ("vibration", "decoy_separable", (), "thermal-drift-exp"),
    ("vibration", "decoy_separable", (), "angle-offset-step"),
    ("vibration", "decoy_separable", (), "output-encoder-eccentricity"),
]

_BUILDERS = {"torsion": _torsion_case, "transmission": _transmission_case, "efficiency": _eff_case,
             "vibration": _vib_case}


def _generate(seed, catalog_dir, per_cell=4):
    """Returns a list of (TruthCase, truth) where truth holds the noise-free measured column."""
    rng = np.random.default_rng(seed)
    models = _load_models(catalog_dir)
    out = []
    for kind, category, effects, form in CELLS:
        for i in range(per_cell):
            m = models[int(rng.integers(len(models)))]
            case, truth = _BUILDERS[kind](rng, m, category, effects, form)
            eff = "+".join(effects) if effects else "none"
            case.name = f"{SUITE}-{kind}-{category}-{eff}-{form}-{i:03d}"
            out.append((case, truth))
    return out


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    return [c for c, _ in _generate(seed, catalog_dir, per_cell)]
