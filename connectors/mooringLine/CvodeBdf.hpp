// The one place that calls SUNDIALS (6.x API, with its SUNContext): CVODE's
// BDF method with a Newton iteration and a banded (or dense) direct linear
// solver whose Jacobian CVODE builds by difference quotients. Every handle
// is owned (RAII), every call is checked, and a failure throws
// std::runtime_error naming the SUNDIALS function, its return flag and
// CVODE's own message.
#ifndef CONNECTORS_MOORINGLINE_CVODEBDF_HPP
#define CONNECTORS_MOORINGLINE_CVODEBDF_HPP

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

namespace connectors {

class CvodeBdf {
public:
    //- dy/dt = f(t, y); returns 0, > 0 for a recoverable failure (CVODE
    //  retries with a smaller step), < 0 to stop. Must not throw.
    using Rhs = std::function<int(double t, const double* y, double* ydot)>;

    struct Options {
        double relativeTolerance = 1e-6;
        double absoluteTolerance = 1e-6;
        //- Half-bandwidth of the Jacobian (upper = lower); < 0: dense
        long halfBandwidth = -1;
        long maxSteps = 100000;
    };

    struct Statistics {
        long steps = 0, rhsEvaluations = 0, jacobianEvaluations = 0,
             errorTestFailures = 0, convergenceFailures = 0;
    };

    CvodeBdf(std::size_t size, Rhs rhs, const Options& options);
    ~CvodeBdf();
    CvodeBdf(const CvodeBdf&) = delete;
    CvodeBdf& operator=(const CvodeBdf&) = delete;

    //- Restarts the integration at t0 from y0 (CVodeReInit: the BDF
    //  history is dropped, the next step is of order 1)
    void restart(double t0, const double* y0);

    //- Called after each of CVODE's internal steps with the step's end
    //  time and state. Must not throw.
    using StepObserver = std::function<void(double t, const double* y)>;

    //- Integrates to exactly tEnd (a stop time: f is never evaluated past
    //  it) and writes y(tEnd); with `onStep`, one internal step at a time
    //  (CV_ONE_STEP: the same steps), calling it after each
    void advance(double tEnd, double* y, const StepObserver& onStep = {});

    //- Counters accumulated since construction
    Statistics statistics() const;

    std::size_t size() const { return size_; }

    //- The right-hand side, as CVODE calls it
    int rhs(double t, const double* y, double* ydot) const
    {
        return rhs_(t, y, ydot);
    }

private:
    struct Handles;
    //- Counters of the current CVODE run (reset by CVodeReInit)
    Statistics current() const;

    std::size_t size_;
    Rhs rhs_;
    std::unique_ptr<Handles> h_;
    std::string lastMessage_;
    Statistics accumulated_;
};

} // namespace connectors

#endif
