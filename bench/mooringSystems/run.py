#!/usr/bin/env python3
"""Cost of mooring systems in rigidBodySim: per simulated second, per line
and per body, and how it grows with the number of lines.

Systems (systems.py): the array, 3 bodies x 3 anchored lines plus 2 shared
lines between neighbours (11 lines), and a scaling series of 1, 10 and 100
anchored lines (1 line on 1 body, 10 lines around each of 1 and 10
bodies). Each is run with mooringLine.fmu lines (lumped mass, 20 segments
a 100 m line), with catenary.fmu lines (quasi-static), and without lines
(the same bodies, push and dampers: the cost of the bodies). Every body
starts 1 m off in sway and is pushed off in surge; it comes to rest where
the statics say (checked on every run of the first round: a failure stops
the benchmark).

Timing: every case runs once to its end time and once for one step (the
start: FMUs loaded, the lines' start shapes); the difference over the
simulated time is the cost per simulated second. The cases run one after
the other in each round, the rounds repeat (the machine is shared: wall
times vary by tens of per cent), and the table gives the medians: wall time
per simulated second, and from it per line (the case minus its bodies
alone, over the lines), per line evaluation (over steps and solves) and per
body (bodies alone, over the bodies); the CPU time of the same runs beside
it.

    tests/run-with-openfoam /usr/bin/python3 bench/mooringSystems/run.py
        [-end-time 40] [-delta-t 0.01] [-n-iter 2] [-rounds 3] [-sizes 1,10,100]
"""
import argparse
import resource
import statistics
import sys
import time

from foamfmi.bridgecase import Case, fmu_path

import systems

LAWS = ("mooringLine", "catenary", None)


def timed(case, n_iter):
    """Wall and CPU time (s) of one rigidBodySim run of the case."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    case.run(n_iter=n_iter)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)


class Setup:
    """One system with one law (None: bodies only): its full and one-step
    cases, its statics, its times per round."""

    def __init__(self, system, law, statics, args):
        self.system, self.law, self.args = system, law, args
        self.x_eq, self.k = statics
        text = systems.model(system, fmu_path(law) if law else None,
                             systems.damping(system, self.k), systems.start_offsets(system),
                             lines=law is not None)
        tag = f"mooringSystems.{len(system.centres)}b{system.n_lines}l.{law}"
        self.full = Case(tag, text, args.end_time, args.delta_t)
        self.start = Case(tag + ".start", text, args.delta_t, args.delta_t)
        self.wall, self.cpu, self.wall_start = [], [], []

    def run_round(self, check):
        wall0, cpu0 = timed(self.start, self.args.n_iter)
        wall, cpu = timed(self.full, self.args.n_iter)
        simulated = self.args.end_time - self.args.delta_t
        self.wall.append((wall - wall0) / simulated)
        self.cpu.append((cpu - cpu0) / simulated)
        self.wall_start.append(wall0)
        if check and self.law:
            return systems.check(self.system, self.full, self.x_eq, self.k, self.law)
        return []

    def cleanup(self):
        self.full.cleanup()
        self.start.cleanup()


def table(setups, args):
    """The medians, per simulated second, per line and per body."""
    evaluations = args.n_iter / args.delta_t  # per line and simulated second
    alone = {id(s.system): s for s in setups if s.law is None}
    print(f"\nWall time per simulated second (median of {args.rounds} rounds; CPU time of "
          f"the same runs in brackets), coupling step {args.delta_t} s, "
          f"{args.n_iter} solves a step, {args.end_time} s simulated:\n")
    print("| system | lines | bodies | lines' FMU | whole case [s/s] | per line [ms/s] "
          "| per line evaluation [us] | per body, bodies alone [ms/s] | start per line [ms] |")
    print("| --- | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: |")
    for s in setups:
        if s.law is None:
            continue
        bodies = alone[id(s.system)]
        n, nb = s.system.n_lines, len(s.system.centres)
        wall, cpu = statistics.median(s.wall), statistics.median(s.cpu)
        wall_b, cpu_b = statistics.median(bodies.wall), statistics.median(bodies.cpu)
        line, line_cpu = (wall - wall_b) / n, (cpu - cpu_b) / n
        start = (statistics.median(s.wall_start) - statistics.median(bodies.wall_start)) / n
        print(f"| {s.system.name} | {n} | {nb} | {s.law} | {wall:.3g} ({cpu:.3g}) "
              f"| {1e3 * line:.3g} ({1e3 * line_cpu:.3g}) "
              f"| {1e6 * line / evaluations:.3g} ({1e6 * line_cpu / evaluations:.3g}) "
              f"| {1e3 * wall_b / nb:.3g} ({1e3 * cpu_b / nb:.3g}) | {1e3 * start:.3g} |")
    spread = max((max(s.wall) - min(s.wall)) / statistics.median(s.wall)
                 for s in setups if statistics.median(s.wall) > 0)
    print(f"\nLargest spread of a case's rounds (max - min over median, wall): {100 * spread:.0f} %")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-end-time", type=float, default=40.0)
    parser.add_argument("-delta-t", type=float, default=0.01)
    parser.add_argument("-n-iter", type=int, default=2)
    parser.add_argument("-rounds", type=int, default=3)
    parser.add_argument("-sizes", default="1,10,100")
    args = parser.parse_args()

    chosen = [systems.array()] + [systems.scaling(int(n)) for n in args.sizes.split(",")]
    setups = []
    for system in chosen:
        statics = system.statics()
        print(f"{system.name}: {system.n_lines} lines, {len(system.centres)} bodies; statics: "
              + ", ".join(f"({x:+.4f}, {y:+.4f}) m" for x, y in statics[0]), flush=True)
        setups += [Setup(system, law, statics, args) for law in LAWS]

    failures = []
    for r in range(args.rounds):
        for s in setups:
            failures += s.run_round(check=r == 0)
        print(f"round {r + 1} of {args.rounds} done", flush=True)
        if failures:
            break
    if failures:
        print("\nNOT at rest where the statics say (cases kept):\n  " + "\n  ".join(failures))
        return 1
    print("Every run came to rest where the statics say; shared lines equal and opposite.")
    table(setups, args)
    for s in setups:
        s.cleanup()
    return 0


if __name__ == "__main__":
    sys.exit(main())
