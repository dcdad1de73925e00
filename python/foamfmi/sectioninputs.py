"""The uncertain inputs of the spring-moored section in waves
(tutorials/mooredSectionWaves) and the sensitivities of its results to
them, one input at a time (ASME V&V 20-2009's u_input).

Each input has the model's value (what constant/dynamicMeshDict and
Allrun set when no option is given), the range the experiment's report
gives for it, and a standard uncertainty from that range: every value in
it equally likely, the half-range over sqrt(3) (uncertainty.
uniform_standard_uncertainty). A run kept with run.dat names the inputs
it was made with (guideFriction, mass, KG, springRate: Allrun -guide-
friction, -mass, -kg, -spring-rate); a run kept before an input was an
option had the model's value. The sensitivity of a result to an input is
the change between a run with the model's inputs and one with that input
alone changed, per unit of the input, on the same wave and mesh.
"""

import collections
import math

from foamfmi import uncertainty

Input = collections.namedtuple("Input", "key label unit nominal low high stated option")
Input.__doc__ = """key: its name in run.dat; label, unit: its name and unit; nominal: the
model's value; low, high: the stated range; stated: where the range comes
from; option: the Allrun option that sets it (None: no run sets it)."""

INPUTS = (
    Input("guideFriction", "guide friction", "N", 0.0, 0.0, 0.5,
          "the rig's static friction, measured 0.2-0.5 N; the model has none",
          "-guide-friction"),
    Input("mass", "mass", "kg", 46.2207, 46.2207, 46.8,
          "the drawn section's displacement at its draft, the model's, to the table's",
          "-mass"),
    Input("KG", "KG", "m", 0.106, 0.106, 0.108,
          "the heel test's, the model's, to the planned", "-kg"),
    Input("springRate", "each spring's rate", "N/m", 29.86, 0.5 * 59.21, 0.5 * 60.88,
          "the offset tests, 59.21-60.88 N/m the two together; the model has their mean",
          "-spring-rate"),
)
# The incident wave's amplitude: a run with the generator's height scaled
# (Allrun -incident-scale S, run.dat's incidentScale) changes it with the
# mesh and the window kept; the sensitivity is per metre of the incident
# amplitude each run separates at WP_4 (the RAOs are per each one's own),
# and its range the CFD's to the experiment's calibrated one
INCIDENT = "incidentScale"


def incident_scale(run):
    """The generator's height over the wave's (1: the wave's own)."""
    return float(run.get(INCIDENT, 1.0))


def value(run, key):
    """The input key of a kept run (its model value when run.dat does not
    name it)."""
    nominal = next(i.nominal for i in INPUTS if i.key == key)
    return float(run.get(key, nominal))


def changed(run):
    """The keys of the inputs the run does not have at the model's
    value, INCIDENT last where its generator's height is scaled."""
    keys = [i.key for i in INPUTS if abs(value(run, i.key) - i.nominal) > 1e-9 * max(1, i.nominal)]
    return keys + [INCIDENT] if abs(incident_scale(run) - 1.0) > 1e-9 else keys


def standard_uncertainty(item):
    """The input's standard uncertainty: uniform over its stated range."""
    return uncertainty.uniform_standard_uncertainty(item.low, item.high)


def sensitivity(base, variant, key, quantity):
    """d(quantity)/d(input key) from two runs' responses: (run, r) of the
    run with the model's inputs and of one with input key changed."""
    (run0, r0), (run1, r1) = base, variant
    dx = value(run1, key) - value(run0, key)
    return (r1[quantity] - r0[quantity]) / dx


def pick_variant(base, variants, key):
    """Of the runs with input key changed (INCIDENT: scaled), the one
    farthest from the base's value (the widest span of the range), or
    None."""
    if not variants:
        return None
    if key == INCIDENT:
        return max(variants, key=lambda v: abs(incident_scale(v[0]) - 1.0))
    x0 = value(base[0], key)
    return max(variants, key=lambda v: abs(value(v[0], key) - x0))


def incident_contribution(base, variant, quantity, calibrated, cfd):
    """s u of the incident amplitude for quantity: s its change per metre
    of incident amplitude between the runs (run, r) base and variant
    (their own incidentAmplitude, separated at WP_4), u uniform over the
    CFD's amplitude cfd to the experiment's calibrated one (m)."""
    (_, r0), (_, r1) = base, variant
    s = (r1[quantity] - r0[quantity]) / (r1["incidentAmplitude"] - r0["incidentAmplitude"])
    return s * uncertainty.uniform_standard_uncertainty(min(cfd, calibrated), max(cfd, calibrated))


def window_range(case, key):
    """The experiment's value of key over its window moved by one period
    either way (experimentRao's raoXWindowLow/High): (low, high), or
    None where the table has no such range. The springs' mean has the
    means of the two gauges' ranges (the range of their mean lies within
    it)."""
    if key == "tensionMean":
        low = [case.get(k + "WindowLow") for k in ("tensionWeather", "tensionLee")]
        high = [case.get(k + "WindowHigh") for k in ("tensionWeather", "tensionLee")]
        if None in low or None in high:
            return None
        return 0.5 * sum(low), 0.5 * sum(high)
    low, high = case.get(key + "WindowLow"), case.get(key + "WindowHigh")
    return None if low is None or high is None else (low, high)


# The quantities that are per the incident amplitude a (RAOs): the
# calibrated wave's spread moves them
PER_AMPLITUDE = ("sway", "heave", "roll", "tensionMean")


def data_uncertainty(case, key, spread_key):
    """The experimental value's standard uncertainty u_D (ASME V&V 20-2009)
    of quantity key of an experiment case (sectionwaves.read_experiment),
    from three independent parts, each None where the data has none:
    repetitions: half the spread of the repeated runs (column
    spread_key; None: one run or no column); calibration: the value
    times half the relative spread of the calibrated incident wave
    (before and after the tests, aSpread over a) for the quantities per
    a; window: the range over the window moved by a period either way as
    a uniform interval (half-range over sqrt 3): the response is still
    building up and beating over the window, and a window placed a
    fraction of a period off, in the experiment or in the CFD, moves the
    value within that range. Returns (u_D, {part: standard uncertainty
    or None})."""
    parts = {"repetitions": None, "calibration": None, "window": None}
    if spread_key and case.get(spread_key) and case.get("nRep", 1) > 1:
        parts["repetitions"] = 0.5 * case[spread_key]
    if key in PER_AMPLITUDE and case.get("amplitudeSpread") is not None:
        parts["calibration"] = abs(case[key]) * 0.5 * case["amplitudeSpread"] / case["amplitude"]
    span = window_range(case, key)
    if span is not None:
        parts["window"] = uncertainty.uniform_standard_uncertainty(*span)
    return math.sqrt(sum(u * u for u in parts.values() if u is not None)), parts
