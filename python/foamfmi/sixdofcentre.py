"""The centre of rotation and the orientation that OpenFOAM's own
sixDoFRigidBodyMotion gives a motion dictionary at its start, read from
sixDoFSim (the project's no-fluid driver, which constructs the motion as
the solver does and writes its state at the start time).

    frame = openfoam_frame(motion)   # (centre, rows of the orientation) or None

motion is a dictionary parsed by foamfmi.foamdict from OpenFOAM's expanded
output (foamDictionary -expand): it is written back as it was read, without
its restraints, into a temporary case of one body, run to time 0.
"""

import os
import shutil
import subprocess
import tempfile

HEADER = "FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n"
CONTROL = ("application sixDoFSim;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\n"
           "endTime 0;\ndeltaT 1;\nwriteControl timeStep;\nwriteInterval 1;\n"
           "writeFormat ascii;\nwritePrecision 17;\n")


class FrameError(RuntimeError):
    """sixDoFSim did not construct the motion; the message has its log."""


def dictionary_text(entries, indent=""):
    """OpenFOAM text of a parsed dictionary (foamdict: values as tokens)."""
    lines = []
    for key, value in entries.items():
        if isinstance(value, dict):
            lines += [indent + key, indent + "{", dictionary_text(value, indent + "    "),
                      indent + "}"]
        else:
            lines.append("%s%s %s;" % (indent, key, " ".join(value)))
    return "\n".join(line for line in lines if line)


def openfoam_frame(motion):
    """(centre of rotation, orientation rows) of the motion at its start as
    sixDoFSim constructs it, or None where there is no sixDoFSim; raises
    FrameError when it fails."""
    if shutil.which("sixDoFSim") is None:
        return None
    body = {k: v for k, v in motion.items() if k not in ("restraints", "report")}
    case = tempfile.mkdtemp(prefix="foamFmiConvert.")
    try:
        for folder in ("system", "constant"):
            os.makedirs(os.path.join(case, folder))
        with open(os.path.join(case, "system", "controlDict"), "w") as f:
            f.write(HEADER % "controlDict" + CONTROL)
        with open(os.path.join(case, "constant", "sixDoFBodies"), "w") as f:
            f.write(HEADER % "sixDoFBodies" + "bodies\n{\n    body\n    {\n"
                    + dictionary_text(body, " " * 8) + "\n    }\n}\n")
        done = subprocess.run(["sixDoFSim", "-case", case], cwd=case,
                              env={**os.environ, "PWD": case},
                              capture_output=True, text=True)
        table = os.path.join(case, "postProcessing", "sixDoFSim", "0", "bodies.dat")
        if done.returncode != 0 or not os.path.isfile(table):
            log = (done.stdout + done.stderr).strip()
            start = log.find("FOAM FATAL")
            raise FrameError("sixDoFSim cannot construct the motion:\n"
                             + (log[start:] if start >= 0 else log[-2000:]))
        with open(table) as f:
            rows = [line.split() for line in f if line.strip()]
        names = rows[0][1:]
        values = dict(zip(names, (float(x) for x in rows[1])))
    finally:
        shutil.rmtree(case, ignore_errors=True)
    centre = [values["body.r." + c] for c in "xyz"]
    orientation = [[values["body.R.%s%s" % (i, j)] for j in "xyz"] for i in "xyz"]
    return centre, orientation
