"""Build the example connector examples/customConnector the way its author
would: a copy of its three files in a temporary folder, its own Makefile,
the FMI 2.0 headers and nothing else of the project. Also: fmusim check,
XSD validation and fingerprints of the OpenFOAM side that loads it.
"""
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLE = os.path.join(TOP, "examples", "customConnector")
FMI_INCLUDE = os.path.join(TOP, "fmu", "include")
SOURCES = ("bungee.c", "modelDescription.xml", "Makefile")

sys.path.insert(0, os.path.join(TOP, "tests", "bridge"))


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


def copy_example(name):
    """The example's sources alone in a fresh temporary folder."""
    folder = tempfile.mkdtemp(prefix=f"customConnector.{name}.")
    for f in SOURCES:
        shutil.copy(os.path.join(EXAMPLE, f), folder)
    return folder


def build(folder):
    """make in folder; returns (path of bungee.fmu, compiler output)."""
    result = subprocess.run(
        ["make", "-C", folder, f"FMI_INCLUDE={FMI_INCLUDE}", "bungee.fmu"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
    )
    if result.returncode != 0:
        raise AssertionError(f"make failed in {folder}:\n{result.stdout}")
    return os.path.join(folder, "bungee.fmu"), result.stdout


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
