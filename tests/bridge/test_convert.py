"""foamFmiConvert: OpenFOAM's built-in restraints turned into fmuConnector
restraints move the bodies as the built-in ones do, with no fluid.

1. rigidBodyMotion (rigidBodySim): a body on a floating joint, its frame
   turned and its centre of mass off the frame origin, on a built-in
   linearSpring (attachment off the origin, damping), a linearDamper and a
   sphericalAngularDamper, under gravity. The case is converted in a copy
   (the controlDict without libs, to see the converter add it) and both
   are run.
2. sixDoFRigidBodyMotion (sixDoFSim, constant/sixDoFBodies): one body with
   a line constraint whose centreOfRotation is not the centre of mass (the
   converter must take A.p from that centre, as OpenFOAM's constructor
   does) and a turned orientation, on a linearSpring and a linearDamper;
   one body with no constraint, turned, on a linearSpring of the same name
   (two built-in restraints; fmuConnector restraints of one name in two
   motions would be one connector: the converter renames them), a
   sphericalAngularDamper, a linearAxialAngularSpring about a tilted
   axis, the body starting 90 deg from its reference about z, and a
   tabulatedAxialAngularSpring about another axis, a softening table in
   degrees from a file, clamped beyond it; one body pinned at its centre
   of mass and spun, tumbling on a sphericalAngularSpring alone, 120 deg
   from its reference at the start (where its moment is no gradient). The line runs through the global origin along z
   and the damper's body moves along it: OpenFOAM's sixDoF linearDamper
   applies its force at the global origin (a moment centreOfRotation x
   force about the centre of rotation), which this geometry makes zero, so
   that the two agree.
3. -dry-run changes no file and prints the diff; the converted case
   names every FMU it copied; a restraint brought in by an #include is
   refused, naming the file and the restraint; the restraints of a
   sixDoFRigidBodyDisplacement patch in 0/pointDisplacement are converted
   with the patch as the body.
"""
import os
import shutil
import subprocess
import sys

from foamfmi.bridgecase import Case, check, foam_file, summary, vec
from foamfmi.sixdofcase import SixDoFCase

CONVERT = os.path.join(os.environ["FOAMFMI_DIR"], "bin", "foamFmiConvert")
ANCHOR = (0.3, 0.2, 1.2)
K, C, L0, COEFF, ANGULAR = 50.0, 0.5, 0.5, 3.0, 0.05
TURNED = "(0 -1 0 1 0 0 0 0 1)"  # 90 deg about z


def convert(case_dir, *args, expect_failure=False):
    done = subprocess.run([CONVERT, *args, case_dir], capture_output=True, text=True)
    if (done.returncode != 0) != expect_failure:
        raise AssertionError(f"foamFmiConvert {' '.join(args)} {case_dir}: exit "
                             f"{done.returncode}\n{done.stdout}{done.stderr}")
    return done.stdout + done.stderr


def copy_case(case, name):
    """A copy of case (its class, its files) in a folder of its own."""
    copy = type(case).__new__(type(case))
    copy.dir = case.dir + "." + name
    shutil.copytree(case.dir, copy.dir)
    return copy


def compare_runs(framework, builtin, converted, bodies):
    """Run both cases (2 solves per step, as PIMPLE's outer correctors)
    and check that the converted one moves every body as the built-in one;
    1 if it does not."""
    builtin.run(n_iter=2)
    converted.run(n_iter=2)
    a, b = builtin.bodies(), converted.bodies()
    failures = 0
    for what in (("c.x", "c.y", "c.z"), ("omega.x", "omega.y", "omega.z")):
        columns = [body + "." + q for body in bodies for q in what]
        worst = max(max(abs(u - v) for u, v in zip(a[c], b[c])) for c in columns)
        scale = max(max(a[c]) - min(a[c]) for c in columns)
        # Both compute the same loads from the same state in another order
        # of operations: round-off of ~1e-16 per step, grown over 2000
        # steps of a damped oscillation, stays far below 1e-9 of the range;
        # A.p in a wrong frame, a wrong centre of rotation or the damper on
        # another point moves the bodies by percents of it
        failures += check(f"{framework}: the converted case moves as the built-in one, {what[0][:-2]}",
                          worst <= 1e-9 * scale and scale > 0.05,
                          f"largest difference {worst:.3e}, range {scale:.3f}")
    builtin.cleanup()
    converted.cleanup()
    return failures


def rigid():
    body = (
        "    box\n    {\n        type rigidBody;\n        parent root;\n"
        "        mass 2;\n        centreOfMass (0 0 0.25);\n"
        "        inertia (0.1 0 0 0.12 0 0.08);\n"
        f"        transform {TURNED} (0.5 0.45 0.1);\n"
        "        joint { type floating; }\n    }\n")
    restraints = (
        "        spring\n        {\n            type linearSpring;\n            body box;\n"
        f"            anchor {vec(ANCHOR)};\n            refAttachmentPt (0.1 -0.1 0.25);\n"
        f"            stiffness {K};\n            damping {C};\n            restLength {L0};\n"
        "        }\n"
        "        damper\n        {\n            type linearDamper;\n            body box;\n"
        f"            coeff {COEFF};\n        }}\n"
        "        turning\n        {\n            type sphericalAngularDamper;\n"
        f"            body box;\n            coeff {ANGULAR};\n        }}\n")
    model = (f"\n    solver {{ type Newmark; }}\n    g (0 0 -9.81);\n"
             f"    bodies\n    {{\n{body}    }}\n    restraints\n    {{\n{restraints}    }}\n")
    builtin = Case("convertRigid", model, 2.0, 0.001)
    control = os.path.join(builtin.dir, "system", "controlDict")
    with open(control) as f:
        text = f.read()
    with open(control, "w") as f:
        f.write(text.replace('libs ("libfoamFmiBridge.so");\n', ""))
    converted = copy_case(builtin, "converted")
    failures = 0

    before = {n: open(os.path.join(converted.dir, n)).read()
              for n in ("constant/dynamicMeshDict", "system/controlDict")}
    out = convert(converted.dir, "-dry-run")
    after = {n: open(os.path.join(converted.dir, n)).read() for n in before}
    failures += check("-dry-run changes nothing",
                      after == before and not os.path.isdir(
                          os.path.join(converted.dir, "constant", "fmu")),
                      "files as they were, no constant/fmu")
    failures += check("-dry-run prints the diff",
                      "+            type         fmuConnector;" in out
                      and '+libs            ("libfoamFmiBridge.so");' in out,
                      "fmuConnector and libs lines in the diff")

    out = convert(converted.dir)
    print(out, end="")
    fmus = sorted(os.listdir(os.path.join(converted.dir, "constant", "fmu")))
    failures += check("FMUs copied", fmus == ["linearSpring.fmu", "rotationalDamper.fmu",
                                                  "translationalDamper.fmu"],
                      f"constant/fmu: {' '.join(fmus)}")
    with open(control.replace(builtin.dir, converted.dir)) as f:
        failures += check("libs added", 'libs            ("libfoamFmiBridge.so");' in f.read(),
                          "system/controlDict loads libfoamFmiBridge.so")
    failures += check("converted again: nothing to do",
                      "no built-in restraint to convert" in convert(converted.dir),
                      "a second conversion finds only fmuConnector restraints")

    return failures + compare_runs("rigidBodyMotion", builtin, converted, ["box"])


def sixdof_body(centre, restraints, extra=""):
    return (f"        mass 2;\n        momentOfInertia (0.1 0.12 0.08);\n"
            f"        centreOfMass {vec(centre)};\n        orientation {TURNED};\n"
            f"        solver {{ type Newmark; }}\n        report off;\n{extra}"
            f"        restraints\n        {{\n{restraints}        }}\n")


def sixdof_spring(attachment):
    return ("            spring\n            {\n"
            "                sixDoFRigidBodyMotionRestraint linearSpring;\n"
            f"                anchor {vec(ANCHOR)};\n"
            f"                refAttachmentPt {vec(attachment)};\n"
            f"                stiffness {K}; damping {C}; restLength {L0};\n"
            "            }\n")


def sixdof():
    damper = ("            damper\n            {\n"
              "                sixDoFRigidBodyMotionRestraint linearDamper;\n"
              f"                coeff {COEFF};\n            }}\n")
    turning = ("            turning\n            {\n"
               "                sixDoFRigidBodyMotionRestraint sphericalAngularDamper;\n"
               f"                coeff {ANGULAR};\n            }}\n")
    # from identity, the body 90 deg away from it about z at the start
    axial = ("            twist\n            {\n"
             "                sixDoFRigidBodyMotionRestraint linearAxialAngularSpring;\n"
             "                axis (0 0.6 0.8);\n"
             "                referenceOrientation (1 0 0 0 1 0 0 0 1);\n"
             "                stiffness 0.4; damping 0.02;\n            }\n")
    # a softening spring in degrees, its table in constant/twistTable
    tabulated = ("            tabled\n            {\n"
                 "                sixDoFRigidBodyMotionRestraint tabulatedAxialAngularSpring;\n"
                 "                axis (0.8 0 0.6);\n"
                 "                file \"$FOAM_CASE/constant/twistTable\";\n"
                 "                outOfBounds clamp;\n"
                 "                angleFormat degrees;\n"
                 "                damping 0.01;\n            }\n")
    # 90 deg about y: 120 deg from the body's start (TURNED), about no axis
    # of the reference (90 deg about x would be an equilibrium of the law)
    spherical = ("            tumble\n            {\n"
                 "                sixDoFRigidBodyMotionRestraint sphericalAngularSpring;\n"
                 "                referenceOrientation (0 0 1 0 1 0 -1 0 0);\n"
                 "                stiffness 0.3; damping 0.005;\n            }\n")
    line = ("        constraints\n        {\n            along\n            {\n"
            "                sixDoFRigidBodyMotionConstraint line;\n"
            "                centreOfRotation (0 0 0.4);\n"
            "                direction (0 0 1);\n            }\n        }\n")
    pinned = ("        constraints\n        {\n            pin\n            {\n"
              "                sixDoFRigidBodyMotionConstraint point;\n"
              "                centreOfRotation (-1 0.5 0.6);\n            }\n        }\n"
              "        angularMomentum (0.01 -0.02 0.015);\n")
    bodies = {
        "constrained": sixdof_body((0.1, 0.05, 0.6), sixdof_spring((0.1, 0.1, 0.45)) + damper,
                                   line),
        "free": sixdof_body((1.0, 0.0, 0.6), sixdof_spring((1.1, 0.05, 0.7)) + turning
                            + axial + tabulated),
        "tumbling": sixdof_body((-1.0, 0.5, 0.6), spherical, pinned),
    }
    builtin = SixDoFCase("convertSixDoF", bodies, 2.0, 0.001, g=(0, 0, -9.81))
    with open(os.path.join(builtin.dir, "constant", "twistTable"), "w") as f:
        f.write("(\n    (-150 0.9)\n    (-60 0.5)\n    (0 0)\n    (45 -0.4)\n    (150 -0.8)\n)\n")
    converted = copy_case(builtin, "converted")
    out = convert(converted.dir, "-dict", "constant/sixDoFBodies")
    print(out, end="")
    failures = check("sixDoF: A.p from the line constraint's centre of rotation",
                     "A.p (0.1 -0.1 0.05)" in out,
                     "refAttachmentPt (0.1 0.1 0.45) - (0 0 0.4), turned back by -90 deg "
                     "about z: (0.1 -0.1 0.05)")
    failures += check("sixDoF: a restraint name of two motions is made two",
                      "renamed spring_constrained" in out and "renamed spring_free" in out,
                      "spring_constrained and spring_free, two connectors")
    failures += check("sixDoF: the damper's moment is named", "note: OpenFOAM's sixDoF "
                      "linearDamper applies its force at the global origin" in out,
                      "a note on the converted linearDamper")
    failures += check("sixDoF: the tabulated spring's table is read from its file",
                      "tabled (tabulatedAxialAngularSpring): fmuConnector "
                      "tabulatedAxialAngularSpring.fmu" in out,
                      "tabled converted to tabulatedAxialAngularSpring.fmu")
    return failures + compare_runs("sixDoFRigidBodyMotion", builtin, converted,
                                   ["constrained", "free", "tumbling"])


def include_refused():
    case = Case("convertInclude", "", 1.0, 0.1)
    with open(os.path.join(case.dir, "constant", "springs"), "w") as f:
        f.write("spring { type linearSpring; body box; anchor (0 0 1); refAttachmentPt (0 0 0);"
                " stiffness 1; damping 0; restLength 1; }\n")
    with open(os.path.join(case.dir, "constant", "dynamicMeshDict"), "w") as f:
        f.write(foam_file("dynamicMeshDict", "rigidBodyMotionCoeffs\n{\n    bodies {}\n"
                          "    restraints\n    {\n        #include \"springs\"\n    }\n}\n"))
    out = convert(case.dir, expect_failure=True)
    case.cleanup()
    return check("a restraint from an #include is refused, named",
                 "constant/dynamicMeshDict, restraint spring: not written in this file" in out,
                 out.strip().splitlines()[-1] if out.strip() else "no message")


def point_patch():
    """The sixDoF restraints of a sixDoFRigidBodyDisplacement patch in
    0/pointDisplacement (the default files): the body is the patch."""
    case = Case("convertPointPatch", "", 1.0, 0.1)
    os.remove(os.path.join(case.dir, "constant", "dynamicMeshDict"))
    os.makedirs(os.path.join(case.dir, "0"))
    with open(os.path.join(case.dir, "0", "pointDisplacement"), "w") as f:
        f.write(foam_file("pointDisplacement", """dimensions [0 1 0 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    walls { type fixedValue; value uniform (0 0 0); }
    hull
    {
        type            sixDoFRigidBodyDisplacement;
        centreOfMass    (1 2 3);
        mass            10;
        momentOfInertia (1 1 1);
        solver          { type Newmark; }
        restraints
        {
            spring
            {
                sixDoFRigidBodyMotionRestraint linearSpring;
                anchor (1 2 5); refAttachmentPt (1 2 3.5);
                stiffness 10; damping 0; restLength 1;
            }
        }
        value           uniform (0 0 0);
    }
}
"""))
    out = convert(case.dir)
    with open(os.path.join(case.dir, "0", "pointDisplacement")) as f:
        text = f.read()
    case.cleanup()
    return check("0/pointDisplacement: the patch's restraint converted, body the patch",
                 "0/pointDisplacement, restraint spring (linearSpring): fmuConnector "
                 "linearSpring.fmu, body hull" in out and "A.p        (0 0 0.5);" in text
                 and "walls { type fixedValue; value uniform (0 0 0); }" in text,
                 "A.p (0 0 0.5) from the centre of mass (1 2 3), the other patches as written")


def main():
    failures = rigid() + sixdof() + include_refused() + point_patch()
    return summary(15, failures)


if __name__ == "__main__":
    sys.exit(main())
