"""Reading the runs bench/peers keeps: a table of numbers (series.dat,
motion.dat), a run's run.dat (postprocessing.read_key_values), and a
column interpolated in time. For
bench/peers/peersReport and its light-body part (lightReport.py)."""

import os

from foamfmi.postprocessing import read_key_values as read_settings  # noqa: F401


def read_table(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    return rows


def interpolate(rows, column, t):
    """rows' column at time t, linear between rows; None outside them."""
    if not rows or t < rows[0][0] or t > rows[-1][0]:
        return None
    lo, hi = 0, len(rows) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if rows[mid][0] <= t:
            lo = mid
        else:
            hi = mid
    a, b = rows[lo], rows[hi]
    if b[0] == a[0]:
        return a[column]
    w = (t - a[0]) / (b[0] - a[0])
    return a[column] + w * (b[column] - a[column])
