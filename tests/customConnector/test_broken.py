"""Broken variants of the example connector are refused, with a message
that tells the author what to fix.

Each variant is made from a fresh copy of examples/customConnector with one
mistake a connector author makes, built with the example's own Makefile,
and must still validate against the FMI 2.0 XSD (the mistake is in the
contract, not in the XML syntax):

- missing-output: the moments are declared as A.T[1..3], not
  A.M[1..3];
- wrong-unit: A.F is declared in kN (with a kN unit definition), not N;
- guid-mismatch: modelDescription.xml carries a new guid, the binary the
  old one (the XML was edited without rebuilding the binary).

fmusim check must fail on each with the key words of its message, and
rigidBodySim, loading it through the fmuConnector restraint, must stop with
a fatal error carrying the key words, the restraint's name, and leave no
time directory behind.

    python3 test_broken.py [variant ...]     # default: every variant
"""
import os
import re
import sys

import customfmu
from bridgecase import Case, rigid_body, vec

MODEL = """
    solver {{ type symplectic; }}
    g (0 0 -9.81);
    bodies
    {{
{body}
    }}
    restraints
    {{
        mooring
        {{
            type fmuConnector;
            body buoy;
            fmu "{fmu}";
            parameters
            {{
                stiffness 50;
                restLength 1;
                A.p {origin};
                B.p {origin};
            }}
        }}
    }}
"""


def edit(xml, old, new, count):
    """Replaces old by new in xml exactly count times."""
    found = xml.count(old)
    if found != count:
        raise AssertionError(f"the example's modelDescription.xml has {found} '{old}', expected {count}")
    return xml.replace(old, new)


def moment_renamed(xml):
    return edit(xml, 'name="A.M[', 'name="A.T[', 3)


def force_in_kN(xml):
    xml = edit(xml, '<Unit name="N">', '<Unit name="kN"><BaseUnit kg="1" m="1" s="-2" factor="1000"/></Unit>\n'
               '    <Unit name="N">', 1)
    return re.sub(r'(name="A\.F\[\d\]".*?<Real unit=")N(")', r"\1kN\2", xml, flags=re.S)


def new_guid(xml):
    return edit(xml, "{6b1f0c7e-3d2a-4c59-9e41-b5a8d0f27c13}", "{0f5e2a9c-7b41-4d2e-8c3a-1e6d9b7f4a20}", 1)


# name: (how the XML is broken, key words of fmusim check's FAIL line
# (check name first), key words of rigidBodySim's fatal error)
VARIANTS = {
    "missing-output": (
        moment_renamed,
        ["FAIL required-variables", "missing A.M[1]"],
        ["mooring", "requires the output A.M", "does not declare it"],
    ),
    "wrong-unit": (
        force_in_kN,
        ["FAIL units", "A.F[1] has unit 'kN'", "expected 'N'"],
        ["mooring", "A.F", "unit", "kN"],
    ),
    "guid-mismatch": (
        new_guid,
        ["FAIL initialization", "GUID mismatch", "rebuild the binary and the XML together"],
        ["mooring", "fmi2Instantiate", "GUID mismatch", "rebuild the binary and the XML together"],
    ),
}


def main(names):
    unknown = [n for n in names if n not in VARIANTS]
    if unknown:
        raise SystemExit(f"unknown variants {unknown}; they are {list(VARIANTS)}")
    failures = checks = 0
    before = customfmu.openfoam_side()
    for name in names or VARIANTS:
        breaking, check_words, bridge_words = VARIANTS[name]
        print(f"-- {name}", flush=True)
        folder = customfmu.copy_example(name)
        xml_path = os.path.join(folder, "modelDescription.xml")
        with open(xml_path) as f:
            xml = breaking(f.read())
        with open(xml_path, "w") as f:
            f.write(xml)
        fmu, _ = customfmu.build(folder)

        problems = customfmu.schema_errors(xml_path)
        checks += 1
        if problems:
            failures += 1
            print(f"FAIL {name}: the variant does not validate against the XSD:\n{problems}")

        code, report = customfmu.fmusim_check(fmu)
        lines = [line for line in report.splitlines() if line.startswith(check_words[0])]
        missing = [w for w in check_words[1:] if not any(w in line for line in lines)]
        checks += 1
        if code == 0 or not lines or missing:
            failures += 1
            print(f"FAIL {name}: fmusim check exit {code}, {check_words[0]} lines {lines}, "
                  f"lacking {missing}\n{report}")
        else:
            print(f"PASS {name}: fmusim check exit {code}: {lines[0][:200]}")

        case = Case("customConnector.broken",
                    MODEL.format(body=rigid_body("buoy", 2, 0.1, (0, 0, -1.2), "floating"),
                                 fmu=fmu, origin=vec((0, 0, 0))),
                    0.01, 0.001)
        try:
            log = case.run(expect_failure=True)
            missing = [w for w in bridge_words if w not in log]
            written = [d for d in os.listdir(case.dir) if d not in ("system", "constant", "postProcessing")]
            error = [line.strip() for line in log.splitlines() if bridge_words[-1] in line]
            checks += 1
            if missing or written:
                failures += 1
                print(f"FAIL {name}: rigidBodySim's message lacks {missing}, left {written}\n{log[-1500:]}")
            else:
                print(f"PASS {name}: rigidBodySim: {error[0][:300] if error else ''}")
        except AssertionError as refused_not:
            checks += 1
            failures += 1
            print(f"FAIL {name}: {str(refused_not).splitlines()[0]}")
        case.cleanup()
        if os.environ.get("KEEP_CASES") != "1":
            customfmu.shutil.rmtree(folder, ignore_errors=True)

    rebuilt = customfmu.compare_openfoam_side(before)
    checks += 1
    if rebuilt:
        failures += 1
        print(f"FAIL OpenFOAM side rebuilt: {rebuilt}")
    else:
        print("PASS OpenFOAM side untouched (sha256 of libfoamFmiBridge.so and rigidBodySim)")
    print(f"{checks - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
