"""Broken variants of the example connector are refused, with a message
that tells the author what to fix.

Each variant is made from a fresh copy of examples/customConnector with one
mistake a connector author makes, built with the example's own Makefile,
and must still validate against the FMI 2.0 XSD (the FMI 3.0 XSD for the
FMI 3.0 twin bungee3.fmu: the mistake is in the contract, not in the XML
syntax):

- missing-output: the moments are declared as A.T[1..3], not
  A.M[1..3];
- wrong-unit: A.F is declared in kN (with a kN unit definition), not N;
- guid-mismatch: modelDescription.xml carries a new guid, the binary the
  old one (the XML was edited without rebuilding the binary);
- fmi3-dimensions: bungee3's A.r is declared an array of 4 elements;
- fmi3-token-mismatch: bungee3's fmi3/modelDescription.xml carries a new
  instantiationToken, the binary the old one.

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
from foamfmi.bridgecase import Case, rigid_body, vec

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


def position_of_four(xml):
    return edit(xml, 'unit="m" start="0 0 0" description="position of A\'s reference point">\n      <Dimension start="3"/>',
                'unit="m" start="0 0 0 0" description="position of A\'s reference point">\n      <Dimension start="4"/>', 1)


def new_token(xml):
    return edit(xml, "{d41c7a55-2f0e-4b8a-9c36-7e19a4b2f5d8}", "{7c0b3e91-58d4-4a6f-b2e7-0d9a1f6c3b85}", 1)


# FMI version: (the example's files, its modelDescription.xml, make target)
EXAMPLES = {
    2: (customfmu.SOURCES, "modelDescription.xml", "bungee.fmu"),
    3: (customfmu.SOURCES3, "fmi3/modelDescription.xml", "bungee3.fmu"),
}

# name: (FMI version, how the XML is broken, key words of fmusim check's
# FAIL line (check name first), key words of rigidBodySim's fatal error)
VARIANTS = {
    "missing-output": (
        2,
        moment_renamed,
        ["FAIL required-variables", "missing A.M[1]"],
        ["mooring", "requires the output A.M", "does not declare it"],
    ),
    "wrong-unit": (
        2,
        force_in_kN,
        ["FAIL units", "A.F[1] has unit 'kN'", "expected 'N'"],
        ["mooring", "A.F", "unit", "kN"],
    ),
    "guid-mismatch": (
        2,
        new_guid,
        ["FAIL initialization", "GUID mismatch", "rebuild the binary and the XML together"],
        ["mooring", "fmi2Instantiate", "GUID mismatch", "rebuild the binary and the XML together"],
    ),
    "fmi3-dimensions": (
        3,
        position_of_four,
        ["FAIL required-variables", "A.r is an array of dimensions [4], expected an array of dimensions [3]"],
        ["mooring", "A.r is an array of dimensions [4], expected an array of dimensions [3]"],
    ),
    "fmi3-token-mismatch": (
        3,
        new_token,
        ["FAIL initialization", "instantiationToken mismatch", "rebuild the binary and the XML together"],
        ["mooring", "fmi3InstantiateCoSimulation", "instantiationToken mismatch",
         "rebuild the binary and the XML together"],
    ),
}


def main(names):
    unknown = [n for n in names if n not in VARIANTS]
    if unknown:
        raise SystemExit(f"unknown variants {unknown}; they are {list(VARIANTS)}")
    failures = checks = 0
    before = customfmu.openfoam_side()
    for name in names or VARIANTS:
        version, breaking, check_words, bridge_words = VARIANTS[name]
        sources, xml_name, target = EXAMPLES[version]
        print(f"-- {name}", flush=True)
        folder = customfmu.copy_example(name, sources)
        xml_path = os.path.join(folder, xml_name)
        with open(xml_path) as f:
            xml = breaking(f.read())
        with open(xml_path, "w") as f:
            f.write(xml)
        fmu, _ = customfmu.build(folder, target)

        problems = customfmu.schema_errors(xml_path) if version == 2 else customfmu.fmi3_schema_errors(fmu)
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
