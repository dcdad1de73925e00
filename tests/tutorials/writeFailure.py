"""No row lost without a word in a CFD run: interFoamAliasSafe on
tutorials/mooredFloatingObjectDynamic (a cube moored by four dynamic lines,
mooringLine.fmu; fmuConnectorFlow gives the lines the flow), coarse mesh
(mesh factor 0.25), no time written.

- A file-size limit (SIGXFSZ ignored, so that a write fails with EFBIG as
  on a full disk), set on the running solver once every connector has
  written 5 rows (the FMU, a larger file, is unpacked by then), 3000 bytes
  above its largest file: in both isolations (none, process). The largest
  files are the connectors' rows (about 1 kB a row); one of them reaches
  the limit within three steps. The run must stop with a FatalError that
  names that file, the row's time and the cause (and the exit handler,
  which then writes the other connectors' completed rows, names each of
  their files that fails too), and every connector file and flow sample
  file must hold whole rows only, each named one within one row of the
  limit.
Before the rows were checked, such a run ended with exit code 0 and cut
rows.
"""
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

from foamfmi import postprocessing
from foamfmi.postprocessing import PostProcessingError, whole_rows
from foamfmi.bridgecase import check, summary

CONNECTORS = ["line1", "line2", "line3", "line4"]
MARGIN = 3000  # bytes above the largest file: about three connector rows


def set_up(work):
    """The tutorial with its mesh and fields, run for 2 ms (a set-up only)."""
    case = os.path.join(work, "setUp")
    shutil.copytree(os.path.join(os.environ["FOAMFMI_DIR"], "tutorials",
                                 "mooredFloatingObjectDynamic"), case)
    result = subprocess.run([os.path.join(case, "Allrun"), "-mesh-factor", "0.25",
                             "-end-time", "0.002"], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    if result.returncode != 0:
        raise SystemExit(f"Allrun failed:\n{result.stdout[-2000:]}")
    return case


def copy_case(set_up_case, work, name, isolation):
    """A copy with the given isolation, 0.3 s long, no time written."""
    case = os.path.join(work, name)
    shutil.copytree(set_up_case, case)
    shutil.rmtree(os.path.join(case, "postProcessing"))
    for path, old, new in [
            ("constant/dynamicMeshDict", "report      off;",
             f"report      off;\n        isolation   {isolation};"),
            ("system/runSettings", "endTime         0.002;", "endTime         0.3;"),
            ("system/controlDict", "writeInterval   0.1;", "writeInterval   10;")]:
        with open(os.path.join(case, path)) as f:
            text = f.read()
        if old not in text:
            raise SystemExit(f"{path} of the tutorial has no '{old}'")
        with open(os.path.join(case, path), "w") as f:
            f.write(text.replace(old, new))
    return case


def files_of(case):
    """{label: path} of the connectors' and the flow samples' tables."""
    files = {}
    for c in CONNECTORS:
        files[f"connector {c}"] = os.path.join(case, "postProcessing", "fmuConnectors", "0",
                                               c + ".dat")
        files[f"flow {c}"] = os.path.join(case, "postProcessing", "lineFlow", "0", c + ".dat")
    return files


def data_rows(path):
    try:
        with open(path) as f:
            return sum(1 for line in f if line.strip() and not line.startswith("#"))
    except OSError:
        return 0


def ignore_sigxfsz():
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)


def run_limited(case):
    """Run the solver; set the limit once every connector has 5 rows.
    Returns (exit code, log, limit). The log is read through a pipe: a log
    file would reach the limit too."""
    process = subprocess.Popen([postprocessing.case_solver(case), "-case", case], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True, preexec_fn=ignore_sigxfsz)
    log = []
    reader = threading.Thread(target=lambda: log.extend(process.stdout))
    reader.start()
    files = files_of(case)
    limit = None
    deadline = time.time() + 300
    while process.poll() is None and time.time() < deadline:
        if limit is None and all(data_rows(files[f"connector {c}"]) >= 5 for c in CONNECTORS):
            limit = max(os.path.getsize(p) for p in files.values()) + MARGIN
            resource.prlimit(process.pid, resource.RLIMIT_FSIZE, (limit, limit))
        time.sleep(0.02)
    if process.poll() is None:
        process.kill()
    code = process.wait()
    reader.join()
    return code, "".join(log), limit


def limit_checks(set_up_case, work, isolation):
    name = f"isolation {isolation}, file-size limit"
    case = copy_case(set_up_case, work, f"limit.{isolation}", isolation)
    code, log, limit = run_limited(case)
    files = files_of(case)
    message = [line for line in log.splitlines() if "cannot write" in line]
    named = [label for label, path in files.items() if any(path in line for line in message)]
    checks = [
        check(f"{name}: the limit was set while the solver ran", limit is not None,
              f"limit {limit} bytes"),
        check(f"{name}: stops with an error", code != 0, f"exit code {code}"),
        # The FatalError names the first file; the exit handler then writes
        # the other connectors' completed rows, whose files (as large) fail
        # too, each named on the standard error
        check(f"{name}: the FatalError names the file, the row's time and the cause; so does "
              "each further failure", len(named) >= 1 and "FOAM FATAL ERROR" in log
              and all("the row of t = " in line and "File too large" in line for line in message),
              " / ".join(message[:2]) or log[-1500:]),
    ]
    for label, path in files.items():
        try:
            rows, longest = whole_rows(path)
            ok, detail = True, f"{rows} whole rows, {os.path.getsize(path)} bytes"
            if label in named and limit is not None:
                ok = limit - longest < os.path.getsize(path) <= limit
                detail += f", within one row ({longest} bytes) of the limit {limit}"
        except (PostProcessingError, OSError) as error:
            ok, detail = False, str(error)
        checks.append(check(f"{name}: {label} has whole rows only", ok, detail))
    return checks


def main():
    work = tempfile.mkdtemp(prefix="writeFailure.")
    set_up_case = set_up(work)
    checks = limit_checks(set_up_case, work, "none") + limit_checks(set_up_case, work, "process")
    failures = sum(checks)
    if not failures and os.environ.get("KEEP_CASES") != "1":
        shutil.rmtree(work, ignore_errors=True)
    else:
        print(f"cases kept in {work}")
    return summary(len(checks), failures)


if __name__ == "__main__":
    sys.exit(main())
