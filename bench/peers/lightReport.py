"""The light-body part of bench/peers/peersReport: FloatStepper's disc in
reduced gravity (lightBodyCompare's runs) and the light floatingObject box
(lightBoxCompare's), their tables for docs/peers.md and the disc's plot
docs/peers/lightBody.png, from bench/peers/results/lightBody/."""

import os

from foamfmi import plots
from peerTables import interpolate, read_settings, read_table

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS = os.path.join(HERE, "results", "lightBody")
PLOTS = os.path.join(os.path.dirname(os.path.dirname(HERE)), "docs", "peers")


LIGHT_TOOLS = ("floatStepper", "addedMassCoupling", "addedMassCouplingNoSlip")
LIGHT_NAMES = {"floatStepper": "floatStepper",
               "addedMassCoupling": "added-mass coupling",
               "addedMassCouplingNoSlip": "added-mass coupling, no-slip wall",
               "addedMassCouplingConverged": "added-mass coupling, converged (1e-2)"}


def load_light_body():
    """[(run, rows)] of bench/peers/results/lightBody/<tool>/ratio<R>/,
    heaviest body first, tools in LIGHT_TOOLS' order."""
    found = []
    for t, tool in enumerate(LIGHT_TOOLS):
        folder = os.path.join(RESULTS, tool)
        if not os.path.isdir(folder):
            continue
        for name in os.listdir(folder):
            path = os.path.join(folder, name)
            if os.path.isfile(os.path.join(path, "run.dat")):
                run = read_settings(os.path.join(path, "run.dat"))
                found.append((-run["ratio"], t, run, read_table(os.path.join(path, "series.dat"))))
    return [(run, rows) for _, _, run, rows in sorted(found, key=lambda x: x[:2])]


def disc_acceleration(run):
    """The disc's acceleration in an ideal fluid (up positive): C_a of a
    disc in a circle held at p = 0, (R2^2 - R1^2)/(R2^2 + R1^2)."""
    r1, r2, ratio = run["R1"], run["R2"], run["ratio"]
    added = (r2 ** 2 - r1 ** 2) / (r2 ** 2 + r1 ** 2)
    return (1 - ratio) / (ratio + added) * run["gravity"]


def light_body_errors(run, rows):
    """Errors against the ideal fluid's uniform acceleration, in % of the
    analytic velocity (displacement) at the run's last time, or of g T
    (g T^2/2) for a body as heavy as the fluid: the velocity at the end,
    the largest velocity error over the run, the height at the end."""
    a = disc_acceleration(run)
    t_end, y_end, v_end = rows[-1]
    scale = abs(a) if abs(a) > 1e-12 * run["gravity"] else run["gravity"]
    v_scale, y_scale = scale * t_end, scale * t_end ** 2 / 2
    largest = max(abs(v - a * t) for t, _, v in rows)
    return (100 * (v_end - a * t_end) / v_scale, 100 * largest / v_scale,
            100 * (y_end - a * t_end ** 2 / 2) / y_scale)


def light_body_table(runs):
    if not runs:
        return ["Not run yet: `bench/peers/lightBodyCompare` keeps the runs."]
    first = runs[0][0]
    lines = ["The disc of FloatStepper's `run/discInGravity` on %d cells (R1 = %g m, "
             "R2 = %g m, g = %g m/s^2, fluid density %g), run to %g s. The analytic "
             "acceleration a = (1 - r)/(r + C_a) g, C_a = %.5f (the rim held at p = 0; "
             "1 in an unbounded fluid). Errors: the velocity at the end and the "
             "largest velocity error over the run in %% of a T, the height at the end "
             "in %% of a T^2/2 (of g T and g T^2/2 where a = 0); flow solves per "
             "step: PIMPLE's outer correctors, and floatStepper's zero-acceleration "
             "solve and probe solve; CPU: execution time per simulated second, one "
             "core, alone under the CFD lock."
             % (first["cells"], first["R1"], first["R2"], first["gravity"],
                first["rhoFluid"], first["endTime"],
                (first["R2"] ** 2 - first["R1"] ** 2) / (first["R2"] ** 2 + first["R1"] ** 2)),
             "",
             "| body/fluid density | tool | end reached | a (m/s^2) | velocity error at "
             "the end | largest velocity error | height error at the end | added mass "
             "(kg/m) | steps | flow solves per step | CPU s per simulated s |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for run, rows in runs:
        if not rows:
            lines.append("| %g | %s | no step | | | | | | | | |"
                         % (run["ratio"], LIGHT_NAMES[run["tool"]]))
            continue
        v_err, v_max, y_err = light_body_errors(run, rows)
        solves = (run["outerCorrectors"] + run["probeSolves"]) / max(run["timeSteps"], 1)
        reached = ("yes" if run["endReached"] == "yes"
                   else "stopped at %.3g s" % run["lastTime"])
        cpu = run["executionTime"] / run["lastTime"] if run["lastTime"] > 0 else 0.0
        lines.append("| %g | %s | %s | %.5f | %+.2f %% | %.2f %% | %+.2f %% | %.5g | %d "
                     "| %.2f | %.1f |"
                     % (run["ratio"], LIGHT_NAMES[run["tool"]], reached,
                        disc_acceleration(run), v_err, v_max, y_err, run["addedMass"],
                        run["timeSteps"], solves, cpu))
    lines += ["", "| run | solver | OpenFOAM | cells | mesh (radial, around a quadrant) "
              "| commit | peers |", "| --- | --- | --- | --- | --- | --- | --- |"]
    seen = set()
    for run, _ in runs:
        key = (run["tool"], run["solver"], run["openfoam"], run["cells"], run["nx"],
               run["ny"], run["commit"], run["peersStamp"])
        if key not in seen:
            seen.add(key)
            lines.append("| %s | %s | %s | %d | %d x %d | %s | %s |"
                         % (LIGHT_NAMES[run["tool"]], run["solver"], run["openfoam"],
                            run["cells"], run["nx"], run["ny"], run["commit"],
                            run["peersStamp"]))
    return lines


CUBE_TOOLS = ("floatStepper", "addedMassCoupling", "addedMassCouplingConverged")


def load_cube():
    """{(tool, maxCo): (run, rows)} of bench/peers/results/lightBody/cube/
    <tool>/ (the tutorial's maxCo 1) and <tool>_maxCo<C>/."""
    found = {}
    folder = os.path.join(RESULTS, "cube")
    for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        tool, _, co = name.partition("_maxCo")
        path = os.path.join(folder, name)
        if tool not in CUBE_TOOLS or not os.path.isfile(os.path.join(path, "run.dat")):
            continue
        run = read_settings(os.path.join(path, "run.dat"))
        found[(tool, float(co) if co else 1.0)] = (run, read_table(os.path.join(path, "series.dat")))
    return found


def cube_order(runs):
    """The runs' keys, the tutorial's maxCo first, then smaller ones; each
    maxCo's tools in CUBE_TOOLS' order."""
    return sorted(runs, key=lambda k: (-k[1], CUBE_TOOLS.index(k[0])))


def cube_table(runs):
    if not runs:
        return ["Not run yet: `bench/peers/lightBoxCompare` keeps the runs."]
    first = next(iter(runs.values()))[0]
    lines = ["The floatingObject tutorial's box at %g kg/m^3 (%.3g kg), free in sway and "
             "pitch, on its %d cells, to %g s, at the tutorial's maxCo (and maxAlphaCo) 1 "
             "and smaller (`-max-co`). Sway: the range of the box origin's y over "
             "the run; pitch: the range of its sine; the largest sway and pitch-sine "
             "difference from floatStepper's run at the same maxCo over the times both "
             "reached; flow solves per step: outer correctors, and floatStepper's "
             "zero-acceleration solve and probe solves."
             % (first["density"], first["mass"], first["cells"], first["endTime"]), "",
             "| tool | maxCo | solver | end reached | steps | flow solves per step | CPU s per "
             "simulated s | sway range (mm) | pitch-sine range | largest sway difference "
             "from floatStepper (mm) | largest pitch-sine difference |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for key in cube_order(runs):
        tool, co = key
        run, rows = runs[key]
        dy = dq = None
        other = runs.get(("floatStepper", co))
        if tool != "floatStepper" and other and rows:
            other = other[1]
            end = min(rows[-1][0], other[-1][0])
            mine = [r for r in rows if r[0] <= end]
            dy = max(abs(r[1] - interpolate(other, 1, r[0])) for r in mine
                     if interpolate(other, 1, r[0]) is not None)
            dq = max(abs(r[2] - interpolate(other, 2, r[0])) for r in mine
                     if interpolate(other, 2, r[0]) is not None)
        reached = ("yes" if run["endReached"] == "yes"
                   else "stopped at %.3g s" % run["lastTime"])
        cpu = ("%.1f" % (run["executionTime"] / run["lastTime"])
               if run["endReached"] == "yes" and run["lastTime"] > 0 else "-")
        ys = [r[1] for r in rows] or [0.0]
        qs = [r[2] for r in rows] or [0.0]
        lines.append("| %s | %g | %s | %s | %d | %.2f | %s | %.4g | %.4g | %s | %s |"
                     % (LIGHT_NAMES[tool], co, run["solver"], reached, run["timeSteps"],
                        run["flowSolves"] / max(run["timeSteps"], 1), cpu,
                        1e3 * (max(ys) - min(ys)), max(qs) - min(qs),
                        "-" if dy is None else "%.3g" % (1e3 * dy),
                        "-" if dq is None else "%.3g" % dq))
    lines += ["", "| run | maxCo | OpenFOAM | commit | peers |",
              "| --- | --- | --- | --- | --- |"]
    for key in cube_order(runs):
        run = runs[key][0]
        lines.append("| %s | %g | %s | %s | %s |" % (LIGHT_NAMES[key[0]], key[1],
                                                     run["openfoam"], run["commit"],
                                                     run["peersStamp"]))
    return lines


def plot_light_body(runs):
    """docs/peers/lightBody.png: the velocity error over time of every run
    with a body lighter than the fluid, one panel a tool."""
    runs = [(run, rows) for run, rows in runs if rows and run["ratio"] < 1]
    if not runs:
        return
    os.makedirs(PLOTS, exist_ok=True)
    tools = [t for t in LIGHT_TOOLS if any(run["tool"] == t for run, _ in runs)]
    ratios = sorted({run["ratio"] for run, _ in runs}, reverse=True)
    first = runs[0][0]
    lines = ["set terminal " + plots.terminal("900,%d" % (300 * len(tools) + 60)),
             "set output '%s'" % os.path.join(PLOTS, "lightBody.png"),
             "set termoption noenhanced",
             "set multiplot layout %d,1 title \"FloatStepper's disc in reduced gravity "
             "(%d cells, OpenFOAM %s): (v - a t)/(a T), a the ideal fluid's\""
             % (len(tools), first["cells"], first["openfoam"]),
             "set grid", "set key top left", "set lmargin 10"]
    for i, tool in enumerate(tools):
        if i == len(tools) - 1:
            lines.append("set xlabel 't (s)'")
        lines.append('set ylabel "%s (%%)"' % LIGHT_NAMES[tool])
        curves = []
        for run, _ in runs:
            if run["tool"] != tool:
                continue
            a = disc_acceleration(run)
            path = os.path.join(RESULTS, tool, "ratio%g" % run["ratio"],
                                "series.dat")
            curves.append("'%s' u 1:(100*($3 - %.12g*$1)/%.12g) w l lw 2 lc %d "
                          "t 'density ratio %g'"
                          % (path, a, a * run["lastTime"], ratios.index(run["ratio"]) + 1,
                             run["ratio"]))
        lines.append("plot " + ", ".join(curves))
    lines.append("unset multiplot")
    script = os.path.join(PLOTS, "lightBody.gp")
    plots.gnuplot(script, lines)
    os.remove(script)
