"""Build the example connector examples/customConnector the way its author
would: a copy of its files in a temporary folder, its own Makefile, the FMI
2.0 (3.0) headers and nothing else of the project. Also: fmusim check,
XSD validation and fingerprints of the OpenFOAM side that loads it.
"""
import hashlib
import os
import shutil
import subprocess
import tempfile

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLE = os.path.join(TOP, "examples", "customConnector")
FMI_INCLUDE = os.path.join(TOP, "fmu", "include")
FMI3_INCLUDE = os.path.join(TOP, "fmu", "third_party", "fmi3")
SOURCES = ("bungee.c", "modelDescription.xml", "Makefile")
# The FMI 3.0 twin (make bungee3.fmu)
SOURCES3 = ("bungee3.c", "fmi3/modelDescription.xml", "fmi3/terminalsAndIcons.xml", "Makefile")


class Checks:
    """Counts the checks and prints each: PASS or FAIL, name, detail."""

    def __init__(self):
        self.passed = self.failed = 0

    def __call__(self, ok, name, detail):
        print(f"{'PASS' if ok else 'FAIL'} {name}: {detail}", flush=True)
        if ok:
            self.passed += 1
        else:
            self.failed += 1


def copy_example(name, sources=SOURCES):
    """The example's sources (SOURCES, SOURCES3 or both) alone in a fresh
    temporary folder."""
    folder = tempfile.mkdtemp(prefix=f"customConnector.{name}.")
    for f in sources:
        os.makedirs(os.path.join(folder, os.path.dirname(f)), exist_ok=True)
        shutil.copy(os.path.join(EXAMPLE, f), os.path.join(folder, f))
    return folder


def build(folder, target="bungee.fmu"):
    """make target (bungee.fmu or bungee3.fmu) in folder; returns (its
    path, compiler output)."""
    result = subprocess.run(
        ["make", "-C", folder, f"FMI_INCLUDE={FMI_INCLUDE}", f"FMI3_INCLUDE={FMI3_INCLUDE}", target],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
    )
    if result.returncode != 0:
        raise AssertionError(f"make failed in {folder}:\n{result.stdout}")
    return os.path.join(folder, target), result.stdout


def fmusim_check(fmu):
    """(exit code, output) of fmusim check."""
    result = subprocess.run(
        ["fmusim", "check", fmu], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
    )
    return result.returncode, result.stdout


def schema_errors(xml):
    """xmllint's complaints about xml against the FMI 2.0 XSD, "" when valid."""
    schema_dir = os.environ.get("FMI2_SCHEMA_DIR", os.path.join(TOP, "..", "shared", "fmi2-schema"))
    schema = os.path.join(schema_dir, "fmi2ModelDescription.xsd")
    if not os.path.isfile(schema):
        raise SystemExit(f"{schema} is missing: the tests expect shared/fmi2-schema beside the repository")
    result = subprocess.run(
        ["xmllint", "--noout", "--schema", schema, xml],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
    )
    return "" if result.returncode == 0 else result.stdout


def fmi3_schema_errors(fmu):
    """The project's own schema check of its FMI 3.0 FMUs
    (tests/fmu/validateSchema.cmake: modelDescription.xml and
    terminalsAndIcons/terminalsAndIcons.xml inside the .fmu against the FMI
    3.0 XSD) on fmu: "" when valid, else its complaints."""
    schema_dir = os.environ.get("FMI3_SCHEMA_DIR", os.path.join(TOP, "..", "shared", "fmi3", "schema"))
    work = tempfile.mkdtemp(prefix="customConnector.schema3.")
    result = subprocess.run(
        ["cmake", f"-DFMU={fmu}", "-DFMI_VERSION=3", f"-DSCHEMA_DIR={schema_dir}",
         f"-DXMLLINT={shutil.which('xmllint') or ''}", f"-DWORK_DIR={work}",
         "-P", os.path.join(TOP, "tests", "fmu", "validateSchema.cmake")],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
    )
    shutil.rmtree(work, ignore_errors=True)
    return "" if result.returncode == 0 else result.stdout


def openfoam_side():
    """sha256 of the OpenFOAM side that runs a connector: the bridge library
    and rigidBodySim as ./Allwmake installed them: path -> digest."""
    digests = {}
    for path in (
        os.path.join(os.environ["FOAM_USER_LIBBIN"], "libfoamFmiBridge.so"),
        os.path.join(os.environ["FOAM_USER_APPBIN"], "rigidBodySim"),
    ):
        with open(path, "rb") as stream:
            digests[path] = hashlib.sha256(stream.read()).hexdigest()
    return digests


def compare_openfoam_side(before):
    """"" when nothing of openfoam_side() changed, else what did."""
    after = openfoam_side()
    return "; ".join(
        f"{os.path.basename(p)}: sha256 {before[p][:12]}... before, {after[p][:12]}... after"
        for p in before if after[p] != before[p]
    )
