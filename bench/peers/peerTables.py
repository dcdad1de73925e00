"""Reading the runs bench/peers keeps: a table of numbers (series.dat,
motion.dat), a run's run.dat, and a column interpolated in time. For
bench/peers/peersReport and its light-body part (lightReport.py)."""

import os


def read_table(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(v) for v in line.split()])
    return rows


def read_settings(path):
    """run.dat's keys and values (numbers where they read as one)."""
    run = {}
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            key, value = line.split(None, 1)
            value = value.strip()
            try:
                run[key] = float(value)
            except ValueError:
                run[key] = value
    return run


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
