"""The numbers of the connectors' rows read back as the doubles written.

rowFileCheck (foam-fmi-bridge/applications/test/rowFileCheck) writes
about 200000 doubles (special values, random bit patterns of every
exponent, subnormals included, and numbers of the size of a connector's
outputs) with rowFile::appendNumber, the connectors' number format, and
checks in C++ that strtod and from_chars read each back to the same bits
and that the form is the shortest that does. It writes them through
rowFile, 10 a row, to numbers.dat, and their bits to numbers.bin. Here the
table's readers read numbers.dat: Python's float (foamfmi.postprocessing,
bridgecase.Case.table and the tests), numpy's conversion (the analyses'
arrays) and foamfmi.postprocessing.read_table (rows of 10, a short last
row left out as a cut one). Each value must have the bits of the double
written: a round trip is exact or it is not, so there is no tolerance.
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile

import numpy

from foamfmi.bridgecase import check, summary
from foamfmi.postprocessing import read_table


def bits(values):
    return [struct.pack("<d", v) for v in values]


def main():
    work = tempfile.mkdtemp(prefix="rowNumbers.")
    result = subprocess.run(["rowFileCheck", work], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    print(result.stdout, end="")
    checks = [check("rowFileCheck", result.returncode == 0, f"exit code {result.returncode}")]

    with open(os.path.join(work, "numbers.bin"), "rb") as f:
        data = f.read()
    written = list(struct.unpack(f"<{len(data) // 8}d", data))
    with open(os.path.join(work, "numbers.dat")) as f:
        tokens = [t for line in f if not line.startswith("#") for t in line.split()]

    def compare(name, read):
        wrong = [i for i, (a, b) in enumerate(zip(bits(read), bits(written))) if a != b]
        ok = len(read) == len(written) and not wrong
        first = f", first: {tokens[wrong[0]]} read as {read[wrong[0]]!r}" if wrong else ""
        return check(name, ok, f"{len(read)} values read, {len(written)} written, "
                               f"{len(wrong)} with other bits{first}")

    checks.append(compare("Python's float reads every value back", [float(t) for t in tokens]))
    checks.append(compare("numpy reads every value back",
                          numpy.array(tokens).astype(numpy.float64).tolist()))
    rows = read_table(os.path.join(work, "numbers.dat"))
    whole = [v for row in rows for v in row]
    ok = len(rows) == len(written) // 10 and bits(whole) == bits(written[:len(whole)])
    checks.append(check("foamfmi.postprocessing.read_table reads the rows back", ok,
                        f"{len(rows)} rows of 10, {len(written)} values written"))

    failures = sum(checks)
    if not failures:
        shutil.rmtree(work, ignore_errors=True)
    return summary(len(checks), failures)


if __name__ == "__main__":
    sys.exit(main())
