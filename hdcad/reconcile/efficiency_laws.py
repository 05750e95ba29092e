"""The efficiency's laws: how the loss of a strain wave gear changes with load and with the
lubricant's temperature (the forms of ``low_load_efficiency`` and ``temperature_dependence``
in :mod:`.effects`).

References
----------
Seed 000 p.023: efficiency depends on ratio, input speed, load torque, temperature and
lubrication; below rated torque η = Ke·ηR, α = T/Tr, Ke = 1 for α ≥ 1 (graph 023-1; one point
survives: α = 0.58 → Ke = 0.93); the example (CSF-20-80) is at 20 °C and 1000 r/min.
"""

from __future__ import annotations

import math

import numpy as np

# Reference lubricant temperature of the efficiency model: the seed's efficiency example
# (000 p.023, CSF-20-80) is at 20 °C; η0 is the efficiency there.
REFERENCE_TEMPERATURE_C = 20.0
# Input speed at which c of the low-load correction is stated: the seed's Ke example
# (000 p.023, CSF-20-80) runs at 1000 r/min.
KE_REFERENCE_SPEED_RPM = 1000.0


def low_load_factor(alpha: np.ndarray, c: float, q: float, speed_rpm: np.ndarray | None = None,
                    s: float = 0.0, viscosity: np.ndarray | None = None,
                    k: float = 0.0, flat: bool = False) -> np.ndarray:
    """Efficiency correction Ke(α) [-] for α = T/Tr < 1; Ke = 1 for α ≥ 1.

    Ke = (α·(1 + c_n)/(α + c_n))^q: a load-independent loss (no-load running torque, seed 000
    p.023) that is the fraction c_n of the rated output power makes η fall as α/(α + c_n);
    the exponent q shapes the curve. Ke(1) = 1, Ke → 0 as α → 0. The no-load running torque
    rises with input speed (seed 000 p.023: efficiency depends on input speed), so
    c_n = c·(n/``KE_REFERENCE_SPEED_RPM``)^s; s = 0 (or no speed given) is a speed-free Ke.
    A drag torque also grows with the oil's viscosity: × g^k, g = ν(t)/ν(20 °C) (``viscosity``;
    k = 0 a drag independent of temperature; Palmgren's no-load torque ∝ (ν·n)^(2/3)).

    ``flat``: the graph's other shape, Ke = 1 − c_n/(1 + c_n)·(1 − α)^q, a drop that reaches
    rated torque with no slope (q > 1) and stays finite at no load (a read-off curve such as
    graph 023-1, where the load-independent loss is not the whole low-load loss); the same
    parameters, so the two shapes are compared by their residual alone.

    References: Palmgren, A. (1959) Ball and Roller Bearing Engineering, 3rd ed., SKF.
    """
    a = np.minimum(np.asarray(alpha, dtype=float), 1.0)
    if speed_rpm is not None and s != 0.0:
        c = c * (np.asarray(speed_rpm, dtype=float) / KE_REFERENCE_SPEED_RPM) ** s
    if viscosity is not None and k != 0.0:
        c = c * np.asarray(viscosity, dtype=float) ** k
    if flat:
        return 1.0 - c / (1.0 + c) * (1.0 - a) ** q
    return (a * (1.0 + c) / (a + c)) ** q


# Viscosity–temperature laws ν ∝ exp(B/(t + C)) by their constant C [°C]: Reynolds'
# exponential (C → ∞), Andrade's (absolute temperature, C = 273.15) and Vogel's with
# Cameron's C = 95 °C for mineral oils; the most curved law commonly used for lubricants.
VISCOSITY_LAWS_C = {"Reynolds": math.inf, "Andrade": 273.15, "Vogel-Cameron": 95.0}


def viscosity_ratio(temperature_C: np.ndarray, slope_per_K: float, reference_C: float,
                    law_C: float = math.inf) -> np.ndarray:
    """ν(t)/ν(t_ref) [-] of the law ν ∝ exp(B/(t + C)) with slope −b = d ln ν/dt at t_ref:
    g = exp(−b·Δt/(1 + Δt/(t_ref + C))), Δt = t − t_ref (C → ∞: Reynolds' exp(−b·Δt)).

    References: Reynolds, O. (1886) Phil. Trans. R. Soc. 177; Andrade, E. N. da C. (1930)
    Nature 125, 309; Vogel, H. (1921) Phys. Z. 22, 645; Cameron, A. (1966) The Principles
    of Lubrication (C = 95 °C for mineral oils).
    """
    dt = np.asarray(temperature_C, dtype=float) - reference_C
    if math.isinf(law_C):
        return np.exp(-slope_per_K * dt)
    return np.exp(-slope_per_K * dt / (1.0 + dt / (reference_C + law_C)))


def band_ratio(temperature_C: np.ndarray, slope_per_K: float, reference_C: float,
               band: tuple[float, float]) -> np.ndarray:
    """g(t) [-] of a loss that changes over a band of temperature (centre t_c [°C], width
    w [K]) and not outside it: ln g = −4·b·w·[σ((t − t_c)/w) − σ((t_ref − t_c)/w)], σ the
    logistic, so the slope is −b at the centre and Reynolds' exp(−b·Δt) is the limit
    w → ∞. An extreme-pressure or anti-wear additive forms its film where the contacts
    pass an activation temperature; a grease changes consistency over a band.

    References: Spikes, H. (2004) "The history and mechanisms of ZDDP", Tribology Letters
    17(3): 469-489 (thermally activated tribofilm formation).
    """
    centre, width = band
    t = np.asarray(temperature_C, dtype=float)
    step = 0.5 * (1.0 + np.tanh(0.5 * (t - centre) / width))  # σ, written without overflow
    at_ref = 0.5 * (1.0 + math.tanh(0.5 * (reference_C - centre) / width))
    return np.exp(-4.0 * slope_per_K * width * (step - at_ref))


def temperature_ratio(temperature_C: np.ndarray, slope_per_K: float, reference_C: float,
                      law_C: float = math.inf, band: tuple[float, float] | None = None
                      ) -> np.ndarray:
    """g(t) of the temperature law: a band's (:func:`band_ratio`) when one is given, else
    the viscosity law's (:func:`viscosity_ratio`)."""
    if band is not None:
        return band_ratio(temperature_C, slope_per_K, reference_C, band)
    return viscosity_ratio(temperature_C, slope_per_K, reference_C, law_C)


def temperature_factor(temperature_C: np.ndarray, share: float, slope_per_K: float,
                       reference_C: float, speed_rpm: np.ndarray | None = None,
                       s: float = 0.0, boundary: float = 0.0,
                       law_C: float = math.inf, speed_loss: float = 0.0,
                       band: tuple[float, float] | None = None) -> np.ndarray:
    """Efficiency relative to that at ``reference_C`` [-] when part of the loss is viscous.

    F = 1 / (1 + a·(g − 1)·v + c·(1/g − 1)/v), g the viscosity relative to t_ref
    (:func:`viscosity_ratio`, law constant ``law_C``), v = (n/n_ref)^s: the churning loss falls
    with the viscosity, so a warmer gear is more efficient for a > 0; a is the viscous loss as
    a share of the input power at t_ref and ``KE_REFERENCE_SPEED_RPM``, b the viscosity's
    temperature coefficient, s how the viscous share grows with input speed (viscous drag goes
    with viscosity × speed, Petroff/Hersey; s = 0 a speed-free law); c (``boundary``) the
    share of boundary friction that grows as the film (viscosity × speed) thins, so that
    efficiency can peak at a middle temperature (Stribeck). F = 1 at t_ref at every speed,
    unless the viscous loss at t_ref grows with speed too: + u·(v − 1), u = ``speed_loss``
    (the law's two references, temperature and speed, then meet at one point only). With a
    ``band`` the loss changes over that band of temperature only (:func:`band_ratio`).
    Seed 000 p.023 lists temperature and input speed among the factors of efficiency.

    References: Stribeck, R. (1902) Z. VDI 46; Hersey, M. D. (1914) J. Wash. Acad. Sci. 4.
    """
    g = temperature_ratio(temperature_C, slope_per_K, reference_C, law_C, band)
    speed = 1.0
    if speed_rpm is not None and s != 0.0:
        speed = (np.asarray(speed_rpm, dtype=float) / KE_REFERENCE_SPEED_RPM) ** s
    loss = share * (g - 1.0) * speed
    if boundary:  # a thinner film (ν·n lower) lets the asperities touch: Stribeck's rise
        loss = loss + boundary * (1.0 / g - 1.0) / speed
    if speed_loss:  # the viscous loss at t_ref also grows with speed
        loss = loss + speed_loss * (speed - 1.0)
    return 1.0 / (1.0 + loss)


# the effects a Stribeck law in Hersey's number takes the place of, together or alone
HERSEY_EFFECTS = ("low_load_efficiency", "temperature_dependence")
# Hersey number's load term: α is clipped here so that a no-load row keeps a finite number
HERSEY_ALPHA_MIN = 0.01


def hersey_number(speed_rpm: np.ndarray, alpha: np.ndarray, viscosity: np.ndarray | float,
                  load_exponent: float) -> np.ndarray:
    """H = g·(n/n_ref)/α^r [-]: Hersey's number ν·N/P relative to its value at 20 °C,
    ``KE_REFERENCE_SPEED_RPM`` and rated torque; g = ν(t)/ν(20 °C) (``viscosity``), the
    contact pressure P ∝ α^r (r = 1 a fixed contact area, 1/2 a Hertzian line contact)."""
    a = np.maximum(np.asarray(alpha, dtype=float), HERSEY_ALPHA_MIN)
    n = np.asarray(speed_rpm, dtype=float) / KE_REFERENCE_SPEED_RPM
    return np.asarray(viscosity, dtype=float) * n / a ** load_exponent


# the amplitudes of the Stribeck law's terms, as :func:`stribeck_terms` gives them
STRIBECK_LABELS = ("boundary_loss", "film_loss", "viscous_loss")


def stribeck_terms(hersey: np.ndarray, boundary_scale: float) -> np.ndarray:
    """(n × 3) [-]: the loss terms of a Stribeck curve in Hersey's number H, boundary
    friction exp(−H/H_b) that fades as the film builds, and the film's shear, √H in an
    elastohydrodynamic contact and H in a full hydrodynamic film (Petroff); the loss is
    d_b·exp(−H/H_b) + d_f·√H + d_v·H, d ≥ 0, lowest between the regimes.

    References: Stribeck, R. (1902) "Die wesentlichen Eigenschaften der Gleit- und
    Rollenlager", Z. VDI 46; Hersey, M. D. (1914) J. Wash. Acad. Sci. 4, 542–552;
    Gelinck, E. R. M.; Schipper, D. J. (2000) "Calculation of Stribeck curves for line
    contacts", Tribol. Int. 33, 175–181 (film friction ∝ √H in the EHL regime); Petroff,
    N. P. (1883) (a full film's friction ∝ ν·N/P).
    """
    h = np.asarray(hersey, dtype=float)
    return np.column_stack([np.exp(-h / boundary_scale), np.sqrt(h), h])
