"""Regenerates the verification report: runs every study, writes the CSV
files and figures into docs/verification/ and docs/verification.md.

Run in the project's environment (bench/verification/Allrun does):
    tests/run-with-openfoam python3 bench/verification/run.py [--report-only]
--report-only rewrites the page from the results of the last full run
(kept in the temporary directory) without running anything.
"""
import os
import pickle
import sys
import tempfile
import time

from foamfmi import cli

import extremes
import report
import stabmaps
import stability as st
import studies
from vcommon import bisect_limit


def measured_values(r):
    """The quantities of documented.csv, from the results."""
    m = {}
    for connector, schemes in r["oscillators"].items():
        for name, d in schemes.items():
            m[f"order {connector} {name}"] = d["order"]
    for name, p in r["hinge"]["order_k"].items():
        m[f"order hinge 1/k {name}"] = p
    for name, p in r["catenary"]["orders"].items():
        m[f"order catenary moored {name}"] = p
    for name, d in r["spring_map"].items():
        for row, lim in d["limits"].items():
            if lim[1] is not None:
                m[f"limit spring {row} {name}"] = lim[0]
    for name, d in r["damper_map"].items():
        if d["limit"][1] is not None:
            m[f"limit damper {name}"] = d["limit"][0]
    for key, kind in (("hinge_map", "hinge"), ("catenary_map", "catenary")):
        for name, d in r[key].items():
            if d["limit"][1] is not None:
                m[f"limit {kind} {name}"] = d["limit"][0]
    return m


def main(argv):
    p = cli.parser("bench/verification/run.py", __doc__)
    p.add_argument("--report-only", action="store_true",
                   help="rewrite the page from the last full run's results")
    args = p.parse_args(argv)
    start = time.time()
    os.makedirs(studies.OUT, exist_ok=True)
    r = {}
    steps = [("oscillators", studies.oscillators), ("hinge", studies.hinge_study),
             ("catenary", studies.catenary_study), ("spring_map", stabmaps.spring_maps),
             ("damper_map", stabmaps.damper_maps), ("hinge_map", stabmaps.hinge_maps),
             ("catenary_map", stabmaps.catenary_maps), ("extremes", extremes.rows)]
    saved = os.path.join(tempfile.gettempdir(), "foamfmi-verification.pickle")
    if args.report_only:
        with open(saved, "rb") as f:
            r = pickle.load(f)
    else:
        for key, study in steps:
            t0 = time.time()
            r[key] = study()
            print(f"{key}: {time.time() - t0:.0f} s", flush=True)
        sym = st.SOLVERS[0]
        lim = r["spring_map"]["symplectic"]["limits"]["two bodies m2/m1 = 1"]
        r["spring_dt"] = bisect_limit(st.is_stable_spring(sym, 1.0, dt=0.001), lim[0] / 1.5, lim[1] * 1.5)
        r["elapsed"] = time.time() - start
        r["measured"] = time.gmtime(start)
        with open(saved, "wb") as f:
            pickle.dump(r, f)
    stabmaps.draw_spring(r["spring_map"])
    stabmaps.draw_damper(r["damper_map"])
    stabmaps.draw_hinge(r["hinge_map"])
    stabmaps.draw_catenary(r["catenary_map"])
    m = measured_values(r)
    report.write(r, m, r["elapsed"], r["measured"])
    for name, value in sorted(m.items()):
        print(f"{name}: {value:.4g}" if value is not None else f"{name}: -")
    print(f"docs/verification.md written in {(time.time() - start) / 60:.1f} min")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
