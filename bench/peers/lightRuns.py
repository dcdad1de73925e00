"""What bench/peers/lightBodyCompare (FloatStepper's disc) and
bench/peers/lightBoxCompare (the floatingObject box) share: running a
case's commands (the solver under the CFD lock), editing its files, the
rows kept, FloatStepper's commit, and the start on OpenFOAM v2312 with
FloatStepper's solver and libraries found after the project's."""

import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
PEERS = os.environ.get("FOAMFMI_PEERS_DIR", "/root/.cache/foamfmi/peers")
LOCK = "/tmp/foamfmi-cfd.lock"
MAX_ROWS = 300                # series.dat's rows at most


def fail(message):
    sys.exit("%s: %s" % (os.path.basename(sys.argv[0]), message))


def in_case(case):
    """The environment with PWD the case's folder (else OpenFOAM warns)."""
    return dict(os.environ, PWD=case)


def run(command, case, log, lock=False):
    with open(os.path.join(case, log), "w") as out:
        done = subprocess.run((["flock", LOCK] if lock else []) + command, cwd=case,
                              env=in_case(case), stdout=out, stderr=subprocess.STDOUT)
    return done.returncode


def must_run(command, case, log):
    if run(command, case, log) != 0:
        fail("%s failed in %s (see %s)" % (command[0], case, os.path.join(case, log)))


def edit(path, pattern, replacement, count=1):
    """Replace pattern (a multiline regular expression) in the file,
    which must match count times."""
    with open(path) as f:
        text = f.read()
    text, n = re.subn(pattern, replacement, text, flags=re.M)
    if n != count:
        fail("%s: %d matches of %r, expected %d" % (path, n, pattern, count))
    with open(path, "w") as f:
        f.write(text)


def thin(rows):
    """At most MAX_ROWS of rows, evenly in step number, the last kept."""
    if len(rows) <= MAX_ROWS:
        return rows
    every = math.ceil(len(rows) / MAX_ROWS)
    kept = rows[::every]
    if kept[-1] is not rows[-1]:
        kept.append(rows[-1])
    return kept


def peers_stamp():
    """The commit FloatStepper was built from (buildPeers' record)."""
    path = os.path.join(PEERS, "stamps", "floatStepper")
    if os.path.isfile(path):
        with open(path) as f:
            return "floatStepper@%s" % f.read().split()[0][:7]
    return "unknown"


def on_v2312(script, argv):
    """Restarts script with argv under tests/openfoamVersions/withV2312
    unless this is OpenFOAM v2312 already; then puts FloatStepper's
    solver, utilities and libraries after the project's and returns the
    project's commit (also in FOAMFMI_COMMIT)."""
    if os.environ.get("WM_PROJECT_VERSION") != "v2312":
        os.execv(os.path.join(TOP, "tests", "openfoamVersions", "withV2312"),
                 ["withV2312", os.path.abspath(script)] + argv)
    os.environ["PATH"] = os.environ["PATH"] + ":" + os.path.join(PEERS, "v2312", "bin")
    os.environ["LD_LIBRARY_PATH"] = (os.environ.get("LD_LIBRARY_PATH", "") + ":"
                                     + os.path.join(PEERS, "v2312", "lib"))
    commit = subprocess.run(["git", "-C", TOP, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    os.environ["FOAMFMI_COMMIT"] = commit
    return commit
