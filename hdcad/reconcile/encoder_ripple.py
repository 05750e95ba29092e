"""An encoder's interpolation ripple: the period it is looked for at and the signatures that
tell it from the gear's own error.

An encoder's interpolation error repeats once per signal period of its grating, periodic in
the angle it reads: the twist in torsion, the output angle in transmission. Its period comes
from the residual's periodogram over that angle; it is a line there (a drift with time is a
continuum), the same over the whole span, and, in transmission, away from the wave
generator's orders, where it is as much the gear's error.

References
----------
Heydemann, P. L. M. (1981) "Determination and correction of quadrature fringe measurement
errors in interferometers", Applied Optics 20(19): 3382-3384 (errors periodic in the
signal period).
"""

from __future__ import annotations

import numpy as np

# Periods an encoder's interpolation error is looked for at: at least PERIODS_MIN of them
# over the measured span (over fewer, a ripple and its harmonics are as much a smooth error
# of the curve's shape, a play's or a joint's), and at least SAMPLES_PER_PERIOD places read
# per period on average.
PERIODS_MIN = 4
SAMPLES_PER_PERIOD = 8
QUANTA_PER_PERIOD = 4
RIPPLE_SHARE_MIN = 0.25


def quantum(angle: np.ndarray) -> float:
    """The step of a quantised reading (the smallest step between the values it takes when
    it takes fewer than half as many values as it has rows), else 0."""
    values = np.unique(angle)
    if len(values) < 2 or len(values) >= len(angle) / 2:
        return 0.0
    return float(np.min(np.diff(values)))


def ripple_everywhere(before: np.ndarray, after: np.ndarray, angle: np.ndarray) -> bool:
    """An encoder's ripple is the same over the whole span of the angle: the fit that adds
    it (residual ``after``, from ``before``) lowers the mean-square residual in each third
    of the span by at least RIPPLE_SHARE_MIN of what it does over all rows. A structure at
    one place (a play at zero twist) fitted by a few periods of ripple is not."""
    edges = np.linspace(angle.min(), angle.max(), 4)
    third = np.clip(np.searchsorted(edges, angle, side="right") - 1, 0, 2)
    overall = np.mean(before ** 2) - np.mean(after ** 2)
    gains = [np.mean(before[third == k] ** 2) - np.mean(after[third == k] ** 2)
             for k in range(3) if np.any(third == k)]
    return overall > 0 and min(gains) >= RIPPLE_SHARE_MIN * overall


def angle_period(residual: np.ndarray, angle: np.ndarray,
                 excluded: tuple[float, ...] = (), width: float = 0.0,
                 fine: bool = False) -> float:
    """Signal period [unit of ``angle``] of the strongest ripple of ``residual`` that
    repeats in the measured ``angle``: the peak of its periodogram over the angle
    (:func:`periodogram_peak`, bins of a quarter of the shortest period), away from the
    frequencies ``excluded`` [1/unit of ``angle``] by more than ``width``; ``fine`` for an
    angle that runs one way over many periods (an output angle), whose fit has a minimum in
    the period narrower than the padded grid's step."""
    span = float(np.ptp(angle)) or 1.0
    # rows at the same angle (the readings of a dwell) count once; a period near the step of
    # a quantised reading would alias into a slow function of it
    places = np.unique(_bins(angle, span, len(angle))).size
    shortest = max(SAMPLES_PER_PERIOD * span / places, QUANTA_PER_PERIOD * quantum(angle))
    longest = span / PERIODS_MIN
    if shortest >= longest:
        return longest
    bins = int(np.ceil(4 * span / shortest))
    return 1.0 / periodogram_peak(residual, angle, bins, (1.0 / longest, 1.0 / shortest),
                                  excluded, width, fine)


def periodogram_peak(values: np.ndarray, angle: np.ndarray, bins: int,
                     band: tuple[float, float], excluded: tuple[float, ...] = (),
                     width: float = 0.0, fine: bool = False) -> float:
    """Frequency [1/unit of ``angle``] within ``band`` (low, high), and further than
    ``width`` from each of ``excluded``, where the periodogram of ``values`` over ``angle``
    peaks: the rows summed into ``bins`` bins of a uniform grid over the span and
    transformed by FFT, zero-padded fourfold to steps of a quarter of the record's
    resolution 1/span (a binned stand-in for the Lomb–Scargle periodogram of unevenly
    sampled data; Lomb 1976, Scargle 1982), then to a sixty-fourth of it about the peak
    when ``fine``."""
    span = float(np.ptp(angle)) or 1.0
    summed = np.bincount(_bins(angle, span, bins), values - values.mean(), bins)
    power = np.abs(np.fft.rfft(summed, 4 * bins)) ** 2
    freqs = np.fft.rfftfreq(4 * bins, span / bins)
    inside = (freqs >= band[0]) & (freqs <= band[1])
    for f in excluded:
        inside &= np.abs(freqs - f) > width
    if not inside.any():
        return band[0]
    peak = float(freqs[inside][int(np.argmax(power[inside]))])
    if not fine:
        return peak
    step = 1.0 / (4.0 * span)  # the padded grid's
    near = peak + np.linspace(-step, step, 33)
    centres = (np.arange(bins) + 0.5) * span / bins
    return float(near[int(np.argmax(_dft_power(summed, centres, near)))])


# A ripple is a line in the periodogram: its power at least LINE_RATIO times the median over
# the band a factor LINE_BAND either side of it (outside LINE_STEPS steps of the record's
# resolution about it). A drift with time (a random walk's power falls as 1/f²) is a
# continuum whose strongest ordinate stands a few times above its neighbours at most.
LINE_RATIO = 10.0
LINE_BAND = 1.5
LINE_STEPS = 2.0


def is_line(residual: np.ndarray, angle: np.ndarray, period: float) -> bool:
    """Whether ``residual`` has a line at ``period`` [unit of ``angle``] in its periodogram
    over ``angle`` standing ``LINE_RATIO`` above the continuum about it."""
    span = float(np.ptp(angle)) or 1.0
    f0 = 1.0 / period
    resolution = 1.0 / span
    freqs = np.linspace(f0 / LINE_BAND, f0 * LINE_BAND, 256)
    near = np.abs(freqs - f0) <= LINE_STEPS * resolution
    if near.all():
        return False
    power = _dft_power(residual - residual.mean(), angle, np.append(freqs[~near], f0))
    return bool(power[-1] >= LINE_RATIO * np.median(power[:-1]))


def _dft_power(values: np.ndarray, angle: np.ndarray, freqs: np.ndarray) -> np.ndarray:
    """|Σ v·exp(−2πi·f·angle)|² at each of ``freqs`` (in blocks, to bound the memory)."""
    out = np.empty(len(freqs))
    for i in range(0, len(freqs), 32):
        f = freqs[i:i + 32]
        out[i:i + 32] = np.abs(np.exp(-2j * np.pi * np.outer(f, angle)) @ values) ** 2
    return out


# The wave generator's orders an output encoder's ripple is kept away from in transmission
# (the gear's own error and its overtones repeat at k per WG revolution), by this many steps
# of the record's resolution 1/span (a line's main lobe: closer, the two are one line)
GEAR_ORDERS = 8
GEAR_ORDER_STEPS = 1.0


def gear_orders(ratio: float, span_rad: float) -> tuple[tuple[float, ...], float]:
    """The frequencies [1/rad of output angle] of the WG orders 1 … ``GEAR_ORDERS`` for a
    gear of ``ratio`` R (k·R/2π: k per WG revolution) and the width kept from each
    (``GEAR_ORDER_STEPS`` of the resolution 1/span of an output-angle record ``span_rad``)."""
    return (tuple(k * ratio / (2.0 * np.pi) for k in range(1, GEAR_ORDERS + 1)),
            GEAR_ORDER_STEPS / (span_rad or 1.0))


def off_the_gear_orders(period_rad: float, ratio: float, span_rad: float) -> bool:
    """Whether an output-angle ripple of ``period_rad`` stays away from every WG order
    (:func:`gear_orders`): one on a WG order is as much the gear's error as the encoder's."""
    orders, width = gear_orders(ratio, span_rad)
    return all(abs(1.0 / period_rad - f) > width for f in orders)


def _bins(angle: np.ndarray, span: float, count: int) -> np.ndarray:
    """The bin (0 … count − 1) of each angle on a uniform grid of ``count`` over the span."""
    return np.minimum(((angle - angle.min()) / span * count).astype(int), count - 1)

