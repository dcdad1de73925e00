"""Figures through gnuplot (pngcairo): log-log curves and stability maps.
Data go inline as gnuplot datablocks; each figure is one gnuplot run."""
import math
import subprocess

HEAD = 'set terminal pngcairo size {w},{h} font "sans,10"\nset output "{png}"\n'
OUTCOME_STYLE = {"stable": ("7", "#1a9641"), "unstable": ("9", "#fdae61"),
                 "failed": ("2", "#d7191c"), "nan": ("3", "#000000")}


def gnuplot(script):
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def datablock(name, lines):
    """A gnuplot datablock $name of the given lines."""
    return f"${name} << EOD\n" + "".join(lines) + "EOD\n"


def plot(script, curves):
    """Run script, then one plot command of the curves."""
    gnuplot(script + "plot " + ", \\\n     ".join(curves) + "\n")


def loglog(png, title, xlabel, ylabel, series, w=800, h=560):
    """series: [(label, [(x, y), ...])]; non-finite points are left out."""
    s = HEAD.format(w=w, h=h, png=png)
    s += (f'set title "{title}"\nset xlabel "{xlabel}"\nset ylabel "{ylabel}"\n'
          "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\n"
          "set grid\nset key outside right top\n")
    plots = []
    for i, (label, points) in enumerate(series):
        pts = [(x, y) for x, y in points if x > 0 and y > 0 and math.isfinite(x) and math.isfinite(y)]
        if not pts:
            continue
        s += datablock(f"d{i}", (f"{x!r} {y!r}\n" for x, y in pts))
        plots.append(f'$d{i} using 1:2 with linespoints lw 2 pt {5 + i % 8} title "{label}"')
    plot(s, plots)


def stability_map(png, title, xlabel, rows, points, w=1000, h=None):
    """rows: y labels from bottom to top; points: [(x, row, outcome)]."""
    h = h or 160 + 24 * len(rows)
    s = HEAD.format(w=w, h=h, png=png)
    xs = [x for x, _, _ in points]
    margin = max(len(r) for r in rows) * 0.9 + 2
    s += (f'set title "{title}"\nset xlabel "{xlabel}"\nset logscale x\n'
          "set format x '10^{%L}'\nset grid x\nset key outside right top\n"
          f"set xrange [{min(xs) / 2!r}:{max(xs) * 2!r}]\n"
          f"set yrange [-0.7:{len(rows) - 0.3}]\nset lmargin {margin:.0f}\n")
    s += "set ytics (" + ", ".join(f'"{r}" {i}' for i, r in enumerate(rows)) + ")\n"
    plots = []
    for outcome, (pt, colour) in OUTCOME_STYLE.items():
        pts = [(x, rows.index(r)) for x, r, o in points if o == outcome]
        if not pts:
            continue
        s += datablock(outcome, (f"{x!r} {y}\n" for x, y in pts))
        plots.append(f'${outcome} using 1:2 with points pt {pt} ps 1.3 lc rgb "{colour}" title "{outcome}"')
    plot(s, plots)
