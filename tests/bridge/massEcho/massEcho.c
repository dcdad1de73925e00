/* massEcho: a connector FMU for the bridge's tests of the optional mass
   inputs (docs/connector-fmu-interface.md). It declares the kinematic
   inputs A.r, A.R, B.r, B.R and the mass properties A.m, A.c[1..3],
   A.J[1..3,1..3] and the same for B, returns zero loads, and echoes every
   mass input in an output of the same name prefixed "echo." at
   instantiation, initialization and after each step, so that the
   connector's output file shows what the bridge fed. Value references:
   modelDescription.xml (written by build.py); the FMI plumbing:
   tests/fixtureFmu. */
#include "fixtureModel.h"

#include <string.h>

enum {
    AR = 3, /* A.R[1,1] */
    BR = 15, /* B.R[1,1] */
    massFirst = 24, /* A.m */
    nMass = 26, /* A.m, A.c, A.J, B.m, B.c, B.J */
    Bm = 37, /* B.m */
    loadsFirst = 50, /* A.F, A.M, B.F, B.M */
    echoFirst = 62,
    nReal = 88
};

static void echo(FixtureValues* v)
{
    memcpy(v->real + echoFirst, v->real + massFirst, nMass * sizeof(double));
}

/* Identity orientations, unit masses until set */
static void setStartValues(FixtureValues* v)
{
    fixtureUnrotated(v, AR, BR);
    v->real[massFirst] = 1;
    v->real[Bm] = 1;
    echo(v);
}

static int initialize(FixtureValues* v, char* message, size_t size)
{
    (void)message, (void)size;
    echo(v);
    return 0;
}

static int doStep(FixtureValues* v, double time, double h, char* message,
                  size_t size)
{
    (void)time, (void)h, (void)message, (void)size;
    echo(v);
    return 0;
}

FIXTURE_MODEL(.nReal = nReal, .firstRealOutput = loadsFirst,
              .nRealOutputs = nReal - loadsFirst,
              .setStartValues = setStartValues, .initialize = initialize,
              .doStep = doStep)
