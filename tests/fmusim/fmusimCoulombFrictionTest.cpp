// coulombFriction.fmu driving a body in `fmusim twobody`: a block launched
// along a guide of the world decelerates under the friction and stops at
// the analytic distance and time (Coulomb's, and the regularised law's
// exact ones); `fmusim check` passes it.
#include "fmusimTest.hpp"

#include <cmath>
#include <string>

namespace {

using namespace harness;

#ifdef CONNECTOR_FMU_DIR

TEST(FmusimCoulombFriction, CheckPasses)
{
    const harness::Result r
        = fmusim("check " CONNECTOR_FMU_DIR "/coulombFriction.fmu");
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, " passed, 0 failed\n")) << r.out;
    EXPECT_TRUE(contains(r.out, "PASS zero-total-moment\n")) << r.out;
    EXPECT_TRUE(contains(r.out, "PASS rest-load\n")) << r.out;
}

// The block of the flume rig: m = 5 kg launched at v0 = 0.2 m/s along x,
// the guide of the world, against F_c = 0.4 N. Coulomb: it stops after
// t_s = m v0/F_c = 2.5 s and d = m v0^2/(2 F_c) = 0.25 m.
const double m = 5.0, v0 = 0.2, Fc = 0.4;

struct Stop {
    double distance; // x at the end of the run [m]
    double timeAtVs; // first time the velocity is down to v_s [s]
};

Stop slide(double vs, const std::string& scheme)
{
    const std::string out = scratch("block.csv");
    const harness::Result r = fmusim(
        "twobody " CONNECTOR_FMU_DIR "/coulombFriction.fmu"
        " --set frictionForce=0.4 --set regularisationVelocity="
        + std::to_string(vs)
        + " --set 'B.axis[1]=1' --B.motion world --A.mass 5"
          " --A.velocity 0.2,0,0 --scheme "
        + scheme + " --step-size 0.001 --stop-time 4 --output-file " + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const harness::Table t = harness::readTable(out);
    const std::vector<double> time = t.values("time"), x = t.values("A.x"),
                              v = t.values("A.vx");
    Stop s {x.back(), NAN};
    for (std::size_t i = 1; i < v.size(); ++i) {
        if (v[i] <= vs) { // linear interpolation between the samples
            s.timeAtVs = time[i - 1]
                + (time[i] - time[i - 1]) * (v[i - 1] - vs) / (v[i - 1] - v[i]);
            break;
        }
    }
    return s;
}

TEST(FmusimCoulombFriction, LaunchedBlockStopsAtTheAnalyticDistanceAndTime)
{
    const double ts = m * v0 / Fc, d = m * v0 * v0 / (2 * Fc);
    for (const double vs : {1e-3, 1e-2}) {
        const Stop s = slide(vs, "implicit");
        // The regularised law's exact answers, m dv/dt = -F_c v/sqrt(v^2 +
        // v_s^2): distance to rest (m/(2F_c)) [v0 sqrt(v0^2 + v_s^2) + v_s^2
        // asinh(v0/v_s)], time to slow down to v, (m/F_c) (S(v0) - S(v)),
        // S(u) = sqrt(u^2 + v_s^2) - v_s ln((v_s + sqrt(u^2 + v_s^2))/u).
        const double tau = m * vs / Fc; // time constant of the creep
        const double exactDistance = m / (2 * Fc)
            * (v0 * std::hypot(v0, vs) + vs * vs * std::asinh(v0 / vs));
        const auto S = [vs](double u) {
            const double r = std::hypot(u, vs);
            return r - vs * std::log((vs + r) / u);
        };
        const double exactTime = m / Fc * (S(v0) - S(vs));
        // The trapezoidal rule is exact for the constant deceleration; the
        // error is made where the force turns (v ~ v_s), of order
        // h^2 F_c/m = 8e-8 m, and the creep left at 4 s, v_s tau
        // exp(-(4 - t_s)/tau) <= 4e-8 m (v_s = 1e-2): 1e-6 of d (measured
        // 8.9e-9 m at v_s = 1e-3, 3.3e-9 m at 1e-2).
        EXPECT_NEAR(s.distance, exactDistance, 1e-6 * d) << "v_s = " << vs;
        // Time: the trapezoidal rule's error where the force turns, of
        // order (h/tau)^2 h = 6e-6 s at v_s = 1e-3 (measured 5.0e-6 s;
        // 4.8e-7 s at v_s = 1e-2): 2e-5 s.
        EXPECT_NEAR(s.timeAtVs, exactTime, 2e-5) << "v_s = " << vs;
        // Against Coulomb: the distance exceeds d by the relative
        // (v_s/v0)^2 (1/2 + ln(2 v0/v_s)) (+ O((v_s/v0)^4)): 1.6e-4 at
        // v_s = 1e-3, 1.05e-2 at v_s = 1e-2; 1 % of it as tolerance
        // (measured 1.6232e-4 and 1.0473e-2).
        const double excess
            = (vs / v0) * (vs / v0) * (0.5 + std::log(2 * v0 / vs));
        EXPECT_NEAR((s.distance - d) / d, excess, 0.01 * excess)
            << "v_s = " << vs;
        // The velocity reaches v_s within the creep time tau of t_s
        // (exactly 0.53 tau before it, to first order in v_s/v0).
        EXPECT_NEAR(s.timeAtVs, ts, tau) << "v_s = " << vs;
        EXPECT_LT(s.timeAtVs, ts) << "v_s = " << vs;
    }
}

TEST(FmusimCoulombFriction, ExplicitCouplingStopsTheBlockToo)
{
    // Symplectic Euler with the load of the step's start, h = 1 ms against
    // tau = m v_s/F_c = 12.5 ms: stable (h < 2 tau). It lags the velocity
    // by a step: the distance is off by about h v0/2 = 1e-4 m, 4e-4 of d
    // (measured -1.0e-4 m; the time at v_s -1.7e-4 s).
    const Stop s = slide(1e-3, "explicit");
    const double d = m * v0 * v0 / (2 * Fc);
    EXPECT_NEAR(s.distance, d, 1e-3 * d);
    EXPECT_NEAR(s.timeAtVs, m * v0 / Fc, m * 1e-3 / Fc);
}

#endif

} // namespace
