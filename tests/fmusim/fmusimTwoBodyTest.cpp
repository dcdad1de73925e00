// `fmusim twobody`: two bodies joined by a spring connector oscillate at the
// analytic frequency and keep their linear momentum; prescribed motion,
// rotation and gravity against closed forms; configuration errors.
#include "fmusimTest.hpp"

#include <algorithm>
#include <cmath>

namespace {

using namespace harness;

// `fmusim twobody` of testSpring with the configuration file config, holding
// text
Result twobodyWithConfig(const std::string& config, const std::string& text)
{
    writeFile(config, text);
    return fmusim("twobody " + fixture("testSpring") + " --config " + config);
}

// Angular frequency from the upward zero crossings of s(t), each located by
// linear interpolation between samples.
double measuredFrequency(const std::vector<double>& t,
                         const std::vector<double>& s)
{
    std::vector<double> crossings;
    for (std::size_t i = 1; i < s.size(); ++i)
        if (s[i - 1] < 0 && s[i] >= 0)
            crossings.push_back(
                t[i - 1] + (t[i] - t[i - 1]) * s[i - 1] / (s[i - 1] - s[i]));
    if (crossings.size() < 2)
        return 0;
    return 2 * M_PI * (crossings.size() - 1)
        / (crossings.back() - crossings.front());
}

struct Oscillation {
    double frequencyError; // relative
    double
        momentumDrift; // largest |total momentum| over the largest |momentum of A|
    double energyDrift; // largest relative change of kinetic + potential energy
};

// A (1 kg) at the origin and B (3 kg) at x = 1.1 m, joined by a spring of
// 100 N/m and rest length 1 m: the stretch oscillates at
// sqrt(k (1/mA + 1/mB)) = 11.547 rad/s.
Oscillation oscillate(const std::string& fmu, const std::string& scheme,
                      const std::string& parameters)
{
    const std::string config = scratch(scheme + ".cfg"),
                      out = scratch(scheme + ".csv");
    harness::writeFile(
        config,
        "# two bodies, one spring\nstop-time = 5\nstep-size = 0.001\nscheme = "
            + scheme
            + "\nA.mass = 1\nA.inertia = 1 1 1\nB.mass = 3\nB.inertia = 2 2 2\n"
              "B.position = 1.1, 0, 0\n");
    const harness::Result r
        = fmusim("twobody " + fmu + " --config " + config + " " + parameters
                 + " --output-file " + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const harness::Table table = harness::readTable(out);
    const std::vector<double> t
        = table.values("time"),
        xA = table.values("A.x"), xB = table.values("B.x"),
        vA = table.values("A.vx"), vB = table.values("B.vx"),
        kA = table.values("A.kineticEnergy"),
        kB = table.values("B.kineticEnergy"),
        pe = table.values("potentialEnergy");
    std::vector<double> stretch;
    double pMax = 0, pA = 0, eMax = 0;
    const double e0 = kA[0] + kB[0] + pe[0];
    for (std::size_t i = 0; i < t.size(); ++i) {
        stretch.push_back(xB[i] - xA[i] - 1.0);
        pMax = std::max(pMax, std::fabs(1 * vA[i] + 3 * vB[i]));
        pA = std::max(pA, std::fabs(vA[i]));
        eMax = std::max(eMax, std::fabs(kA[i] + kB[i] + pe[i] - e0) / e0);
    }
    const double omega = std::sqrt(100 * (1 + 1.0 / 3));
    return {std::fabs(measuredFrequency(t, stretch) - omega) / omega, pMax / pA,
            eMax};
}

const char* const springParameters = "--set stiffness=100 --set restLength=1";

// The test spring's oscillation by `scheme`: its frequency error and energy
// drift below the bounds given, its momentum kept
void expectSpringOscillation(const char* scheme, double frequencyError,
                             double energyDrift)
{
    const Oscillation o
        = oscillate(fixture("testSpring"), scheme, springParameters);
    EXPECT_LT(o.frequencyError, frequencyError);
    // Equal and opposite forces change the momenta by exactly opposite
    // amounts; only the rounding of v + h F/m remains (~1e-16 per step).
    EXPECT_LT(o.momentumDrift, 1e-12);
    EXPECT_LT(o.energyDrift, energyDrift);
}

TEST(FmusimTwoBody, ExplicitSpringOscillatesAtTheAnalyticFrequency)
{
    // Symplectic Euler: frequency error (omega h)^2/24 = 5.6e-6 at h = 1 ms.
    // A symplectic scheme keeps the energy error bounded, of order
    // omega h / 2 = 5.8e-3 here.
    expectSpringOscillation("explicit", 2e-5, 1e-2);
}

TEST(FmusimTwoBody, ImplicitSpringOscillatesAtTheAnalyticFrequency)
{
    // Trapezoidal rule: frequency error (omega h)^2/12 = 1.1e-5 at h = 1 ms.
    // The trapezoidal rule conserves the energy of a linear oscillator; what
    // is left comes from the coupling tolerance (1e-10 of the loads) and
    // round-off (measured: 6e-14).
    expectSpringOscillation("implicit", 3e-5, 1e-10);
}

// The CSV of `fmusim twobody testSpring <options>`, which must succeed
void twobodyTable(const std::string& options, harness::Table& t)
{
    const CsvRun run = fmusimCsv("twobody", "testSpring", options);
    ASSERT_EQ(run.result.exitCode, 0) << run.result.err;
    t = harness::readTable(run.csv);
}

// Each value of the column `name` of t within `tolerance` of f(time)
template <class F>
void expectColumn(const harness::Table& t, const std::string& name, F&& f,
                  double tolerance)
{
    const std::vector<double> time = t.values("time"), v = t.values(name);
    for (std::size_t i = 0; i < time.size(); ++i)
        EXPECT_NEAR(v[i], f(time[i]), tolerance) << name << " t = " << time[i];
}

TEST(FmusimTwoBody, BodyFixedToTheWorld)
{
    // B fixed: A alone oscillates at sqrt(k/mA) = 10 rad/s.
    harness::Table t;
    ASSERT_NO_FATAL_FAILURE(twobodyTable(
        std::string(springParameters)
            + " --B.motion fixed --B.position 1,0,0 --A.position=-0.2,0,0"
              " --stop-time 4",
        t));
    // The rest position of A is x = 0; symplectic Euler: (omega h)^2/24 = 4e-6.
    EXPECT_NEAR(measuredFrequency(t.values("time"), t.values("A.x")), 10.0,
                10.0 * 2e-5);
    for (const double x : t.values("B.x"))
        EXPECT_EQ(x, 1.0);
}

TEST(FmusimTwoBody, SinusoidalMotionFollowsItsFormula)
{
    harness::Table t;
    ASSERT_NO_FATAL_FAILURE(twobodyTable(
        "--B.motion sinusoidal --B.position 1,0,0 --B.amplitude 0,0.1,0"
        " --B.frequency 0.5 --B.phase 0.3 --stop-time 1 --step-size 0.01",
        t));
    // The formula itself, evaluated the same way: round-off only.
    expectColumn(
        t, "B.y", [](double s) { return 0.1 * std::sin(M_PI * s + 0.3); },
        1e-15);
    expectColumn(
        t, "B.vy",
        [](double s) { return 0.1 * M_PI * std::cos(M_PI * s + 0.3); }, 1e-15);
}

TEST(FmusimTwoBody, SpinAboutAPrincipalAxis)
{
    // No load (stiffness 0), spin of 2 rad/s about the body z axis, a
    // principal axis: q(t) = (cos t, 0, 0, sin t). The gyroscopic term
    // vanishes, so each step applies the same exact rotation.
    for (const char* scheme : {"explicit", "implicit"}) {
        const std::string out = scratch(std::string(scheme) + ".csv");
        const harness::Result r = fmusim(
            "twobody " + fixture("testSpring")
            + " --set stiffness=0 --B.position 1,0,0 --A.inertia 1,2,3 --A.angular-velocity 0,0,2"
              " --stop-time 3 --step-size 0.01 --scheme "
            + scheme + " --output-file " + out);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const harness::Table t = harness::readTable(out);
        const std::vector<double> time = t.values("time"),
                                  qw = t.values("A.qw"), qz = t.values("A.qz"),
                                  energy = t.values("A.kineticEnergy");
        for (std::size_t i = 0; i < time.size(); ++i) {
            EXPECT_NEAR(qw[i], std::cos(time[i]), 1e-12)
                << scheme << " t = " << time[i]; // 300 rounded products
            EXPECT_NEAR(qz[i], std::sin(time[i]), 1e-12)
                << scheme << " t = " << time[i];
            EXPECT_NEAR(energy[i], 0.5 * 3 * 4, 1e-12) << scheme;
        }
    }
}

TEST(FmusimTwoBody, FreeFallUnderGravity)
{
    // stiffness 0: both bodies fall freely. The trapezoidal rule is exact for
    // constant acceleration: z = -g t^2/2, vz = -g t.
    harness::Table t;
    ASSERT_NO_FATAL_FAILURE(
        twobodyTable("--set stiffness=0 --B.position 1,0,0 --gravity "
                     "0,0,-9.81 --scheme implicit --stop-time 2 --step-size "
                     "0.01",
                     t));
    expectColumn(
        t, "B.z", [](double s) { return -0.5 * 9.81 * s * s; }, 1e-12);
    expectColumn(
        t, "A.vz", [](double s) { return -9.81 * s; }, 1e-12);
}

TEST(FmusimTwoBodyErrors, BadConfigurations)
{
    const std::string config = scratch("bad.cfg");
    const harness::Result unknown
        = twobodyWithConfig(config, "stop-time = 1\nA.mas = 2\n");
    EXPECT_TRUE(failed(unknown, 4, config + ":2: unknown key 'A.mas'"));

    const harness::Result inertia
        = twobodyWithConfig(config, "A.inertia = 1 2\n");
    EXPECT_TRUE(failed(inertia, 4,
                       config + ":1: A.inertia: expected 3 (Jxx Jyy Jzz), 6"));

    const harness::Result mass
        = fmusim("twobody " + fixture("testSpring") + " --A.mass -1");
    EXPECT_TRUE(failed(mass, 2, "--A.mass: A.mass: the mass must be positive"));

    const harness::Result scheme
        = fmusim("twobody " + fixture("testSpring") + " --scheme rk4");
    EXPECT_EQ(scheme.exitCode, 2);

    const harness::Result notConnector
        = fmusim("twobody " + fixture("firstOrderLag"));
    EXPECT_TRUE(
        failed(notConnector, 3,
               "is not a connector: it does not declare A.r, A.R, A.F, A.M"));
}

TEST(FmusimTwoBodyErrors, FailingConnectorIsASimulationError)
{
    // Both bodies at the same point with restLength 1: the spring direction
    // is undefined and the FMU returns fmi2Error.
    const harness::Result r
        = fmusim("twobody " + fixture("testSpring") + " --B.position 0,0,0");
    EXPECT_TRUE(failed(r, 5, "the spring direction is undefined"));
}

#ifdef CONNECTOR_FMU_DIR
TEST(FmusimTwoBodyConnectors, LinearSpringOscillatesAtTheAnalyticFrequency)
{
    for (const char* scheme : {"explicit", "implicit"}) {
        // B.p at B's reference point, as the test spring's
        const Oscillation o
            = oscillate(CONNECTOR_FMU_DIR "/linearSpring.fmu", scheme,
                        std::string(springParameters) + " --set B.p[1]=0");
        EXPECT_LT(o.frequencyError, 3e-5) << scheme; // as for testSpring above
        EXPECT_LT(o.momentumDrift, 1e-12) << scheme;
    }
}
#endif

} // namespace
