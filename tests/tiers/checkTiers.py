#!/usr/bin/env python3
"""Checks that every CTest test of the build carries exactly one tier label
(quick, cfd, long), and that the cfd and long tests run alone (RUN_SERIAL:
./Alltest runs CTest on every core), as tests/CMakeLists.txt describes.

Usage: checkTiers.py CTEST BUILD_DIR
"""
import json
import subprocess
import sys

TIERS = ("quick", "cfd", "long")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    ctest, build = sys.argv[1:]
    listing = subprocess.run([ctest, "--test-dir", build, "--show-only=json-v1"],
                             check=True, capture_output=True, text=True).stdout
    tests = json.loads(listing)["tests"]
    counts = dict.fromkeys(TIERS, 0)
    problems = []
    for test in tests:
        properties = {p["name"]: p["value"] for p in test.get("properties", [])}
        labels = properties.get("LABELS", [])
        tiers = [t for t in labels if t in TIERS]
        if len(tiers) != 1:
            problems.append(f"{test['name']}: tiers {tiers or 'none'} (labels {labels})")
            continue
        counts[tiers[0]] += 1
        alone = bool(properties.get("RUN_SERIAL", False))
        if alone != (tiers[0] != "quick"):
            problems.append(f"{test['name']}: a {tiers[0]} test with RUN_SERIAL"
                            f" {alone}: cfd and long tests run alone, quick ones do not")
    if len(tests) < 100:
        problems.append(f"only {len(tests)} tests listed by {ctest} in {build}")
    for problem in problems:
        print("FAIL [tiers]:", problem, file=sys.stderr)
    if problems:
        sys.exit(1)
    print("ok   [tiers]:", len(tests), "tests,",
          ", ".join(f"{counts[t]} {t}" for t in TIERS))


if __name__ == "__main__":
    main()
