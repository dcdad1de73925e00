"""The scripts' command lines: OpenFOAM-style single-dash options
(-no-plot, -window T0 T1) parsed by argparse, -help, -h and --help
printing the script's docstring, and errors that name the script."""

import argparse
import contextlib
import shutil
import sys
import tempfile


def parser(prog, doc):
    """An ArgumentParser for the script prog whose help is its docstring
    doc (kept as written) followed by the options."""
    p = argparse.ArgumentParser(prog=prog, description=doc, add_help=False,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("-h", "-help", "--help", action="help", help="print this help and exit")
    return p


def add_case(p):
    """The optional positional CASE, default the current folder."""
    p.add_argument("case", nargs="?", default=".", metavar="CASE",
                   help="the case folder (default: .)")


def add_no_plot(p):
    p.add_argument("-no-plot", dest="plot", action="store_false",
                   help="no plots (gnuplot)")


def add_window(p):
    p.add_argument("-window", nargs=2, type=float, metavar=("T0", "T1"),
                   help="the analysis window in s (default: see above)")


def add_keep(p):
    p.add_argument("-keep", action="store_true", help="keep the runs' folder")


@contextlib.contextmanager
def scratch(prefix, keep):
    """A temporary folder for a script's runs, removed when it is done
    (also by an exit), or with keep (-keep) kept and its path printed."""
    work = tempfile.mkdtemp(prefix=prefix)
    try:
        yield work
    finally:
        if keep:
            print(f"runs kept in {work}")
        else:
            shutil.rmtree(work, ignore_errors=True)


def run(prog, doc, analyse, argv, window=False):
    """The command line 'prog [-no-plot] [-window T0 T1] [CASE]' of a
    case's analysis: analyse(case, plot) or, with window,
    analyse(case, plot, (T0, T1) or None); what it raises (a missing file
    or entry, too few samples, gnuplot failing) ends the program with
    'prog: message'."""
    p = parser(prog, doc)
    add_no_plot(p)
    if window:
        add_window(p)
    add_case(p)
    args = p.parse_args(argv)
    try:
        if window:
            analyse(args.case, args.plot, args.window)
        else:
            analyse(args.case, args.plot)
    except (OSError, ValueError, RuntimeError) as err:
        fail(prog, str(err))


def fail(prog, message):
    """Exit with status 1 and 'prog: message' on standard error."""
    sys.exit("%s: %s" % (prog, message))
