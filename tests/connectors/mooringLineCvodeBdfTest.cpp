// The SUNDIALS adapter: accuracy on a problem with a known solution,
// counters across restarts, and failures that name the function and flag.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "mooringLine/CvodeBdf.hpp"

namespace {

using connectors::CvodeBdf;

//- Damped oscillator x'' + 2 zeta w x' + w^2 x = 0, stiffly coupled to a
//  fast decaying component y' = -1e6 (y - x)
int oscillator(double, const double* s, double* ds)
{
    const double w = 2.0, zeta = 0.1;
    ds[0] = s[1];
    ds[1] = -2.0 * zeta * w * s[1] - w * w * s[0];
    ds[2] = -1e6 * (s[2] - s[0]);
    return 0;
}

double exact(double t)
{
    const double w = 2.0, zeta = 0.1, wd = w * std::sqrt(1 - zeta * zeta);
    return std::exp(-zeta * w * t)
        * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
}

TEST(CvodeBdf, AccurateOnAStiffProblemWithRestartsEveryStep)
{
    // dense, then banded: half-bandwidth 2 covers ds[2]/ds[0]
    for (const long band : {-1L, 2L}) {
        CvodeBdf::Options o;
        o.relativeTolerance = 1e-9;
        o.absoluteTolerance = 1e-12;
        o.halfBandwidth = band;
        CvodeBdf cvode(3, oscillator, o);
        double s[3] = {1.0, 0.0, 1.0};
        double t = 0.0;
        for (int k = 0; k < 50; ++k) {
            cvode.restart(t, s);
            t += 0.1;
            cvode.advance(t, s);
        }
        // BDF at rtol 1e-9 over 5 s: global error ~ 1e-8; the stiff
        // component follows x to 1e-6 of its rate
        EXPECT_NEAR(s[0], exact(5.0), 1e-7) << band;
        EXPECT_NEAR(s[2], s[0], 1e-5);
        const CvodeBdf::Statistics st = cvode.statistics();
        EXPECT_GT(st.steps, 50); // counted across the 50 restarts
        EXPECT_GT(st.rhsEvaluations, st.steps);
    }
}

TEST(CvodeBdf, FailuresNameTheFunction)
{
    CvodeBdf::Options o;
    CvodeBdf cvode(
        1, [](double, const double*, double*) { return -1; }, o);
    const double y0 = 1.0;
    double y = 0.0;
    cvode.restart(0.0, &y0);
    try {
        cvode.advance(1.0, &y);
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("CVode failed at t = 0", 0), 0u) << m;
        EXPECT_NE(m.find("CV_RHSFUNC_FAIL"), std::string::npos) << m;
    }
    CvodeBdf::Options bad;
    bad.relativeTolerance = -1.0;
    try {
        CvodeBdf broken(1, oscillator, bad);
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("CVodeSStolerances failed: CV_ILL_INPUT", 0), 0u)
            << m;
    }
}

} // namespace
