"""Build and run rigid-body cases with no fluid through rigidBodySim.

Each test writes a throw-away OpenFOAM case (system/controlDict and
constant/dynamicMeshDict) into a temporary directory, runs rigidBodySim on
it and reads back the bodies' motion and the connectors' outputs.
"""
import math
import os
import shutil
import subprocess
import tempfile

FOOTER = "\n// " + "*" * 73 + " //\n"


def foam_file(object_name, body):
    return (
        "FoamFile\n{\n    version 2.0;\n    format ascii;\n"
        f"    class dictionary;\n    object {object_name};\n}}\n\n"
        + body + FOOTER
    )


class Case:
    """A temporary case; removed when the test is done unless KEEP_CASES=1."""

    def __init__(self, name, model, end_time, delta_t, write_interval=None):
        self.dir = tempfile.mkdtemp(prefix=f"{name}.")
        os.makedirs(os.path.join(self.dir, "system"))
        os.makedirs(os.path.join(self.dir, "constant"))
        self.set_time(0, end_time, delta_t, write_interval or end_time)
        with open(os.path.join(self.dir, "constant", "dynamicMeshDict"), "w") as f:
            f.write(foam_file("dynamicMeshDict", "rigidBodyMotionCoeffs\n{\n" + model + "\n}\n"))

    def set_time(self, start_time, end_time, delta_t, write_interval):
        control = (
            "application rigidBodySim;\nlibs (\"libfoamFmiBridge.so\");\n"
            f"startFrom startTime;\nstartTime {start_time};\n"
            f"stopAt endTime;\nendTime {end_time};\ndeltaT {delta_t};\n"
            "writeControl adjustable;\n"
            f"writeInterval {write_interval};\n"
            "purgeWrite 0;\nwriteFormat ascii;\nwritePrecision 17;\n"
            "timePrecision 8;\nrunTimeModifiable false;\n"
        )
        with open(os.path.join(self.dir, "system", "controlDict"), "w") as f:
            f.write(foam_file("controlDict", control))

    def run(self, n_iter=1, expect_failure=False):
        """Run rigidBodySim; return its log (stdout and stderr)."""
        return self.run_application(
            ["rigidBodySim", "-case", self.dir, "-nIter", str(n_iter)], expect_failure)

    def run_application(self, command, expect_failure):
        """Run command, an application on this case; return its log (stdout
        and stderr) and keep its exit code in self.returncode. Raises
        AssertionError when it fails, or with expect_failure when it does not."""
        result = subprocess.run(
            command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
        )
        self.returncode = result.returncode
        if expect_failure:
            if result.returncode == 0:
                raise AssertionError(f"{command[0]} succeeded on {self.dir}, expected a failure")
        elif result.returncode != 0:
            raise AssertionError(f"{command[0]} failed on {self.dir}:\n{result.stdout[-3000:]}")
        return result.stdout

    def table(self, *path):
        """Columns of a whitespace table whose last '#' line names them."""
        names, rows = None, []
        with open(os.path.join(self.dir, *path)) as f:
            for line in f:
                if line.startswith("#"):
                    names = line[1:].split()
                elif line.strip():
                    rows.append([float(x) for x in line.split()])
        return {name: [row[i] for row in rows] for i, name in enumerate(names)}

    def bodies(self, start="0"):
        return self.table("postProcessing", "rigidBodySim", start, "bodies.dat")

    def connector(self, name, start="0"):
        return self.table("postProcessing", "fmuConnectors", start, name + ".dat")

    def cleanup(self):
        if os.environ.get("KEEP_CASES") != "1":
            shutil.rmtree(self.dir, ignore_errors=True)


def check(name, ok, detail):
    """Print a PASS or FAIL line for a check; 1 if it failed, else 0."""
    print(f"{'PASS' if ok else 'FAIL'} {name}: {detail}")
    return 0 if ok else 1


def check_order(name, errors, low, high, log=math.log2, what="errors", unit=""):
    """check that the observed orders of convergence, log(e[i] / e[i + 1])
    of the errors of runs each finer than the one before (math.log2: half the
    step; math.log10: a tenth), all lie between low and high."""
    orders = [log(errors[i] / errors[i + 1]) for i in range(len(errors) - 1)]
    return check(
        name,
        all(low < o < high for o in orders),
        f"{what} {', '.join(f'{e:.2e}' for e in errors)}{unit}; orders "
        f"{', '.join(f'{o:.2f}' for o in orders)}",
    )


def summary(checks, failures):
    """Print the closing line, "<passed> passed, <failed> failed"; return the
    exit code, 1 if a check failed."""
    print(f"{checks - failures} passed, {failures} failed")
    return 1 if failures else 0


def fmu_path(name):
    path = os.path.join(os.environ["FOAMFMI_FMU_DIR"], name + ".fmu")
    if not os.path.isfile(path):
        raise SystemExit(f"{path} is missing: build the FMUs first (./Allwmake)")
    return path


def rigid_body(name, mass, inertia, origin, joint, parent="root"):
    """A body whose frame origin is its centre of mass."""
    return (
        f"    {name}\n    {{\n        type rigidBody;\n        parent {parent};\n"
        f"        mass {mass};\n        centreOfMass (0 0 0);\n"
        f"        inertia ({inertia} 0 0 {inertia} 0 {inertia});\n"
        f"        transform (1 0 0 0 1 0 0 0 1) ({origin[0]} {origin[1]} {origin[2]});\n"
        f"        joint {{ type {joint}; }}\n    }}\n"
    )


def vec(v):
    return "(" + " ".join(repr(float(x)) for x in v) + ")"


def value(v):
    """An entry's value as OpenFOAM reads it: text as it stands, a tuple or
    list as a vector (vec), a float by repr (every digit), else str."""
    if isinstance(v, str):
        return v
    if isinstance(v, (tuple, list)):
        return vec(v)
    return repr(float(v)) if isinstance(v, float) else str(v)


def entries(values, indent):
    """Entries 'key value;', one a line, indented by indent spaces; a value
    that is a dict is a sub-dictionary, a None value is left out."""
    pad = " " * indent
    text = ""
    for key, v in values.items():
        if isinstance(v, dict):
            text += f"{pad}{key}\n{pad}{{\n{entries(v, indent + 4)}{pad}}}\n"
        elif v is not None:
            text += f"{pad}{key} {value(v)};\n"
    return text


def restraint(name, values, extra="", indent=8):
    """A restraint of rigidBodyMotionCoeffs' restraints: name { values },
    and extra, entries as text, after them."""
    pad = " " * indent
    return f"{pad}{name}\n{pad}{{\n{entries(values, indent + 4)}" + (
        f"{pad}    {extra}\n" if extra else "") + f"{pad}}}\n"


def fmu_restraint(name, fmu, body, parameters, body_b=None, extra="", indent=8,
                  type_key="type", **options):
    """An fmuConnector restraint: the FMU file fmu, the bodies body and
    body_b (None: the world), the FMU's parameters {name: value} (or their
    entries as text, on one line), further entries as options (report,
    isolation, ...) and as text, extra. indent and type_key: those of
    sixDoFRigidBodyMotion's restraints (sixdofcase.fmu_restraint)."""
    if isinstance(parameters, str):
        extra = f"parameters {{ {parameters} }}" + (f"\n{' ' * indent}    {extra}" if extra else "")
        parameters = None
    return restraint(name, {type_key: "fmuConnector", "body": body, "bodyB": body_b,
                            "fmu": f'"{fmu}"', **options, "parameters": parameters}, extra, indent)


def solver_entry(solver, **options):
    """The solver sub-dictionary: a type and its options."""
    settings = "".join(f" {key} {v};" for key, v in options.items())
    return f"solver {{ type {solver};{settings} }}"


def rigid_body_model(bodies, restraints, solver="symplectic", g=(0, 0, 0), extra=""):
    """rigidBodyMotionCoeffs' entries: the solver (a type, or a whole entry
    of solver_entry), further entries extra (qDot, ...), gravity g (None:
    left out, OpenFOAM's zero), the bodies' text (rigid_body) and the
    restraints' (restraint, fmu_restraint)."""
    if not solver.startswith("solver"):
        solver = solver_entry(solver)
    gravity = "" if g is None else f"    g {value(g)};\n"
    return (f"\n    {solver}\n{extra}{gravity}    bodies\n    {{\n{bodies}\n    }}\n"
            f"    restraints\n    {{\n{restraints}    }}\n")


def linear_spring(name, body, anchor, attachment, stiffness, damping, rest_length):
    """OpenFOAM's linearSpring restraint from the world point anchor to the
    point attachment of body (body frame, from its frame origin)."""
    return restraint(name, {"type": "linearSpring", "body": body, "anchor": anchor,
                            "refAttachmentPt": attachment, "stiffness": stiffness,
                            "damping": damping, "restLength": rest_length})


def spring_fmu(name, body, anchor, attachment, stiffness, damping, rest_length,
               fmu="linearSpring", **options):
    """The same spring as linear_spring through the linearSpring FMU (fmu:
    its name in build/fmus, fmi3/linearSpring for the FMI 3.0 one)."""
    return fmu_restraint(name, fmu_path(fmu), body,
                         {"stiffness": stiffness, "damping": damping, "restLength": rest_length,
                          "A.p": attachment, "B.p": anchor}, **options)
