"""Build massEcho.fmu (massEcho.c) into a directory: the C compiler, the
FMI headers of fmu/include, the fixture FMUs' FMI plumbing (tests/fixtureFmu)
and modelDescription.xml written here."""
import contextlib
import os
import shutil
import subprocess
import tempfile
import zipfile

from foamfmi.bridgecase import check

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
PLUMBING = os.path.join(TOP, "tests", "fixtureFmu")
GUID = "{6d1f0e6a-7c1b-4c55-9d1e-massecho0001}"


def variables():
    """(name, causality, unit) in value-reference order (massEcho.c)."""
    out = []
    vector = lambda n: [f"{n}[{i}]" for i in (1, 2, 3)]
    matrix = lambda n: [f"{n}[{i},{j}]" for i in (1, 2, 3) for j in (1, 2, 3)]
    for body in "AB":
        out += [(n, "input", "m") for n in vector(body + ".r")]
        out += [(n, "input", "1") for n in matrix(body + ".R")]
    mass = []
    for body in "AB":
        mass += [(body + ".m", "kg")] + [(n, "m") for n in vector(body + ".c")]
        mass += [(n, "kg.m2") for n in matrix(body + ".J")]
    out += [(n, "input", u) for n, u in mass]
    for body in "AB":
        out += [(n, "output", "N") for n in vector(body + ".F")]
        out += [(n, "output", "N.m") for n in vector(body + ".M")]
    out += [("echo." + n, "output", u) for n, u in mass]
    assert len(out) == 88
    return out


def model_description():
    rows = []
    for vr, (name, causality, unit) in enumerate(variables()):
        if causality == "input":
            start = "1" if name in ("A.m", "B.m") or (".R[" in name and name[-4] == name[-2]) else "0"
            attrs = f'causality="input" variability="continuous"><Real unit="{unit}" start="{start}"/>'
        else:
            attrs = f'causality="output" variability="continuous" initial="calculated"><Real unit="{unit}"/>'
        rows.append(f'    <ScalarVariable name="{name}" valueReference="{vr}" {attrs}</ScalarVariable>')
    units = "".join(f'    <Unit name="{u}"/>\n' for u in ("1", "kg", "kg.m2", "m", "N", "N.m"))
    outputs = "".join(f'      <Unknown index="{i + 1}"/>\n' for i in range(50, 88))
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="massEcho" guid="{GUID}"
  variableNamingConvention="structured" numberOfEventIndicators="0">
  <CoSimulation modelIdentifier="massEcho" canHandleVariableCommunicationStepSize="true"
    canGetAndSetFMUstate="true" canSerializeFMUstate="true"/>
  <UnitDefinitions>
{units}  </UnitDefinitions>
  <ModelVariables>
{chr(10).join(rows)}
  </ModelVariables>
  <ModelStructure>
    <Outputs>
{outputs}    </Outputs>
  </ModelStructure>
</fmiModelDescription>
"""


def build(directory):
    """Build massEcho.fmu in directory; return its path."""
    so = os.path.join(directory, "massEcho.so")
    subprocess.run(["cc", "-shared", "-fPIC", "-O1", "-fvisibility=hidden", "-DFIXTURE_CS_ONLY", f"-DFIXTURE_GUID=\"{GUID}\"",
                    "-I", os.path.join(TOP, "fmu", "include"), "-I", PLUMBING, os.path.join(HERE, "massEcho.c"),
                    os.path.join(PLUMBING, "fixtureFmu.c"), os.path.join(PLUMBING, "fixtureUnsupported.c"),
                    "-o", so], check=True)
    fmu = os.path.join(directory, "massEcho.fmu")
    with zipfile.ZipFile(fmu, "w") as z:
        z.writestr("modelDescription.xml", model_description())
        z.write(so, "binaries/linux64/massEcho.so")
    return fmu


@contextlib.contextmanager
def built():
    """massEcho.fmu built in a temporary folder, removed afterwards."""
    directory = tempfile.mkdtemp(prefix="massEcho.")
    try:
        yield build(directory)
    finally:
        shutil.rmtree(directory, ignore_errors=True)


def check_echo(name, row, values, tolerance):
    """Print PASS or FAIL for the echoed mass properties of a connector's
    last row, {column: value}, against values {input name: value}; 1 if
    one is off by more than tolerance, else 0."""
    worst = max(abs(row["echo." + k] - v) for k, v in values.items())
    return check(name, worst <= tolerance, f"largest difference {worst:.3e}")
