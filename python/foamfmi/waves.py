"""Linear water waves and the second-order Stokes pieces the analyses use.

Units SI: omega in rad/s, depth h in m, wave number k in rad/m.
"""

import math
import os

from foamfmi import dictionary, foamdict

G = 9.81  # m/s^2, the tutorials' gravity (constant/g)


def wave_number(omega, depth, g=G):
    """k of the linear dispersion relation omega^2 = g k tanh(k h).

    Newton's method on f(k) = g k tanh(k h) - omega^2 (f increases with k:
    one root) from Guo's explicit approximation (2002, within 0.75 %);
    a few iterations reach the root to rounding in deep water
    (k -> omega^2/g), shallow water (k -> omega/sqrt(g h)) and between."""
    if omega <= 0 or depth <= 0 or g <= 0:
        raise ValueError("wave_number: omega, depth and g must be positive, got %g, %g, %g"
                         % (omega, depth, g))
    x = omega * math.sqrt(depth / g)  # kh in shallow water
    k = x * x / depth * (-math.expm1(-x ** 2.4908)) ** (-1 / 2.4908)
    for _ in range(50):
        kh = k * depth
        t = math.tanh(kh)
        f = g * k * t - omega * omega
        df = g * t + g * kh * (1 - t * t)
        step = f / df
        k -= step
        if abs(step) <= 1e-15 * k:
            break
    return k


def wavelength(omega, depth, g=G):
    """L = 2 pi/k of the linear dispersion relation."""
    return 2 * math.pi / wave_number(omega, depth, g)


def group_velocity(omega, k, depth):
    """c_g = omega/(2 k) (1 + 2 k h/sinh(2 k h)) of linear waves of
    frequency omega and wave number k in water of depth h."""
    kh = k * depth
    ratio = 2 * kh / math.sinh(2 * kh) if kh < 350 else 0.0
    return 0.5 * (omega / k) * (1 + ratio)


def group_velocity_of_period(period, depth, g=G):
    """c_g of linear waves of period T (s), k from the dispersion relation."""
    omega = 2 * math.pi / period
    return group_velocity(omega, wave_number(omega, depth, g), depth)


def stokes2_second_harmonic(a, k, depth):
    """Amplitude of the second harmonic of a second-order Stokes wave of
    first-harmonic amplitude a: k a^2/4 cosh(k h) (2 + cosh(2 k h))/sinh^3(k h)."""
    h = depth
    return (k * a * a / 4 * math.cosh(k * h) * (2 + math.cosh(2 * k * h))
            / math.sinh(k * h) ** 3)


def read_wave_properties(case):
    """Height H (m), period T (s) and rampTime (s) of the waves generated at
    the inlet: the entries of `inlet` in CASE/constant/waveProperties, its
    #include files and $macros expanded (foamdict)."""
    path = os.path.join(case, "constant", "waveProperties")
    inlet = foamdict.parse(path, case).get("inlet")
    if not isinstance(inlet, dict):
        raise dictionary.DictionaryError("no inlet dictionary in %s" % path)
    values = []
    for key in ("waveHeight", "wavePeriod", "rampTime"):
        if key not in inlet:
            raise dictionary.DictionaryError("no %s in inlet in %s" % (key, path))
        try:
            values.append(float(foamdict.word(inlet[key])))
        except ValueError:
            raise dictionary.DictionaryError("%s in inlet in %s: not a number: %s"
                                             % (key, path, " ".join(inlet[key]))) from None
    return tuple(values)
