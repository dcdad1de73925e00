"""stepFmus.py's comparisons of the outputs of two runs (another system's,
--reference) and of an FMU's FMI 2.0 and 3.0 builds (--same-versions).
"""

RTOL = 1e-9  # --reference: agreement, relative to an output's scale


def compare(results, reference):
    """(summary per FMU, failures) of two runs' outputs. An output agrees
    when every step's value is within RTOL times the largest magnitude it
    takes in the run, or than 1 (SI units) for an output that stays near
    zero: glibc's libm differs between versions in the last bit of some
    functions (hypot, asinh, tanh, atan2 between 2.31 and 2.36), which the
    dynamic line's integrator carries on."""
    summary, failures = [], []
    for identifier in sorted(set(results) | set(reference)):
        ours, theirs = results.get(identifier), reference.get(identifier)
        if ours is None or theirs is None or set(ours) != set(theirs):
            failures.append(f"{identifier}: not the same outputs in the two runs")
            continue
        worst, identical = 0.0, 0
        for name in sorted(ours):
            a, b = ours[name], theirs[name]
            if len(a) != len(b):
                failures.append(f"{identifier}.{name}: {len(a)} steps against {len(b)}")
                continue
            identical += a == b
            scale = max(max(map(abs, a + b)), 1.0)
            for k, (x, y) in enumerate(zip(a, b)):
                difference = abs(x - y) / scale
                worst = max(worst, difference)
                if difference > RTOL:
                    failures.append(f"{identifier}.{name}: step {k + 1}: {x!r} against {y!r}")
                    break
        summary.append(f"{identifier}: {identical} of {len(ours)} outputs bit-identical, "
                       f"the largest difference {worst:.2g} of an output's scale")
    return summary, failures


def compare_versions(results):
    """(summary, failures) of the 2.0 and 3.0 FMUs of each modelIdentifier
    of results: the same outputs, bitwise. 2.0's X.x[i], X.y[i], X.z[i]
    (a line's shape) are the 3.0 arrays X.x, X.y, X.z; FMUs built before
    those had the n x 3 array X, whose row i they are."""
    summary, failures = [], []
    for identifier in sorted(set(results) & {k[len("fmi3/"):] for k in results
                                             if k.startswith("fmi3/")}):
        two, three = results[identifier], results["fmi3/" + identifier]
        names = {}
        for name in two:
            base, _, index = name.partition("[")
            column = "xyz".find(base[-1:]) + 1 if base[-2:-1] == "." else 0
            if name not in three and column and index:
                names[name] = f"{base[:-2]}[{index[:-1]},{column}]"
            else:
                names[name] = name
        if sorted(names.values()) != sorted(three):
            failures.append(f"{identifier}: the 3.0 FMU's outputs are not the 2.0 FMU's: "
                            f"{', '.join(sorted(set(three) ^ set(names.values()))[:6])}")
            continue
        differ = [name for name in two if two[name] != three[names[name]]]
        if differ:
            failures.append(f"{identifier}: {len(differ)} outputs of the 3.0 FMU differ from "
                            f"the 2.0 FMU's, {differ[0]} first")
        summary.append(f"{identifier}: {len(two) - len(differ)} of {len(two)} outputs of "
                       "the 3.0 FMU bit-identical to the 2.0 FMU's")
    return summary, failures
