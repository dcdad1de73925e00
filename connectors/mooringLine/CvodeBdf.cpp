#include "mooringLine/CvodeBdf.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cstdlib>
#include <type_traits>
#include <stdexcept>

namespace connectors {

namespace {

struct ContextDeleter {
    void operator()(SUNContext ctx) const { SUNContext_Free(&ctx); }
};
struct VectorDeleter {
    void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct MatrixDeleter {
    void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
struct SolverDeleter {
    void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};
struct CvodeDeleter {
    void operator()(void* mem) const { CVodeFree(&mem); }
};

std::string flagName(long flag)
{
    char* name = CVodeGetReturnFlagName(flag);
    std::string out = name != nullptr ? name : "unknown";
    std::free(name);
    return out;
}

template <class Pointer> Pointer created(Pointer p, const char* function)
{
    if (p == nullptr) {
        throw std::runtime_error(std::string(function)
                                 + " failed (returned NULL)");
    }
    return p;
}

void errorHandler(int, const char*, const char* function, char* message,
                  void* data)
{
    *static_cast<std::string*>(data)
        = std::string(function) + ": " + (message != nullptr ? message : "");
}

} // namespace

struct CvodeBdf::Handles {
    std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter> context;
    std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter> y;
    std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter> matrix;
    std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverDeleter>
        solver;
    std::unique_ptr<void, CvodeDeleter> cvode;
};

namespace {

int rhsCallback(realtype t, N_Vector y, N_Vector ydot, void* self)
{
    return static_cast<const CvodeBdf*>(self)->rhs(t, N_VGetArrayPointer(y),
                                                   N_VGetArrayPointer(ydot));
}

} // namespace

CvodeBdf::CvodeBdf(std::size_t size, Rhs rhs, const Options& options)
    : size_(size), rhs_(std::move(rhs)), h_(std::make_unique<Handles>())
{
    const auto check = [this](int flag, const char* function) {
        if (flag < 0) {
            throw std::runtime_error(
                std::string(function) + " failed: " + flagName(flag)
                + (lastMessage_.empty() ? "" : " (" + lastMessage_ + ")"));
        }
    };
    SUNContext context = nullptr;
    check(SUNContext_Create(nullptr, &context), "SUNContext_Create");
    h_->context.reset(context);
    const auto n = sunindextype(size);
    h_->y.reset(created(N_VNew_Serial(n, context), "N_VNew_Serial"));
    N_VConst(0.0, h_->y.get());
    if (options.halfBandwidth >= 0 && options.halfBandwidth < long(size)) {
        const auto b = sunindextype(options.halfBandwidth);
        h_->matrix.reset(
            created(SUNBandMatrix(n, b, b, context), "SUNBandMatrix"));
        h_->solver.reset(
            created(SUNLinSol_Band(h_->y.get(), h_->matrix.get(), context),
                    "SUNLinSol_Band"));
    } else {
        h_->matrix.reset(
            created(SUNDenseMatrix(n, n, context), "SUNDenseMatrix"));
        h_->solver.reset(
            created(SUNLinSol_Dense(h_->y.get(), h_->matrix.get(), context),
                    "SUNLinSol_Dense"));
    }
    h_->cvode.reset(created(CVodeCreate(CV_BDF, context), "CVodeCreate"));
    void* mem = h_->cvode.get();
    check(CVodeSetErrHandlerFn(mem, errorHandler, &lastMessage_),
          "CVodeSetErrHandlerFn");
    check(CVodeInit(mem, rhsCallback, 0.0, h_->y.get()), "CVodeInit");
    check(CVodeSetUserData(mem, this), "CVodeSetUserData");
    check(CVodeSStolerances(mem, options.relativeTolerance,
                            options.absoluteTolerance),
          "CVodeSStolerances");
    check(CVodeSetLinearSolver(mem, h_->solver.get(), h_->matrix.get()),
          "CVodeSetLinearSolver");
    check(CVodeSetMaxNumSteps(mem, options.maxSteps), "CVodeSetMaxNumSteps");
}

CvodeBdf::~CvodeBdf() = default;

void CvodeBdf::restart(double t0, const double* y0)
{
    double* y = N_VGetArrayPointer(h_->y.get());
    std::copy(y0, y0 + size_, y);
    lastMessage_.clear();
    const Statistics run = current();
    accumulated_.steps += run.steps;
    accumulated_.rhsEvaluations += run.rhsEvaluations;
    accumulated_.jacobianEvaluations += run.jacobianEvaluations;
    accumulated_.errorTestFailures += run.errorTestFailures;
    accumulated_.convergenceFailures += run.convergenceFailures;
    const int flag = CVodeReInit(h_->cvode.get(), t0, h_->y.get());
    if (flag < 0) {
        throw std::runtime_error("CVodeReInit failed: " + flagName(flag) + " ("
                                 + lastMessage_ + ")");
    }
}

void CvodeBdf::advance(double tEnd, double* yOut, const StepObserver& onStep)
{
    void* mem = h_->cvode.get();
    int flag = CVodeSetStopTime(mem, tEnd);
    if (flag < 0) {
        throw std::runtime_error("CVodeSetStopTime failed: " + flagName(flag)
                                 + " (" + lastMessage_ + ")");
    }
    const double* y = N_VGetArrayPointer(h_->y.get());
    double t = 0.0;
    do {
        flag = CVode(mem, tEnd, h_->y.get(), &t,
                     onStep ? CV_ONE_STEP : CV_NORMAL);
        if (flag < 0) {
            throw std::runtime_error("CVode failed at t = " + std::to_string(t)
                                     + ": " + flagName(flag) + " ("
                                     + lastMessage_ + ")");
        }
        if (onStep) {
            onStep(t, y);
        }
    } while (onStep && flag == CV_SUCCESS && t < tEnd);
    std::copy(y, y + size_, yOut);
}

CvodeBdf::Statistics CvodeBdf::statistics() const
{
    Statistics s = current();
    s.steps += accumulated_.steps;
    s.rhsEvaluations += accumulated_.rhsEvaluations;
    s.jacobianEvaluations += accumulated_.jacobianEvaluations;
    s.errorTestFailures += accumulated_.errorTestFailures;
    s.convergenceFailures += accumulated_.convergenceFailures;
    return s;
}

CvodeBdf::Statistics CvodeBdf::current() const
{
    void* mem = h_->cvode.get();
    Statistics s;
    const auto get = [](int flag, const char* function) {
        if (flag < 0) {
            throw std::runtime_error(std::string(function)
                                     + " failed: " + flagName(flag));
        }
    };
    get(CVodeGetNumSteps(mem, &s.steps), "CVodeGetNumSteps");
    get(CVodeGetNumRhsEvals(mem, &s.rhsEvaluations), "CVodeGetNumRhsEvals");
    get(CVodeGetNumJacEvals(mem, &s.jacobianEvaluations),
        "CVodeGetNumJacEvals");
    get(CVodeGetNumErrTestFails(mem, &s.errorTestFailures),
        "CVodeGetNumErrTestFails");
    get(CVodeGetNumNonlinSolvConvFails(mem, &s.convergenceFailures),
        "CVodeGetNumNonlinSolvConvFails");
    return s;
}

} // namespace connectors
