#include "check/CheckProbes.hpp"

#include "io/Csv.hpp"
#include "Session.hpp"
#include "io/Values.hpp"

#include <cmath>
#include <iostream>
#include <limits>

namespace fmusim {

namespace {

// Balance tolerances relative to the size of the loads: a massless
// connector's forces and moments cancel exactly in exact arithmetic; a law
// that evaluates them separately leaves differences of a few ulps of the
// largest term, far below 1e-9.
constexpr double balanceTolerance = 1e-9;

class Prober {
public:
    Prober(const fmuImport::Fmu& fmu, const ConnectorIo& connector,
           const ProbeOptions& options)
        : fmu_(fmu), connector_(connector), options_(options),
          rng_(options.seed)
    {
        for (const fmuImport::Variable* v : outputsOf(fmu))
            if (v->type == fmuImport::Type::Real)
                outputs_.push_back(v);
    }

    // An instance initialised with the start values, at t = 0.
    fmuImport::Instance started(const std::string& name)
    {
        fmuImport::Instance instance
            = instantiate(fmu_, name, verboseLogger(options_.verbose), false);
        instance.setupExperiment(0.0);
        instance.enterInitializationMode();
        instance.exitInitializationMode();
        return instance;
    }

    Kinematics random()
    {
        std::uniform_real_distribution<double> position(-2.0, 2.0),
            rate(-1.0, 1.0);
        std::normal_distribution<double> normal;
        Kinematics k;
        Eigen::Quaterniond q(normal(rng_), normal(rng_), normal(rng_),
                             normal(rng_));
        k.R = q.normalized().toRotationMatrix();
        k.r = Eigen::Vector3d(position(rng_), position(rng_), position(rng_));
        k.v = Eigen::Vector3d(rate(rng_), rate(rng_), rate(rng_));
        k.omega = Eigen::Vector3d(rate(rng_), rate(rng_), rate(rng_));
        return k;
    }

    // Sets the kinematics and steps from t to t + stepSize.
    void step(fmuImport::Instance& instance, double t, const Kinematics& A,
              const Kinematics& B)
    {
        connector_.setKinematics(instance, A, B);
        instance.doStep(t, options_.stepSize);
    }

    // A step with random kinematics of both bodies (B is the world for a
    // one-body connector); advances t.
    void randomStep(fmuImport::Instance& instance, double& t,
                    Kinematics* A = nullptr, Kinematics* B = nullptr)
    {
        const Kinematics a = random();
        const Kinematics b
            = connector_.variables().twoBody() ? random() : Kinematics();
        step(instance, t, a, b);
        t += options_.stepSize;
        if (A)
            *A = a;
        if (B)
            *B = b;
    }

    std::vector<double> outputs(fmuImport::Instance& instance)
    {
        std::vector<unsigned int> vrs;
        for (const fmuImport::Variable* v : outputs_)
            vrs.push_back(v->valueReference);
        return instance.getReal(vrs);
    }

    // "" when equal, else the first output that differs.
    std::string difference(const std::vector<double>& expected,
                           const std::vector<double>& actual) const
    {
        for (std::size_t i = 0; i < expected.size(); ++i)
            if (!(expected[i] == actual[i]))
                return outputs_[i]->name + " is " + formatNumber(actual[i])
                    + " instead of " + formatNumber(expected[i]);
        return "";
    }

    std::string nonFinite(const std::vector<double>& values) const
    {
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!std::isfinite(values[i]))
                return outputs_[i]->name + " = " + formatNumber(values[i]);
        return "";
    }

    const fmuImport::Fmu& fmu_;
    const ConnectorIo& connector_;
    const ProbeOptions& options_;
    std::mt19937 rng_;
    std::vector<const fmuImport::Variable*> outputs_;
    double forceScale_ = 0,
           momentScale_ = 0; // largest loads seen in the random probe
};

CheckResult pass(const std::string& name)
{
    return {name, CheckResult::pass, ""};
}
CheckResult fail(const std::string& name, const std::string& why)
{
    return {name, CheckResult::fail, why};
}
CheckResult skip(const std::string& name, const std::string& why)
{
    return {name, CheckResult::skip, why};
}

// Random kinematics: every step succeeds, outputs are finite, loads balance.
void randomProbes(Prober& p,
                  const std::function<void(const CheckResult&)>& report)
{
    std::string stepError, nonFinite, forces, moments;
    try {
        fmuImport::Instance instance = p.started("random");
        double t = 0;
        for (int n = 0; n < p.options_.samples; ++n) {
            Kinematics A, B;
            p.randomStep(instance, t, &A, &B);
            const std::vector<double> values = p.outputs(instance);
            if (nonFinite.empty())
                nonFinite = p.nonFinite(values);
            Loads a, b;
            p.connector_.getLoads(instance, a, b);
            p.forceScale_ = std::max({p.forceScale_, a.F.norm(), b.F.norm()});
            p.momentScale_ = std::max({p.momentScale_, a.M.norm(), b.M.norm()});
            const double fScale = std::max(a.F.norm(), b.F.norm());
            const Eigen::Vector3d net = a.F + b.F;
            if (forces.empty() && net.norm() > balanceTolerance * fScale)
                forces = "A.F + B.F = " + formatNumber(net.norm())
                    + " N for loads of " + formatNumber(fScale)
                    + " N in sample " + std::to_string(n + 1);
            const Eigen::Vector3d total
                = a.M + b.M + A.r.cross(a.F) + B.r.cross(b.F);
            const double mScale = a.M.norm() + b.M.norm()
                + A.r.norm() * a.F.norm() + B.r.norm() * b.F.norm();
            if (moments.empty() && total.norm() > balanceTolerance * mScale)
                moments = "total moment about the origin "
                    + formatNumber(total.norm()) + " N.m for moments of "
                    + formatNumber(mScale) + " N.m in sample "
                    + std::to_string(n + 1);
        }
    } catch (const std::exception& e) {
        stepError = e.what();
    }
    report(stepError.empty() ? pass("random-kinematics")
                             : fail("random-kinematics", stepError));
    report(nonFinite.empty()
               ? pass("finite-outputs")
               : fail("finite-outputs", "non-finite output " + nonFinite));
    if (!p.connector_.hasLoadsB()) {
        report(
            skip("equal-and-opposite-forces", "the FMU declares no B.F, B.M"));
        report(skip("zero-total-moment", "the FMU declares no B.F, B.M"));
        return;
    }
    if (!stepError.empty()) {
        report(skip("equal-and-opposite-forces", "random-kinematics failed"));
        report(skip("zero-total-moment", "random-kinematics failed"));
        return;
    }
    report(forces.empty() ? pass("equal-and-opposite-forces")
                          : fail("equal-and-opposite-forces", forces));
    report(moments.empty() ? pass("zero-total-moment")
                           : fail("zero-total-moment", moments));
}

// Zero load at the rest configuration the FMU declares, if any (the start
// values of its inputs when the constant Boolean inputsStartAtRest is true).
void restProbe(Prober& p, const std::function<void(const CheckResult&)>& report)
{
    const std::string name = "rest-load";
    if (!p.fmu_.hasVariable("inputsStartAtRest"))
        return report(
            skip(name,
                 "the FMU declares no rest configuration (inputsStartAtRest)"));
    const fmuImport::Variable& flag = p.fmu_.variable("inputsStartAtRest");
    if (flag.type != fmuImport::Type::Boolean
        || flag.variability != fmuImport::Variability::constant
        || !flag.hasStart)
        return report(fail(
            name,
            "inputsStartAtRest must be a constant Boolean with a start value"));
    if (flag.start == 0)
        return report(skip(name, "inputsStartAtRest is false"));
    std::vector<std::string> noStart;
    for (const auto& input : p.connector_.kinematicInputs())
        if (!p.fmu_.variable(input.first).hasStart)
            noStart.push_back(input.first);
    if (!noStart.empty())
        return report(fail(name,
                           "inputs without a start value: " + noStart.front()
                               + (noStart.size() > 1 ? " and others" : "")));
    try {
        fmuImport::Instance instance = p.started("rest");
        instance.doStep(0.0, p.options_.stepSize);
        Loads a, b;
        p.connector_.getLoads(instance, a, b);
        // Round-off of the law at rest, relative to the loads of the random
        // probe (1 N and 1 N.m when that probe saw none).
        const double fTol
            = balanceTolerance * (p.forceScale_ > 0 ? p.forceScale_ : 1.0);
        const double mTol
            = balanceTolerance * (p.momentScale_ > 0 ? p.momentScale_ : 1.0);
        const double f = std::max(a.F.norm(), b.F.norm()),
                     m = std::max(a.M.norm(), b.M.norm());
        if (f > fTol || m > mTol)
            return report(fail(name,
                               "force " + formatNumber(f) + " N, moment "
                                   + formatNumber(m) + " N.m at rest"));
        report(pass(name));
    } catch (const std::exception& e) {
        report(fail(name, e.what()));
    }
}

// FMU state: get/set restores the outputs, a repeated step after restoring
// the state gives the same result, a serialized state restarts another
// instance.
void stateProbes(Prober& p,
                 const std::function<void(const CheckResult&)>& report)
{
    const fmuImport::ModelDescription& md = p.fmu_.modelDescription();
    if (!md.canGetAndSetFMUstate) {
        report(fail("state-get-set", "canGetAndSetFMUstate is not true"));
        report(fail("repeatable-step", "canGetAndSetFMUstate is not true"));
    }
    const double h = p.options_.stepSize;
    const double tSaved = 2 * h; // the state is saved after two steps
    std::vector<double> savedOutputs, first;
    std::vector<char> bytes;
    Kinematics A1, B1;
    if (md.canGetAndSetFMUstate) {
        try {
            fmuImport::Instance instance = p.started("state");
            double t = 0;
            p.randomStep(instance, t);
            p.randomStep(instance, t);
            const fmuImport::Instance::State saved = instance.getState();
            savedOutputs = p.outputs(instance);
            p.randomStep(instance, t, &A1, &B1);
            first = p.outputs(instance);
            p.randomStep(instance, t);
            instance.setState(saved);
            const std::string restored
                = p.difference(savedOutputs, p.outputs(instance));
            report(restored.empty()
                       ? pass("state-get-set")
                       : fail("state-get-set",
                              "after fmi2SetFMUstate " + restored));

            // The same step twice with a different one in between, as a
            // PIMPLE loop does: the results must be identical, bit for bit.
            t = tSaved;
            p.randomStep(instance, t);
            instance.setState(saved);
            p.step(instance, tSaved, A1, B1);
            const std::string repeated
                = p.difference(first, p.outputs(instance));
            report(repeated.empty()
                       ? pass("repeatable-step")
                       : fail("repeatable-step", "repeated step: " + repeated));
            if (md.canSerializeFMUstate)
                bytes = instance.serializeState(saved);
        } catch (const std::exception& e) {
            report(fail("state-get-set", e.what()));
            report(skip("repeatable-step", "state-get-set failed"));
        }
    }
    if (!md.canSerializeFMUstate)
        return report(
            fail("state-serialize", "canSerializeFMUstate is not true"));
    if (bytes.empty())
        return report(skip("state-serialize", "no state was saved"));
    try {
        // A restart: the serialized state in a fresh instance.
        fmuImport::Instance other = p.started("restart");
        other.setState(other.deserializeState(bytes));
        const std::string restored
            = p.difference(savedOutputs, p.outputs(other));
        if (!restored.empty())
            return report(
                fail("state-serialize", "after deserializing " + restored));
        p.step(other, tSaved, A1, B1);
        const std::string stepped = p.difference(first, p.outputs(other));
        report(stepped.empty() ? pass("state-serialize")
                               : fail("state-serialize",
                                      "step after deserializing: " + stepped));
    } catch (const std::exception& e) {
        report(fail("state-serialize", e.what()));
    }
}

// Steps of changing size from one instance.
void stepSizeProbe(Prober& p,
                   const std::function<void(const CheckResult&)>& report)
{
    try {
        fmuImport::Instance instance = p.started("stepSize");
        double t = 0;
        for (const double h : {1.0, 2.5, 0.4, 1e-3}) {
            const Kinematics A = p.random();
            const Kinematics B = p.connector_.variables().twoBody()
                ? p.random()
                : Kinematics();
            p.connector_.setKinematics(instance, A, B);
            instance.doStep(t, h * p.options_.stepSize);
            t += h * p.options_.stepSize;
        }
        report(pass("variable-step-size"));
    } catch (const std::exception& e) {
        report(fail("variable-step-size", e.what()));
    }
}

// A non-finite value in one component of each declared kinematic input must
// give fmi2Error (from fmi2SetReal, fmi2DoStep or the fmi2GetReal of the
// outputs), with a message naming the input, and never a non-finite output.
void nonFiniteProbe(Prober& p,
                    const std::function<void(const CheckResult&)>& report)
{
    const double bad[] = {std::numeric_limits<double>::quiet_NaN(),
                          std::numeric_limits<double>::infinity(),
                          -std::numeric_limits<double>::infinity()};
    std::vector<std::string> problems;
    int k = 0;
    for (const auto& input : p.connector_.kinematicInputs()) {
        const std::string& name = input.first;
        const std::string base = name.substr(0, name.find('['));
        if (name != base + "[1]" && name != base + "[1,1]")
            continue; // one component per block
        const double value = bad[k++ % 3];
        try {
            fmuImport::Instance instance = p.started("nonFinite");
            double t = 0;
            p.randomStep(instance, t);
            Kinematics A = p.random(),
                       B = p.connector_.variables().twoBody() ? p.random()
                                                              : Kinematics();
            p.connector_.setKinematics(instance, A, B);
            std::string nonFinite;
            try {
                instance.setReal({input.second}, {value});
                instance.doStep(t, p.options_.stepSize);
                nonFinite = p.nonFinite(p.outputs(instance));
            } catch (const fmuImport::Error& e) {
                if (std::string(e.what()).find(base) == std::string::npos)
                    problems.push_back("the error for " + name + " = "
                                       + formatNumber(value)
                                       + " does not name it: " + e.what());
                continue;
            }
            problems.push_back(
                name + " = " + formatNumber(value) + " was accepted"
                + (nonFinite.empty() ? "" : " and gave " + nonFinite));
        } catch (const std::exception& e) {
            problems.push_back(name + ": " + e.what());
        }
    }
    if (problems.empty())
        return report(pass("non-finite-inputs"));
    std::string why = problems.front();
    for (std::size_t i = 1; i < problems.size(); ++i)
        why += "; " + problems[i];
    report(fail("non-finite-inputs", why));
}

} // namespace

void runProbes(const fmuImport::Fmu& fmu, const ConnectorIo& connector,
               const ProbeOptions& options,
               const std::function<void(const CheckResult&)>& report)
{
    Prober p(fmu, connector, options);
    try {
        p.started("initialization");
        report(pass("initialization"));
    } catch (const std::exception& e) {
        report(fail("initialization", e.what()));
        report(skip("probes",
                    "the FMU does not initialise with its start values"));
        return;
    }
    randomProbes(p, report);
    restProbe(p, report);
    stateProbes(p, report);
    stepSizeProbe(p, report);
    nonFiniteProbe(p, report);
}

} // namespace fmusim
