"""Truth suite "i" for ``hdcad reconcile`` (independent; written from CONTRACT.md, the catalog
tables and the physics literature only -- see NOTES_i.md for every formulation, reference,
parameter range and interpretation).

numpy + scipy only; imports nothing from hdcad.

    cases = generate_cases(seed, catalog_dir, per_cell=4)

Every (kind, category, effect-combination, formulation) cell gets ``per_cell`` cases.  Each
cell owns a child generator seeded from ``numpy.random.default_rng(seed)`` in a fixed cell order,
so the cases of a cell do not depend on ``per_cell`` of other cells and the first n cases of a
cell are the same for every per_cell >= n.
"""
from __future__ import annotations

import csv
import math
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import optimize, signal, special

SUITE = "i"

# --------------------------------------------------------------------------------------------
# case container (contract fields + one optional extension field ``details``)
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
    # extension (not in the contract, ignored by a scorer that does not know it): protocol,
    # per-effect SNR, physical parameters actually used.
    details: dict = field(default_factory=dict)

    def write_csv(self, path) -> None:
        names = list(self.columns)
        cols = [np.asarray(self.columns[c], dtype=float) for c in names]
        n = len(cols[0])
        with open(path, "w", newline="", encoding="utf-8") as fh:
            fh.write(",".join(names) + "\n")
            for i in range(n):
                fh.write(",".join(repr(float(c[i])) for c in cols) + "\n")


# --------------------------------------------------------------------------------------------
# small helpers
# --------------------------------------------------------------------------------------------

KIND_COLUMNS = {
    "torsion": ("torque_Nm", "twist_rad"),
    "transmission": ("input_angle_rad", "output_angle_rad"),
    "efficiency": ("input_speed_rpm", "load_torque_Nm", "temperature_C", "efficiency_pct"),
    "vibration": ("time_s", "input_speed_rpm", "output_vibration_rad"),
}


def _rms(x) -> float:
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.mean(x * x))) if x.size else 0.0


def _rms0(x) -> float:
    x = np.asarray(x, dtype=float)
    return _rms(x - x.mean()) if x.size else 0.0


def _k(rng) -> float:
    """Effect size factor k from CONTRACT 'Effect sizes': uniform in [4, 12]."""
    return float(rng.uniform(4.0, 12.0))


def _loguniform(rng, lo, hi) -> float:
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def _stiffness_scale(rng) -> float:
    """Nuisance stiffness scale: symmetric Beta(2,2) mapped onto 1 +- 10 %."""
    return float(1.0 + 0.10 * (2.0 * rng.beta(2.0, 2.0) - 1.0))


def _edge_stiffness_scale(rng) -> float:
    return float(1.0 + rng.choice([-1.0, 1.0]) * rng.uniform(0.08, 0.10))


def _make_noise(rng, n, sigma, kind):
    """White Gaussian or AR(1) (phi in [0.3, 0.8]) noise with sample RMS exactly sigma."""
    info = {"noise": kind}
    e = rng.standard_normal(n)
    if kind == "ar1":
        phi = float(rng.uniform(0.3, 0.8))
        info["ar1_phi"] = phi
        w = signal.lfilter([1.0], [1.0, -phi], e * math.sqrt(1.0 - phi * phi))
    else:
        w = e
    w = w / _rms(w) * sigma
    return w, info


def _add_outliers(rng, w, sigma):
    """0.5 % of rows (at least 1) get a gross error of 8-15 x sigma, random sign."""
    n = len(w)
    m = max(1, int(round(0.005 * n)))
    idx = np.sort(rng.choice(n, m, replace=False))
    w = w.copy()
    w[idx] += rng.choice([-1.0, 1.0], m) * rng.uniform(8.0, 15.0, m) * sigma
    return w, idx


def _noise_block(rng, n, sigma, mode):
    """mode: 'white' | 'ar1' | 'outliers' (outliers on white or AR(1))."""
    if mode == "outliers":
        base = "white" if rng.random() < 0.5 else "ar1"
        w, info = _make_noise(rng, n, sigma, base)
        w, idx = _add_outliers(rng, w, sigma)
        info["outliers"] = int(len(idx))
        info["noise"] = base + "+outliers"
    else:
        w, info = _make_noise(rng, n, sigma, mode)
    return w, info


def _effect_noise_mode(rng):
    return "white" if rng.random() < 0.5 else "ar1"


# --------------------------------------------------------------------------------------------
# catalog (read-only tables in catalog_dir)
# --------------------------------------------------------------------------------------------


def _num(x):
    x = (x or "").strip()
    return float(x) if x else None


def _read(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


class _Catalog:
    def __init__(self, catalog_dir):
        d = Path(catalog_dir)
        self.stiff = _read(d / "gh_stiffness_052-1_060-1.csv")
        self.hyst = _read(d / "gh_hysteresis_052_060.csv")
        self.back = _read(d / "gh_backlash_052-2_060-2.csv")
        self.perf = _read(d / "gh_performance_051-1_059-1.csv")
        self.rate = _read(d / "gh_ratings_050-1_058-1.csv")
        self.ke = _read(d / "ke_curve_023-1.csv")
        self.lub = _read(d / "lubricant_temperature_016-2_019.csv")
        self.flange = _read(d / "gh_motor_flange.csv")
        self.seals = _read(d / "shaft_seal_iso6194.csv")
        self.examples = _read(d / "component_examples.csv")
        self.models = self._build()
        if not self.models:
            raise RuntimeError("no usable gear-head model in the catalog tables")

    @staticmethod
    def _in_group(row, ratio):
        lo = _num(row["ratio_min"])
        hi = _num(row["ratio_max"])
        return lo is not None and ratio >= lo and (hi is None or ratio <= hi)

    def _build(self):
        out = []
        for r in self.rate:
            series, size, ratio = r["series"], int(r["size"]), int(r["ratio"])
            st = [s for s in self.stiff if s["series"] == series and int(s["size"]) == size
                  and self._in_group(s, ratio)]
            hy = [h for h in self.hyst if h["series"] == series and self._in_group(h, ratio)]
            bl = [b for b in self.back if b["series"] == series and int(b["size"]) == size
                  and int(b["ratio"]) == ratio]
            pf = [p for p in self.perf if p["series"] == series and int(p["size"]) == size
                  and int(p["ratio"]) == ratio]
            if not (st and hy and bl and pf):
                continue
            # input-code group: 'all' if printed, else the first group listed (E, KP..KS)
            pf_all = [p for p in pf if p["input_codes"] == "all"]
            p = pf_all[0] if pf_all else pf[0]
            s = st[0]
            bores = [_num(f["coupling_bore_max_mm"]) for f in self.flange
                     if f["series"] == series and int(f["size"]) == size]
            bores = [b for b in bores if b is not None]
            m = dict(
                series=series, size=size, ratio=ratio,
                code=f"{series.split('-')[0]}-{size}-{ratio}-GH",
                rated=_num(r["rated_torque_2000_Nm"]),
                avg_in_rpm=_num(r["avg_input_speed_max_rpm"]),
                max_in_rpm=_num(r["max_input_speed_rpm"]),
                T1=_num(s["T1_Nm"]), T2=_num(s["T2_Nm"]),
                K1=_num(s["K1_Nm_per_rad"]), K2=_num(s["K2_Nm_per_rad"]),
                K3=_num(s["K3_Nm_per_rad"]),
                theta1=_num(s["theta1_rad"]), theta2=_num(s["theta2_rad"]),
                hyst=_num(hy[0]["hysteresis_rad"]),
                backlash=_num(bl[0]["backlash_rad"]),
                acc=_num(p["accuracy_rad"]),
                backdrive=_num(p["backdriving_torque_Nm"]),
                input_codes=p["input_codes"],
                coupling_bore_max_mm=max(bores) if bores else None,
            )
            out.append(m)
        return out

    def pick(self, rng, need=()):
        pool = [m for m in self.models if all(m.get(k) is not None for k in need)]
        return pool[int(rng.integers(len(pool)))]

    def ke_anchor(self):
        """(alpha, Ke) point of graph 023-1 below rated torque (ke_curve_023-1.csv)."""
        pts = [(float(r["alpha"]), float(r["Ke"])) for r in self.ke if float(r["alpha"]) < 1.0]
        return pts[0]

    def seal_for(self, d_mm):
        rows = sorted(self.seals, key=lambda r: float(r["d1_mm"]))
        for r in rows:
            if float(r["d1_mm"]) >= d_mm:
                return r
        return rows[-1]

    def eta_rated_example(self):
        """Efficiency at rated torque of the seed's worked example (component_examples.csv,
        CSF-20-80, 000 p.023: 78 %)."""
        for r in self.examples:
            v = _num(r.get("efficiency_rated_pct"))
            if v is not None:
                return v
        raise RuntimeError("no efficiency example in component_examples.csv")

    def lubricants(self):
        """Rows of table 016-2/019-1 usable as a test-lubricant temperature range."""
        rows = []
        for r in self.lub:
            if r["basis"] in ("ambient", "lubricated_part") and _num(r["use_min_C"]) is not None:
                rows.append(r)
        return rows


# --------------------------------------------------------------------------------------------
# torsion: catalog curve with Hermite-blended corners
# --------------------------------------------------------------------------------------------


def _hermite(t, h, ya, yb, ma, mb, order):
    if order == 3:
        t2, t3 = t * t, t * t * t
        return ((2 * t3 - 3 * t2 + 1) * ya + (t3 - 2 * t2 + t) * h * ma
                + (-2 * t3 + 3 * t2) * yb + (t3 - t2) * h * mb)
    t3, t4, t5 = t ** 3, t ** 4, t ** 5
    return ((1 - 10 * t3 + 15 * t4 - 6 * t5) * ya + (t - 6 * t3 + 8 * t4 - 3 * t5) * h * ma
            + (10 * t3 - 15 * t4 + 6 * t5) * yb + (-4 * t3 + 7 * t4 - 3 * t5) * h * mb)


def _make_curve(m, rng):
    """Odd twist curve theta(T): the contract's three lines (T/K1; theta1+(T-T1)/K2;
    theta2+(T-T2)/K3 with the catalog theta1/theta2) joined by a local cubic (C1) or quintic
    (C2) Hermite bridge of half-width w around T1 and T2."""
    T1, T2, K1, K2, K3 = m["T1"], m["T2"], m["K1"], m["K2"], m["K3"]
    th1, th2 = m["theta1"], m["theta2"]
    order = 3 if rng.random() < 0.5 else 5
    frac = float(rng.uniform(0.05, 0.20))
    L = [lambda x: x / K1, lambda x: th1 + (x - T1) / K2, lambda x: th2 + (x - T2) / K3]
    S = [1.0 / K1, 1.0 / K2, 1.0 / K3]
    for _ in range(12):
        w1 = frac * min(T1, T2 - T1)
        w2 = frac * (T2 - T1)

        def fn(T, w1=w1, w2=w2):
            T = np.asarray(T, dtype=float)
            x = np.abs(T)
            y = np.where(x <= T1, L[0](x), np.where(x <= T2, L[1](x), L[2](x)))
            for (c, w, i) in ((T1, w1, 0), (T2, w2, 1)):
                a, b = c - w, c + w
                msk = (x > a) & (x < b)
                if np.any(msk):
                    t = (x[msk] - a) / (b - a)
                    y[msk] = _hermite(t, b - a, L[i](a), L[i + 1](b), S[i], S[i + 1], order)
            return np.sign(T) * y

        g = np.linspace(0.0, 1.3 * max(T2, m["rated"]), 4001)
        if np.all(np.diff(fn(g)) > 0):
            return fn, {"corner": "cubic-hermite" if order == 3 else "quintic-hermite",
                        "corner_halfwidth_frac": frac}
        frac = min(0.45, frac * 1.3)
    raise RuntimeError("could not build a monotone catalog curve")


# --------------------------------------------------------------------------------------------
# torsion: hysteresis, play and series-spring unit components (torque-driven)
# --------------------------------------------------------------------------------------------


def _af_unit(T, Ty, Xsat):
    """Armstrong-Frederick nonlinear kinematic hardening, torque controlled, C = 1.
    Yield |T - X| <= Ty; dX = C dthp - gamma X |dthp|, gamma = C/Xsat.  Exact per increment:
    on a plastic increment with flow sign s, X(lam) = s Xsat + (X0 - s Xsat) exp(-lam/Xsat)."""
    out = np.empty(len(T))
    X = 0.0
    tp = 0.0
    for i, Ti in enumerate(np.asarray(T, dtype=float)):
        d = Ti - X
        if d > Ty:
            s, Xn = 1.0, Ti - Ty
        elif d < -Ty:
            s, Xn = -1.0, Ti + Ty
        else:
            out[i] = tp
            continue
        a0, a1 = X - s * Xsat, Xn - s * Xsat
        lam = Xsat * math.log(a0 / a1)
        tp += s * lam
        X = Xn
        out[i] = tp
    return out


def _md_unit(T, Ts):
    """Cattaneo-Mindlin-Deresiewicz microslip of a radially preloaded contact (delta_s = 1),
    gross-slip torque Ts: backbone g(x) = 1 - (1 - x/Ts)^(2/3); branches by Masing's rule
    (reversal point + 2 g(dT/2)), which is Mindlin-Deresiewicz's own unloading law.  The no-slip
    tangential compliance (2/3)/Ts (the initial tangent) is removed: it belongs to the elastic
    curve the catalog already describes, so only the slip part is returned."""
    T = np.asarray(T, dtype=float)

    def g(x):
        return 1.0 - np.power(np.clip(1.0 - x / Ts, 0.0, None), 2.0 / 3.0)

    out = np.empty(len(T))
    virgin = True
    d = 0.0
    Tr = 0.0
    dr = 0.0
    prevT = 0.0
    prevD = 0.0
    for i, Ti in enumerate(T):
        dT = Ti - prevT
        if dT != 0.0:
            sd = 1.0 if dT > 0 else -1.0
            if d == 0.0:
                d = sd
            elif sd != d:  # reversal at the previous sample
                virgin = False
                Tr, dr = prevT, prevD
                d = sd
        if virgin:
            val = float(np.sign(Ti) * g(abs(Ti)))
        else:
            val = dr + d * 2.0 * float(g(abs(Ti - Tr) / 2.0))
        out[i] = val
        prevT, prevD = Ti, val
    return out - (2.0 / 3.0) / Ts * T


def _play_unit(T, thr, g0=0.0):
    """Play of total width 1 (state -0.5 .. +0.5) that is carried across when the torque
    passes +thr / -thr (thr = 0: exact dead zone, T == 0 keeps the previous state)."""
    T = np.asarray(T, dtype=float)
    st = np.full(len(T), np.nan)
    st[T > thr] = 0.5
    st[T < -thr] = -0.5
    if thr == 0.0:
        st[T > 0] = 0.5
        st[T < 0] = -0.5
    # forward fill
    idx = np.where(~np.isnan(st), np.arange(len(T)), 0)
    np.maximum.accumulate(idx, out=idx)
    res = st[idx]
    first = np.argmax(~np.isnan(st)) if np.any(~np.isnan(st)) else len(T)
    res[:first] = g0
    res[np.isnan(res)] = g0
    return res


def _loop_loss(unit, T0, n=1500):
    """Twist difference B-B' at zero torque on the major loop 0 -> +T0 -> -T0 -> +T0."""
    up0 = np.linspace(0.0, T0, n)
    dn = np.linspace(T0, -T0, 2 * n)[1:]
    up = np.linspace(-T0, T0, 2 * n)[1:]
    T = np.concatenate([up0, dn, up])
    h = unit(T)
    hd = h[n:n + len(dn)]
    hu = h[n + len(dn):]
    v_d = np.interp(0.0, dn[::-1], hd[::-1])
    v_u = np.interp(0.0, up, hu)
    return float(v_d - v_u)


# --------------------------------------------------------------------------------------------
# torsion: test protocols
# --------------------------------------------------------------------------------------------


def _waypoints(T0, cycles):
    w = [0.0, T0]
    for _ in range(cycles):
        w += [-T0, T0]
    w.append(0.0)
    return w


def _protocol_torque_ramp(rng, T0):
    """P1: torque-controlled triangular ramps between +-T0, sampled at a fixed rate."""
    cycles = int(rng.integers(1, 3))
    nq = int(rng.integers(60, 151))
    tq = float(rng.uniform(20.0, 60.0))  # s per T0 of torque travel
    W = _waypoints(T0, cycles)
    Ts = [np.array([0.0])]
    for a, b in zip(W[:-1], W[1:]):
        n = max(2, int(round(abs(b - a) / T0 * nq)))
        Ts.append(np.linspace(a, b, n + 1)[1:])
    T = np.concatenate(Ts)
    t = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(T)))]) / T0 * tq
    return dict(T=T, t=t, name=f"P1 torque-ramp {cycles} cycle(s), {nq} samples per T0, "
                f"{tq:.0f} s per T0", controlled="torque")


def _protocol_staircase(rng, T0):
    """P2: stepwise (staircase) loading, dwell at each level, several readings per dwell."""
    cycles = int(rng.integers(1, 3))
    ms = int(rng.integers(8, 16))
    reps = int(rng.integers(3, 9))
    dwell = float(rng.uniform(10.0, 30.0))
    W = _waypoints(T0, cycles)
    levels = [0.0]
    for a, b in zip(W[:-1], W[1:]):
        n = max(1, int(round(abs(b - a) / T0 * ms)))
        levels += list(np.linspace(a, b, n + 1)[1:])
    T = np.repeat(np.array(levels), reps)
    step_t = np.repeat(np.arange(len(levels)) * dwell, reps)
    within = np.tile(dwell * (0.5 + 0.5 * np.arange(reps) / reps), len(levels))
    t = step_t + within
    return dict(T=T, t=t, levels=np.array(levels), reps=reps,
                name=f"P2 staircase {cycles} cycle(s), {ms} steps per T0, {reps} readings per "
                f"step, dwell {dwell:.0f} s", controlled="torque")


def _dense_path(T0, cycles, n_dense, insert_gap, n_ins=60):
    """Dense torque path for the displacement-controlled protocol; with insert_gap, a traverse
    of the unit play (state -0.5 .. +0.5) is inserted at T = 0 whenever the torque changes
    sign (the slider crosses its clearance with no torque)."""
    W = _waypoints(T0, cycles)
    T_l, G_l, L_l = [np.array([0.0])], [np.array([0.0])], [np.array([0])]
    gap = 0.0
    for leg, (a, b) in enumerate(zip(W[:-1], W[1:])):
        d = 1.0 if b > a else -1.0
        pieces = [(a, b)]
        if a * b < 0:
            pieces = [(a, 0.0), (0.0, b)]
        for (p, q) in pieces:
            n = max(2, int(round(abs(q - p) / T0 * n_dense)))
            seg = np.linspace(p, q, n + 1)[1:]
            if insert_gap and p == 0.0 and q != 0.0 and gap != 0.5 * d:
                ins = np.linspace(gap, 0.5 * d, n_ins + 1)[1:]
                T_l.append(np.zeros(n_ins))
                G_l.append(ins)
                L_l.append(np.full(n_ins, leg))
                gap = 0.5 * d
            T_l.append(seg)
            G_l.append(np.full(len(seg), gap))
            L_l.append(np.full(len(seg), leg))
    return np.concatenate(T_l), np.concatenate(G_l), np.concatenate(L_l), W


class _TorsionRun:
    """Holds the torque history and unit components; ``evaluate(amps)`` gives samples.

    components: name -> ('fn', callable(T)->unit array) or ('gap', None) for the inserted play.
    """

    def __init__(self, rng, T0, protocol, curve_fn, scale, comps, need_gap):
        self.T0 = T0
        self.protocol = protocol
        self.comps = comps
        if protocol in ("P1", "P2"):
            p = _protocol_torque_ramp(rng, T0) if protocol == "P1" else _protocol_staircase(rng, T0)
            self.T, self.t, self.pname = p["T"], p["t"], p["name"]
            self.base = curve_fn(self.T) / scale
            self.units = {}
            for k, (typ, fn) in comps.items():
                self.units[k] = fn(self.T)
            self.info = p
        else:  # P3 displacement (screw jack) controlled through a compliant lever
            cycles = int(rng.integers(1, 3))
            self.nq = int(rng.integers(60, 151))
            self.kf = float(rng.uniform(0.3, 1.5))  # lever+jack stiffness / K1 (set later)
            self.cycles = cycles
            Td, Gd, Ld, W = _dense_path(T0, cycles, 1500, need_gap)
            self.Td, self.Ld, self.W = Td, Ld, W
            self.base_d = curve_fn(Td) / scale
            self.units_d = {}
            for k, (typ, fn) in comps.items():
                self.units_d[k] = Gd if typ == "gap" else fn(Td)
            self.jack_s = float(rng.uniform(20.0, 60.0))  # s per T0-equivalent of jack travel
            self.pname = (f"P3 displacement-controlled screw jack through a compliant lever, "
                          f"{cycles} cycle(s), ~{self.nq} samples per T0")

    def set_lever(self, K1):
        if self.protocol == "P3":
            self.kf_abs = self.kf * K1

    def evaluate(self, amps):
        if self.protocol in ("P1", "P2"):
            comps = {k: amps[k] * self.units[k] for k in self.units}
            return self.T.copy(), self.t.copy(), self.base.copy(), comps
        th = self.base_d.copy()
        for k, u in self.units_d.items():
            th = th + amps[k] * u
        phi = th + self.Td / self.kf_abs
        idx_s = []
        u_all = np.arange(len(self.Td), dtype=float)
        phi_total = 0.0
        t_s = []
        for leg in range(len(self.W) - 1):
            sel = np.where(self.Ld == leg)[0]
            if leg == 0:
                sel = np.concatenate([[0], sel]) if sel[0] != 0 else sel
            else:
                sel = np.concatenate([[sel[0] - 1], sel])
            ph = phi[sel]
            d = 1.0 if ph[-1] > ph[0] else -1.0
            n = max(2, int(round(abs(self.W[leg + 1] - self.W[leg]) / self.T0 * self.nq)))
            targets = np.linspace(ph[0], ph[-1], n + 1)
            if leg > 0:
                targets = targets[1:]
            # phi is monotone along a leg; make it strictly so for interpolation
            phm = d * ph
            phm = np.maximum.accumulate(phm) + np.arange(len(phm)) * 1e-18
            uu = np.interp(d * targets, phm, u_all[sel])
            idx_s.append(uu)
            tt = phi_total + np.abs(targets - ph[0])
            t_s.append(tt)
            phi_total += abs(ph[-1] - ph[0])
        uu = np.concatenate(idx_s)
        T = np.interp(uu, u_all, self.Td)
        base = np.interp(uu, u_all, self.base_d)
        comps = {k: amps[k] * np.interp(uu, u_all, u) for k, u in self.units_d.items()}
        scale_t = self.jack_s / (self.T0 / self.kf_abs + 1e-300)
        t = np.concatenate(t_s) * scale_t
        return T, t, base, comps


# --------------------------------------------------------------------------------------------
# torsion: effect parameterisations (physical first)
# --------------------------------------------------------------------------------------------


def _hyst_component(rng, m, T0, form):
    target = m["hyst"] * float(rng.uniform(0.6, 1.4))
    if form == "armstrong-frederick":
        Ty = float(rng.uniform(0.05, 0.25)) * T0
        Xsat = (T0 - Ty) * float(rng.uniform(1.15, 2.0))
        fn = lambda T, Ty=Ty, Xsat=Xsat: _af_unit(T, Ty, Xsat)
        par = {"yield_torque_Nm": Ty, "backstress_saturation_Nm": Xsat}
    else:
        Ts = T0 / float(rng.uniform(0.6, 0.95))
        fn = lambda T, Ts=Ts: _md_unit(T, Ts)
        par = {"gross_slip_torque_Nm": Ts}
    L = _loop_loss(fn, T0)
    amp = target / L
    par["loss_BBprime_rad"] = target
    par["catalog_hysteresis_rad"] = m["hyst"]
    return ("fn", fn), amp, par


def _backlash_component(rng, m, T0, form):
    b = m["backlash"] * float(rng.uniform(0.5, 1.0))
    par = {"play_rad": b, "catalog_max_backlash_rad": m["backlash"]}
    if form == "exact-deadzone":
        return ("gap", lambda T: _play_unit(T, 0.0)), b, par
    thr = min(float(rng.uniform(0.1, 0.4)) * m["backdrive"], 0.15 * T0)
    par["breakaway_torque_Nm"] = thr
    par["catalog_backdriving_torque_Nm"] = m["backdrive"]
    return ("fn", lambda T, thr=thr: _play_unit(T, thr)), b, par


def _housing_component(rng, m, form):
    D = m["size"] * 2.54e-3  # pitch-circle scale D = size x 0.00254 m (seed 000 p.027)
    K1 = m["K1"]
    for _ in range(50):
        r_o = 0.5 * D * float(rng.uniform(0.75, 0.95))
        if form == "huth-bolt-circle":
            n_b = int(rng.choice([6, 8, 12, 16]))
            d = min([3, 4, 5, 6, 8, 10, 12, 16], key=lambda q: abs(q - 0.06 * D * 1e3)) * 1e-3
            t1 = float(rng.uniform(0.8, 2.0)) * d
            t2 = float(rng.uniform(0.8, 2.0)) * d
            E1 = float(rng.choice([7.0e10, 2.1e11]))
            E2 = E3 = 2.1e11
            a, bb, nsh = 2.0 / 3.0, 3.0, 1.0
            C = (((t1 + t2) / (2 * d)) ** a * (bb / nsh)
                 * (1 / (t1 * E1) + 1 / (nsh * t2 * E2) + 1 / (2 * t1 * E3) + 1 / (2 * nsh * t2 * E3)))
            Kh = n_b * r_o ** 2 / C
            par = {"bolts": n_b, "bolt_d_m": d, "bolt_circle_r_m": r_o, "t1_m": t1, "t2_m": t2,
                   "E1_Pa": E1, "fastener_flexibility_m_per_N": C}
        else:
            r_i = r_o * float(rng.uniform(0.3, 0.6))
            t = float(rng.uniform(0.04, 0.12)) * D
            G = float(rng.choice([2.6e10, 7.93e10]))
            Kh = 4 * math.pi * G * t / (1 / r_i ** 2 - 1 / r_o ** 2)
            par = {"r_inner_m": r_i, "r_outer_m": r_o, "thickness_m": t, "G_Pa": G}
        if 2.0 <= Kh / K1 <= 40.0:
            break
    par["K_h_Nm_per_rad"] = Kh
    par["K_h_over_K1"] = Kh / K1
    return ("fn", lambda T: np.asarray(T, dtype=float)), 1.0 / Kh, par


# --------------------------------------------------------------------------------------------
# torsion case builder
# --------------------------------------------------------------------------------------------


def _thermal_drift_shape(t, form, rng):
    tn = t / max(t[-1], 1e-12)
    if form == "sqrt-t-conduction":
        return np.sqrt(tn), {}
    tau1 = float(rng.uniform(0.15, 0.6))
    tau2 = tau1 * float(rng.uniform(0.1, 0.4))
    shp = 1.0 - (tau1 * np.exp(-tn / tau1) - tau2 * np.exp(-tn / tau2)) / (tau1 - tau2)
    return shp, {"tau1_frac": tau1, "tau2_frac": tau2}


def _build_torsion(rng, cat, cell, idx):
    cate, effs, forms, decoy = cell["category"], cell["effects"], cell["forms"], cell.get("decoy")
    m = cat.pick(rng)
    T0 = m["rated"]
    curve, cinfo = _make_curve(m, rng)
    s = _edge_stiffness_scale(rng) if decoy == "stiffness-scale-edge" else _stiffness_scale(rng)
    nuis = {"stiffness_scale": s}
    det = {"T0_Nm": T0, "catalog_curve": cinfo}

    comps, amps, params = {}, {}, {}
    for e in effs:
        f = forms[e]
        if e == "hysteresis":
            comps[e], amps[e], params[e] = _hyst_component(rng, m, T0, f)
        elif e == "backlash":
            comps[e], amps[e], params[e] = _backlash_component(rng, m, T0, f)
        else:
            comps[e], amps[e], params[e] = _housing_component(rng, m, f)
    # rig-side components of data-equivalent decoys
    if decoy == "lever-lvdt-compliance":
        comps["rig"] = ("fn", lambda T: np.asarray(T, dtype=float))
        amps["rig"] = 1.0
    elif decoy == "lever-spline-clearance":
        comps["rig"] = ("gap", lambda T: _play_unit(T, 0.0))
        amps["rig"] = 1.0

    allowed = cell.get("protocols", ("P1", "P2", "P3"))
    if any(e == "backlash" and forms[e] == "backdrive-held-play" for e in effs):
        allowed = tuple(p for p in allowed if p != "P3")
    protocol = allowed[int(rng.integers(len(allowed)))]
    need_gap = any(c[0] == "gap" for c in comps.values())
    run = _TorsionRun(rng, T0, protocol, curve, s, comps, need_gap)
    run.set_lever(m["K1"])
    det["protocol"] = run.pname

    mode = cell.get("noise", None) or _effect_noise_mode(rng)
    th_T0 = float(curve(np.array([T0]))[0])
    gear_keys = [e for e in effs]
    ks = {}
    if cate in ("single", "pair"):
        # physical amplitudes first; in a pair the two amplitudes are moved by reciprocal
        # factors (geometric split) until their RMS ratio equals k2/k1; the first effect's
        # RMS then sets the noise (sigma = rms1 / k1)
        ks = {e: _k(rng) for e in gear_keys}
        phys = dict(amps)
        for _ in range(10):
            T, t, base, cps = run.evaluate(amps)
            if len(gear_keys) < 2:
                break
            e1, e2 = gear_keys
            F = (ks[e2] / ks[e1]) / (_rms(cps[e2]) / _rms(cps[e1]))
            if abs(F - 1) < 1e-6:
                break
            amps[e1] /= math.sqrt(F)
            amps[e2] *= math.sqrt(F)
        T, t, base, cps = run.evaluate(amps)
        sigma = _rms(cps[gear_keys[0]]) / ks[gear_keys[0]]
        # amplitude actually used relative to the physical draw in params (loss B-B', play
        # and 1/K_h scale linearly with it)
        det["scale_vs_physical"] = {e: amps[e] / phys[e] for e in gear_keys}
    else:
        sigma = th_T0 * 10 ** float(rng.uniform(-3.0, -1.7))
        T, t, base, cps = run.evaluate(amps)
        if "rig" in comps:
            k = _k(rng)
            ks["rig"] = k
            for _ in range(6):
                fac = k * sigma / _rms(cps["rig"])
                amps["rig"] *= fac
                T, t, base, cps = run.evaluate(amps)
                if abs(fac - 1) < 1e-4:
                    break

    twist = base + sum(cps.values()) if cps else base.copy()
    hidden = sum(cps[e] for e in gear_keys) if gear_keys else np.zeros_like(twist)
    torque = T.copy()
    meas = ()
    equiv = ()
    decoy_contrib = np.zeros_like(twist)
    if decoy == "lever-lvdt-compliance":
        equiv = ("housing_compliance",)
        decoy_contrib = cps["rig"]
        det["rig_compliance_rad_per_Nm"] = amps["rig"]
        det["rig_K_over_K1"] = 1.0 / (amps["rig"] * m["K1"])
    elif decoy == "lever-spline-clearance":
        equiv = ("backlash",)
        decoy_contrib = cps["rig"]
        det["rig_play_rad"] = amps["rig"]
    elif decoy == "deadweight-pulley-friction":
        equiv = ("hysteresis",)
        lev = run.info["levels"]
        reps = run.info["reps"]
        mag = np.abs(lev)
        sd = np.sign(np.diff(np.concatenate([[0.0], mag])))
        # a level with no change keeps the previous direction
        for i in range(1, len(sd)):
            if sd[i] == 0:
                sd[i] = sd[i - 1]
        eps0 = float(rng.uniform(0.005, 0.03))
        tf0 = float(rng.uniform(0.002, 0.02)) * T0
        k = _k(rng)
        ks["rig"] = k

        def true_levels(f):
            tt = mag * (1.0 - sd * eps0 * f) - sd * tf0 * f
            tt = np.where(mag == 0, 0.0, np.clip(tt, 0.0, None))
            return np.sign(lev) * tt

        def contrib(f):
            Tt = np.repeat(true_levels(f), reps)
            return curve(Tt) / s - base

        f = 1.0  # physical first: sheave loss 0.5-3 %, hanger friction 0.2-2 % of T0
        sigma = _rms(contrib(f)) / k
        Tt = np.repeat(true_levels(f), reps)
        twist = curve(Tt) / s
        decoy_contrib = twist - base
        det.update({"pulley_loss_frac": eps0 * f, "hanger_friction_Nm": tf0 * f})
    elif decoy == "torque-bridge-shuntcal":
        meas = ("sensor_gain",)
        k = _k(rng)
        ks["sensor_gain"] = k
        # physical first: bridge gain error 1-5 %, the noise follows from k
        g = 1.0 + rng.choice([-1.0, 1.0]) * float(rng.uniform(0.01, 0.05))
        sigma = _rms(base - curve(g * T) / s) / k
        torque = g * T
        decoy_contrib = base - curve(g * T) / s
        det["torque_gain"] = g
    elif decoy == "rehome-step":
        meas = ("angle_offset",)
        k = _k(rng)
        ks["angle_offset"] = k
        # re-homing at a torque reversal: constant a0, then a0 + step
        rev = np.where(np.diff(np.sign(np.diff(T))) != 0)[0]
        cut = int(rev[len(rev) // 2] + 1) if len(rev) else len(T) // 2
        shape = np.zeros(len(T))
        a0 = float(rng.uniform(-1, 1))
        shape[:] = a0
        shape[cut:] += rng.choice([-1.0, 1.0]) * float(rng.uniform(0.5, 2.0))
        off = shape / _rms(shape) * k * sigma
        twist = twist + off
        decoy_contrib = off
        det["offset_before_rad"] = float(off[0])
        det["offset_after_rad"] = float(off[-1])
    elif decoy in ("sqrt-t-conduction", "two-node-lag"):
        meas = ("thermal_drift",)
        k = _k(rng)
        ks["thermal_drift"] = k
        shp, dinf = _thermal_drift_shape(t, decoy, rng)
        dr = rng.choice([-1.0, 1.0]) * shp / _rms(shp) * k * sigma
        twist = twist + dr
        decoy_contrib = dr
        det.update(dinf)
        det["drift_end_rad"] = float(dr[-1])
    elif decoy == "twist-degrees":
        meas = ("wrong_units",)
    elif decoy == "torque-kNm":
        meas = ("wrong_units",)

    n = len(twist)
    w, ninfo = _noise_block(rng, n, sigma, mode)
    det.update(ninfo)
    twist = twist + w
    if protocol in ("P1", "P3"):
        torque = torque + rng.standard_normal(n) * 5e-5 * T0  # torque-cell noise, 0.005 % of T0
    noise_rms = _rms(w)
    if decoy == "twist-degrees":
        decoy_contrib = twist * (180.0 / math.pi) - twist
        twist = twist * (180.0 / math.pi)
    elif decoy == "torque-kNm":
        decoy_contrib = base - curve(torque * 1e-3) / s
        torque = torque * 1e-3

    if decoy == "stiffness-scale-edge":
        decoy_contrib = base - curve(T) / 1.0  # departure from the catalog average (scale 1)
    total = hidden if gear_keys else decoy_contrib
    snr = _rms(total) / noise_rms if noise_rms > 0 and cate != "clean" else 0.0
    det["effect_snr"] = {e: _rms(cps[e]) / noise_rms for e in gear_keys}
    if ks:
        det["k_drawn"] = ks
    det["params"] = params
    return dict(model=m["code"], columns={"torque_Nm": torque, "twist_rad": twist},
                load_inertia_kgm2=None, gear_effects=tuple(effs), measurement_effects=meas,
                nuisance=nuis, equivalent_effects=equiv, noise_rms=noise_rms, snr=snr,
                details=det)


# --------------------------------------------------------------------------------------------
# transmission error shapes (unit amplitude of the leading harmonic; phi = input angle)
# --------------------------------------------------------------------------------------------


def _te_shape(rng, phi, form, allow3=True):
    """Unit TE shape (leading harmonic amplitude 1) and its parameters."""
    if form == "zone-imbalance-cs-eccentricity":
        p1 = float(rng.uniform(0, 2 * np.pi))
        r3 = float(rng.uniform(0.0, 0.15)) if allow3 else 0.0
        p3 = float(rng.uniform(0, 2 * np.pi))
        shape = np.sin(phi + p1) + r3 * np.sin(3 * phi + p3)
        return shape, {"phase": p1, "triangularity_ratio_3x": r3}
    if form == "two-zone-cs-pitch-error":
        pexp = float(rng.uniform(3.0, 4.0))
        shape = np.zeros_like(phi)
        ph = {}
        for mm in (2, 4, 6, 8):
            pm = float(rng.uniform(0, 2 * np.pi))
            shape = shape + (mm / 2.0) ** (-pexp) * np.sin(mm * phi + pm)
            ph[mm] = pm
        return shape, {"spectrum_exponent": pexp}
    raise ValueError(form)


def _stiffmod(phi, eps1, p1, eps2, p2):
    """Mesh-stiffness modulation under a constant output drag torque: TE = -(T_d/K) *
    [1/(1 + eps1 cos(phi+p1) + eps2 cos(2 phi+p2)) - mean]  (unit T_d/K)."""
    g = 1.0 / (1.0 + eps1 * np.cos(phi + p1) + eps2 * np.cos(2 * phi + p2))
    # mean over one input revolution
    q = np.linspace(0, 2 * np.pi, 4097)[:-1]
    gm = np.mean(1.0 / (1.0 + eps1 * np.cos(q + p1) + eps2 * np.cos(2 * q + p2)))
    return -(g - gm)


# --------------------------------------------------------------------------------------------
# transmission case builder
# --------------------------------------------------------------------------------------------


def _te_effects(rng, phi, effs, forms):
    """TE specification for te_1x / te_2x (single or pair): ('additive', unit shapes) or
    ('stiffmod', modulation depths, phases); amplitudes are applied by _te_eval."""
    par = {}
    pair_form = forms.get("pair")
    if pair_form == "drag-stiffness-modulation" or (
            not pair_form and any(forms[e].startswith("drag-stiffness") for e in effs)):
        eps = {"te_1x": 0.0, "te_2x": 0.0}
        ph = {"te_1x": float(rng.uniform(0, 2 * np.pi)), "te_2x": float(rng.uniform(0, 2 * np.pi))}
        for e in effs:
            eps[e] = float(rng.uniform(0.04, 0.15))
        par.update({"eps_1x": eps["te_1x"], "eps_2x": eps["te_2x"]})
        return ("stiffmod", eps, ph), par
    shapes = {}
    for e in effs:
        f = "zone-imbalance-cs-eccentricity" if e == "te_1x" else "two-zone-cs-pitch-error"
        shapes[e], par[e] = _te_shape(rng, phi, f)
    return ("additive", shapes, None), par


def _te_eval(spec, phi, amps):
    """spec from _te_effects; amps: e -> amplitude factor. Returns (total, contributions)."""
    typ, a, b = spec
    if typ == "additive":
        cont = {e: amps[e] * a[e] for e in a}
        return sum(cont.values()), cont
    eps, ph = a, b
    A = amps["_A"]
    e1 = eps["te_1x"] * amps.get("te_1x", 1.0)
    e2 = eps["te_2x"] * amps.get("te_2x", 1.0)
    full = A * _stiffmod(phi, e1, ph["te_1x"], e2, ph["te_2x"])
    cont = {}
    if eps["te_1x"] > 0:
        cont["te_1x"] = full - A * _stiffmod(phi, 0.0, 0.0, e2, ph["te_2x"])
    if eps["te_2x"] > 0:
        cont["te_2x"] = full - A * _stiffmod(phi, e1, ph["te_1x"], 0.0, 0.0)
    return full, cont


def _te_physical_amp(rng, m):
    acc = m["acc"]
    return float(rng.uniform(0.2, 0.8)) * acc / 2.0


def _scale_te(spec, phi, effs, rng, m, ks, demean=True):
    """Physical-first amplitude for effs[0]; sigma from k0; effs[1] scaled to k1*sigma."""
    typ = spec[0]
    rmsf = _rms0 if demean else _rms
    amps = {e: 1.0 for e in effs}
    a_phys = _te_physical_amp(rng, m)
    if typ == "additive":
        amps[effs[0]] = a_phys
        sigma = rmsf(amps[effs[0]] * spec[1][effs[0]]) / ks[effs[0]]
        for e in effs[1:]:
            amps[e] = ks[e] * sigma / rmsf(spec[1][e])
        tot, cont = _te_eval(spec, phi, amps)
        return amps, sigma, tot, cont
    # stiffness modulation: A*eps ~ a_phys for the first effect
    eps0 = spec[1][effs[0]]
    amps["_A"] = a_phys / eps0
    for _ in range(8):
        tot, cont = _te_eval(spec, phi, amps)
        sigma = rmsf(cont[effs[0]]) / ks[effs[0]]
        done = True
        for e in effs[1:]:
            fac = ks[e] * sigma / rmsf(cont[e])
            if abs(fac - 1) > 1e-5:
                done = False
            amps[e] *= fac
        if done:
            break
    tot, cont = _te_eval(spec, phi, amps)
    sigma = rmsf(cont[effs[0]]) / ks[effs[0]]
    return amps, sigma, tot, cont


def _build_transmission(rng, cat, cell, idx):
    cate, effs, forms, decoy = cell["category"], cell["effects"], cell["forms"], cell.get("decoy")
    m = cat.pick(rng, need=("acc",))
    R = m["ratio"]
    full = decoy == "dual-head-residual" or rng.random() < 0.35
    if full:
        n_rev = R * (1.0 + float(rng.uniform(0.0, 0.1)))
        spr = int(rng.choice([16, 20, 24]))
    else:
        n_rev = float(rng.integers(6, 21))
        spr = int(rng.choice([64, 96, 128]))
    N = int(round(n_rev * spr))
    speed = float(rng.uniform(10.0, 60.0))  # input r/min during the TE run
    phi0 = float(rng.uniform(0, 2 * np.pi))
    phi = phi0 + 2 * np.pi * n_rev * np.arange(N) / N
    t = (phi - phi0) / (2 * np.pi * speed / 60.0)
    offset = float(rng.uniform(-0.5, 0.5))
    nuis = {"output_offset_rad": offset}
    det = {"protocol": f"constant input speed {speed:.1f} r/min, {n_rev:.2f} input revolutions "
                       f"({'about one output revolution' if full else 'several WG revolutions'}),"
                       f" {spr} samples per input revolution",
           "catalog_accuracy_rad": m["acc"]}
    mode = cell.get("noise", None) or _effect_noise_mode(rng)
    inp = phi.copy()
    out = phi / R + offset
    meas, equiv = (), ()
    hidden = np.zeros(N)
    gear_snr = {}
    if cate in ("single", "pair"):
        ks = {e: _k(rng) for e in effs}
        spec, par = _te_effects(rng, phi, effs, forms)
        amps, sigma, tot, cont = _scale_te(spec, phi, effs, rng, m, ks)
        out = out + tot
        hidden = tot
        det["params"] = par
        det["k_drawn"] = ks
        det["te_amplitude"] = {k: float(v) for k, v in amps.items()}
        contribs = cont
    else:
        sigma = m["acc"] * _loguniform(rng, 0.006, 0.07)
        contribs = {}
    dcon = np.zeros(N)
    if cate in ("decoy_separable", "decoy_equivalent"):
        k = _k(rng)
        det["k_drawn"] = {"decoy": k}
        if decoy == "roller-pickup-scale":
            meas = ("sensor_gain",)
            base = phi / R + offset
            g1 = k * sigma / _rms0(base) * rng.choice([-1.0, 1.0])
            out = (1.0 + g1) * out
            dcon = g1 * base
            det["angle_gain"] = 1.0 + g1
        elif decoy == "count-slip":
            meas = ("angle_offset",)
            counts = 2 ** 23
            fr = float(rng.uniform(0.3, 0.7))
            step = k * sigma / math.sqrt(fr * (1 - fr))
            nc = max(1, int(round(step / (2 * np.pi / counts))))
            stepq = nc * 2 * np.pi / counts * rng.choice([-1.0, 1.0])
            dcon = np.where(np.arange(N) >= int(fr * N), stepq, 0.0)
            out = out + dcon
            det.update({"slip_counts": nc, "counts_per_rev": counts, "slip_at_frac": fr})
        elif decoy == "dual-head-residual":
            meas = ("encoder_eccentricity",)
            p = float(rng.uniform(0, 2 * np.pi))
            amp = k * sigma * math.sqrt(2.0)
            dcon = amp * np.cos(phi / R + p)
            out = out + dcon
            det.update({"residual_amplitude_rad": amp})
        elif decoy == "sqrt-t-conduction":
            meas = ("thermal_drift",)
            shp = np.sqrt(t / t[-1])
            dcon = rng.choice([-1.0, 1.0]) * shp * k * sigma / _rms0(shp)
            out = out + dcon
        elif decoy == "output-degrees":
            meas = ("wrong_units",)
        elif decoy == "friction-wheel-input":
            equiv = ("te_1x",)
            p = float(rng.uniform(0, 2 * np.pi))
            a = k * sigma * math.sqrt(2.0)  # output-side amplitude (e/r)/R
            er = a * R
            inp = phi + er * (np.sin(phi + p) - np.sin(phi0 + p))
            dcon = out - (inp / R + offset)
            det.update({"eccentricity_over_radius": er})
        elif decoy == "input-windup-2x-drag":
            equiv = ("te_2x",)
            p = float(rng.uniform(0, 2 * np.pi))
            a = k * sigma * math.sqrt(2.0)
            dcon = -a * np.cos(2 * phi + p)
            out = out + dcon
            det.update({"windup_ripple_output_rad": a})
    w, ninfo = _noise_block(rng, N, sigma, mode)
    det.update(ninfo)
    out = out + w
    noise_rms = _rms(w)
    if decoy == "output-degrees":
        dcon = out * (180 / math.pi) - out
        out = out * (180 / math.pi)
    gear_snr = {e: _rms0(c) / noise_rms for e, c in contribs.items()}
    det["effect_snr"] = gear_snr
    total = hidden if effs else dcon
    snr = _rms0(total) / noise_rms if cate != "clean" else 0.0
    return dict(model=m["code"], columns={"input_angle_rad": inp, "output_angle_rad": out},
                load_inertia_kgm2=None, gear_effects=tuple(effs), measurement_effects=meas,
                nuisance=nuis, equivalent_effects=equiv, noise_rms=noise_rms, snr=snr,
                details=det)


# --------------------------------------------------------------------------------------------
# efficiency: viscosity (Seeton 2006) and loss models
# --------------------------------------------------------------------------------------------


def _seeton_Z(nu):
    nu = np.asarray(nu, dtype=float)
    return np.log(np.log(nu + 0.7 + np.exp(-nu) * special.k0(nu + 1.244067)))


class _Oil:
    """Kinematic viscosity nu(T) (cSt) from Seeton's correlation
    ln(ln(nu + 0.7 + e^-nu K0(nu + 1.244067))) = A - B ln(T/K), fitted through nu40, nu100."""

    def __init__(self, nu40, nu100):
        z40, z100 = _seeton_Z(nu40), _seeton_Z(nu100)
        self.B = float((z40 - z100) / (math.log(373.15) - math.log(313.15)))
        self.A = float(z40 + self.B * math.log(313.15))
        self.nu40, self.nu100 = nu40, nu100
        self._cache = {}

    def nu(self, T_C):
        T_C = np.atleast_1d(np.asarray(T_C, dtype=float))
        out = np.empty_like(T_C)
        for i, T in enumerate(T_C):
            key = round(float(T), 6)
            if key not in self._cache:
                target = self.A - self.B * math.log(T + 273.15)
                self._cache[key] = optimize.brentq(lambda v: float(_seeton_Z(v)) - target,
                                                   0.3, 1e8, xtol=1e-10, rtol=1e-12)
            out[i] = self._cache[key]
        return out


def _draw_oil(rng, lub_row):
    if lub_row["kind"] == "oil":  # ISO VG68: nu40 = 68 cSt by the ISO 3448 grade definition
        nu40 = 68.0
    else:  # grease base oil (not in the catalog): assumed ISO VG 32..150 class
        nu40 = _loguniform(rng, 32.0, 150.0)
    nu100 = 0.63 * nu40 ** 0.62 * float(rng.uniform(0.95, 1.15))
    return _Oil(nu40, nu100)


def _temp_grid(rng, lub_row):
    lo = _num(lub_row["use_min_C"])
    hi = _num(lub_row["use_max_C"])
    if lub_row["basis"] == "ambient":
        hi = hi + 40.0  # 016-2 note: temperature rise over ambient 40 C or less
    lo = max(lo, -10.0) + 5.0
    hi = min(hi, 100.0) - 5.0
    nT = int(rng.integers(3, 6))
    return np.round(np.linspace(lo, hi, nT), 1)


def _derjaguin_ke(alpha, c):
    """Derjaguin binomial friction F = mu (N + N0): load-independent adhesion share c (relative
    to rated load) -> Ke = alpha (1 + c) / (alpha + c), Ke(1) = 1."""
    return alpha * (1 + c) / (alpha + c)


def _palmgren_raw(alpha, m1, p, M0=0.0):
    """WG-bearing moment M = M0 + M1, M1 = f1 P d_m with f1 ~ (P/C0)^0.5 (Palmgren, ball
    bearings) -> M1 proportional to (p + alpha)^1.5 (p: radial preload share)."""
    return alpha / (alpha + M0 + m1 * (p + alpha) ** 1.5)


def _rowe_mu(Tc, n, E, beta, mu_m, mu_f, n_ref=2000.0):
    """Kingsbury/Rowe: fraction of film defect a = 1 - exp(-beta (n_ref/n) exp(-E/(R T)));
    mu = a mu_metal + (1 - a) mu_film."""
    Rg = 8.314
    a = 1.0 - np.exp(-beta * (n_ref / n) * np.exp(-E / (Rg * (Tc + 273.15))))
    return a * mu_m + (1 - a) * mu_f


def _build_efficiency(rng, cat, cell, idx):
    cate, effs, forms, decoy = cell["category"], cell["effects"], cell["forms"], cell.get("decoy")
    need = ("coupling_bore_max_mm",) if decoy in ("lip-seal-ambient", "lip-seal-heated") else ()
    m = cat.pick(rng, need=need)
    Tr = m["rated"]
    R = m["ratio"]
    lubs = cat.lubricants()
    lub = lubs[int(rng.integers(len(lubs)))]
    temps = _temp_grid(rng, lub)
    cand = [v for v in (500, 1000, 1500, 2000, 2500, 3000, 3500) if v <= m["avg_in_rpm"]]
    ns = int(rng.integers(3, min(5, len(cand)) + 1))
    speeds = np.sort(rng.choice(cand, ns, replace=False)).astype(float)
    na = int(rng.integers(7, 12))
    alphas = np.linspace(float(rng.uniform(0.05, 0.15)), float(rng.uniform(0.95, 1.05)), na)
    TT, NN, AA = np.meshgrid(temps, speeds, alphas, indexing="ij")
    Tset, n, alpha = TT.ravel(), NN.ravel(), AA.ravel()
    Tmeas = Tset + rng.normal(0.0, 0.3, Tset.size)  # lubricant temperature at the reading
    load = alpha * Tr
    etaR = cat.eta_rated_example()  # 78 % (CSF-20-80 example, seed 000 p.023)
    level = float(rng.uniform(etaR - 13.0, etaR + 10.0))
    if decoy == "level-edge":
        level = (float(rng.uniform(etaR - 23.0, etaR - 16.0)) if rng.random() < 0.5
                 else float(rng.uniform(etaR + 11.0, etaR + 15.0)))
    nuis = {"efficiency_level_pct": level}
    T_ref = 25.0
    oil = _draw_oil(rng, lub)
    det = {"protocol": f"grid: lubricant temperatures {list(temps)} C ({lub['lubricant']}, "
                       f"table {lub['table']}), input speeds {list(speeds)} r/min, {na} loads "
                       f"{alphas[0]:.2f}..{alphas[-1]:.2f} x rated torque {Tr} N m",
           "oil_nu40_cSt": oil.nu40, "oil_nu100_cSt": oil.nu100, "T_ref_C": T_ref}
    a_anchor, ke_anchor = cat.ke_anchor()
    mode = cell.get("noise", None) or _effect_noise_mode(rng)

    F = np.ones_like(alpha)
    contribs = {}
    params = {}
    if cate in ("single", "pair"):
        ks = {e: _k(rng) for e in effs}
        form = forms.get("pair") or forms[effs[0]]
        if form == "derjaguin-binomial":
            c0 = a_anchor * (1 - ke_anchor) / (ke_anchor - a_anchor)
            c = c0 * float(rng.uniform(0.6, 1.6))
            F = _derjaguin_ke(alpha, c)
            contribs["low_load_efficiency"] = level * (F - 1)
            params = {"adhesion_share_c": c, "c_from_catalog_Ke_point": c0}
        elif form == "palmgren-wg-bearing":
            for _ in range(100):
                p = float(rng.uniform(0.5, 1.2))
                target = ke_anchor * float(rng.uniform(0.965, 1.03))
                # Ke at the anchor for m1 -> infinity; the target must lie above it
                lim = a_anchor * ((p + 1.0) / (p + a_anchor)) ** 1.5
                if lim < target - 0.005:
                    break
            fun = lambda m1: _palmgren_raw(a_anchor, m1, p) / _palmgren_raw(1.0, m1, p) - target
            m1 = optimize.brentq(fun, 1e-6, 1e4)
            F = _palmgren_raw(alpha, m1, p) / _palmgren_raw(1.0, m1, p)
            contribs["low_load_efficiency"] = level * (F - 1)
            params = {"preload_share_p": p, "m1": m1, "Ke_at_anchor": target}
        elif form == "kingsbury-rowe-adsorption":
            E = float(rng.uniform(40e3, 80e3))
            Tc = float(rng.uniform(np.percentile(temps, 35), np.percentile(temps, 85)))
            beta = math.log(2.0) * math.exp(E / (8.314 * (Tc + 273.15)))
            mu_m, mu_f = float(rng.uniform(0.3, 0.5)), float(rng.uniform(0.05, 0.10))
            kap = float(rng.uniform(0.25, 0.5))
            mu = _rowe_mu(Tmeas, n, E, beta, mu_m, mu_f)
            mu_r = _rowe_mu(np.full_like(n, T_ref), n, E, beta, mu_m, mu_f)
            F = (1 - kap * mu) / (1 - kap * mu_r)
            contribs["temperature_dependence"] = level * (F - 1)
            params = {"E_J_per_mol": E, "T_transition_C": Tc, "mu_metal": mu_m, "mu_film": mu_f,
                      "loss_per_unit_mu": kap}
        elif form == "newtonian-ehl-film":
            kf = float(rng.uniform(0.08, 0.25))
            nu = oil.nu(Tmeas)
            nur = oil.nu(T_ref)[0]
            sp = (n / 2000.0) ** 0.3
            F = (1 - kf * sp * (nu / nur) ** 0.3) / (1 - kf * sp)
            contribs["temperature_dependence"] = level * (F - 1)
            params = {"film_loss_share_at_ref": kf}
        elif form == "product-derjaguin-rowe":
            E = float(rng.uniform(40e3, 80e3))
            Tc = float(rng.uniform(np.percentile(temps, 35), np.percentile(temps, 85)))
            beta = math.log(2.0) * math.exp(E / (8.314 * (Tc + 273.15)))
            mu_m, mu_f = float(rng.uniform(0.3, 0.5)), float(rng.uniform(0.05, 0.10))
            mu = _rowe_mu(Tmeas, n, E, beta, mu_m, mu_f)
            mu_r = _rowe_mu(np.full_like(n, T_ref), n, E, beta, mu_m, mu_f)
            # the two k draws are assigned larger -> low load, smaller -> temperature (the
            # physical temperature term is the smaller one for a catalog-like Ke)
            k1, k2 = max(ks.values()), min(ks.values())
            ks["low_load_efficiency"], ks["temperature_dependence"] = k1, k2
            c0 = a_anchor * (1 - ke_anchor) / (ke_anchor - a_anchor)

            def parts(c, kap):
                Ke = _derjaguin_ke(alpha, c)
                g = (1 - kap * mu) / (1 - kap * mu_r)
                return level * g * (Ke - 1), level * Ke * (g - 1), Ke, g

            def ratio(c, kap):
                lo_c, te_c, _, _ = parts(c, kap)
                return _rms0(te_c) / _rms0(lo_c) - k2 / k1

            # physical adhesion share (anchored at the graph 023-1 point); the temperature
            # sensitivity kappa (loss per unit friction coefficient) is set for k2/k1; if no
            # kappa <= 0.5 reaches it, kappa stays at that bound and c is lowered.
            c = c0 * float(rng.uniform(0.6, 1.6))
            kmax = 0.5
            if ratio(c, kmax) >= 0:
                kap = optimize.brentq(lambda q: ratio(c, q), 1e-6, kmax)
            else:
                kap = kmax
                c = optimize.brentq(lambda q: ratio(q, kap), 1e-6, c)
            lo_c, te_c, Ke, g = parts(c, kap)
            F = Ke * g
            contribs["low_load_efficiency"] = lo_c
            contribs["temperature_dependence"] = te_c
            params = {"adhesion_share_c": c, "c_from_catalog_Ke_point": c0, "E_J_per_mol": E,
                      "T_transition_C": Tc, "mu_metal": mu_m, "mu_film": mu_f,
                      "loss_per_unit_mu": kap}
        elif form == "coupled-palmgren-viscous":
            nur = oil.nu(T_ref)[0]
            nu = oil.nu(Tmeas)
            for _ in range(60):
                p = float(rng.uniform(0.5, 1.2))
                share = float(rng.uniform(0.2, 0.9))
                target = ke_anchor * float(rng.uniform(0.965, 1.03))

                def build(mtot, p=p, share=share):
                    m0 = share * mtot
                    m1 = (1 - share) * mtot
                    M0 = m0 * (nu * n / (nur * 2000.0)) ** (2.0 / 3.0)
                    M0r = m0 * (n / 2000.0) ** (2.0 / 3.0)
                    raw = _palmgren_raw(alpha, m1, p, M0)
                    return raw, M0, M0r, m1

                def anchor(mtot, p=p, share=share):
                    m0 = share * mtot
                    m1 = (1 - share) * mtot
                    return _palmgren_raw(a_anchor, m1, p, m0) / _palmgren_raw(1.0, m1, p, m0) - target

                mtot = optimize.brentq(anchor, 1e-6, 50.0)
                raw, M0, M0r, m1 = build(mtot)
                norm = float(np.max(raw))  # efficiency level = best point of the grid
                F = raw / norm
                F_rated = _palmgren_raw(1.0, m1, p, M0) / norm
                F_Tref = _palmgren_raw(alpha, m1, p, M0r) / norm
                c_low = level * (F - F_rated)
                c_tmp = level * (F - F_Tref)
                sigma = _rms0(c_low) / ks["low_load_efficiency"]
                k2 = _rms0(c_tmp) / sigma
                if 4.0 <= k2 <= 12.0:
                    break
            ks["temperature_dependence"] = k2
            contribs["low_load_efficiency"] = c_low
            contribs["temperature_dependence"] = c_tmp
            params = {"preload_share_p": p, "viscous_share": share, "m_total": mtot}
        e0 = effs[0]
        sigma = _rms0(contribs[e0]) / ks[e0]
        det["k_drawn"] = ks
        det["params"] = params
    else:
        sigma = _loguniform(rng, 0.3, 2.0)

    if level * float(np.max(F)) > 95.0:  # keep the true efficiency physical (<= 95 %)
        fac = 95.0 / (level * float(np.max(F)))
        level *= fac
        nuis["efficiency_level_pct"] = level
        contribs = {e: c * fac for e, c in contribs.items()}
        sigma *= fac
    eta = level * F
    meas, equiv = (), ()
    dcon = np.zeros_like(eta)
    load_col = load.copy()
    if cate in ("decoy_separable", "decoy_equivalent") and decoy != "level-edge":
        k = _k(rng)
        det["k_drawn"] = {"decoy": k}
        if decoy == "output-torque-meter":
            meas = ("sensor_gain",)
            g = 1.0 + rng.choice([-1.0, 1.0]) * float(rng.uniform(0.01, 0.05))
            sigma = abs(g - 1.0) * _rms(eta) / k
            load_col = load * g
            dcon = eta * (g - 1)
            eta = eta * g
            det["output_torque_gain"] = g
        elif decoy == "input-torque-meter":
            meas = ("sensor_gain",)
            g = 1.0 + rng.choice([-1.0, 1.0]) * float(rng.uniform(0.01, 0.05))
            sigma = abs(1.0 / g - 1.0) * _rms(eta) / k
            dcon = eta / g - eta
            eta = eta / g
            det["input_torque_gain"] = g
        elif decoy in ("lip-seal-ambient", "lip-seal-heated"):
            d_mm = m["coupling_bore_max_mm"]
            seal = cat.seal_for(d_mm)
            d1 = float(seal["d1_mm"]) * 1e-3
            # physical size: M = mu * F_r' * pi d1 * d1 / 2 (radial lip load per length 0.1-0.25 N/mm)
            Fr = float(rng.uniform(100.0, 250.0))
            mu_s = float(rng.uniform(0.2, 0.5))
            Ms = mu_s * Fr * math.pi * d1 * d1 / 2.0
            if decoy == "lip-seal-ambient":
                equiv = ("low_load_efficiency",)
                shape = np.ones_like(eta)
            else:
                equiv = ("low_load_efficiency", "temperature_dependence")
                nur = oil.nu(T_ref)[0]
                shape = (oil.nu(Tmeas) / nur * n / 2000.0) ** (1.0 / 3.0)
            # measured: eta_m = T_out / (R (T_in + Ms*shape*f)) with T_in = T_out/(R eta)
            Tin = load / (R * eta / 100.0)

            def meas_eta(f):
                return 100.0 * load / (R * (Tin + Ms * f * shape))

            f = 1.0  # physical first: the seal torque as computed; the noise follows from k
            em = meas_eta(f)
            sigma = _rms0(em - eta) / k
            dcon = em - eta
            eta = em
            det.update({"seal_d1_mm": float(seal["d1_mm"]), "seal_from_coupling_bore_mm": d_mm,
                        "seal_torque_physical_Nm": Ms, "seal_torque_used_Nm": Ms * f})
        elif decoy == "fraction":
            meas = ("wrong_units",)
    w, ninfo = _noise_block(rng, eta.size, sigma, mode)
    det.update(ninfo)
    eta = eta + w
    noise_rms = _rms(w)
    if decoy == "fraction":
        dcon = eta / 100.0 - eta
        eta = eta / 100.0
    if decoy == "level-edge":
        dcon = np.full_like(eta, level - (etaR - 1.5))  # departure from the usual range's middle
    total = level * (F - 1) if effs else dcon
    det["effect_snr"] = {e: _rms0(c) / noise_rms for e, c in contribs.items()}
    if effs:
        snr = _rms0(total) / noise_rms
    else:  # decoys: level/gain/unit changes are (nearly) constant shifts, so plain RMS
        snr = _rms(total) / noise_rms if cate != "clean" else 0.0
    cols = {"input_speed_rpm": n, "load_torque_Nm": load_col, "temperature_C": Tmeas,
            "efficiency_pct": eta}
    return dict(model=m["code"], columns=cols, load_inertia_kgm2=None, gear_effects=tuple(effs),
                measurement_effects=meas, nuisance=nuis, equivalent_effects=equiv,
                noise_rms=noise_rms, snr=snr, details=det)


# --------------------------------------------------------------------------------------------
# vibration: run-up through resonance
# --------------------------------------------------------------------------------------------


def _lti_foh(J, c, K, dt):
    """Exact first-order-hold discretisation of 1/(J s^2 + c s + K) (force -> angle)."""
    numd, dend, _ = signal.cont2discrete(([1.0], [J, c, K]), dt, method="foh")
    return np.ravel(numd), np.ravel(dend)


def _build_vibration(rng, cat, cell, idx):
    cate, effs, forms, decoy = cell["category"], cell["effects"], cell["forms"], cell.get("decoy")
    m = cat.pick(rng, need=("acc",))
    K1, T1, R = m["K1"], m["T1"], m["ratio"]
    s = _stiffness_scale(rng)
    zeta = float(rng.uniform(0.03, 0.10))
    fmax = min(40.0, m["max_in_rpm"] / (60.0 * 1.45 * 1.06))
    fn_cat = float(rng.uniform(8.0, fmax))
    J = K1 / (2 * np.pi * fn_cat) ** 2
    K = s * K1
    wn = math.sqrt(K / J)
    c = 2 * zeta * math.sqrt(K * J)
    f0, f1 = 0.3 * fn_cat, 1.45 * fn_cat  # input revolution frequency range (Hz)
    Ts = math.log(f1 / f0) / (2.5 * zeta ** 2 * fn_cat)
    Ts = float(min(max(Ts, 20.0), 120.0))
    fs = 12.0 * 2.0 * f1 * float(rng.uniform(1.0, 1.3))
    over = 4
    dt = 1.0 / (fs * over)
    t_pre = 6.0 / (zeta * wn)
    n_pre = int(math.ceil(t_pre / dt))
    n_main = int(math.ceil(Ts / dt)) + 1
    tm = np.arange(n_main) * dt
    r = math.log(f1 / f0)
    phi0 = float(rng.uniform(0, 2 * np.pi))
    phi_main = phi0 + 2 * np.pi * f0 * Ts / r * (np.exp(r * tm / Ts) - 1.0)
    f_main = f0 * np.exp(r * tm / Ts)
    tp = (np.arange(-n_pre, 0)) * dt
    phi_pre = phi0 + 2 * np.pi * f0 * tp
    phi = np.concatenate([phi_pre, phi_main])
    numd, dend = _lti_foh(J, c, K, dt)
    det = {"protocol": f"logarithmic run-up (IEC 60068-2-6 type) of the input from "
                       f"{60 * f0:.0f} to {60 * f1:.0f} r/min in {Ts:.1f} s, sampled at "
                       f"{fs:.0f} Hz; steady pre-roll at the start speed discarded",
           "fn_catalog_Hz": fn_cat, "fn_true_Hz": wn / (2 * np.pi), "J_kgm2": J}
    nuis = {"stiffness_scale": s, "damping_ratio": zeta}
    mode = cell.get("noise", None) or _effect_noise_mode(rng)

    def resp_base(e):  # spring-only base excitation, damping to ground (load bearing)
        return signal.lfilter(numd, dend, K * e)

    def resp_param(eps, psi, Td=1.0):
        # J y'' + c y' + K (1 + eps cos psi) y = Td eps cos psi  (Picard iteration)
        fext = Td * eps * np.cos(psi)
        y = signal.lfilter(numd, dend, fext)
        for _ in range(200):
            yn = signal.lfilter(numd, dend, fext - K * eps * np.cos(psi) * y)
            dlt = np.max(np.abs(yn - y))
            y = yn
            if dlt <= 1e-10 * max(np.max(np.abs(y)), 1e-300):
                break
        return y

    def excitation(e, form, rng):
        if form in ("base-excitation-zone-imbalance", "base-excitation-two-zone"):
            f = "zone-imbalance-cs-eccentricity" if e == "te_1x" else "two-zone-cs-pitch-error"
            shape, par = _te_shape(rng, phi, f, allow3=False)
            return ("base", shape), par
        k = 1 if e == "te_1x" else 2
        eps = float(rng.uniform(0.3, 0.8)) * 1.6 * zeta
        p = float(rng.uniform(0, 2 * np.pi))
        return ("param", (eps, k * phi + p)), {"eps": eps, "harmonic": k}

    def unit_response(ex):
        typ, val = ex
        if typ == "base":
            return resp_base(val)
        return resp_param(*val)

    sl = slice(n_pre, None, over)
    t_out = tm[::over]
    speed_out = 60.0 * f_main[::over]
    hidden = np.zeros(len(t_out))
    contribs = {}
    meas, equiv = (), ()
    params = {}
    if cate in ("single", "pair"):
        ks = {e: _k(rng) for e in effs}
        units = {}
        for e in effs:
            form = forms.get("pair") or forms[e]
            if form == "base-excitation":
                form = "base-excitation-zone-imbalance" if e == "te_1x" else "base-excitation-two-zone"
            elif form == "parametric-drag":
                form = "parametric-drag-1x" if e == "te_1x" else "parametric-drag-2x"
            ex, params[e] = excitation(e, form, rng)
            y = unit_response(ex)
            # mesh torque of the unit response (stays in the K1 region: |T| <= q T1)
            if ex[0] == "base":
                tq = K * (y - ex[1])
            else:
                eps, psi = ex[1]
                tq = K * (1 + eps * np.cos(psi)) * y - eps * np.cos(psi)
            units[e] = (y[sl], float(np.max(np.abs(tq[n_pre:]))), ex[0])
        e0 = effs[0]
        # physical first: TE amplitude from the catalog accuracy (base excitation) or a load
        # drag torque of 0.5-3 % of rated torque (parametric); capped so that the peak mesh
        # torque stays in the K1 region (<= 0.6 T1)
        if units[e0][2] == "base":
            a0 = float(rng.uniform(0.2, 0.8)) * m["acc"] / 2.0
        else:
            a0 = float(rng.uniform(0.005, 0.03)) * m["rated"]
        if a0 * units[e0][1] > 0.6 * T1:
            a0 = 0.6 * T1 / units[e0][1]
        sigma = _rms(a0 * units[e0][0]) / ks[e0]
        amp = {e0: a0}
        for e in effs[1:]:
            amp[e] = ks[e] * sigma / _rms(units[e][0])
        peak = sum(amp[e] * units[e][1] for e in effs)
        if peak > 0.6 * T1:  # keep the summed peak mesh torque in the K1 region (ratios kept)
            fac = 0.6 * T1 / peak
            amp = {e: a * fac for e, a in amp.items()}
            sigma *= fac
            peak *= fac
        for e in effs:
            contribs[e] = amp[e] * units[e][0]
        hidden = sum(contribs.values())
        det["peak_mesh_torque_over_T1"] = peak / T1
        det["k_drawn"] = ks
        det["excitation_amplitude"] = amp
        det["params"] = params
    else:
        x_ref = 0.4 * T1 / K1 / 10.0
        sigma = x_ref * 10 ** float(rng.uniform(-1.5, -0.5))
    x = hidden.copy()
    dcon = np.zeros_like(x)
    if cate in ("decoy_separable", "decoy_equivalent"):
        k = _k(rng)
        det["k_drawn"] = {"decoy": k}
        if decoy == "two-node-lag":
            meas = ("thermal_drift",)
            shp, dinf = _thermal_drift_shape(t_out, decoy, rng)
            dcon = rng.choice([-1.0, 1.0]) * shp / _rms(shp) * k * sigma
            det.update(dinf)
        elif decoy == "rereference-step":
            meas = ("angle_offset",)
            fr = float(rng.uniform(0.3, 0.7))
            shp = np.where(np.arange(len(x)) >= int(fr * len(x)), 1.0, 0.0)
            dcon = rng.choice([-1.0, 1.0]) * shp / _rms(shp) * k * sigma
            det["step_at_frac"] = fr
        elif decoy == "output-rev-eccentricity":
            meas = ("encoder_eccentricity",)
            p = float(rng.uniform(0, 2 * np.pi))
            shp = np.sin(phi[sl] / R + p)
            dcon = shp / _rms(shp) * k * sigma
        elif decoy in ("servo-encoder-eccentricity", "servo-resolver-imbalance"):
            kk = 1 if decoy == "servo-encoder-eccentricity" else 2
            equiv = ("te_1x",) if kk == 1 else ("te_2x",)
            p = float(rng.uniform(0, 2 * np.pi))
            y = resp_base(np.sin(kk * phi + p))[sl]
            a = k * sigma / _rms(y)
            dcon = a * y
            det["input_angle_error_amplitude_rad"] = a * R
            if kk == 1:
                det["mechanism"] = "servo feedback encoder eccentricity: true input angle has a 1x error"
            else:
                det["mechanism"] = "single-speed resolver amplitude imbalance (delta/2) sin 2 theta in the loop"
        x = x + dcon
    w, ninfo = _noise_block(rng, len(x), sigma, mode)
    det.update(ninfo)
    x = x + w
    noise_rms = _rms(w)
    det["effect_snr"] = {e: _rms(cn) / noise_rms for e, cn in contribs.items()}
    total = hidden if effs else dcon
    snr = _rms(total) / noise_rms if cate != "clean" else 0.0
    cols = {"time_s": t_out, "input_speed_rpm": speed_out, "output_vibration_rad": x}
    return dict(model=m["code"], columns=cols, load_inertia_kgm2=J, gear_effects=tuple(effs),
                measurement_effects=meas, nuisance=nuis, equivalent_effects=equiv,
                noise_rms=noise_rms, snr=snr, details=det)


# --------------------------------------------------------------------------------------------
# cells
# --------------------------------------------------------------------------------------------


def _cells():
    C = []

    def add(kind, category, effects, forms, tag, form_str, **kw):
        C.append(dict(kind=kind, category=category, effects=tuple(effects), forms=dict(forms),
                      tag=tag, formulation=form_str, **kw))

    # ---------------- torsion
    for nm in ("white", "ar1", "outliers"):
        add("torsion", "clean", (), {}, "clean", nm, noise=nm)
    H = {"armstrong-frederick": "armstrong-frederick kinematic hardening",
         "mindlin-deresiewicz": "mindlin-deresiewicz microslip (masing)"}
    B = {"exact-deadzone": "exact dead zone (nordin-gutman)",
         "backdrive-held-play": "play carried at a back-driving breakaway torque"}
    Hc = {"huth-bolt-circle": "huth fastener flexibility of the output bolt circle",
          "annular-disc-shear": "annular-disc in-plane torsion of the output flange"}
    for f, d in H.items():
        add("torsion", "single", ("hysteresis",), {"hysteresis": f}, "hysteresis", d)
    for f, d in B.items():
        add("torsion", "single", ("backlash",), {"backlash": f}, "backlash", d)
    for f, d in Hc.items():
        add("torsion", "single", ("housing_compliance",), {"housing_compliance": f},
            "housing_compliance", d)
    pairs = [
        (("hysteresis", "backlash"), ("armstrong-frederick", "exact-deadzone")),
        (("hysteresis", "backlash"), ("mindlin-deresiewicz", "backdrive-held-play")),
        (("hysteresis", "housing_compliance"), ("armstrong-frederick", "huth-bolt-circle")),
        (("hysteresis", "housing_compliance"), ("mindlin-deresiewicz", "annular-disc-shear")),
        (("backlash", "housing_compliance"), ("exact-deadzone", "annular-disc-shear")),
        (("backlash", "housing_compliance"), ("backdrive-held-play", "huth-bolt-circle")),
    ]
    alld = {**H, **B, **Hc}
    for effs, fs in pairs:
        add("torsion", "pair", effs, dict(zip(effs, fs)), "+".join(effs),
            " + ".join(alld[f] for f in fs))
    for dec, meas_d in (("torque-bridge-shuntcal", "sensor_gain: torque bridge gain (shunt-cal mismatch)"),
                        ("rehome-step", "angle_offset: re-homing step at a reversal"),
                        ("sqrt-t-conduction", "thermal_drift: sqrt(t) conduction into the fixture"),
                        ("two-node-lag", "thermal_drift: two-node thermal lag"),
                        ("twist-degrees", "wrong_units: twist in degrees"),
                        ("torque-kNm", "wrong_units: torque in kN m"),
                        ("stiffness-scale-edge", "nuisance: stiffness scale at the edge of +-10 %")):
        add("torsion", "decoy_separable", (), {}, dec, meas_d, decoy=dec)
    add("torsion", "decoy_equivalent", (), {}, "lever-lvdt-compliance",
        "twist read by LVDTs on the loading lever: lever bending + adapter in the loop",
        decoy="lever-lvdt-compliance")
    add("torsion", "decoy_equivalent", (), {}, "lever-spline-clearance",
        "twist read on the lever: lever-hub spline clearance", decoy="lever-spline-clearance")
    add("torsion", "decoy_equivalent", (), {}, "deadweight-pulley-friction",
        "dead-weight loading over a pulley: sheave loss + hanger friction",
        decoy="deadweight-pulley-friction", protocols=("P2",))

    # ---------------- transmission
    for nm in ("white", "ar1", "outliers"):
        add("transmission", "clean", (), {}, "clean", nm, noise=nm)
    add("transmission", "single", ("te_1x",), {"te_1x": "zone-imbalance-cs-eccentricity"}, "te_1x",
        "two-zone sampling of CS eccentricity with unequal zone load share (1x + small 3x)")
    add("transmission", "single", ("te_1x",), {"te_1x": "drag-stiffness-modulation-1x"}, "te_1x",
        "once-per-rev mesh-stiffness modulation under output drag torque")
    add("transmission", "single", ("te_2x",), {"te_2x": "two-zone-cs-pitch-error"}, "te_2x",
        "CS cumulative pitch error averaged by two diametral mesh zones (even harmonics)")
    add("transmission", "single", ("te_2x",), {"te_2x": "drag-stiffness-modulation-2x"}, "te_2x",
        "twice-per-rev mesh-stiffness modulation under output drag torque")
    add("transmission", "pair", ("te_1x", "te_2x"), {"pair": "two-zone-sampling",
                                                       "te_1x": "zone-imbalance-cs-eccentricity",
                                                       "te_2x": "two-zone-cs-pitch-error"},
        "te_1x+te_2x", "two-zone sampling of CS errors (odd x imbalance, even)")
    add("transmission", "pair", ("te_1x", "te_2x"), {"pair": "drag-stiffness-modulation",
                                                       "te_1x": "drag-stiffness-modulation-1x",
                                                       "te_2x": "drag-stiffness-modulation-2x"},
        "te_1x+te_2x", "1x + 2x mesh-stiffness modulation under output drag torque")
    for dec, d in (("roller-pickup-scale", "sensor_gain: output roller pickup scale"),
                   ("count-slip", "angle_offset: output encoder count slip"),
                   ("dual-head-residual", "encoder_eccentricity: dual read-head residual"),
                   ("sqrt-t-conduction", "thermal_drift: sqrt(t) conduction"),
                   ("output-degrees", "wrong_units: output angle in degrees")):
        add("transmission", "decoy_separable", (), {}, dec, d, decoy=dec)
    add("transmission", "decoy_equivalent", (), {}, "friction-wheel-input",
        "input angle from a friction wheel on an eccentric shaft surface",
        decoy="friction-wheel-input")
    add("transmission", "decoy_equivalent", (), {}, "input-windup-2x-drag",
        "input encoder at the motor end of a compliant shaft, WG drag 2x per rev",
        decoy="input-windup-2x-drag")

    # ---------------- efficiency
    for nm in ("white", "ar1", "outliers"):
        add("efficiency", "clean", (), {}, "clean", nm, noise=nm)
    add("efficiency", "single", ("low_load_efficiency",), {"low_load_efficiency": "derjaguin-binomial"},
        "low_load_efficiency", "derjaguin binomial friction (adhesion + load), Ke anchored at graph 023-1 point")
    add("efficiency", "single", ("low_load_efficiency",), {"low_load_efficiency": "palmgren-wg-bearing"},
        "low_load_efficiency", "palmgren WG-bearing load moment (P/C0)^0.5 with radial preload")
    add("efficiency", "single", ("temperature_dependence",),
        {"temperature_dependence": "kingsbury-rowe-adsorption"}, "temperature_dependence",
        "kingsbury-rowe adsorption boundary friction")
    add("efficiency", "single", ("temperature_dependence",),
        {"temperature_dependence": "newtonian-ehl-film"}, "temperature_dependence",
        "newtonian EHL film shear with dowson-higginson film, seeton viscosity")
    add("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"),
        {"pair": "product-derjaguin-rowe"}, "low_load_efficiency+temperature_dependence",
        "product: derjaguin Ke x kingsbury-rowe")
    add("efficiency", "pair", ("low_load_efficiency", "temperature_dependence"),
        {"pair": "coupled-palmgren-viscous"}, "low_load_efficiency+temperature_dependence",
        "coupled palmgren M0 (nu n)^(2/3) + M1 with seeton viscosity")
    for dec, d in (("output-torque-meter", "sensor_gain: output torque meter gain"),
                   ("input-torque-meter", "sensor_gain: input torque meter gain"),
                   ("fraction", "wrong_units: efficiency as a fraction"),
                   ("level-edge", "nuisance: efficiency level at the edge")):
        add("efficiency", "decoy_separable", (), {}, dec, d, decoy=dec)
    add("efficiency", "decoy_equivalent", (), {}, "lip-seal-ambient",
        "input lip seal inside the input torque measurement (ambient side)", decoy="lip-seal-ambient")
    add("efficiency", "decoy_equivalent", (), {}, "lip-seal-heated",
        "input lip seal running in the heated lubricant (viscosity dependent)", decoy="lip-seal-heated")

    # ---------------- vibration
    for nm in ("white", "ar1", "outliers"):
        add("vibration", "clean", (), {}, "clean", nm, noise=nm)
    add("vibration", "single", ("te_1x",), {"te_1x": "base-excitation-zone-imbalance"}, "te_1x",
        "kinematic 1x TE as base excitation through the gear spring")
    add("vibration", "single", ("te_1x",), {"te_1x": "parametric-drag-1x"}, "te_1x",
        "parametric 1x mesh-stiffness modulation under load drag (Hill equation)")
    add("vibration", "single", ("te_2x",), {"te_2x": "base-excitation-two-zone"}, "te_2x",
        "kinematic 2x TE (two-zone CS pitch error) as base excitation")
    add("vibration", "single", ("te_2x",), {"te_2x": "parametric-drag-2x"}, "te_2x",
        "parametric 2x mesh-stiffness modulation under load drag (Hill equation)")
    add("vibration", "pair", ("te_1x", "te_2x"), {"pair": "base-excitation"}, "te_1x+te_2x",
        "kinematic 1x + 2x TE base excitation")
    add("vibration", "pair", ("te_1x", "te_2x"), {"pair": "parametric-drag"}, "te_1x+te_2x",
        "parametric 1x + 2x mesh-stiffness modulation")
    for dec, d in (("two-node-lag", "thermal_drift: two-node thermal lag"),
                   ("rereference-step", "angle_offset: re-reference step"),
                   ("output-rev-eccentricity", "encoder_eccentricity: once per output revolution")):
        add("vibration", "decoy_separable", (), {}, dec, d, decoy=dec)
    add("vibration", "decoy_equivalent", (), {}, "servo-encoder-eccentricity",
        "servo feedback-encoder eccentricity imposes a 1x input-angle error",
        decoy="servo-encoder-eccentricity")
    add("vibration", "decoy_equivalent", (), {}, "servo-resolver-imbalance",
        "single-speed resolver amplitude imbalance in the servo loop imposes a 2x error",
        decoy="servo-resolver-imbalance")
    return C


_BUILDERS = {"torsion": _build_torsion, "transmission": _build_transmission,
             "efficiency": _build_efficiency, "vibration": _build_vibration}


def _slug(s):
    out = "".join(ch if ch.isalnum() else "-" for ch in s.lower())
    while "--" in out:
        out = out.replace("--", "-")
    return out.strip("-")


def generate_cases(seed: int, catalog_dir, per_cell: int = 4) -> list[TruthCase]:
    cat = _Catalog(catalog_dir)
    cells = _cells()
    master = np.random.default_rng(seed)
    cell_seeds = master.integers(0, 2 ** 63 - 1, size=len(cells))
    cases = []
    for cell, cs in zip(cells, cell_seeds):
        rng = np.random.default_rng(int(cs))
        ftag = _slug(cell.get("decoy") or cell["forms"].get("pair")
                     or "-".join(cell["forms"].get(e, "") for e in cell["effects"])
                     or cell["formulation"])
        for i in range(per_cell):
            r = _BUILDERS[cell["kind"]](rng, cat, cell, i)
            tag = cell["tag"] if cell["category"] != "clean" else "clean"
            name = f"{SUITE}-{cell['kind']}-{cell['category'].replace('_', '-')}-{_slug(tag)}-{ftag}-{i:03d}"
            det = r["details"]
            det["cell_formulation"] = cell["formulation"]
            cases.append(TruthCase(
                name=name, kind=cell["kind"], model=r["model"],
                columns={k: np.asarray(v, dtype=float) for k, v in r["columns"].items()},
                load_inertia_kgm2=r["load_inertia_kgm2"], gear_effects=tuple(r["gear_effects"]),
                measurement_effects=tuple(r["measurement_effects"]), nuisance=dict(r["nuisance"]),
                category=cell["category"], equivalent_effects=tuple(r["equivalent_effects"]),
                noise_rms=float(r["noise_rms"]), formulation=cell["formulation"],
                snr=float(r["snr"]), details=det))
    return cases


# --------------------------------------------------------------------------------------------
# self-check
# --------------------------------------------------------------------------------------------

if __name__ == "__main__":
    import collections
    import sys
    import tempfile

    here = Path(__file__).resolve().parent
    catdir = here.parent / "catalog"
    t0 = time.process_time()
    w0 = time.time()
    cases = generate_cases(11, catdir, per_cell=2)
    cpu = time.process_time() - t0
    wall = time.time() - w0
    cnt = collections.Counter((c.kind, c.category) for c in cases)
    print(f"{len(cases)} cases, cpu {cpu:.1f} s, wall {wall:.1f} s")
    for kind in ("torsion", "transmission", "efficiency", "vibration"):
        row = ", ".join(f"{cat}={cnt[(kind, cat)]}" for cat in
                        ("clean", "single", "pair", "decoy_separable", "decoy_equivalent"))
        print(f"  {kind:13s} {sum(v for (k, _), v in cnt.items() if k == kind):3d}: {row}")
    names = [c.name for c in cases]
    assert len(set(names)) == len(names), "duplicate case names"
    bad = []
    for c in cases:
        cols = list(c.columns)
        assert tuple(cols) == KIND_COLUMNS[c.kind], (c.name, cols)
        n = {len(v) for v in c.columns.values()}
        assert len(n) == 1, c.name
        assert all(np.all(np.isfinite(v)) for v in c.columns.values()), c.name
        for e, v in c.details.get("effect_snr", {}).items():
            if not (3.9 <= v <= 12.1):
                bad.append((c.name, e, round(v, 2)))
        print(f"  {c.name:78s} {c.model:15s} rows={n.pop():6d} cols={len(cols)} "
              f"noise={c.noise_rms:.3g} snr={c.snr:.2f}")
    if bad:
        print("per-effect SNR outside [4, 12]:", bad)
    # determinism and prefix property
    again = generate_cases(11, catdir, per_cell=1)
    first = {c.name: c for c in cases}
    for c in again:
        ref = first[c.name]
        for k in c.columns:
            assert np.array_equal(c.columns[k], ref.columns[k]), ("not deterministic", c.name)
    print("determinism/prefix check: ok")
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "x.csv"
        cases[0].write_csv(p)
        print("write_csv:", p.read_text().splitlines()[0], "...", len(p.read_text().splitlines()) - 1, "rows")
    sys.exit(0)
