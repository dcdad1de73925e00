"""The section's kept runs as its validation compares them
(tutorials/mooredSectionWaves/validationReport): each run analysed as
sectionResponse does, which run of a measured case is the production one,
the three meshes of its grid convergence, the runs of one input changed
at a time, and the uncertainties they give (ASME V&V 20-2009, through
foamfmi.uncertainty and foamfmi.sectioninputs).

A run is (name, run, series, responses, case): run.dat's settings, the
response series, sectionwaves.analyse's responses and the experiment's
case of the same wave.
"""

import os

from foamfmi import sectioninputs, sectionwaves, uncertainty

PRODUCTION_MESH = 0.5
# The mesh of the runs of one input changed at a time
SENSITIVITY_MESH = 0.296
REFERENCE_OPENFOAM = "v1912"


class SectionRunsError(ValueError):
    """A results folder that cannot be read as kept runs."""


def load_runs(results, experiment):
    """The experiment's cases (its table, experiment) and [(name, run,
    series, responses, case)] of the runs kept in results, by name;
    SectionRunsError for a missing folder or a run that ends before its
    window."""
    if not os.path.isdir(results):
        raise SectionRunsError("no folder %s (runs kept by sectionResponse -keep)" % results)
    cases = sectionwaves.read_experiment(experiment)
    runs = []
    for name in sorted(os.listdir(results)):
        folder = os.path.join(results, name)
        if not os.path.isfile(os.path.join(folder, "run.dat")):
            continue
        run, series = sectionwaves.read_run(folder)
        exp = sectionwaves.experiment_case(cases, run["period"], run["height"])
        r = sectionwaves.analyse(run, series, exp)
        if r is None:
            raise SectionRunsError("%s: the run ends at %g s, before its window"
                                   % (folder, series["Time"][-1]))
        runs.append((name, run, series, r, exp))
    return cases, runs


def openfoam(run):
    """The OpenFOAM the run was made on (runs kept before run.dat named it
    were made on v1912)."""
    return str(run.get("openfoam", REFERENCE_OPENFOAM))


def nominal(run):
    """Whether the run has the model's inputs (no guide friction, the
    model's mass, KG and springs, the wave's own height generated)."""
    return not sectioninputs.changed(run)


def flume(run):
    """The run's flume switches {key: value} (sectionwaves.FLUME_KEYS; empty:
    the case's own flume)."""
    return {key: run[key] for key in sectionwaves.FLUME_KEYS if key in run}


def flume_label(run):
    """The run's flume switches in words, "the case's" without any."""
    words = {"cellsPerHeight": "%g cells a wave height", "cellsPerWavelength":
             "%g cells a wavelength", "stepsPerPeriod": "T/%g", "ddt": "%s",
             "momentumDdt": "the momentum's %s", "momentumScheme": "%s",
             "phaseAdvection": "the phase fraction by %s", "inletAbsorption": "inlet absorption %s"}
    switches = flume(run)
    if not switches:
        return "the case's"
    return ", ".join(words[key] % (str(value).replace("_", " ") if isinstance(value, str)
                                   else value) for key, value in switches.items())


def generator(run):
    """The generator's distance before the section (m)."""
    return sectionwaves.SECTION_X - run["xIn"]


def in_experiment_flume(run):
    """Whether the run's generator is where the experiment's was."""
    return abs(generator(run) - sectionwaves.EXPERIMENT_GENERATOR) < 1e-9


def production(runs, case):
    """The case's run on the production mesh without friction, in the
    experiment's flume if one is kept, else in the longest flume."""
    candidates = [(abs(generator(run) - sectionwaves.EXPERIMENT_GENERATOR), name, run, r)
                  for name, run, series, r, exp in runs
                  if (exp is case and abs(run["meshFactor"] - PRODUCTION_MESH) < 1e-9
                      and nominal(run))]
    if not candidates:
        return None
    _, name, run, r = min(candidates, key=lambda c: c[0])
    return name, run, r


def convergence(runs, case):
    """The three runs of the case on different mesh factors (the model's
    inputs, the experiment's flume), finest first, or None."""
    meshes = {}
    for name, run, series, r, exp in runs:
        if exp is case and nominal(run) and in_experiment_flume(run):
            meshes[run["meshFactor"]] = (name, run, r)
    if len(meshes) < 3:
        return None
    finest = sorted(meshes, reverse=True)[:3]
    return [meshes[f] for f in finest]


def sensitivity_runs(runs, case):
    """The case's runs on SENSITIVITY_MESH in the experiment's flume: the
    one with the model's inputs as (run, r), or None, and per input key
    the runs with that input alone changed [(run, r)]."""
    base, variants = None, {i.key: [] for i in sectioninputs.INPUTS}
    variants[sectioninputs.INCIDENT] = []
    for name, run, series, r, exp in runs:
        if (exp is not case or abs(run["meshFactor"] - SENSITIVITY_MESH) > 1e-9
                or not in_experiment_flume(run)):
            continue
        keys = sectioninputs.changed(run)
        if not keys:
            base = (run, r)
        elif len(keys) == 1:
            variants[keys[0]].append((run, r))
    return base, variants


def input_contributions(runs, case, quantity):
    """Per input (sectioninputs.INPUTS, then the incident amplitude) its
    contribution s_i u_i to u_input of the quantity, or None where its
    run is missing; and u_input of those run."""
    base, variants = sensitivity_runs(runs, case)
    contributions = []
    for item in sectioninputs.INPUTS:
        variant = chosen_variant(base, variants, item.key)
        contributions.append(None if variant is None else
                             sectioninputs.sensitivity(base, variant, item.key, quantity)
                             * sectioninputs.standard_uncertainty(item))
    variant = chosen_variant(base, variants, sectioninputs.INCIDENT)
    contributions.append(None if variant is None else sectioninputs.incident_contribution(
        base, variant, quantity, *incident_range(runs, case, base)))
    return contributions, uncertainty.input_uncertainty(c for c in contributions if c is not None)


def chosen_variant(base, variants, key):
    """Of sensitivity_runs' base and variants, the run of input key the
    sensitivity takes (sectioninputs.pick_variant), or None."""
    return sectioninputs.pick_variant(base, variants[key], key) if base else None


def incident_range(runs, case, base):
    """The incident amplitude's range (m): the experiment's calibrated one
    and the CFD's (its production run's, else that of base (run, r))."""
    found = production(runs, case)
    return case["amplitude"], (found[2] if found else base[1])["incidentAmplitude"]


def same_settings(a, b, same_flume=True):
    """Whether runs a and b differ in nothing but their OpenFOAM (and,
    same_flume False, their flume's switches)."""
    return ((not same_flume or flume(a) == flume(b))
            and a["period"] == b["period"] and a["height"] == b["height"]
            and a["meshFactor"] == b["meshFactor"] and generator(a) == generator(b)
            and all(sectioninputs.value(a, i.key) == sectioninputs.value(b, i.key)
                    for i in sectioninputs.INPUTS)
            and sectioninputs.incident_scale(a) == sectioninputs.incident_scale(b))


def numerical_uncertainty(runs, case, key):
    """U_num of the case's three meshes for key (uncertainty.numerical_
    uncertainty), 0 without three meshes."""
    three = convergence(runs, case)
    if three is None:
        return 0.0
    return uncertainty.numerical_uncertainty([m[2][key] for m in three],
                                             [1 / m[1]["meshFactor"] for m in three])[0]
