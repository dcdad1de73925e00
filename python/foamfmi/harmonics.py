"""Harmonic analysis of periodic records (wave gauges, body motion, line
tensions): least-squares fits of a mean and harmonics of a known frequency
(numpy.linalg.lstsq), the period from up-crossings, and the incident and
reflected waves from two or more gauges.

Convention: a harmonic n of complex amplitude Z_n = a_n - i b_n is
a_n cos(n omega t) + b_n sin(n omega t) = Re(Z_n exp(i n omega t)).
"""

import cmath
import collections
import math
import sys

try:
    import numpy as np
except ImportError as err:
    raise ImportError("numpy not found for %s: install Debian's python3-numpy "
                      "(bin/setup -tests does) and run the script with "
                      "/usr/bin/python3" % sys.executable) from err

# A sample is in the window [t0, t1] within this much (s): times written
# with 6 digits
WINDOW_TOLERANCE = 1e-9

HarmonicFit = collections.namedtuple("HarmonicFit", "mean amplitudes rms samples")
HarmonicFit.__doc__ = """mean; amplitudes: the complex amplitudes Z_1, Z_2, ...;
rms: root mean square of the residual; samples: how many were fitted."""


class FitError(ValueError):
    """Too few samples for a fit."""


def design_matrix(t, omega, harmonics=2):
    """Columns 1, cos(omega t), sin(omega t), cos(2 omega t), ... at the
    times t (array)."""
    columns = [np.ones_like(t)]
    for n in range(1, harmonics + 1):
        columns += [np.cos(n * omega * t), np.sin(n * omega * t)]
    return np.column_stack(columns)


def fit(t, y, omega, harmonics=2):
    """Least-squares fit of y(t) by a mean and the first harmonics of omega."""
    t = np.asarray(t, dtype=float)
    y = np.asarray(y, dtype=float)
    if len(t) < 2 * harmonics + 1:
        raise FitError("%d samples for a mean and %d harmonics" % (len(t), harmonics))
    a = design_matrix(t, omega, harmonics)
    c = np.linalg.lstsq(a, y, rcond=None)[0]
    rms = math.sqrt(float(np.mean((a @ c - y) ** 2)))
    amplitudes = [complex(c[2 * n - 1], -c[2 * n]) for n in range(1, harmonics + 1)]
    return HarmonicFit(float(c[0]), amplitudes, rms, len(t))


def in_window(times, values, t0, t1, min_samples=10):
    """The samples (t, value) with t in [t0, t1] (within WINDOW_TOLERANCE),
    as two arrays; FitError with fewer than min_samples."""
    t = np.asarray(times, dtype=float)
    y = np.asarray(values, dtype=float)
    inside = (t >= t0 - WINDOW_TOLERANCE) & (t <= t1 + WINDOW_TOLERANCE)
    if np.count_nonzero(inside) < min_samples:
        raise FitError("only %d samples in the window %g-%g s"
                       % (np.count_nonzero(inside), t0, t1))
    return t[inside], y[inside]


def fit_window(times, values, omega, t0, t1, harmonics=2):
    """fit() over the samples in the window [t0, t1] (at least 10)."""
    return fit(*in_window(times, values, t0, t1), omega, harmonics)


def first_harmonic(times, values, omega, t0, t1):
    """Mean and first-harmonic amplitude of a fit of a mean, the first and
    the second harmonic over [t0, t1]."""
    f = fit_window(times, values, omega, t0, t1)
    return f.mean, abs(f.amplitudes[0])


def upcrossing_period(times, values, t0):
    """Mean interval between the up-crossings of the mean after t0, and the
    number of intervals (nan, 0: fewer than two up-crossings)."""
    samples = [(t, v) for t, v in zip(times, values) if t >= t0]
    if len(samples) < 3:
        return float("nan"), 0
    mean = sum(v for _, v in samples) / len(samples)
    crossings = []
    for (ta, va), (tb, vb) in zip(samples, samples[1:]):
        if va < mean <= vb and vb > va:
            crossings.append(ta + (mean - va) / (vb - va) * (tb - ta))
    if len(crossings) < 2:
        return float("nan"), 0
    return (crossings[-1] - crossings[0]) / (len(crossings) - 1), len(crossings) - 1


def incident_reflected(z1, z2, x1, x2, k):
    """Complex amplitudes at x = 0 of the incident wave Z_I exp(-i k x) and
    the reflected wave Z_R exp(i k x) whose sum has the complex amplitudes
    z1 at x1 and z2 at x2 (Goda and Suzuki 1976). k (x2 - x1) must not be
    near a multiple of pi."""
    d = 2j * math.sin(k * (x2 - x1))
    zi = (z1 * cmath.exp(1j * k * x2) - z2 * cmath.exp(1j * k * x1)) / d
    zr = (z2 * cmath.exp(-1j * k * x1) - z1 * cmath.exp(-1j * k * x2)) / d
    return zi, zr


def separate_waves(z, x, k, decay=0.0):
    """Complex amplitudes at x = 0 of the incident wave Z_I exp(-i k x) and
    the reflected wave Z_R exp(i k x) from the complex amplitudes z_j of
    their sum at two or more gauges x_j: the least-squares solution
    (Mansard and Funke 1980; with two gauges, Goda and Suzuki's exact one).
    Spacings near a multiple of half a wavelength leave it ill-posed.
    decay: the incident wave's relative loss rate per metre of travel,
    Z_I exp(-(i k + decay) x) (a flume that damps it; 0: none)."""
    if len(z) != len(x) or len(z) < 2:
        raise ValueError("separate_waves: %d amplitudes at %d gauges (two or more)"
                         % (len(z), len(x)))
    xs = np.asarray(x, dtype=float)
    a = np.column_stack([np.exp(-(1j * k + decay) * xs), np.exp(1j * k * xs)])
    c = np.linalg.lstsq(a, np.asarray(z, dtype=complex), rcond=None)[0]
    return complex(c[0]), complex(c[1])


FreeDecay = collections.namedtuple("FreeDecay", "period damping_ratio amplitude mean rms samples")
FreeDecay.__doc__ = """A damped oscillation fitted to a record: period, the
damped period 2 pi/omega_d (s); damping_ratio, zeta = sigma/omega_n with
omega_n^2 = omega_d^2 + sigma^2; amplitude at the window's start; mean, the
level it decays to; rms of the residual; samples fitted."""


def free_decay(times, values, t0, t1):
    """Least-squares fit of y = m + exp(-sigma t')(a cos(omega_d t') +
    b sin(omega_d t')), t' = t - t0, over the samples in [t0, t1]: one
    damped mode (a free decay). The nonlinear pair (sigma, omega_d) by
    scipy.optimize.least_squares with m, a and b solved linearly at each
    (variable projection), started from the up-crossing period of the
    window's first half and a damping ratio of 0.05, and from half and
    twice that period; FitError with fewer than 10 samples or no two
    up-crossings."""
    try:
        from scipy.optimize import least_squares
    except ImportError as err:
        raise ImportError("scipy not found for a free decay's fit: install Debian's "
                          "python3-scipy (bin/setup -tests does)") from err

    t, y = in_window(times, values, t0, t1)
    s = t - t0

    def linear(p):
        sigma, omega = p
        e = np.exp(-sigma * s)
        a = np.column_stack([np.ones_like(s), e * np.cos(omega * s), e * np.sin(omega * s)])
        return a, np.linalg.lstsq(a, y, rcond=None)[0]

    def residual(p):
        a, c = linear(p)
        return a @ c - y

    guess, intervals = upcrossing_period(t[s <= 0.5 * (t1 - t0)], y[s <= 0.5 * (t1 - t0)], t0)
    if intervals == 0:
        guess, intervals = upcrossing_period(t, y, t0)
    if intervals == 0:
        raise FitError("no two up-crossings in %g-%g s: no oscillation to fit" % (t0, t1))
    best = None
    for start in (guess, 0.5 * guess, 2 * guess):
        omega = 2 * math.pi / start
        r = least_squares(residual, [0.05 * omega, omega],
                          bounds=([-np.inf, 0.1 * omega], [np.inf, 10 * omega]),
                          xtol=1e-12, ftol=1e-12, gtol=1e-12)
        if best is None or r.cost < best.cost:
            best = r
    sigma, omega = best.x
    _, c = linear(best.x)
    return FreeDecay(period=2 * math.pi / omega,
                     damping_ratio=sigma / math.hypot(sigma, omega),
                     amplitude=math.hypot(c[1], c[2]), mean=float(c[0]),
                     rms=math.sqrt(2 * best.cost / len(t)), samples=len(t))
