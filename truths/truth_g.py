"""Truth suite "g" for `hdcad reconcile`: synthetic strain-wave-gear test data with known hidden effects.

Written from the physics literature, the contract (truths/CONTRACT.md), the catalog tables and the
seeds only.  numpy + scipy only; nothing from hdcad is imported.  See NOTES_g.md for every cell,
formulation, reference and judgement call.

    generate_cases(seed, catalog_dir, per_cell=4) -> list[TruthCase]

Run `python truth_g.py [catalog_dir]` for the self-check (determinism, names, snr, noise, CSV
round trip, cell table).
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy.optimize import brentq
from scipy.signal import cont2discrete, lfilter
from scipy.special import erf, erfc

SUITE = "g"

KMIN, KMAX = 4.0, 12.0          # contract: effect RMS = k * noise_rms, k in [4, 12]
DEG = 180.0 / math.pi           # wrong_units: degrees for radians


# ----------------------------------------------------------------------------------------------
# the contract's dataclass
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
        """Header row + rows, repr-precision floats."""
        names = list(self.columns.keys())
        cols = [np.asarray(self.columns[n], dtype=float).tolist() for n in names]
        with open(path, "w", encoding="utf-8", newline="") as fh:
            fh.write(",".join(names) + "\n")
            fh.write("\n".join(",".join(repr(v) for v in row) for row in zip(*cols)))
            fh.write("\n")


# ----------------------------------------------------------------------------------------------
# small helpers
# ----------------------------------------------------------------------------------------------
def _rms(x) -> float:
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def _rms_eff(x, demean: bool) -> float:
    x = np.asarray(x, dtype=float)
    return _rms(x - x.mean()) if demean else _rms(x)


def _u(rng, a, b) -> float:
    return float(rng.uniform(a, b))


def _choice(rng, seq):
    return seq[int(rng.integers(len(seq)))]


def _slug(s: str) -> str:
    out = "".join(c.lower() if c.isalnum() else "-" for c in s)
    while "--" in out:
        out = out.replace("--", "-")
    return out.strip("-")


# ----------------------------------------------------------------------------------------------
# catalog
# ----------------------------------------------------------------------------------------------
def _read(path: Path) -> list[dict]:
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _f(x):
    x = (x or "").strip()
    return float(x) if x else None


@dataclass
class Model:
    code: str
    family: str                 # "GH" | "component" | "FD"
    series: str
    size: int
    ratio: int
    T1: float | None = None
    T2: float | None = None
    K1: float | None = None
    K2: float | None = None
    K3: float | None = None
    rated: float | None = None
    peak: float | None = None
    max_speed: float | None = None
    hysteresis: float | None = None
    backlash: float | None = None
    eta_R: float | None = None
    speeds: tuple = ()          # efficiency-grid input speeds usable with one rated torque
    lubrication: str = "grease"
    note: dict = field(default_factory=dict)


class Catalog:
    def __init__(self, catalog_dir):
        d = Path(catalog_dir)
        stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
        ratings = _read(d / "gh_ratings_050-1_058-1.csv")
        hyst = _read(d / "gh_hysteresis_052_060.csv")
        back = _read(d / "gh_backlash_052-2_060-2.csv")
        comp = _read(d / "component_examples.csv")
        fd_ratio = _read(d / "fd_ratios_304-1.csv")
        fd_rt = _read(d / "fd_rated_torque_310-1.csv")
        fd_speed = _read(d / "fd_max_input_speed_313-3_313-4.csv")

        def in_range(r, ratio):
            lo = _f(r["ratio_min"])
            hi = _f(r["ratio_max"])
            return (lo is None or ratio >= lo) and (hi is None or ratio <= hi)

        self.gh: list[Model] = []
        for r in ratings:
            series, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
            srow = [s for s in stiff if s["series"] == series and int(s["size"]) == size
                    and in_range(s, ratio)]
            if not srow:
                continue
            s = srow[0]
            h = [x for x in hyst if x["series"] == series and in_range(x, ratio)]
            b = [x for x in back if x["series"] == series and int(x["size"]) == size
                 and int(x["ratio"]) == ratio]
            self.gh.append(Model(
                code=f"{series.split('-')[0]}-{size}-{ratio}-GH", family="GH", series=series,
                size=size, ratio=ratio, T1=_f(s["T1_Nm"]), T2=_f(s["T2_Nm"]),
                K1=_f(s["K1_Nm_per_rad"]), K2=_f(s["K2_Nm_per_rad"]), K3=_f(s["K3_Nm_per_rad"]),
                rated=_f(r["rated_torque_2000_Nm"]), peak=_f(r["peak_torque_Nm"]),
                max_speed=_f(r["max_input_speed_rpm"]),
                hysteresis=_f(h[0]["hysteresis_rad"]) if h else None,
                backlash=_f(b[0]["backlash_rad"]) if b else None,
                speeds=tuple(v for v in (500.0, 1000.0, 1500.0, 2000.0)
                             if v <= (_f(r["max_input_speed_rpm"]) or 0))))

        # component sets (CSF-...-2A-GR) from the seed's worked examples
        self.comp: dict[str, Model] = {}
        csf_hyst = {int(x["ratio_min"]): _f(x["hysteresis_rad"]) for x in hyst
                    if x["series"] == "CSF-GH"}
        for r in comp:
            series, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
            code = f"{series}-{size}-{ratio}-2A-GR"
            m = Model(code=code, family="component", series=series, size=size, ratio=ratio,
                      T1=_f(r["T1_Nm"]), K1=_f(r["K1_Nm_per_rad"]), K2=_f(r["K2_Nm_per_rad"]),
                      rated=_f(r["rated_torque_Nm"]), peak=_f(r["peak_torque_Nm"]),
                      max_speed=_f(r["max_input_speed_rpm"]), eta_R=_f(r["efficiency_rated_pct"]))
            # the CSF-GH hysteresis row is per series and ratio, not per size: it is used as the
            # order of magnitude of the CSF component set's loss (judgement call, NOTES_g.md)
            m.hysteresis = csf_hyst.get(80 if ratio >= 80 else 50)
            if code == "CSF-20-80-2A-GR":
                m.speeds = (500.0, 1000.0, 1500.0, 2000.0, 3000.0)
            if code == "CSF-40-120-2A-GR":
                m.speeds = (500.0, 1000.0, 2000.0, 3000.0, 3500.0)
            if code == "CSF-25-100-2A-GR":
                # seed 000 p.020: 39 N*m lies between T1 and T2, so T2 >= 39 N*m (T2, K3 missing)
                m.note["T_max_known_segment"] = 39.0
            self.comp[code] = m

        # FD differential units used as reducers (WG input, CS S fixed, CS D output: table 304-1)
        oil_max = {int(r["size"]): _f(r["oil_max_rpm"]) for r in fd_speed}
        self.fd: list[Model] = []
        for r in fd_ratio:
            size, ratio = int(r["size"]), int(r["ratio"])
            rows = [x for x in fd_rt if int(x["size"]) == size and int(x["ratio"]) == ratio]
            if not rows:
                continue
            by_speed = {float(x["speed_rpm"]): float(x["rated_torque_Nm"]) for x in rows}
            t500 = by_speed.get(500.0)
            # listed speeds on the low-speed plateau (rated torque equal to the 500 r/min value)
            plateau = tuple(sorted(s for s, t in by_speed.items()
                                   if t == t500 and s <= oil_max.get(size, 0)))
            self.fd.append(Model(code=f"FD-{size}-{ratio}", family="FD", series="FD", size=size,
                                 ratio=ratio, rated=t500, max_speed=oil_max.get(size),
                                 speeds=plateau, lubrication="oil"))

    # model pools per kind ------------------------------------------------------------------
    def torsion_model(self, rng, allow_component=True) -> Model:
        if allow_component and rng.random() < 0.2:
            return self.comp["CSF-25-100-2A-GR"]
        return _choice(rng, self.gh)

    def vibration_model(self, rng) -> Model:
        if rng.random() < 0.2:
            return self.comp["CSF-25-100-2A-GR"]
        return _choice(rng, self.gh)

    def transmission_model(self, rng) -> Model:
        u = rng.random()
        if u < 0.5:
            return _choice(rng, self.fd)
        if u < 0.8:
            return _choice(rng, list(self.comp.values()))
        return _choice(rng, self.gh)

    def efficiency_model(self, rng, need_eta_R=False) -> Model:
        if need_eta_R:
            return self.comp["CSF-20-80-2A-GR"]
        u = rng.random()
        if u < 0.4:
            return _choice(rng, [self.comp["CSF-20-80-2A-GR"], self.comp["CSF-40-120-2A-GR"]])
        if u < 0.7:
            return _choice(rng, [m for m in self.fd if len(m.speeds) >= 3])
        return _choice(rng, [m for m in self.gh if len(m.speeds) >= 3])


def catalog_twist(m: Model, T):
    """Catalog three-segment curve (continuous: theta1 = T1/K1, theta2 = theta1 + (T2-T1)/K2),
    odd in T.  For the component set without T2/K3 the test stays below the known segment."""
    T = np.asarray(T, dtype=float)
    a = np.abs(T)
    th1 = m.T1 / m.K1
    if m.T2 is None:
        th = np.where(a <= m.T1, a / m.K1, th1 + (a - m.T1) / m.K2)
    else:
        th2 = th1 + (m.T2 - m.T1) / m.K2
        th = np.where(a <= m.T1, a / m.K1,
                      np.where(a <= m.T2, th1 + (a - m.T1) / m.K2, th2 + (a - m.T2) / m.K3))
    return np.sign(T) * th


# ----------------------------------------------------------------------------------------------
# noise (white, AR(1) phi 0.3-0.8, 0.5 % outliers at 8-15x, heteroscedastic, quantised)
# ----------------------------------------------------------------------------------------------
def make_noise(rng, kind: str, sigma: float, clean: np.ndarray, weight=None):
    """Returns the noise actually added (measured - clean).  RMS is exactly sigma except for
    'quantised', whose RMS is close to sigma and is measured afterwards."""
    n = clean.size
    if kind == "quantised":
        q = sigma * _u(rng, 0.5, 1.6)                       # quantisation step
        w = math.sqrt(max(sigma ** 2 - q * q / 12.0, (0.3 * sigma) ** 2))
        meas = q * np.round((clean + w * rng.standard_normal(n)) / q)
        return meas - clean
    e = rng.standard_normal(n)
    if kind.startswith("ar1"):
        phi = _u(rng, 0.3, 0.8)
        e = lfilter([1.0], [1.0, -phi], e)
    if kind.startswith("hetero") and weight is not None:
        e = e * weight
    e = e / _rms(e)
    if kind.endswith("outliers"):
        k = max(1, int(round(0.005 * n)))
        idx = rng.choice(n, size=k, replace=False)
        e[idx] += rng.choice([-1.0, 1.0], size=k) * rng.uniform(8.0, 15.0, size=k)
    return e * (sigma / _rms(e))


# ----------------------------------------------------------------------------------------------
# pair snr balancing
# ----------------------------------------------------------------------------------------------
def _draw_ks(rng, n):
    if n <= 1:
        return [_u(rng, 4.4, 11.5)] * n
    return [_u(rng, 4.4, 7.8) for _ in range(n)]


def _balance(parts: list, ks: list, sigma: float, demean: bool) -> list:
    """Given built parts (at ks*sigma), return new ks (each in [4.2, 11.8]) so that the combined
    RMS is within [4.3, 11.7] * sigma assuming linear scaling of each part."""
    if len(parts) < 2:
        return ks
    unit = [p / max(_rms_eff(p, demean), 1e-300) for p in parts]

    def comb(lam, up):
        kk = [4.3 + (k - 4.3) * lam if not up else k + (11.5 - k) * lam for k in ks]
        return _rms_eff(sum(k * u for k, u in zip(kk, unit)), demean), kk

    c0, _ = comb(1.0, False)
    if c0 > 11.7:
        lam = brentq(lambda L: comb(L, False)[0] - 11.0, 0.0, 1.0)
        return comb(lam, False)[1]
    if c0 < 4.3:
        lam = brentq(lambda L: comb(L, True)[0] - 6.0, 0.0, 1.0)
        return comb(lam, True)[1]
    return ks


# ----------------------------------------------------------------------------------------------
# TORSION: protocols, hysteresis, backlash, housing
# ----------------------------------------------------------------------------------------------
def torsion_protocol(rng, name: str, T0: float):
    """Returns (T [N*m], t [s]) in test order.  All protocols are cycles between +-T0."""
    if name == "triangular":
        turns = [0.0, 1.0, -1.0, 1.0, -1.0, 1.0]
        nq = int(rng.integers(55, 130))
        amps = None
    elif name == "staircase":
        levels = int(rng.integers(4, 6))
        amps = np.linspace(1.0 / levels, 1.0, levels)
        turns = [0.0]
        for a in amps:
            turns += [a, -a, 0.0]
        nq = int(rng.integers(22, 40))
    elif name == "holds":           # few points per branch, load-hold readings, many cycles
        cyc = int(rng.integers(5, 8))
        turns = [0.0] + [1.0, -1.0] * cyc + [0.0]
        nq = int(rng.integers(14, 21))
    else:
        raise ValueError(name)
    xs = [np.array([0.0])]
    for a, b in zip(turns[:-1], turns[1:]):
        n = max(3, int(round(nq * abs(b - a))))
        xs.append(np.linspace(a, b, n + 1)[1:])
    x = np.concatenate(xs)
    if name == "holds":
        t = np.arange(x.size) * _u(rng, 4.0, 12.0)          # dwell per reading
    else:
        path = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(x)))])
        t = path / path[-1] * _u(rng, 600.0, 2400.0)
    return x * T0, t


# --- hysteresis formulations (input: normalised torque history x = T/T0) ----------------------
def _kp_model(rng):
    """Krasnosel'skii-Pokrovskii: weighted sum of continuous ramp-relay (KP) kernels."""
    N = 200
    w = _u(rng, 0.2, 0.4) * np.exp(_u(rng, 0.3, 0.6) * rng.standard_normal(N))
    c = _u(rng, 0.08, 0.2) * rng.standard_normal(N)
    a = _u(rng, 0.2, 0.5) * w
    s1, s2 = c - w, c + w

    def run(x):
        kap = np.where(c > 0, -1.0, 1.0)                     # demagnetised virgin state
        out = np.empty(x.size)
        prev = 0.0
        for i, u in enumerate(x):
            if u > prev:
                kap = np.maximum(kap, np.clip(2.0 * (u - s2) / a + 1.0, -1.0, 1.0))
            elif u < prev:
                kap = np.minimum(kap, np.clip(2.0 * (u - s1) / a - 1.0, -1.0, 1.0))
            out[i] = kap.mean()
            prev = u
        return out
    return run


def _everett_model(rng):
    """Classical Preisach model evaluated through its Everett function (Mayergoyz): lognormal
    coercive-width x Gaussian interaction density, memory of alternating dominant extrema with
    the wiping-out property; virgin state from an AC-demagnetising pre-history."""
    L, G = 1.3, 261
    g = np.linspace(-L, L, G)
    h = g[1] - g[0]
    A, B = np.meshgrid(g, g, indexing="ij")                  # A = alpha (up), B = beta (down)
    W, C = (A - B) / 2.0, (A + B) / 2.0
    wm, sw, sc = _u(rng, 0.2, 0.45), _u(rng, 0.35, 0.7), _u(rng, 0.06, 0.18)
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = np.where(W > 0, np.exp(-0.5 * (np.log(np.maximum(W, 1e-12) / wm) / sw) ** 2) / W, 0.0)
    mu *= np.exp(-0.5 * (C / sc) ** 2)
    mu /= mu.sum()
    F = np.cumsum(mu, axis=0)
    F = np.cumsum(F[:, ::-1], axis=1)[:, ::-1]               # F[i,j] = sum_{a<=A_i, b>=B_j}
    Fl = F.tolist()

    def Fe(a, b):
        if a <= b:
            return 0.0
        x = min(max((a + L) / h, 0.0), G - 1.000001)
        y = min(max((b + L) / h, 0.0), G - 1.000001)
        i, j = int(x), int(y)
        fx, fy = x - i, y - j
        r0, r1 = Fl[i], Fl[i + 1]
        return ((1 - fx) * ((1 - fy) * r0[j] + fy * r0[j + 1])
                + fx * ((1 - fy) * r1[j] + fy * r1[j + 1]))

    Ftot = Fe(L, -L)

    def run(x):
        # history: negative saturation, demagnetising pre-history, then the test
        pre = [(-1) ** (k + 1) * 1.2 * 0.8 ** k for k in range(30)] + [0.0]
        seq = pre + list(map(float, x))
        ext: list[float] = []
        inc = True
        prev = -L
        outs = []
        for u in seq:
            if u > prev:
                if not inc:
                    ext.append(prev)
                    inc = True
                while len(ext) >= 2 and ext[-2] <= u:
                    ext.pop(); ext.pop()
            elif u < prev:
                if inc:
                    ext.append(prev)
                    inc = False
                while len(ext) >= 3 and ext[-2] >= u:
                    ext.pop(); ext.pop()
            prev = u
            s = 0.0
            mprev = -L
            npair = len(ext) // 2
            for k in range(npair):
                M, m = ext[2 * k], ext[2 * k + 1]
                s += Fe(M, mprev) - Fe(M, m)
                mprev = m
            if inc:
                s += Fe(u, mprev)
            else:
                M = ext[-1]
                s += Fe(M, mprev) - Fe(M, u)
            outs.append(-Ftot + 2.0 * s)
        return np.array(outs[len(pre):])
    return run


def _bwbn_model(rng):
    """Bouc-Wen-Baber-Noori element with pinching (Baber & Noori 1986; Foliente 1995) in its
    standard displacement form, restoring torque r = a u + (1-a) z,
    dz/du = h(z) [A - |z|^n (beta sgn(du z) + gamma)],
    h(z) = 1 - zeta1 exp(-((z sgn(du) - q z_u)/zeta2)^2); driven by torque, so the element's
    deflection u is obtained by inverting r(u) incrementally (du = dr / (a + (1-a) dz/du))."""
    n = _u(rng, 1.2, 2.8)
    a = _u(rng, 0.2, 0.5)
    Fy = _u(rng, 0.4, 0.8)                                   # yield torque / T0
    zu = Fy / (1 - a)
    frac = _u(rng, 0.55, 0.9)
    A = 1.0
    beta, gamma = frac * A / zu ** n, (1 - frac) * A / zu ** n
    z1, q, z2 = _u(rng, 0.1, 0.3), _u(rng, 0.0, 0.2), _u(rng, 0.15, 0.35) * zu

    def rates(z, s):
        h = 1.0 - z1 * math.exp(-((z * s - q * zu) / z2) ** 2)
        sg = 1.0 if z * s >= 0 else -1.0
        gz = h * (A - abs(z) ** n * (beta * sg + gamma))      # dz/du
        den = a + (1 - a) * gz
        return gz / den, 1.0 / den                            # dz/dr, du/dr

    def run(x):
        z = u = 0.0
        prev = 0.0
        out = np.empty(x.size)
        for i, r in enumerate(x):
            d = r - prev
            if d != 0.0:
                m = max(1, int(math.ceil(abs(d) / 0.004)))
                dr = d / m
                s = 1.0 if d > 0 else -1.0
                for _ in range(m):
                    kz1, ku1 = rates(z, s)
                    kz2, ku2 = rates(z + dr * kz1, s)
                    z += 0.5 * dr * (kz1 + kz2)
                    u += 0.5 * dr * (ku1 + ku2)
            out[i] = u
            prev = r
        return out
    return run


def _dupont_model(rng):
    """Single-state elasto-plastic friction (Dupont, Hayward, Armstrong, Altpeter 2002) in
    parallel with a spring, driven by torque: pure elastic presliding below the breakaway
    z_ba (no loss at very small torque), plastic sliding at z_ss."""
    zss = _u(rng, 0.25, 0.5)
    zba = _u(rng, 0.35, 0.75) * zss
    Kp = _u(rng, 0.15, 0.5)

    def alpha(z, s):
        if z * s <= 0:
            return 0.0
        a = abs(z)
        if a <= zba:
            return 0.0
        if a >= zss:
            return 1.0
        return 0.5 * math.sin(math.pi * (a - 0.5 * (zss + zba)) / (zss - zba)) + 0.5

    def run(x):
        z = y = 0.0
        prev = 0.0
        out = np.empty(x.size)
        for i, u in enumerate(x):
            d = u - prev
            if d != 0.0:
                m = max(1, int(math.ceil(abs(d) / 0.004)))
                dx = d / m
                s = 1.0 if d > 0 else -1.0
                for _ in range(m):
                    g = 1.0 - alpha(z, s) * z / zss * s
                    dy = dx / (Kp + g)
                    y += dy
                    z += g * dy
            out[i] = y
            prev = u
        return out
    return run


HYST = {"kp": _kp_model, "everett-preisach": _everett_model, "bwbn-pinching": _bwbn_model,
        "elastoplastic-dupont": _dupont_model}


def hysteresis_shape(rng, form: str, x):
    """Loop contribution whose centre line (mean of the major-loop branches) is removed, so the
    catalog curve is the loop's centre line; normalised to a loss B-B' of 1 at zero torque."""
    run = HYST[form](rng)
    up1 = np.linspace(0, 1, 201)
    dn = np.linspace(1, -1, 401)[1:]
    up = np.linspace(-1, 1, 401)[1:]
    maj = run(np.concatenate([up1, dn, up]))
    ydn = maj[201:601][::-1]                                  # on ascending grid -1..1
    yup = maj[601:]
    xd = dn[::-1]
    centre_x = up
    centre = 0.5 * (np.interp(centre_x, xd, ydn) + yup)
    loss = float(np.interp(0.0, xd, ydn) - np.interp(0.0, up, yup))
    hx = run(np.asarray(x, dtype=float))
    hx = hx - np.interp(x, centre_x, centre)
    return hx / loss


def backlash_shape(rng, form: str, x):
    """Odd play contribution (function of the sign of the transmitted torque), saturating at
    +-1/2 (i.e. total play 1)."""
    x = np.asarray(x, dtype=float)
    if form == "erf-deadzone":
        s = _u(rng, 0.01, 0.04)
        return 0.5 * erf(x / (math.sqrt(2.0) * s))
    if form == "oldham-2slot":
        c2 = 1.0
        c1 = _u(rng, 0.2, 0.7)
        r = _u(rng, 0.5, 2.0)                                 # k2/k1
        Ts = _u(rng, 0.01, 0.05)                              # torque closing the 2nd slot
        k1 = Ts / (c2 - c1)
        k2 = r * k1
        a = np.abs(x)
        d = np.where(a <= Ts, c1 + a / k1, (a + k1 * c1 + k2 * c2) / (k1 + k2))
        y = np.sign(x) * (d - a / (k1 + k2))
        sat = (k1 * c1 + k2 * c2) / (k1 + k2)
        return 0.5 * y / sat
    raise ValueError(form)


def _soft_or_gain_equiv_ok(m, T, s_or_g, sigma):
    """Residual of the 'housing + stiffness scale within +-10 %' reading of a uniformly softer
    curve; used to keep the decoy truly data-equivalent (residual < 0.5 noise)."""
    th = catalog_twist(m, T)
    y = th * s_or_g
    best = np.inf
    for a in np.linspace(1 / 1.1, 1 / 0.9, 41):
        r = y - a * th
        c = float(np.dot(r, T) / np.dot(T, T))
        if c < 0:
            continue
        best = min(best, _rms(r - c * T))
    return best < 0.5 * sigma


def torsion_cell(spec):
    """spec: dict(effects=[(name, form)], meas=..., protocol=..., category, formulation)."""
    def build(ctx):
        rng, cat = ctx.rng, ctx.cat
        meas = spec.get("meas")
        effects = spec.get("effects", [])
        has_backlash = any(e == "backlash" for e, _ in effects)
        m = cat.torsion_model(rng, allow_component=not has_backlash)   # catalog backlash: GH
        if meas == "soft-seg1" or (meas == "twist_gain" and ctx.attempt >= 4):
            T0 = _u(rng, 0.75, 1.0) * m.T1
        elif meas == "twist_gain" and ctx.attempt >= 2 and m.T2 is not None:
            T0 = _u(rng, 0.5, 1.0) * (m.T1 + m.T2)
        elif m.family == "component":
            T0 = _u(rng, 0.75, 1.0) * m.note["T_max_known_segment"]
        else:
            T0 = min(_u(rng, 1.05, 1.4) * max(m.rated, m.T2), 0.9 * m.peak)
        T, t = torsion_protocol(rng, spec["protocol"], T0)
        x = T / T0
        s = _u(rng, 0.92, 1.08)                               # stiffness scale (catalog spread)
        nuis = {"stiffness_scale": s}
        base = catalog_twist(m, T) / s
        shapes, anchors = [], []
        for name, form in effects:
            if name == "hysteresis":
                sh = hysteresis_shape(rng, form, x)
                anchors.append(m.hysteresis * _u(rng, 0.5, 1.2) if m.hysteresis else None)
            elif name == "backlash":
                sh = backlash_shape(rng, form, x)
                anchors.append(m.backlash * _u(rng, 0.4, 1.0) if m.backlash else None)
            elif name == "housing_compliance":
                sh = x.copy()                                 # series spring, linear in T
                anchors.append(None)
            else:
                raise ValueError(name)
            shapes.append(sh)
        # physical anchor: magnitude in rad of the loss / play
        r_sig = _u(rng, 0.002, 0.01) * _rms(base)
        extra = {}
        if meas == "stiffness_scale":
            s = _u(rng, 1.05, 1.10)
            nuis["stiffness_scale"] = s
            base = catalog_twist(m, T)                        # the catalog reading (scale 1)
            shapes = [catalog_twist(m, T) * (1.0 / s - 1.0)]
        elif meas == "torque_gain":
            g = _u(rng, 1.04, 1.12)
            extra["torque_gain"] = g
        elif meas in ("soft-seg1", "twist_gain"):
            extra["srel"] = _u(rng, 0.012, 0.035)
            if meas == "soft-seg1":
                del nuis["stiffness_scale"]                   # set in make()
        elif meas == "offset":
            shapes = [np.ones_like(T) * _choice(rng, [-1.0, 1.0])]
        elif meas == "drift":
            tau = _u(rng, 0.3, 1.0) * t[-1]
            shapes = [_choice(rng, [-1.0, 1.0]) * (1.0 - np.exp(-t / tau))]
        elif meas == "fixture_play":
            shapes = [backlash_shape(rng, "erf-deadzone", x)]
        elif meas == "reversal_step":
            tauT = _u(rng, 0.02, 0.08)
            y = np.empty_like(x)
            cur, prev, sgn = 0.0, 0.0, 1.0
            for i, u in enumerate(x):
                d = u - prev
                if d != 0:
                    sgn = 1.0 if d > 0 else -1.0
                    tgt = 0.5 * sgn
                    cur = tgt + (cur - tgt) * math.exp(-abs(d) / tauT)
                y[i] = cur
                prev = u
            shapes = [y]
        extra["r_sig"] = r_sig

        def make(ks):
            cols_T = T.copy()
            clean = base.copy()
            parts = []
            if meas in (None, "offset", "drift", "fixture_play", "reversal_step"):
                if not shapes:
                    return dict(T=cols_T, y=clean, base=base, parts=[], sigma=r_sig)
                # anchor the noise on the catalog-backed magnitude: the play when there is one
                # (the smaller effect, so neither effect exceeds its catalog order), else the loss
                ia = next((i for i, (e, _) in enumerate(effects)
                           if e == "backlash" and anchors[i] is not None),
                          0 if anchors and anchors[0] is not None else None)
                if ia is not None:                            # shape has loss/play 1 -> rad
                    sigma = _rms(shapes[ia] * anchors[ia]) / ks[ia]
                else:
                    sigma = r_sig
                for sh, k in zip(shapes, ks):
                    p = sh / _rms(sh) * k * sigma
                    parts.append(p)
                    clean = clean + p
                return dict(T=cols_T, y=clean, base=base, parts=parts, sigma=sigma)
            if meas == "stiffness_scale":
                p = shapes[0]
                clean = base + p
                return dict(T=cols_T, y=clean, base=base, parts=[p], sigma=_rms(p) / ks[0])
            if meas in ("soft-seg1", "twist_gain"):
                # clearly outside the +-10 % catalog spread: relative change >= 0.18
                srel = max(extra["srel"], 0.18 / ks[0])
                fac = 1.0 + ks[0] * srel                      # = 1/s (soft gear) or twist gain
                th = catalog_twist(m, T) / (1.0 if meas == "soft-seg1" else s)
                p = th * (fac - 1.0)
                nu = ({"stiffness_scale": 1.0 / fac} if meas == "soft-seg1"
                      else {"twist_gain": fac})
                extra["fac"] = fac
                return dict(T=cols_T, y=th + p, base=th, parts=[p], sigma=srel * _rms(th),
                            nuisance=nu)
            if meas == "torque_gain":
                g = extra["torque_gain"]
                Tm = g * T
                b = catalog_twist(m, Tm) / s
                p = base - b
                return dict(T=Tm, y=base.copy(), base=b, parts=[p], sigma=_rms(p) / ks[0])
            if meas == "deg":
                y = base * DEG
                return dict(T=cols_T, y=y, base=base, parts=[y - base], sigma=r_sig * DEG,
                            exempt=True)
            if meas == "kNm":
                Tm = T * 1e-3
                b = catalog_twist(m, Tm) / s
                return dict(T=Tm, y=base.copy(), base=b, parts=[base - b], sigma=r_sig,
                            exempt=True)
            raise ValueError(meas)

        def finish(res, sigma):
            if meas == "twist_gain":
                # keep it truly data-equivalent: shrink the test range until the housing reading
                # fits within half the noise (segment 1 makes it exact)
                return _soft_or_gain_equiv_ok(m, T, extra["fac"] / s, sigma)
            return True

        cols = lambda res, y: {"torque_Nm": res["T"], "twist_rad": y}
        return dict(model=m.code, nuisance=nuis, make=make, columns=cols, measured="twist_rad",
                    demean=False, check=finish, retry_T1=(meas == "twist_gain"), m=m,
                    protocol=spec["protocol"])
    return build


# ----------------------------------------------------------------------------------------------
# TRANSMISSION
# ----------------------------------------------------------------------------------------------
def transmission_protocol(rng, name: str, R: int):
    if name == "short":
        nrev = _u(rng, 4.0, 12.0)
        spr = int(rng.integers(240, 720))
    elif name == "long":                                     # 1-2.2 OUTPUT revolutions
        nrev = R * _u(rng, 1.05, 2.2)
        spr = int(np.clip(19000.0 / nrev, 24, 200))
    elif name == "coarse":                                   # fractional, coarse sampling
        nrev = _u(rng, 40.3, 90.7)
        spr = int(rng.integers(30, 60))
    else:
        raise ValueError(name)
    n = int(nrev * spr)
    th0 = _u(rng, 0.0, 2 * math.pi)
    th = th0 + np.linspace(0.0, nrev * 2 * math.pi, n)
    rpm = _u(rng, 30.0, 300.0)
    t = (th - th0) / (rpm / 60.0 * 2 * math.pi)
    return th, t


def te_shape(rng, form: str, th, R):
    """Unit-amplitude TE shapes (rad per unit amplitude), th = input (WG) angle."""
    thout = th / R
    if form == "wg-runout":
        return np.sin(th + _u(rng, 0, 2 * math.pi))
    if form == "runout-sidebands":
        mm = _u(rng, 0.2, 0.5)
        return (1 + mm * np.cos(thout + _u(rng, 0, 6.3))) * np.sin(th + _u(rng, 0, 6.3))
    if form == "ellipse-series":
        r4 = _u(rng, 0.1, 0.25)
        return np.sin(2 * th + _u(rng, 0, 6.3)) + r4 * np.sin(4 * th + _u(rng, 0, 6.3))
    if form == "mesh-sidebands":
        mm = _u(rng, 0.2, 0.5)
        return (1 + mm * np.cos(thout + _u(rng, 0, 6.3))) * np.sin(2 * th + _u(rng, 0, 6.3))
    raise ValueError(form)


def transmission_cell(spec):
    def build(ctx):
        rng, cat = ctx.rng, ctx.cat
        m = cat.transmission_model(rng)
        R = m.ratio
        th, t = transmission_protocol(rng, spec["protocol"], R)
        off = _u(rng, -math.pi, math.pi)
        nuis = {"offset_rad": off}
        base = th / R + off
        sigma_phys = _u(rng, 1.5e-6, 8e-6)
        meas = spec.get("meas")
        shapes = [te_shape(rng, form, th, R) for _, form in spec.get("effects", [])]
        anchor = None
        th_in_meas = th
        if meas == "encoder_eccentricity":
            shapes = [np.sin(th / R + _u(rng, 0, 6.3))]
        elif meas == "scale":
            shapes = [th / R - np.mean(th / R)]
        elif meas == "step":
            p = _u(rng, 0.3, 0.7)
            shapes = [np.where(t > p * t[-1], 1.0, 0.0) * _choice(rng, [-1.0, 1.0])]
        elif meas == "drift":
            tau = _u(rng, 0.3, 1.5) * t[-1]
            shapes = [(1 - np.exp(-t / tau)) * _choice(rng, [-1.0, 1.0])]
        elif meas == "input_ecc":                             # eccentric INPUT encoder disc
            eps = _u(rng, 1e-3, 5e-3)                          # e/r
            ph = _u(rng, 0, 6.3)
            err = eps * np.sin(th + ph)
            th_in_meas = th + err
            shapes = [-err / R]
            anchor = _rms(shapes[0] - shapes[0].mean())
        elif meas == "resolver":                              # input resolver gain imbalance
            dlt = _u(rng, 0.004, 0.02) * _choice(rng, [-1.0, 1.0])
            wr = np.mod(th + math.pi, 2 * math.pi) - math.pi
            err = np.arctan2((1 + dlt) * np.sin(th), np.cos(th)) - wr
            err = np.mod(err + math.pi, 2 * math.pi) - math.pi
            th_in_meas = th + err
            shapes = [-err / R]
            anchor = _rms(shapes[0] - shapes[0].mean())
            nuis["resolver_gain_imbalance"] = dlt

        def make(ks):
            if meas == "deg":
                y = base * DEG
                return dict(x=th, y=y, base=base, parts=[y - base], sigma=sigma_phys * DEG,
                            exempt=True, demean=False)
            if anchor is not None:
                sigma = anchor / ks[0]
                p = shapes[0]
                return dict(x=th_in_meas, y=base.copy(), base=th_in_meas / R + off, parts=[p],
                            sigma=sigma)
            sigma = sigma_phys
            parts = [sh / _rms(sh - sh.mean()) * k * sigma for sh, k in zip(shapes, ks)]
            y = base + (sum(parts) if parts else 0.0)
            return dict(x=th, y=y, base=base, parts=parts, sigma=sigma)

        cols = lambda res, y: {"input_angle_rad": res["x"], "output_angle_rad": y}
        return dict(model=m.code, nuisance=nuis, make=make, columns=cols,
                    measured="output_angle_rad", demean=True, m=m, protocol=spec["protocol"])
    return build


# ----------------------------------------------------------------------------------------------
# EFFICIENCY
# ----------------------------------------------------------------------------------------------
def efficiency_grid(rng, name: str, m: Model):
    sp = np.array(m.speeds, dtype=float)
    temps_all = np.array([0.0, 10.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 70.0])
    if name == "full":
        ns = np.sort(rng.choice(sp, size=min(len(sp), int(rng.integers(3, 5))), replace=False))
        te = np.sort(rng.choice(temps_all, size=int(rng.integers(3, 6)), replace=False))
        al = np.array(sorted(set(np.round(rng.choice(
            [0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0],
            size=int(rng.integers(6, 9)), replace=False), 3)) | {1.0}))
        pts = [(n, a, T) for T in te for n in ns for a in al]
    elif name == "sparse":                                   # irregular, not a grid
        k = int(rng.integers(36, 70))
        pts = [(float(_choice(rng, list(sp))), _u(rng, 0.1, 1.0), _u(rng, 0.0, 70.0))
               for _ in range(k)]
        pts.sort(key=lambda p: p[2])                          # warm-up order
    elif name == "fixed-temp":
        T = float(_choice(rng, [20.0, 25.0, 40.0]))
        ns = np.sort(rng.choice(sp, size=min(len(sp), int(rng.integers(3, 5))), replace=False))
        al = np.linspace(0.1, 1.0, int(rng.integers(12, 17)))
        pts = [(n, a, T) for n in ns for a in al]
    elif name == "temp-sweep":                               # 2 speeds, many temperatures
        ns = np.sort(rng.choice(sp, size=2, replace=False))
        te = np.arange(0.0, 71.0, float(_choice(rng, [10.0, 7.5])))
        al = np.array([0.25, 0.5, 0.75, 1.0]) if rng.random() < 0.5 else np.array([0.3, 0.6, 1.0])
        pts = [(n, a, T) for T in te for n in ns for a in al]
    else:
        raise ValueError(name)
    n = np.array([p[0] for p in pts])
    a = np.array([p[1] for p in pts])
    T = np.array([p[2] for p in pts])
    return n, a, T


def _wlf_visc(Tc, nu40):
    """WLF temperature shift (Williams-Landel-Ferry 1955) with constants fitted to an ISO VG68
    type oil (nu100 ~ 8.7 cSt): log10(nu/nu40) = -C1 (T-40)/(C2 + T - 40)."""
    C1, C2 = 3.13, 150.0
    return nu40 * 10.0 ** (-C1 * (Tc - 40.0) / (C2 + Tc - 40.0))


def _ehl_mu(rng):
    """Mixed-EHL mesh friction vs temperature: Hamrock-Dowson central film h ~ (eta0 u)^0.67,
    lambda = h/sigma, Gaussian-overlap asperity share erfc(lambda/(2 sqrt 2)), fluid traction
    ~ viscosity^(0.25..0.4); returns mu(T)."""
    nu40 = _u(rng, 50.0, 150.0)
    lam40 = _u(rng, 1.5, 3.0)
    mub, muf40 = _u(rng, 0.08, 0.13), _u(rng, 0.02, 0.045)
    xf = _u(rng, 0.25, 0.4)

    def mu(Tc):
        nu = _wlf_visc(np.asarray(Tc, float), nu40)
        lam = lam40 * (nu / nu40) ** 0.67
        fc = erfc(lam / (2 * math.sqrt(2.0)))
        return fc * mub + (1 - fc) * muf40 * (nu / nu40) ** xf
    return mu


def _eyring_mu(rng):
    """Eyring limiting-shear traction (Johnson & Tevaarwerk 1977): tau = tauE asinh(eta gdot/tauE),
    tauE ~ kT/V, Arrhenius viscosity; mu = tau / p."""
    Q = _u(rng, 25e3, 45e3)
    X40 = _u(rng, 5.0, 60.0)

    def mu(Tc):
        TK = np.asarray(Tc, float) + 273.15
        T40 = 313.15
        eta = np.exp(Q / 8.314 * (1 / TK - 1 / T40))
        return (TK / T40) * np.arcsinh(X40 * eta * T40 / TK) / np.arcsinh(X40)
    return mu


def efficiency_cell(spec):
    def build(ctx):
        rng, cat = ctx.rng, ctx.cat
        meas = spec.get("meas")
        m = cat.efficiency_model(rng, need_eta_R=(meas == "level"))
        n, a, Tc = efficiency_grid(rng, spec["protocol"], m)
        load = a * m.rated
        if m.eta_R is not None:
            eta0 = m.eta_R * _u(rng, 0.97, 1.03)
        elif m.family == "FD":
            eta0 = _u(rng, 60.0, 80.0)
        else:
            eta0 = _u(rng, 62.0, 84.0)
        sig_phys = _u(rng, 0.3, 1.2)
        noise_weight = 1.0 / np.sqrt(a)                      # torque-sensor error ~ 1/T
        effects = [f for _, f in spec.get("effects", [])]
        ef = tuple(e for e, _ in spec.get("effects", []))
        x58 = 0.58 ** (-1.0 / 3.0) - 1.0
        K58 = _u(rng, 0.90, 0.96)                            # Ke(0.58) near graph 023-1's 0.93
        tref = 40.0
        prm = {}
        if "bowden-tabor" in effects or "bowden-tabor x ehl" in effects:
            c = (1 - K58) / x58
            prm["Ke"] = 1.0 - c * np.where(a < 1, a ** (-1 / 3) - 1, 0.0)
        if "schlenk-idle" in effects:
            lm = _u(rng, 0.05, 0.15)

            def ke_s(tau0):
                def eta(al):
                    em = 1 - lm * al ** 0.2
                    return em * al / (al + em * tau0)
                return eta(a) / eta(1.0), eta(0.58) / eta(1.0)
            tau0 = brentq(lambda t0: ke_s(t0)[1] - K58, 1e-6, 5.0)
            prm["Ke"] = ke_s(tau0)[0]
        mufn = None
        if "ehl-mixed" in effects or "bowden-tabor x ehl" in effects:
            mufn = _ehl_mu(rng)
        if "eyring-traction" in effects:
            mufn = _eyring_mu(rng)
        if mufn is not None:
            mu_T, mu_ref = mufn(Tc), float(mufn(tref))

            def kt(H):
                return (1 - H * mu_T) / (1 - H * mu_ref)
            prm["kt"] = kt
            span = _u(rng, 6.0, 16.0)
            Tg = np.linspace(Tc.min(), Tc.max(), 50)
            mg = mufn(Tg)
            fspan = lambda H: eta0 * float(np.ptp((1 - H * mg) / (1 - H * mu_ref))) - span
            Hmax = 0.95 / max(float(mg.max()), mu_ref)
            prm["H_anchor"] = brentq(fspan, 1e-9, Hmax) if fspan(Hmax) > 0 else Hmax
            prm["Hmax"] = Hmax
        if "hb-grease-drag" in effects:
            etam = eta0 / 100.0
            phy, mexp = _u(rng, 0.3, 0.6), _u(rng, 0.2, 0.45)
            nf = phy + (1 - phy) * (n / 1000.0) ** mexp

            def eta_hb(dref, E, Tcel):
                aT = np.exp(E / 8.314 * (1 / (Tcel + 273.15) - 1 / (tref + 273.15)))
                d = dref * aT * nf
                return 100.0 * etam * a / (a + etam * d)

            def ke58(dref):          # at reference temperature and 1000 r/min
                d = dref
                e = lambda al: etam * al / (al + etam * d)
                return e(0.58) / e(1.0)
            dref = brentq(lambda d: ke58(d) - K58, 1e-8, 10.0)
            prm["hb"] = (eta_hb, dref)

        def make(ks):
            if meas == "level":
                d = ks[0] * sig_phys * _choice(rng_fixed, [-1.0, 1.0])
                y = np.full_like(a, m.eta_R + d)
                base = np.full_like(a, m.eta_R)
                return dict(y=y, base=base, parts=[y - base], sigma=sig_phys, demean=False,
                            nuisance={"level_pct": float(m.eta_R + d)})
            if meas == "fraction":
                y = np.full_like(a, eta0) / 100.0
                base = np.full_like(a, eta0)
                return dict(y=y, base=base, parts=[y - base], sigma=sig_phys / 100.0, exempt=True,
                            demean=False)
            if meas == "drift_temp":
                shape = 1 - np.exp(-(Tc - Tc.min()) / _u(rng_fixed, 15.0, 60.0))
                shape = shape / np.ptp(shape) * _choice(rng_fixed, [-1.0, 1.0])
                p = shape * eta0 * _u(rng_fixed, 0.03, 0.12)   # 3-12 % span drift over 0-70 C
                base = np.full_like(a, eta0)
                return dict(y=base + p, base=base, parts=[p], sigma=_rms(p - p.mean()) / ks[0])
            base = np.full_like(a, eta0)
            if not ef:
                return dict(y=base.copy(), base=base, parts=[], sigma=sig_phys)
            if ef == ("low_load_efficiency",):
                p = eta0 * (prm["Ke"] - 1)
                sigma = _rms(p - p.mean()) / ks[0]
                return dict(y=base + p, base=base, parts=[p], sigma=sigma)
            if ef == ("temperature_dependence",):
                p = eta0 * (prm["kt"](prm["H_anchor"]) - 1)
                sigma = _rms(p - p.mean()) / ks[0]
                return dict(y=base + p, base=base, parts=[p], sigma=sigma)
            if "bowden-tabor x ehl" in effects:
                sigma = sig_phys
                u1 = eta0 * (prm["Ke"] - 1)
                p1 = u1 * ks[0] * sigma / _rms(u1 - u1.mean())
                Ke = 1 + p1 / eta0
                f = lambda H: _rms_eff(eta0 * Ke * (prm["kt"](H) - 1), True) - ks[1] * sigma
                Hm = prm["Hmax"]
                H = brentq(f, 1e-9, Hm) if f(Hm) > 0 else Hm
                p2 = eta0 * Ke * (prm["kt"](H) - 1)
                return dict(y=base + p1 + p2, base=base, parts=[p1, p2], sigma=sigma)
            if "hb-grease-drag" in effects:
                eta_hb, _ = prm["hb"]
                sigma = sig_phys
                g1 = lambda d: _rms_eff(eta_hb(d, 0.0, Tc) - eta0, True) - ks[0] * sigma
                dg = np.geomspace(1e-5, 3.0, 60)
                hi = next(d for d in dg if g1(d) > 0)         # first crossing (monotone part)
                dref = brentq(g1, 1e-9, hi)
                e_ref = eta_hb(dref, 0.0, Tc)                  # drag at reference temperature
                p1 = e_ref - eta0
                f = lambda E: _rms_eff(eta_hb(dref, E, Tc) - e_ref, True) - ks[1] * sigma
                E = brentq(f, 1.0, 150e3) if f(150e3) > 0 else 150e3
                e = eta_hb(dref, E, Tc)
                return dict(y=e, base=base, parts=[p1, e - e_ref], sigma=sigma)
            raise ValueError(effects)

        rng_fixed = np.random.default_rng(int(rng.integers(2 ** 31)))
        cols = lambda res, y: {"input_speed_rpm": n, "load_torque_Nm": load, "temperature_C": Tc,
                               "efficiency_pct": y}
        def plausible(res, sigma):
            y = np.asarray(res["y"]) * (100.0 if meas == "fraction" else 1.0)
            return bool(y.min() >= 12.0 and y.max() <= 92.0)
        return dict(model=m.code, nuisance={"level_pct": float(eta0)}, make=make, columns=cols,
                    measured="efficiency_pct", demean=True, m=m, protocol=spec["protocol"],
                    noise_weight=noise_weight, check=plausible)
    return build


# ----------------------------------------------------------------------------------------------
# VIBRATION
# ----------------------------------------------------------------------------------------------
def _speed_profile(kind, f0, f1, D, t):
    if kind == "ramp":
        f = f0 + (f1 - f0) * t / D
        ph = 2 * math.pi * (f0 * t + 0.5 * (f1 - f0) * t * t / D)
    else:                                                    # S-curve, non-constant acceleration
        f = f0 + (f1 - f0) * 0.5 * (1 - np.cos(math.pi * t / D))
        ph = 2 * math.pi * (f0 * t + (f1 - f0) * 0.5 * (t - D / math.pi * np.sin(math.pi * t / D)))
    return f, ph


def _hb_linear(K, J, c, w):
    Z = J * w * w / np.sqrt((K - J * w * w) ** 2 + (c * w) ** 2)
    psi = np.arctan2(c * w, K - J * w * w)
    return Z, psi                                            # per unit excitation amplitude


def _hb_coulomb(K, J, c, F, E, w):
    """Den Hartog / Jacobsen equivalent linearisation, base-excited, friction on the spring's
    twist rate: c_eq = c + 4F/(pi w Z)."""
    a2 = (K - J * w * w) ** 2 + (c * w) ** 2
    a1 = 8 * F * c * w / math.pi
    a0 = 16 * F * F / math.pi ** 2 - (J * w * w * E) ** 2
    disc = np.maximum(a1 * a1 - 4 * a2 * a0, 0.0)
    Z = np.where(a0 < 0, (-a1 + np.sqrt(disc)) / (2 * a2), 0.0)
    psi = np.arctan2(c * w * Z + 4 * F / math.pi, (K - J * w * w) * np.maximum(Z, 1e-300))
    return Z, psi


def _hb_duffing(K, K3, J, c, E, w):
    """Harmonic balance of the hardening Duffing oscillator (Nayfeh & Mook): follow the branch
    continuously on a run-up (upper branch until it ends, then the jump)."""
    Z = np.empty_like(w)
    psi = np.empty_like(w)
    a = 0.75 * K3
    prev = None
    for i, wi in enumerate(w):
        d = K - J * wi * wi
        F0 = J * wi * wi * E
        r = np.roots([a * a, 2 * a * d, d * d + (c * wi) ** 2, -F0 * F0])
        r = np.real(r[(np.abs(np.imag(r)) < 1e-9 * max(1.0, np.abs(r).max())) & (np.real(r) > 0)])
        if r.size == 0:
            Y = 0.0
        elif prev is None:
            Y = float(r.min())
        else:
            Y = float(r[np.argmin(np.abs(np.log(r) - math.log(max(prev, 1e-300))))])
        prev = Y
        Z[i] = math.sqrt(Y)
        psi[i] = math.atan2(c * wi, d + a * Y)
    return Z, psi


def vibration_cell(spec):
    def build(ctx):
        rng, cat = ctx.rng, ctx.cat
        m = cat.vibration_model(rng)
        s = _u(rng, 0.92, 1.08)
        K = m.K1 * s
        nmax = m.max_speed if m.max_speed else 3500.0
        f_hi = min(45.0, 0.9 * nmax / (60.0 * 1.32))
        fn = _u(rng, 15.0, max(16.0, f_hi))
        J = K / (2 * math.pi * fn) ** 2
        proto = spec["protocol"]
        form = spec.get("form", "linear-hb")
        fast = proto.startswith("fast")
        zeta = _u(rng, 0.07, 0.12) if not fast else _u(rng, 0.03, 0.1)
        if form == "coulomb-hb":
            zeta = _u(rng, 0.05, 0.09)
        c = 2 * zeta * math.sqrt(K * J)
        f0, f1 = 0.3 * fn, 1.32 * fn                          # input frequency range (Hz)
        only1x = (tuple(e for e, _ in spec.get("effects", [])) == ("te_1x",)
                  or spec.get("meas") == "belt")
        fmax = f1 if only1x else 2 * f1                       # highest frequency in the signal
        if fast:
            D = _u(rng, 5.0, 10.0)
            fs = max(_u(rng, 14.0, 20.0) * fmax, 5200.0 / D)
        else:
            # slow run-up: sweep rate of the exciting harmonic through resonance well below the
            # ISO 7626-2 style limit, so the quasi-steady (harmonic-balance) response holds
            D = 6.0 / (fn * zeta ** 2)
            fs = min(max(_u(rng, 6.0, 8.0) * fmax, 5200.0 / D), 17500.0 / D)
        N = int(D * fs)
        t = np.arange(N) / fs
        kind = "scurve" if ("scurve" in proto) else "ramp"
        f_in, Ph = _speed_profile(kind, f0, f1, D, t)
        rpm = 60.0 * f_in
        nuis = {"stiffness_scale": s, "damping_ratio": zeta}
        sig_phys = _u(rng, 1e-6, 5e-6)
        meas = spec.get("meas")
        harmonics = [1 if e == "te_1x" else 2 for e, _ in spec.get("effects", [])]
        phases = [_u(rng, 0, 6.3) for _ in harmonics]
        if form == "duffing-hb":
            # resonant relative twist ~ E/(2 zeta) of 0.6-1.2 theta1: large enough to reach the
            # K1 -> K2 transition, small enough for the cubic to stay a fair fit of it
            E_anchor = [_u(rng, 0.6, 1.2) * (m.T1 / m.K1) * 2 * zeta for k in harmonics]
        else:
            E_anchor = [(_u(rng, 1e-5, 4e-5) if k == 1 else _u(rng, 2e-5, 6e-5))
                        for k in harmonics]
        fr_cou = _u(rng, 0.15, 0.45)
        K3 = s * (m.K2 - m.K1) / (3 * (m.T1 / m.K1) ** 2)     # Duffing fit of K1 -> K2 at theta1
        extra = {}
        if meas == "cardan":
            beta = _u(rng, 0.1, 0.2)                          # rad, Hooke's-joint angle
            nuis["cardan_angle_rad"] = beta
            extra["beta"] = beta
        if meas == "belt":
            eps = _u(rng, 1e-3, 5e-3)
            nuis["pulley_runout_ratio"] = eps
            extra["eps"] = eps

        def respond(e_fun_amp, k, phi, E, how):
            """Output deviation for a k-per-rev kinematic error E cos(k Ph + phi)."""
            if how == "foh":
                tp = np.arange(-int(1.0 * fs), 0) / fs         # 1 s lead-in at f0, tapered
                ph_pre = 2 * math.pi * f0 * tp
                taper = 0.5 * (1 - np.cos(math.pi * (tp - tp[0]) / (tp[-1] - tp[0] + 1e-12)))
                e_all = np.concatenate([E * taper * np.cos(k * ph_pre + phi),
                                        E * np.cos(k * Ph + phi)])
                b, aa, _ = cont2discrete(([c, K], [J, c, K]), 1.0 / fs, method="foh")
                y = lfilter(np.ravel(b), aa, e_all)
                return y[tp.size:]
            w = 2 * math.pi * k * f_in
            wg = np.linspace(w.min(), w.max(), 900)
            if how == "linear-hb":
                Zg, pg = _hb_linear(K, J, c, wg)
                Zg = Zg * E
            elif how == "coulomb-hb":
                F = fr_cou * math.pi * K * E / 4.0
                Zg, pg = _hb_coulomb(K, J, c, F, E, wg)
            elif how == "duffing-hb":
                Zg, pg = _hb_duffing(K, K3, J, c, E, wg)
            Z = np.interp(w, wg, Zg)
            psi = np.interp(w, wg, pg)
            arg = k * Ph + phi
            return E * np.cos(arg) + Z * np.cos(arg - psi)

        how = "foh" if fast else form

        def make(ks):
            if meas in (None,) and not harmonics:
                return dict(y=np.zeros(N), base=np.zeros(N), parts=[], sigma=sig_phys)
            if harmonics:
                parts0 = [respond(None, k, ph, E, how)
                          for k, ph, E in zip(harmonics, phases, E_anchor)]
                sigma = _rms(parts0[0] - parts0[0].mean()) / ks[0]
                parts = [parts0[0]]
                for p, k, ph, E, kk in zip(parts0[1:], harmonics[1:], phases[1:], E_anchor[1:],
                                           ks[1:]):
                    # linear formulations only in pairs: rescale exactly
                    parts.append(p / _rms(p - p.mean()) * kk * sigma)
                y = sum(parts)
                return dict(y=y, base=np.zeros(N), parts=parts, sigma=sigma)
            if meas == "cardan":
                bta = extra["beta"]
                # the error is a 2-per-rev (plus tiny 4-per-rev) kinematic input: respond linearly
                # via its two Fourier components
                tg = np.linspace(0, 2 * math.pi, 4096, endpoint=False)
                eg = np.arctan2(np.sin(tg), np.cos(tg) * math.cos(bta)) - tg
                eg = (np.mod(eg + math.pi, 2 * math.pi) - math.pi) / m.ratio
                c2 = np.mean(eg * np.exp(-2j * tg)) * 2       # err ~ Re(c2 e^{2i th}) + ...
                c4 = np.mean(eg * np.exp(-4j * tg)) * 2
                y = respond(None, 2, np.angle(c2), abs(c2), "linear-hb" if not fast else "foh")
                y = y + respond(None, 4, np.angle(c4), abs(c4), "linear-hb" if not fast else "foh")
                return dict(y=y, base=np.zeros(N), parts=[y], sigma=_rms(y - y.mean()) / ks[0])
            if meas == "belt":
                E = extra["eps"] / m.ratio
                y = respond(None, 1, _u(rng_fixed, 0, 6.3), E, "linear-hb")
                return dict(y=y, base=np.zeros(N), parts=[y], sigma=_rms(y - y.mean()) / ks[0])
            if meas == "drift":
                sh = (1 - np.exp(-t / (_u(rng_fixed, 0.3, 1.5) * D))) * _choice(rng_fixed, [-1., 1.])
            elif meas == "step":
                sh = np.where(t > _u(rng_fixed, 0.3, 0.7) * D, 1.0, 0.0)
            elif meas == "encoder_eccentricity":
                sh = np.sin(Ph / m.ratio + _u(rng_fixed, 0, 6.3))
            else:
                raise ValueError(meas)
            p = sh / _rms(sh - sh.mean()) * ks[0] * sig_phys
            return dict(y=p, base=np.zeros(N), parts=[p], sigma=sig_phys)

        rng_fixed = np.random.default_rng(int(rng.integers(2 ** 31)))
        cols = lambda res, y: {"time_s": t, "input_speed_rpm": rpm, "output_vibration_rad": y}
        return dict(model=m.code, nuisance=nuis, make=make, columns=cols,
                    measured="output_vibration_rad", demean=True, m=m, protocol=proto,
                    J=J)
    return build


# ----------------------------------------------------------------------------------------------
# the cells
# ----------------------------------------------------------------------------------------------
@dataclass
class Cell:
    kind: str
    category: str
    gear: tuple
    meas: tuple
    formulation: str
    builder: object
    noise: tuple
    equivalent: tuple = ()
    tag: str = ""


def _cells() -> list[Cell]:
    C = []
    W, A, O, H, Q = "white", "ar1", "white+outliers", "hetero", "quantised"
    AO = "ar1+outliers"

    # ------------------------------ torsion ------------------------------
    def tc(cat, gear, forms, proto, noise, meas=None, mnames=(), formulation=None, eq=(), tag=""):
        eff = list(zip(gear, forms))
        f = formulation or ("+".join(forms) + "/" + proto)
        C.append(Cell("torsion", cat, tuple(gear), tuple(mnames), f,
                      torsion_cell(dict(effects=eff, meas=meas, protocol=proto)), noise, eq, tag))

    tc("clean", (), (), "triangular", (W, A), formulation="catalog/triangular")
    tc("clean", (), (), "staircase", (A, O), formulation="catalog/staircase")
    tc("clean", (), (), "holds", (O, Q), formulation="catalog/holds")
    tc("single", ("hysteresis",), ("kp",), "triangular", (W, A))
    tc("single", ("hysteresis",), ("everett-preisach",), "staircase", (W, A, O))
    tc("single", ("hysteresis",), ("everett-preisach",), "triangular", (W, Q))
    tc("single", ("hysteresis",), ("bwbn-pinching",), "holds", (W, A))
    tc("single", ("hysteresis",), ("elastoplastic-dupont",), "triangular", (W, A, O))
    tc("single", ("backlash",), ("erf-deadzone",), "triangular", (W, A))
    tc("single", ("backlash",), ("oldham-2slot",), "staircase", (W, A, O))
    tc("single", ("housing_compliance",), ("saint-venant-shaft",), "triangular", (W, A))
    tc("single", ("housing_compliance",), ("mindlin-bolted-flange",), "staircase", (W, O))
    tc("pair", ("hysteresis", "backlash"), ("kp", "erf-deadzone"), "triangular", (W, A))
    tc("pair", ("hysteresis", "backlash"), ("elastoplastic-dupont", "oldham-2slot"), "staircase",
       (W, O))
    tc("pair", ("hysteresis", "housing_compliance"), ("everett-preisach", "saint-venant-shaft"),
       "triangular", (W, A))
    tc("pair", ("hysteresis", "housing_compliance"), ("bwbn-pinching", "mindlin-bolted-flange"),
       "holds", (W, A))
    tc("pair", ("backlash", "housing_compliance"), ("erf-deadzone", "saint-venant-shaft"),
       "staircase", (W, A))
    tc("pair", ("backlash", "housing_compliance"), ("oldham-2slot", "mindlin-bolted-flange"),
       "triangular", (W, O))
    tc("decoy_separable", (), (), "triangular", (W, A), meas="stiffness_scale",
       formulation="stiffer-gear s=1.05-1.10/triangular", tag="stiffness_scale")
    tc("decoy_separable", (), (), "staircase", (W, A), meas="torque_gain", mnames=("sensor_gain",),
       formulation="torque-channel gain 1.04-1.12/staircase")
    tc("decoy_separable", (), (), "triangular", (W, O), meas="offset", mnames=("angle_offset",),
       formulation="constant twist zero offset/triangular")
    tc("decoy_separable", (), (), "holds", (W, A), meas="drift", mnames=("thermal_drift",),
       formulation="exponential warm-up drift/holds")
    tc("decoy_separable", (), (), "triangular", (W,), meas="deg", mnames=("wrong_units",),
       formulation="twist in degrees/triangular")
    tc("decoy_separable", (), (), "staircase", (W,), meas="kNm", mnames=("wrong_units",),
       formulation="torque in kN*m/staircase")
    tc("decoy_equivalent", (), (), "triangular", (W, A), meas="soft-seg1",
       formulation="soft gear s=0.70-0.85, test within segment 1/triangular",
       eq=("housing_compliance",), tag="stiffness_scale")
    tc("decoy_equivalent", (), (), "staircase", (W, A), meas="twist_gain",
       mnames=("sensor_gain",), formulation="twist-channel gain 1.18-1.42/staircase",
       eq=("housing_compliance",))
    tc("decoy_equivalent", (), (), "triangular", (W, A), meas="fixture_play",
       mnames=("angle_offset",), formulation="reaction-fixture key play (torque-sign step)/triangular",
       eq=("backlash",))
    tc("decoy_equivalent", (), (), "triangular", (W, A), meas="reversal_step",
       mnames=("angle_offset",), formulation="sensor-arm slip at each reversal/triangular",
       eq=("hysteresis",))

    # ------------------------------ transmission ------------------------------
    def trc(cat, gear, forms, proto, noise, meas=None, mnames=(), formulation=None, eq=(), tag=""):
        eff = list(zip(gear, forms))
        f = formulation or ("+".join(forms) + "/" + proto)
        C.append(Cell("transmission", cat, tuple(gear), tuple(mnames), f,
                      transmission_cell(dict(effects=eff, meas=meas, protocol=proto)), noise, eq,
                      tag))

    trc("clean", (), (), "short", (W, Q), formulation="catalog/short")
    trc("clean", (), (), "long", (A, O), formulation="catalog/long")
    trc("clean", (), (), "coarse", (Q, W), formulation="catalog/coarse")
    trc("single", ("te_1x",), ("wg-runout",), "short", (W, Q))
    trc("single", ("te_1x",), ("runout-sidebands",), "long", (W, A))
    trc("single", ("te_1x",), ("wg-runout",), "coarse", (W, O))
    trc("single", ("te_2x",), ("ellipse-series",), "short", (W, A))
    trc("single", ("te_2x",), ("mesh-sidebands",), "long", (W, Q))
    trc("single", ("te_2x",), ("ellipse-series",), "coarse", (W, O))
    trc("pair", ("te_1x", "te_2x"), ("wg-runout", "ellipse-series"), "short", (W, A))
    trc("pair", ("te_1x", "te_2x"), ("runout-sidebands", "mesh-sidebands"), "long", (W, Q))
    trc("decoy_separable", (), (), "long", (W, A), meas="encoder_eccentricity",
        mnames=("encoder_eccentricity",), formulation="output encoder eccentricity/long")
    trc("decoy_separable", (), (), "long", (W, Q), meas="scale", mnames=("sensor_gain",),
        formulation="output angle-scale error (thermal expansion of scale)/long")
    trc("decoy_separable", (), (), "short", (W, A), meas="step", mnames=("angle_offset",),
        formulation="stepped output offset (coupling slip)/short")
    trc("decoy_separable", (), (), "short", (W, Q), meas="drift", mnames=("thermal_drift",),
        formulation="exponential thermal drift/short")
    trc("decoy_separable", (), (), "short", (W,), meas="deg", mnames=("wrong_units",),
        formulation="output angle in degrees/short")
    trc("decoy_equivalent", (), (), "short", (W, A), meas="input_ecc",
        mnames=("encoder_eccentricity",), formulation="eccentric INPUT encoder disc/short",
        eq=("te_1x",))
    trc("decoy_equivalent", (), (), "coarse", (W, Q), meas="resolver", mnames=("sensor_gain",),
        formulation="input resolver sin/cos gain imbalance/coarse", eq=("te_2x",))

    # ------------------------------ efficiency ------------------------------
    def ec(cat, gear, forms, proto, noise, meas=None, mnames=(), formulation=None, eq=(), tag=""):
        eff = list(zip(gear, forms))
        f = formulation or ("+".join(sorted(set(forms))) + "/" + proto)
        C.append(Cell("efficiency", cat, tuple(gear), tuple(mnames), f,
                      efficiency_cell(dict(effects=eff, meas=meas, protocol=proto)), noise, eq,
                      tag))

    ec("clean", (), (), "full", (W, H), formulation="constant level/full")
    ec("clean", (), (), "sparse", (W, O), formulation="constant level/sparse")
    ec("single", ("low_load_efficiency",), ("bowden-tabor",), "full", (W, H))
    ec("single", ("low_load_efficiency",), ("bowden-tabor",), "sparse", (W, A))
    ec("single", ("low_load_efficiency",), ("schlenk-idle",), "fixed-temp", (W, H))
    ec("single", ("temperature_dependence",), ("ehl-mixed",), "full", (W, A))
    ec("single", ("temperature_dependence",), ("ehl-mixed",), "temp-sweep", (W, H))
    ec("single", ("temperature_dependence",), ("eyring-traction",), "full", (W, O))
    ec("pair", ("low_load_efficiency", "temperature_dependence"),
       ("bowden-tabor x ehl", "bowden-tabor x ehl"), "full", (W, H))
    ec("pair", ("low_load_efficiency", "temperature_dependence"),
       ("hb-grease-drag", "hb-grease-drag"), "full", (W, A))
    ec("decoy_separable", (), (), "full", (W,), meas="level",
       formulation="level off the catalog 78 % (CSF-20-80)/full", tag="level")
    ec("decoy_separable", (), (), "full", (W,), meas="fraction", mnames=("wrong_units",),
       formulation="efficiency as a fraction/full")
    ec("decoy_equivalent", (), (), "full", (W, A), meas="drift_temp", mnames=("thermal_drift",),
       formulation="torque-transducer gain drift with rig temperature/full",
       eq=("temperature_dependence",))

    # ------------------------------ vibration ------------------------------
    def vc(cat, gear, form, proto, noise, meas=None, mnames=(), formulation=None, eq=(), tag=""):
        eff = [(g, form) for g in gear]
        f = formulation or (form + "/" + proto)
        C.append(Cell("vibration", cat, tuple(gear), tuple(mnames), f,
                      vibration_cell(dict(effects=eff, meas=meas, protocol=proto, form=form)),
                      noise, eq, tag))

    vc("clean", (), "none", "slow-ramp", (W, A), formulation="no excitation/slow-ramp")
    vc("clean", (), "none", "slow-scurve", (A, O), formulation="no excitation/slow-scurve")
    vc("clean", (), "none", "fast-scurve", (Q, W), formulation="no excitation/fast-scurve")
    vc("single", ("te_1x",), "coulomb-hb", "slow-ramp", (W, A))
    vc("single", ("te_1x",), "duffing-hb", "slow-scurve", (W, O))
    vc("single", ("te_2x",), "duffing-hb", "slow-ramp", (W, A))
    vc("single", ("te_2x",), "foh-exact", "fast-scurve", (W, Q))
    vc("pair", ("te_1x", "te_2x"), "linear-hb", "slow-scurve", (W, A))
    vc("pair", ("te_1x", "te_2x"), "foh-exact", "fast-scurve", (W, O))
    vc("decoy_separable", (), "none", "slow-ramp", (W, A), meas="drift", mnames=("thermal_drift",),
       formulation="exponential drift/slow-ramp")
    vc("decoy_separable", (), "none", "slow-scurve", (W, O), meas="step", mnames=("angle_offset",),
       formulation="stepped offset/slow-scurve")
    vc("decoy_separable", (), "none", "slow-ramp", (W, A), meas="encoder_eccentricity",
       mnames=("encoder_eccentricity",), formulation="output encoder eccentricity/slow-ramp")
    vc("decoy_equivalent", (), "none", "slow-ramp", (W, A), meas="cardan",
       formulation="Cardan joint in the input line (2/rev)/slow-ramp", eq=("te_2x",),
       tag="drive_line")
    vc("decoy_equivalent", (), "none", "slow-scurve", (W, A), meas="belt",
       formulation="1:1 belt drive, eccentric pulley (1/rev)/slow-scurve", eq=("te_1x",),
       tag="drive_line")
    return C


CELLS = _cells()


class _Ctx:
    def __init__(self, rng, cat):
        self.rng, self.cat = rng, cat
        self.attempt = 0


def _one_case(cell: Cell, idx: int, rng, cat) -> TruthCase:
    ctx = _Ctx(rng, cat)
    for attempt in range(6):
        ctx.attempt = attempt
        b = cell.builder(ctx)
        n_eff = (len(cell.gear) if cell.gear else (0 if cell.category == "clean" else 1))
        ks = _draw_ks(rng, n_eff)
        try:
            res = b["make"](ks)
            demean = res.get("demean", b["demean"])
            if n_eff >= 2:
                ks2 = _balance(res["parts"], ks, res["sigma"], demean)
                if ks2 != ks:
                    res = b["make"](ks2)
        except (ValueError, StopIteration):
            if attempt == 5:
                raise
            continue                                          # parameters not realisable: redraw
        chk = b.get("check")
        ok = chk is None or chk(res, res["sigma"])
        if ok:
            break
    noise_kind = _choice(rng, list(cell.noise))
    clean = np.asarray(res["y"], dtype=float)
    weight = b.get("noise_weight") if noise_kind == "hetero" else None
    noise = make_noise(rng, noise_kind, res["sigma"], clean, weight)
    y = clean + noise
    cols = b["columns"](res, y)
    cols = {k: np.asarray(v, dtype=float).copy() for k, v in cols.items()}
    nrms = _rms(noise)
    parts = [np.asarray(p, dtype=float) for p in res["parts"]]
    snr = _rms_eff(sum(parts), demean) / nrms if parts else 0.0
    tag = "+".join(cell.gear) or "+".join(cell.meas) or cell.tag or "catalog"
    name = f"{SUITE}-{cell.kind}-{cell.category}-{_slug(tag)}-{_slug(cell.formulation)}-{idx:03d}"
    tc = TruthCase(
        name=name, kind=cell.kind, model=b["model"], columns=cols,
        load_inertia_kgm2=float(b["J"]) if cell.kind == "vibration" else None,
        gear_effects=tuple(cell.gear), measurement_effects=tuple(cell.meas),
        nuisance={k: float(v) for k, v in {**b["nuisance"], **res.get("nuisance", {})}.items()},
        category=cell.category,
        equivalent_effects=tuple(cell.equivalent), noise_rms=float(nrms),
        formulation=cell.formulation, snr=float(snr))
    # private, for the self-check only (not part of the contract)
    tc._clean = clean
    tc._parts = parts
    tc._demean = demean
    tc._exempt = bool(res.get("exempt", False))
    tc._noise_kind = noise_kind
    tc._measured = b["measured"]
    tc._check_failed = not ok
    tc._attempts = attempt + 1
    return tc


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    rng = np.random.default_rng(seed)
    cat = Catalog(catalog_dir)
    out = []
    for cell in CELLS:
        for i in range(per_cell):
            out.append(_one_case(cell, i, rng, cat))
    return out


# ----------------------------------------------------------------------------------------------
# self-check
# ----------------------------------------------------------------------------------------------
def _selfcheck(catalog_dir):
    import tempfile
    import time
    from collections import Counter

    problems = []
    t0 = time.time()
    c11 = generate_cases(11, catalog_dir, 2)
    t11 = time.time() - t0
    print(f"generate_cases(11, ..., 2): {len(c11)} cases in {t11:.2f} s")
    for seed in (7, 11, 13):
        a = generate_cases(seed, catalog_dir, 2) if seed != 11 else c11
        b = generate_cases(seed, catalog_dir, 2)
        for x, y in zip(a, b):
            if x.name != y.name or x.model != y.model or any(
                    not np.array_equal(x.columns[k], y.columns[k]) for k in x.columns):
                problems.append(f"seed {seed}: not deterministic: {x.name}")
        names = [c.name for c in a]
        if len(set(names)) != len(names):
            problems.append(f"seed {seed}: duplicate names")
        for c in a:
            nm = c._measured
            noise = c.columns[nm] - c._clean
            if abs(_rms(noise) - c.noise_rms) > 1e-9 * max(c.noise_rms, 1e-30):
                problems.append(f"{c.name}: noise_rms mismatch")
            if c.category in ("clean", "decoy_separable", "decoy_equivalent") and c.gear_effects:
                problems.append(f"{c.name}: decoy/clean with gear effects")
            if c.category == "decoy_equivalent" and not c.equivalent_effects:
                problems.append(f"{c.name}: no equivalent_effects")
            if c.category == "clean":
                if c.snr != 0.0 or c._parts:
                    problems.append(f"{c.name}: clean with effects")
                continue
            if getattr(c, "_check_failed", False):
                problems.append(f"{c.name}: plausibility/equivalence check failed 6 times")
            if c._exempt:
                continue
            ratios = [_rms_eff(p, c._demean) / c.noise_rms for p in c._parts]
            tot = _rms_eff(sum(c._parts), c._demean) / c.noise_rms
            if abs(tot - c.snr) > 1e-6 * tot:
                problems.append(f"{c.name}: snr field {c.snr} != {tot}")
            for r in ratios + [tot]:
                if not (KMIN <= r <= KMAX):
                    problems.append(f"{c.name}: snr {r:.2f} out of [4, 12] (parts {ratios})")
            for k, v in c.columns.items():
                if not np.all(np.isfinite(v)):
                    problems.append(f"{c.name}: non-finite {k}")
        with tempfile.TemporaryDirectory() as td:
            for c in a:
                p = Path(td) / (c.name + ".csv")
                c.write_csv(p)
                with open(p) as fh:
                    hdr = fh.readline().strip().split(",")
                arr = np.loadtxt(p, delimiter=",", skiprows=1, ndmin=2)
                if hdr != list(c.columns) or arr.shape[0] != len(next(iter(c.columns.values()))):
                    problems.append(f"{c.name}: CSV shape")
                for j, k in enumerate(hdr):
                    if not np.array_equal(arr[:, j], c.columns[k]):
                        problems.append(f"{c.name}: CSV round trip {k}")
    # cell table
    cnt = Counter((c.kind, c.category, "+".join(c.gear_effects) or "+".join(c.measurement_effects)
                   or "-", c.formulation) for c in c11)
    print(f"\n{len(CELLS)} cells")
    print(f"{'kind':13s} {'category':17s} {'effects':42s} {'formulation':62s} n")
    for (k, cat_, eff, f), n in cnt.items():
        print(f"{k:13s} {cat_:17s} {eff:42s} {f:62s} {n}")
    rows = {k: [] for k in ("torsion", "transmission", "efficiency", "vibration")}
    for c in c11:
        rows[c.kind].append(len(next(iter(c.columns.values()))))
    for k, v in rows.items():
        print(f"rows {k}: {min(v)}-{max(v)}")
    snrs = [c.snr for c in c11 if c.snr and not c._exempt]
    print(f"snr range (non-exempt): {min(snrs):.2f}-{max(snrs):.2f}")
    print(Counter(c.model.split('-')[0] + ('-GH' if c.model.endswith('GH') else '') for c in c11))
    print("\nPROBLEMS:" if problems else "\nall checks passed", *problems[:60], sep="\n")
    return problems


if __name__ == "__main__":
    import sys
    _selfcheck(sys.argv[1] if len(sys.argv) > 1 else "/work/main/catalog")
