#!/bin/bash
#------------------------------------------------------------------------------
# The README's worked example, as written: OpenFOAM's floatingObject
# tutorial with a spring to the tank wall, the restraint dictionaries taken
# from README.md (between "<!-- readme example: NAME -->" and
# "<!-- readme example: end -->"), the case copied, the FMU copied and the
# controlDict set as its steps say, run by the README's commands to 1 s:
#  - rigidBodyMotion: the README's fmuConnector restraint against the
#    README's built-in linearSpring;
#  - sixDoFRigidBodyMotion (the tutorial's dynamicMeshDict.sixDoF): the
#    README's fmuConnector restraint against the built-in sixDoF
#    linearSpring whose refAttachmentPt is the tutorial's centre of rotation
#    plus the README's A.p, as the README says.
# Checks: each pair moves alike (tolerance below), the connector's rows obey
# the spring law, and the spring pulls (so the comparison is not made on a
# slack spring).
#------------------------------------------------------------------------------
. "$(dirname "$0")/../tutorials/tutorialTestFunctions"
. "$(dirname "$0")/../tutorials/connectorTestFunctions"

endTime=1
tutorial="$FOAM_TUTORIALS/multiphase/interFoam/RAS/floatingObject"
[ -d "$tutorial" ] || fail "OpenFOAM's floatingObject tutorial not found: $tutorial"
requireBridge linearSpring "the spring FMU (build it: ./Allwmake)"
makeWorkDir

# The README's dictionaries, and the cases made from them
python3 - "$FOAMFMI_DIR/README.md" "$tutorial" "$workDir" "$endTime" \
    "$FOAMFMI_FMU_DIR/linearSpring.fmu" <<'EOF' || fail "cannot make the cases from README.md"
import os, re, shutil, sys, textwrap

from foamfmi.floatingobject import add_restraints, sixdof_dictionary

readme, tutorial, work, end_time, fmu = sys.argv[1:]
text = open(readme).read()
blocks = dict(re.findall(r"<!-- readme example: (\S+) -->\n(.*?)<!-- readme example: end -->",
                         text, re.S))
for name in ("builtin", "rigidBodyMotion", "sixDoFRigidBodyMotion", "run"):
    if name not in blocks:
        sys.exit(f"README.md: no example block {name}")
    blocks[name] = textwrap.dedent(blocks[name])


def vector(block, key):
    found = re.search(key + r"\s+\(([^)]*)\)", block)
    if not found:
        sys.exit(f"README.md: no {key} in the block\n{block}")
    return [float(v) for v in found.group(1).split()]


# The built-in sixDoF spring: refAttachmentPt = centreOfRotation + A.p
sixdof_dict = open(os.path.join(tutorial, "constant", "dynamicMeshDict.sixDoF")).read()
centre = vector(sixdof_dict, "centreOfRotation")
attachment = [c + a for c, a in zip(centre, vector(blocks["sixDoFRigidBodyMotion"], "A.p"))]
builtin = blocks["builtin"]
blocks["sixDoFbuiltin"] = (
    builtin.replace("type            linearSpring;",
                    "sixDoFRigidBodyMotionRestraint linearSpring;")
    .replace("refAttachmentPt (0 -0.1 0.25);",
             "refAttachmentPt (%s);" % " ".join("%.12g" % x for x in attachment)))
if blocks["sixDoFbuiltin"].count("sixDoFRigidBodyMotionRestraint") != 1 \
        or "refAttachmentPt (0 -0.1" in blocks["sixDoFbuiltin"]:
    sys.exit("README.md: the built-in spring block is not the one this test reads")

solver = "interFoamAliasSafe" if shutil.which("interFoamAliasSafe") else "interFoam"
for case, block in [("rigidBuiltin", "builtin"), ("rigidFmu", "rigidBodyMotion"),
                    ("sixDoFBuiltin", "sixDoFbuiltin"), ("sixDoFFmu", "sixDoFRigidBodyMotion")]:
    path = os.path.join(work, case)
    shutil.copytree(tutorial, path)
    constant = os.path.join(path, "constant")
    if case.startswith("sixDoF"):
        # Its #codeStream moment of inertia as the value it computes
        # (OpenFOAM compiles no dynamic code for root)
        open(os.path.join(constant, "dynamicMeshDict"), "w").write(sixdof_dictionary(tutorial))
    os.makedirs(os.path.join(constant, "fmu"))
    shutil.copy(fmu, os.path.join(constant, "fmu"))
    add_restraints(path, blocks[block])
    control = os.path.join(path, "system", "controlDict")
    text = open(control).read()
    text = re.sub(r"\napplication\s+\w+;", f"\napplication     {solver};", text)
    text = re.sub(r"\nendTime\s+[^;]+;", f"\nendTime         {end_time};", text)
    text = text.replace("\nstartFrom", '\nlibs            ("libfoamFmiBridge.so");\n\nstartFrom', 1)
    open(control, "w").write(text)
# The README's commands, from the folder above the case, for the solver
# there is (interFoam on an OpenFOAM without the rebuilt solvers)
run = blocks["run"].replace("cd mySpring\n", 'cd "$1"\n').replace("interFoamAliasSafe", solver)
if 'cd "$1"' not in run:
    sys.exit("README.md: the run block does not start with cd mySpring")
open(os.path.join(work, "run"), "w").write("set -e\n" + run)
print(solver)
EOF
pass "cases made from README.md's blocks"

for case in rigidBuiltin rigidFmu sixDoFBuiltin sixDoFFmu
do
    (cd "$workDir" && bash run "$case") \
        || fail "$case: the README's commands failed (see the logs in $workDir/$case)"
    checkRanToEnd "$workDir/$case" $endTime
    log=$(solverLog "$workDir/$case")
    if [ "${case#sixDoF}" != "$case" ]
    then
        "$FOAMFMI_DIR/tutorials/bin/rigidBodyMotionFromLog" -sixDoF floatingObject \
            "$log" "$workDir/$case/motion" > /dev/null
    else
        "$FOAMFMI_DIR/tutorials/bin/rigidBodyMotionFromLog" \
            "$log" "$workDir/$case/motion" > /dev/null
    fi || fail "$case: no body motion in $log"
done

# The spring law, and a spring that pulls: tension = 100 N/m (length -
# 0.35 m), to the rounding of the written values (1e-9 of the tension plus
# k times 1e-11 m); largest tension above 0.5 N (about 0.35 N per mm of
# sway: a spring that never stretches would compare nothing)
for case in rigidFmu sixDoFFmu
do
    dat="$workDir/$case/postProcessing/fmuConnectors/0/spring.dat"
    requireFile "$dat" "connector output"
    cols=$(columnsOf "$dat" length tension) || exit 1
    awk -v cols="$cols" "$checkAwk"'
    BEGIN { split(cols, c, " ") }
    /^#/ { next }
    {
        n++; L = $(c[1]); T = $(c[2])
        if (abs(T - 100*(L - 0.35)) > 1e-9*abs(T) + 1e-9) bad("t = " $1 ": tension " T " N at length " L " m")
        if (abs(T) > maxT) maxT = abs(T)
    }
    END {
        if (failed) exit 1
        if (maxT < 0.5) bad("largest tension " maxT " N: the spring hardly acts")
        printf("%d rows obey the spring law, largest tension %.3g N\n", n, maxT)
    }' "$dat" > "$workDir/check.out" || fail "$case: $dat"
    pass "$case: $(cat "$workDir/check.out")"
done

# The FMU against the built-in spring. The two compute the same force from
# the same state (under rigidBodyMotion to the same bits: the motions are
# identical); the motion is read from the solver's log, which prints 6
# significant digits: the centre at 0.45 m to 5e-7 m, 2e-5 of the sway's
# range (0.023 m over 1 s). Tolerance 1e-4 of the range over the run of the
# centre of rotation's coordinates and of the rotation vector's components:
# a wrong attachment point (A.p in the wrong frame: 0.25 m off), a wrong
# anchor or stiffness changes the motion by percents of its range.
for framework in rigid sixDoF
do
    # Debian's python3 has numpy (python3-numpy)
    /usr/bin/python3 - "$workDir/${framework}Builtin/motion/floatingObject.dat" \
        "$workDir/${framework}Fmu/motion/floatingObject.dat" \
        > "$workDir/check.out" <<'EOF' || fail "$framework: the README's fmuConnector does not move the body as the built-in spring does"
import sys
import numpy as np

builtin, fmu = (np.loadtxt(f, comments="#", ndmin=2) for f in sys.argv[1:])
failed = False
for what, columns, unit in (("centre of rotation", [1, 2, 3], "m"),
                            ("rotation vector", [5, 6, 7], "deg")):
    reference = builtin[:, columns]
    scale = (reference.max(axis=0) - reference.min(axis=0)).max()
    difference = max(np.abs(np.interp(builtin[:, 0], fmu[:, 0], fmu[:, c]) - builtin[:, c]).max()
                     for c in columns)
    ok = difference <= 1e-4 * scale + 1e-12
    failed |= not ok
    print(f"{what}: largest difference {difference:.3g} {unit}, "
          f"{difference / scale if scale else 0:.3g} of its range {scale:.3g} {unit}"
          + ("" if ok else " (more than 1e-4)"), file=sys.stdout if ok else sys.stderr)
sys.exit(1 if failed else 0)
EOF
    pass "$framework: the README's fmuConnector against the built-in spring:" \
         "$(tr '\n' ';' < "$workDir/check.out")"
done
