"""fmusim check and the fmuConnector restraint judge a connector FMU's
interface variables by one vocabulary (fmuImport::connector) and agree.

Each variant is linearSpring.fmu with its modelDescription.xml edited in one
way (the binary is unchanged, so the FMU still runs):

- R-without-unit: A.R and B.R declare no unit. A rotation matrix has no
  other unit than 1, so both accept it (before the shared vocabulary,
  fmusim check accepted it and the bridge refused it);
- length-in-mm: the diagnostic length is declared in mm: both refuse it,
  with the same words;
- force-discrete: A.F[1] has variability discrete: both refuse it, with the
  same words.

For each, fmusim check's interface checks (required-variables,
optional-variables, units) pass exactly when rigidBodySim runs the FMU in an
fmuConnector restraint, and every problem fmusim check names is in the
bridge's fatal error.

    python3 test_vocabulary.py        # FMUSIM: the fmusim to use (default: on PATH)
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile

from foamfmi.bridgecase import Case, fmu_path
from test_errors import GOOD, model

INTERFACE_CHECKS = ("required-variables", "optional-variables", "units")


def variable(xml, name, edit):
    """xml with the ScalarVariable of that name passed through edit."""
    pattern = re.compile(r'<ScalarVariable name="' + re.escape(name) + r'".*?</ScalarVariable>', re.S)
    found = pattern.findall(xml)
    if len(found) != 1:
        raise AssertionError(f"linearSpring's modelDescription.xml has {len(found)} variables {name}")
    return pattern.sub(lambda m: edit(m.group(0)), xml)


def without_rotation_unit(xml):
    for body in "AB":
        for i in (1, 2, 3):
            for j in (1, 2, 3):
                xml = variable(xml, f"{body}.R[{i},{j}]", lambda v: v.replace(' unit="1"', ""))
    return xml


def length_in_mm(xml):
    xml = xml.replace("<UnitDefinitions>", '<UnitDefinitions>\n    <Unit name="mm"><BaseUnit m="1" factor="0.001"/></Unit>', 1)
    return variable(xml, "length", lambda v: v.replace('unit="m"', 'unit="mm"'))


def force_discrete(xml):
    return variable(xml, "A.F[1]", lambda v: v.replace('variability="continuous"', 'variability="discrete"'))


# name: (edit, whether both accept it)
VARIANTS = {
    "R-without-unit": (without_rotation_unit, True),
    "length-in-mm": (length_in_mm, False),
    "force-discrete": (force_discrete, False),
}


def variant_fmu(folder, name, edit):
    """linearSpring.fmu with its modelDescription.xml edited, in folder."""
    path = os.path.join(folder, name + ".fmu")
    with zipfile.ZipFile(fmu_path("linearSpring")) as src, zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as dst:
        for item in src.infolist():
            data = src.read(item.filename)
            if item.filename == "modelDescription.xml":
                edited = edit(data.decode())
                if edited == data.decode():
                    raise AssertionError(f"{name}: the edit changed nothing")
                data = edited.encode()
            dst.writestr(item, data)
    return path


def fmusim_interface(fmu):
    """{check name: (passed, reason)} of fmusim check's interface checks."""
    result = subprocess.run([os.environ.get("FMUSIM", "fmusim"), "check", fmu],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    verdicts = {}
    for line in result.stdout.splitlines():
        m = re.match(r"(PASS|FAIL|SKIP) ([\w-]+)(?:: (.*))?$", line)
        if m and m.group(2) in INTERFACE_CHECKS:
            verdicts[m.group(2)] = (m.group(1) == "PASS", m.group(3) or "")
    if set(verdicts) != set(INTERFACE_CHECKS):
        raise AssertionError(f"fmusim check gave no verdict on every interface check:\n{result.stdout}")
    return verdicts


def main():
    folder = tempfile.mkdtemp(prefix="vocabulary.")
    failures = 0
    for name, (edit, accepted) in VARIANTS.items():
        print(f"-- {name}", flush=True)
        fmu = variant_fmu(folder, name, edit)
        verdicts = fmusim_interface(fmu)
        checkAccepts = all(passed for passed, _ in verdicts.values())
        problems = [p for passed, reason in verdicts.values() if not passed
                    for p in reason.split("; ") if not p.startswith("and ")]

        case = Case("vocabulary", model(fmu, GOOD), 0.02, 0.01)
        try:
            log, bridgeAccepts = case.run(), True
        except AssertionError as failure:
            log, bridgeAccepts = str(failure), False
        missing = [p for p in problems if p not in log]

        if checkAccepts != accepted or bridgeAccepts != accepted or missing:
            failures += 1
            print(f"FAIL {name}: expected {'acceptance' if accepted else 'refusal'}; fmusim check "
                  f"{'accepts' if checkAccepts else 'refuses'} ({verdicts}), the bridge "
                  f"{'accepts' if bridgeAccepts else 'refuses'}; its log lacks {missing}\n"
                  f"{log[-2000:]}")
        else:
            print(f"PASS {name}: both {'accept' if accepted else 'refuse'}" + (f": {problems}" if problems else ""))
        case.cleanup()
    shutil.rmtree(folder, ignore_errors=True)
    print(f"{len(VARIANTS) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
