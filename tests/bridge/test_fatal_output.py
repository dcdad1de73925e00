"""A run ended by a FatalError keeps every completed row of connector
outputs; a connector that asks to end the simulation ends it with its
reason.

The restraint collects its rows in memory and writes them at write times;
a FatalError ends the process with exit(), which destroys no restraint, so
an exit handler must write them. The test FMU faultySpring (testSpring with
fault parameters, tests/fmusim/fixtures) returns a NaN force from
t = nanTime on; the bridge stops with a FatalError naming the output. No
time is written before that (writeInterval beyond the end), so every row
must come from the exit handler: one per completed step before nanTime.

With endTime instead, faultySpring refuses the step from that time with
fmi2Discard and fmi2Terminated (FMI 2.0's way for a co-simulation FMU to
end the simulation): the run stops with a FatalError that says so and
gives the FMU's reason.
"""
import os
import sys

from bridgecase import Case, rigid_body, vec

DT, NAN_TIME, END = 0.01, 0.3, 1.0


def model(fmu, fault="nanTime"):
    return f"""
    solver {{ type symplectic; }}
    g (0 0 -9.81);
    bodies
    {{
{rigid_body("weight", 1.0, 0.1, (0, 0, 0), "Pz")}
    }}
    restraints
    {{
        spring
        {{
            type fmuConnector;
            body weight;
            fmu "{fmu}";
            parameters
            {{
                stiffness 100;
                restLength 0.5;
                {fault} {NAN_TIME};
                A.p {vec((0, 0, 0))};
                B.p {vec((0, 0, 0.5))};
            }}
        }}
    }}
"""


def main():
    fmu = os.path.join(os.environ["FOAMFMI_BUILD_DIR"], "tests", "fixture-fmus", "faultySpring.fmu")
    if not os.path.isfile(fmu):
        raise SystemExit(f"{fmu} is missing: build the test fixtures first (./Allwmake)")

    case = Case("fatalOutput", model(fmu), END, DT, write_interval=10 * END)
    log = case.run(expect_failure=True)
    failures = 0

    stopped = "output A.F[1] is not finite" in log
    print(f"{'PASS' if stopped else 'FAIL'} the NaN force stops the run: "
          f"{'FatalError names A.F[1]' if stopped else log[-1500:]}")
    failures += 0 if stopped else 1

    rows = case.connector("spring")["Time"]
    # The step that reaches nanTime fails; every step before it completed.
    # Times are sums of 0.01: compare with half a step of slack.
    expected = [DT * (i + 1) for i in range(int(round(NAN_TIME / DT)) - 1)]
    ok = len(rows) == len(expected) and all(abs(a - b) < DT / 2 for a, b in zip(rows, expected))
    print(f"{'PASS' if ok else 'FAIL'} rows kept: {len(rows)} rows, last t = "
          f"{rows[-1] if rows else None}, expected {len(expected)} up to t = {expected[-1]:g}")
    failures += 0 if ok else 1

    case.cleanup()

    case = Case("endRequest", model(fmu, "endTime"), END, DT, write_interval=10 * END)
    log = case.run(expect_failure=True)
    expected = ("restraint spring: the connector asks to end the simulation at t = 0.3",
                "the spring asks to end the simulation at endTime = 0.3 s")
    ended = all(e in log for e in expected)
    rows = case.connector("spring")["Time"]
    ok = ended and len(rows) == 29
    print(f"{'PASS' if ok else 'FAIL'} the connector ends the simulation at its endTime: "
          f"message {'found' if ended else 'missing'}, {len(rows)} rows"
          + ("" if ended else "\n" + log[-1500:]))
    failures += 0 if ok else 1
    case.cleanup()

    print(f"{3 - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
