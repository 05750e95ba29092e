"""The load joint: the run-up response of the load inertia on the gear's spring to a
transmission error, linear (K1) and on the catalog's three-segment spring when the twist
leaves the first segment.

J·θ'' + c·θ' + T(θ − e) = 0, with T(·) the catalog torque–twist curve (breakpoints T1, T2
from the table, slopes K1 … K3 × the stiffness scale), c = 2ζ·√(s·K1·J) and e(t) the
transmission error. Near resonance the twist is the error times the resonance gain
(≈ 1/2ζ); it passes T1/K1 and the joint stiffens (K2 > K1), which moves the resonance with
the amplitude. Below T1/K1 the joint is the linear one (:func:`joint_response`).

Between samples each segment is an exact linear map with e linear between samples
(first-order hold); the segment is the one the twist is in at the step's start, or at its
middle when the step crosses a corner. The tangent ∂θ/∂a of every excitation column runs
through the same maps, so that the excitation amplitudes are fitted by Gauss–Newton with an
exact Jacobian.

References
----------
Seed 000 p.019 (torsional stiffness: T1, T2, K1 … K3) and p.021 (formula 021-3,
f_n = √(K/J)/2π). Franklin, G. F., Powell, J. D., Workman, M. L. (1998), *Digital Control
of Dynamic Systems*, 3rd ed., §6.3.2 (triangle-hold equivalent).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import signal
from scipy.linalg import expm

from ..checks.stiffness import StiffnessCurve

# up to this many tangent columns one float loop per column is faster than one numpy step
# per sample for all of them
_FLOAT_COLUMNS = 16


# --------------------------------------------------------------------------- linear joint
def joint_response(time_s: np.ndarray, excitation_rad: np.ndarray, K_Nm_per_rad: float,
                   J_kgm2: float, zeta: float, on_twist: bool = False) -> np.ndarray:
    """Load angle θ [rad] of J·θ'' + c·θ' + K·θ = K·e(t), c = 2ζ·√(K·J) (``excitation_rad``
    n or n × m: one response per column); with ``on_twist`` the damper acts on the joint's
    twist θ − e instead (the gear's own damping, in the mesh and the flexspline), so the
    error drives the load through it as well as through the spring:
    J·θ'' + c·(θ' − e') + K·(θ − e) = 0, whose θ is the first system's θ_a + (c/K)·θ_a'
    (the same system driven by (1 + (c/K)·s)·e), c/K = 2ζ/ω_n, θ_a' from the same state.

    The load starts at rest in static equilibrium, θ(0) = e(0), θ'(0) = 0 (a run-up from
    standstill). Exact discretisation of the linear joint with e(t) linear between samples
    (first-order hold): a fixed IIR filter when the samples are evenly spaced
    (:func:`joint_filter`), the same modal recursion step by step otherwise. 0 ≤ ζ < 1.
    """
    wn = math.sqrt(K_Nm_per_rad / J_kgm2)
    weight = 2.0 * zeta / wn if on_twist else 0.0
    dt = np.diff(time_s)
    e = np.asarray(excitation_rad, dtype=float)
    if dt.size and np.ptp(dt) <= 1e-6 * dt.mean():
        b, a = joint_filter(wn, zeta, float(dt.mean()), weight)
        # steady state of a constant input; columns of a 2-D excitation filtered at once
        zi = np.multiply.outer(signal.lfilter_zi(b, a), e[0])
        return signal.lfilter(b, a, e, axis=0, zi=zi)[0]
    if e.ndim == 2:
        return np.column_stack([_joint_uneven(dt, col, wn, zeta, weight) for col in e.T])
    return _joint_uneven(dt, e, wn, zeta, weight)


def _modes(wn: float, zeta: float):
    """Eigenvalues λ, eigenvectors V (columns [1, λ]) and V⁻¹ of the joint's state matrix."""
    wd = wn * math.sqrt(1.0 - zeta * zeta)
    lam = np.array([-zeta * wn + 1j * wd, -zeta * wn - 1j * wd])
    V = np.array([[1.0, 1.0], lam])
    return lam, V, np.linalg.inv(V)


def _joint_uneven(dt: np.ndarray, e: np.ndarray, wn: float, zeta: float,
                  velocity_weight: float = 0.0) -> np.ndarray:
    """Modal first-order-hold recursion with a step of its own per sample interval; the
    output θ + ``velocity_weight``·θ' (θ = q + q̄, θ' = λq + conj(λq) in the first mode q)."""
    lam, V, Vinv = _modes(wn, zeta)
    beta = (Vinv @ np.array([0.0, wn * wn]))[0]          # first mode; the second is its conjugate
    lam0 = lam[0]
    read = 1.0 + velocity_weight * lam0
    a = np.exp(lam0 * dt)
    g0 = (a - 1.0) / lam0
    g1 = (a - 1.0 - lam0 * dt) / (lam0 * lam0 * dt)
    b_now, b_next = (g0 - g1) * beta, g1 * beta
    q = (Vinv @ np.array([e[0], 0.0]))[0]               # static equilibrium θ = e, θ' = 0
    out = np.empty(len(e))
    out[0] = 2.0 * (read * q).real
    for k in range(len(dt)):
        q = a[k] * q + b_now[k] * e[k] + b_next[k] * e[k + 1]
        out[k + 1] = 2.0 * (read * q).real
    return out


def joint_filter(wn: float, zeta: float, dt: float, velocity_weight: float = 0.0
                 ) -> tuple[np.ndarray, np.ndarray]:
    """IIR coefficients (b, a) of θ'' + 2ζω·θ' + ω²·θ = ω²·e sampled every dt [s], e linear
    between samples (first-order hold), 0 ≤ ζ < 1, read as θ + ``velocity_weight``·θ'.

    Modal form: A = V·Λ·V⁻¹ with λ = −ζω ± iω√(1 − ζ²); x[k+1] = Φ·x[k] + (M0 − M1)·e[k] +
    M1·e[k+1] with Φ = e^(AΔ), M0 = ∫₀^Δ e^(Aτ)dτ·B, M1 = ∫₀^Δ e^(A(Δ−s))·s/Δ ds·B, all
    diagonal in the modes (closed form, no matrix exponential).
    """
    lam, V, Vinv = _modes(wn, zeta)
    B = np.array([0.0, wn * wn])
    e = np.exp(lam * dt)
    modal = lambda d: (V @ np.diag(d) @ Vinv).real
    phi = modal(e)
    m0 = modal((e - 1.0) / lam) @ B
    m1 = modal((e - 1.0 - lam * dt) / (lam * lam * dt)) @ B
    # ξ = x − M1·e removes the e[k+1] term: ξ[k+1] = Φξ[k] + (ΦM1 + M0 − M1)e[k],
    # θ[k] = ξ₀[k] + M1₀·e[k]
    bd = phi @ m1 + m0 - m1
    a = np.array([1.0, -np.trace(phi), np.linalg.det(phi)])
    # C·adj(zI − Φ)·bd/det + D with C = [1, w] (θ + w·θ'), D = C·M1; the adjugate is
    # [[z − Φ₁₁, Φ₀₁], [Φ₁₀, z − Φ₀₀]]
    w = velocity_weight
    n1 = bd[0] + w * bd[1]
    n2 = (phi[0, 1] * bd[1] - phi[1, 1] * bd[0]) + w * (phi[1, 0] * bd[0] - phi[0, 0] * bd[1])
    d0 = m1[0] + w * m1[1]
    b = np.array([d0, n1 + d0 * a[1], n2 + d0 * a[2]])
    return b, a


def steady_response(pairs: np.ndarray, omega_rad_s: np.ndarray, K_Nm_per_rad: float,
                    J_kgm2: float, zeta: float) -> np.ndarray:
    """Load angle θ [rad] in the steady state of each instant's excitation frequency, for
    excitations given in (sin, cos) pairs of columns (n × 2m; pair j turns at
    ``omega_rad_s[:, j]`` [rad/s]), through a spring of complex stiffness K·(1 + i·η),
    η = 2ζ (structural, hysteretic damping: the material's loss factor, the same at every
    frequency; at resonance it damps as the viscous ζ does).

    θ = H(ω)·e, H = K*/(K* − J·ω²), applied to the phasor p·e^{ia} of the pair
    (p·sin a, p·cos a): the sine column's response is Re H·p·sin a + Im H·p·cos a, the
    cosine's Re H·p·cos a − Im H·p·sin a. The free vibration a run-up excites as it passes
    the resonance is not in it: structural damping has no time-domain form that is causal,
    and a slow sweep or order-tracked data carry the steady state only.

    References
    ----------
    Crandall, S. H. (1970) "The role of damping in vibration theory", J. Sound Vib. 11(1):
    3-18. Nashif, A. D.; Jones, D. I. G.; Henderson, J. P. (1985) Vibration Damping, Wiley,
    ch. 3 (complex modulus, loss factor).
    """
    stiffness = K_Nm_per_rad * (1.0 + 2j * zeta)
    H = stiffness / (stiffness - J_kgm2 * np.asarray(omega_rad_s) ** 2)
    s, c = pairs[:, 0::2], pairs[:, 1::2]
    out = np.empty_like(pairs, dtype=float)
    out[:, 0::2] = H.real * s + H.imag * c
    out[:, 1::2] = H.real * c - H.imag * s
    return out


# --------------------------------------------------------------------------- catalog curve
@dataclass(frozen=True)
class Spring:
    """The curve's slopes [N·m/rad], breakpoints in twist [rad] and the force offset of
    each segment [N·m]: T(d) = K_i·d + sign(d)·F_i on segment i."""

    K: tuple[float, float, float]
    theta1: float
    theta2: float
    F: tuple[float, float, float]

    @classmethod
    def from_curve(cls, curve: StiffnessCurve, scale: float) -> "Spring":
        K1, K2, K3 = (curve.K1 * scale, curve.K2 * scale, curve.K3 * scale)
        th1 = curve.T1 / K1
        th2 = th1 + (curve.T2 - curve.T1) / K2
        return cls((K1, K2, K3), th1, th2, (0.0, curve.T1 - K2 * th1, curve.T2 - K3 * th2))


def has_curve(curve: StiffnessCurve | None) -> bool:
    """Whether the catalog gives all three segments (FD tables give one spring constant)."""
    return (curve is not None and None not in (curve.K1, curve.K2, curve.K3, curve.T1, curve.T2)
            and math.isfinite(curve.T1))


def segment_maps(spring: Spring, J: float, c: float, dt: float):
    """Per segment: Φ (2×2), the hold gains g0, g1 of e[k], e[k+1] and the offset gain of
    sign(d) (2,), for the state [θ, θ'] over one step dt [s]."""
    phi, g0, g1, goff = (np.empty((3, 2, 2)), np.empty((3, 2)), np.empty((3, 2)),
                         np.empty((3, 2)))
    for i, (k, f) in enumerate(zip(spring.K, spring.F)):
        m = np.zeros((4, 4))
        m[:2, :2] = [[0.0, 1.0], [-k / J, -c / J]]
        m[1, 2] = k / J
        m[2, 3] = 1.0 / dt
        e = expm(m * dt)
        phi[i], g0[i], g1[i] = e[:2, :2], e[:2, 2] - e[:2, 3], e[:2, 3]
        goff[i] = -e[:2, 2] * f / k  # a constant force −F·sign(d) held over the step
    return phi, g0, g1, goff


def _float_maps(spring: Spring, J: float, c: float, dt: float) -> list[tuple[float, ...]]:
    """:func:`segment_maps` as plain floats per segment: Φ row-major, g0, g1, offset."""
    phi, g0, g1, goff = segment_maps(spring, J, c, dt)
    return [tuple(map(float, (*phi[i].ravel(), *g0[i], *g1[i], *goff[i]))) for i in range(3)]


def respond(excitation: np.ndarray, dt: float, spring: Spring, J: float, c: float
            ) -> tuple[np.ndarray, np.ndarray]:
    """θ [rad] for the error ``excitation`` (n,) sampled every dt [s], and the segment the
    twist is in at each step (0, 1, 2). Starts at rest in static equilibrium, θ(0) = e(0).

    Plain floats, the step written out: the recursion is sequential, and numpy's (or a
    function call's) cost per step is larger than the arithmetic.
    """
    maps = _float_maps(spring, J, c, dt)
    e = np.asarray(excitation, dtype=float).tolist()
    th1, th2 = spring.theta1, spring.theta2
    # each segment's map with its offset for a negative twist (the offset is odd in it)
    signed = [(m, m[:8] + (-m[8], -m[9]) if i else m) for i, m in enumerate(maps)]
    x, v = e[0], 0.0
    out, segments = [x], []
    for k in range(len(e) - 1):
        e0, e1 = e[k], e[k + 1]
        d = x - e0
        a = d if d >= 0 else -d
        seg = 0 if a <= th1 else (1 if a <= th2 else 2)
        p00, p01, p10, p11, a0, b0, a1, b1, o0, o1 = signed[seg][d < 0]
        x1 = p00 * x + p01 * v + a0 * e0 + a1 * e1 + o0
        v1 = p10 * x + p11 * v + b0 * e0 + b1 * e1 + o1
        end = x1 - e1
        a = end if end >= 0 else -end
        if (0 if a <= th1 else (1 if a <= th2 else 2)) != seg:
            # the step crosses a corner: the segment of its mid-twist
            mid = 0.5 * (d + end)
            seg = _segment(mid, th1, th2)
            p00, p01, p10, p11, a0, b0, a1, b1, o0, o1 = signed[seg][mid < 0]
            x1 = p00 * x + p01 * v + a0 * e0 + a1 * e1 + o0
            v1 = p10 * x + p11 * v + b0 * e0 + b1 * e1 + o1
        x, v = x1, v1
        out.append(x)
        segments.append(seg)
    return np.array(out), np.array(segments, dtype=np.int8)


def _segment(d: float, th1: float, th2: float) -> int:
    """The curve's segment (0, 1, 2) a twist d [rad] is on."""
    a = d if d >= 0 else -d
    return 0 if a <= th1 else (1 if a <= th2 else 2)


def tangents(basis: np.ndarray, segments: np.ndarray, dt: float, spring: Spring, J: float,
             c: float) -> np.ndarray:
    """∂θ/∂a_j (n × m) of θ for e = Σ a_j·basis_j, along the segments of :func:`respond`:
    each column runs through the segments' linear maps (the offsets do not depend on a)."""
    U = np.asarray(basis, dtype=float)
    n, m = U.shape
    seg = segments.tolist()
    if m > _FLOAT_COLUMNS:  # many columns: one vector step per sample
        phi, g0, g1, _ = segment_maps(spring, J, c, dt)
        hold = np.stack([g0, g1], axis=-1)
        X = np.zeros((2, m))
        X[0] = U[0]
        out = np.empty((n, m))
        out[0] = X[0]
        for k in range(n - 1):
            s = seg[k]
            X = phi[s] @ X + hold[s] @ U[k:k + 2]
            out[k + 1] = X[0]
        return out
    maps = _float_maps(spring, J, c, dt)
    steps = [maps[s] for s in seg]
    cols = []
    for j in range(m):
        u = U[:, j].tolist()
        x, v = u[0], 0.0
        out = [x]
        for k, (p00, p01, p10, p11, a0, b0, a1, b1, _, _) in enumerate(steps):
            x, v = (p00 * x + p01 * v + a0 * u[k] + a1 * u[k + 1],
                    p10 * x + p11 * v + b0 * u[k] + b1 * u[k + 1])
            out.append(x)
        cols.append(out)
    return np.array(cols).T


def peak_twist(theta: np.ndarray, excitation: np.ndarray) -> float:
    """The largest twist |θ − e| [rad] over the record."""
    return float(np.max(np.abs(theta - excitation)))
