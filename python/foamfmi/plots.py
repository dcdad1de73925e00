"""Figures (PNG) through gnuplot, as the analyses draw them: the terminal
(pngcairo, or png where gnuplot has no cairo), the shaded analysis window,
running a script, and the response figure of a moored body in waves."""

import os
import subprocess


class PlotError(RuntimeError):
    """gnuplot missing, or failing on a script."""


def has_pngcairo():
    """Whether gnuplot has its pngcairo terminal."""
    try:
        return subprocess.run(["gnuplot", "-e", "set terminal pngcairo"],
                              stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL).returncode == 0
    except OSError:
        return False


def terminal(size):
    """gnuplot's terminal for a PNG of size 'W,H' pixels."""
    if has_pngcairo():
        return "pngcairo size %s font 'DejaVu Sans,10'" % size
    return "png size %s" % size


def shade(t0, t1, colour="#e8e8e8"):
    """The analysis window t0-t1 as a grey band behind the curves."""
    return ("set object 1 rect from %g, graph 0 to %g, graph 1 behind "
            "fc rgb '%s' fs solid 1.0 noborder" % (t0, t1, colour))


def gnuplot(script, lines):
    """Write the lines to the file script and run gnuplot on it."""
    with open(script, "w") as f:
        f.write("\n".join(lines) + "\n")
    try:
        result = subprocess.run(["gnuplot", script])
    except OSError as e:
        raise PlotError("cannot run gnuplot (Debian package gnuplot-nox): %s" % e.strerror)
    if result.returncode:
        raise PlotError("gnuplot failed on " + script)


def body_response(plot_dir, name, title, gauge_x, height, window, motion, x0, z0,
                  tension_label, tensions):
    """plot_dir/name.png (script name.gp): five panels over time, the
    window shaded: the elevation at two gauges (plot_dir/elevation.dat,
    columns 2 and 3, at gauge_x) with +-height/2, sway, heave and roll of
    the body (motion: rigidBodyMotionFromLog's table, x and z less x0 and
    z0), and the tensions {label: (file, column index from 0)}."""
    curves = ", ".join("'%s' u 1:%d w l lw 1.2 t '%s'" % (f, c + 1, n)
                       for n, (f, c) in tensions.items())
    gnuplot(os.path.join(plot_dir, name + ".gp"), [
        "set terminal " + terminal("1000,1200"),
        "set output '%s/%s.png'" % (plot_dir, name),
        "set multiplot layout 5,1 title '%s'" % title,
        "set grid", "set key bottom left opaque", shade(*window),
        "set ylabel 'elevation (m)'",
        "plot '%s/elevation.dat' u 1:2 w l lw 1.2 t 'gauge x = %.3g m', "
        "'%s/elevation.dat' u 1:3 w l lw 1.2 t 'gauge x = %.3g m', "
        "%g w l dt 2 lc rgb 'black' t '+-H/2', %g w l dt 2 lc rgb 'black' notitle"
        % (plot_dir, gauge_x[0], plot_dir, gauge_x[1], 0.5 * height, -0.5 * height),
        "set ylabel 'sway x (m)'",
        "plot '%s' u 1:($2-%.9g) w l lw 1.5 notitle" % (motion, x0),
        "set ylabel 'heave z (m)'",
        "plot '%s' u 1:($4-%.9g) w l lw 1.5 notitle" % (motion, z0),
        "set ylabel 'roll, about y (deg)'",
        "plot '%s' u 1:7 w l lw 1.5 notitle" % motion,
        "set ylabel '%s'" % tension_label, "set xlabel 't (s)'",
        "plot " + curves,
        "unset multiplot"])
