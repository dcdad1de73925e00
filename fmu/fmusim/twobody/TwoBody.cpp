#include "Subcommands.hpp"

#include "io/Csv.hpp"
#include "io/Values.hpp"
#include "Errors.hpp"
#include "Session.hpp"
#include "twobody/TwoBodyConfig.hpp"

#include <chrono>
#include <cmath>
#include <iostream>

namespace fmusim {

const char* twoBodyUsage()
{
    return "fmusim twobody connector.fmu [--config file] [--key value ...] [--set name=value ...]\n"
           "               [--parameters file] [--logging]\n"
           "  Integrates two rigid bodies A and B (6 DoF, unit quaternions, reference point\n"
           "  at the centre of mass) coupled through the connector FMU, and writes time,\n"
           "  X.x X.y X.z X.qw X.qx X.qy X.qz X.vx X.vy X.vz X.wx X.wy X.wz X.kineticEnergy\n"
           "  for X = A, B, every FMU output and, for the implicit scheme,\n"
           "  couplingIterations. The config file holds 'key = value' lines; the same keys\n"
           "  are options (--key value) and win over the file:\n"
           "    start-time (0), stop-time (10), step-size (0.001)            [s]\n"
           "    scheme: explicit (default) or implicit\n"
           "      explicit: the loads at the start of the step, semi-implicit (symplectic)\n"
           "        Euler: v1 = v0 + h a0, x1 = x0 + h v1, q1 = exp(h omega1) q0; one\n"
           "        fmi2DoStep per step, first order\n"
           "      implicit: trapezoidal rule with the loads at both ends of the step; the\n"
           "        loads at the end are iterated to convergence by fixed-point iteration\n"
           "        with Aitken relaxation, the FMU state restored before each repeated\n"
           "        fmi2DoStep; second order; needs canGetAndSetFMUstate\n"
           "    coupling-tolerance (1e-10): change of the loads relative to the largest\n"
           "      loads so far; max-coupling-iterations (50); initial-relaxation (0.5)\n"
           "    gravity (0 0 0) [m/s2]; output-file (standard output); write-every (1)\n"
           "    timeout (0, no limit) [s]: end the run (exit code 6) when one call into\n"
           "      the FMU takes longer\n"
           "    isolation: none (default), or process: the FMU in a process of its own (a\n"
           "      crash or exit() of the FMU ends the run with exit code 7)\n"
           "    per body, prefix A. or B.:\n"
           "      motion: free (default), fixed, sinusoidal, world (B only; the default for\n"
           "        B when the connector declares no B. inputs)\n"
           "      mass (1) [kg]; inertia (1 1 1) [kg.m2]: Jxx Jyy Jzz [Jxy Jxz Jyz] or 9\n"
           "        values, body frame, about the centre of mass\n"
           "      position [m], orientation (quaternion w x y z, 1 0 0 0), velocity [m/s],\n"
           "        angular-velocity [rad/s, global frame]: the initial state\n"
           "      amplitude [m], rotation-amplitude [rad, rotation vector], frequency [Hz],\n"
           "        phase [rad]: sinusoidal motion x = x0 + amplitude sin(2 pi f t + phase),\n"
           "        R = exp(rotation-amplitude sin(2 pi f t + phase)) R0\n"
           "  Vectors are three numbers separated by blanks or commas. --set and\n"
           "  --parameters set FMU parameters as in 'fmusim run'. A NaN or infinite FMU\n"
           "  output stops the run (exit code 5).\n";
}

namespace {

using LoadVector = Eigen::Matrix<double, 12, 1>;

LoadVector pack(const Loads& a, const Loads& b)
{
    LoadVector l;
    l << a.F, a.M, b.F, b.M;
    return l;
}

void unpack(const LoadVector& l, Loads& a, Loads& b)
{
    a.F = l.segment<3>(0);
    a.M = l.segment<3>(3);
    b.F = l.segment<3>(6);
    b.M = l.segment<3>(9);
}

std::vector<std::string> bodyColumns(const std::string& prefix)
{
    std::vector<std::string> names;
    for (const char* c : {"x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy",
                          "vz", "wx", "wy", "wz", "kineticEnergy"})
        names.push_back(prefix + "." + c);
    return names;
}

void appendBody(std::vector<std::string>& row, const Body& body,
                const BodyState& s)
{
    for (const double value :
         {s.x.x(), s.x.y(), s.x.z(), s.q.w(), s.q.x(), s.q.y(), s.q.z(),
          s.v.x(), s.v.y(), s.v.z(), s.omega.x(), s.omega.y(), s.omega.z(),
          kineticEnergy(body, s)})
        row.push_back(formatNumber(value));
}

// The names of the components of a LoadVector.
const std::vector<std::string>& loadNames()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (const char* base : {"A.F", "A.M", "B.F", "B.M"})
            for (const std::string& name : fmuImport::connector::componentNames(
                     base, fmuImport::connector::Shape::vector))
                all.push_back(name);
        return all;
    }();
    return names;
}

bool finite(const BodyState& s)
{
    return s.x.allFinite() && s.v.allFinite() && s.omega.allFinite()
        && s.q.coeffs().allFinite();
}

class Simulation {
public:
    Simulation(const TwoBodyConfig& config, const fmuImport::Fmu& fmu,
               const ConnectorIo& connector)
        : c_(config), fmu_(fmu), connector_(connector),
          instance_(instantiate(fmu, "twobody", stderrLogger(config.logging),
                                config.logging)),
          out_(config.outputFile), outputs_(outputsOf(fmu))
    {
    }

    void run()
    {
        const auto wallStart = std::chrono::steady_clock::now();
        initialize();
        const long steps = static_cast<long>(
            std::ceil((c_.stopTime - c_.startTime) / c_.stepSize - 1e-9));
        long n = 0;
        for (; n < steps; ++n) {
            const double t = c_.startTime + n * c_.stepSize;
            const double next = n + 1 == steps
                ? c_.stopTime
                : c_.startTime + (n + 1) * c_.stepSize;
            try {
                if (c_.scheme == Scheme::explicitEuler)
                    explicitStep(t, next - t);
                else
                    implicitStep(t, next - t);
            } catch (const SimulationEnded&) {
                break; // the rows end at the last step written
            }
            if (!finite(a_) || !finite(b_))
                throw fmuImport::Error(
                    "the state of a body is not finite at t = "
                    + formatNumber(next));
            if ((n + 1) % c_.writeEvery == 0 || n + 1 == steps)
                write(next);
        }
        instance_.terminate();
        out_.finish();
        const double wall = std::chrono::duration<double>(
                                std::chrono::steady_clock::now() - wallStart)
                                .count();
        std::cerr << "fmusim twobody: " << n << " steps, " << doSteps_
                  << " fmi2DoStep calls ("
                  << static_cast<double>(doSteps_) / std::max(n, 1L)
                  << " per step), " << wall << " s\n";
    }

private:
    // Thrown by evaluate when the FMU asks to end the simulation
    struct SimulationEnded { };

    BodyState advance(const Body& body, const BodyState& s0, const Loads& l0,
                      const Loads* l1, double t1, double h) const
    {
        if (!body.isFree())
            return prescribedState(body, t1);
        return l1 ? trapezoidalStep(body, s0, l0, *l1, c_.gravity, h)
                  : fmusim::explicitStep(body, s0, l0, c_.gravity, h);
    }

    void initialize()
    {
        a_ = c_.A.isFree() ? c_.A.initial : prescribedState(c_.A, c_.startTime);
        b_ = c_.B.isFree() ? c_.B.initial : prescribedState(c_.B, c_.startTime);
        instance_.setupExperiment(c_.startTime, true, c_.stopTime);
        applySettings(fmu_, instance_, c_.fmuSettings);
        instance_.enterInitializationMode();
        connector_.setMassProperties(instance_, massPropertiesOf(c_.A),
                                     massPropertiesOf(c_.B));
        connector_.setKinematics(instance_, kinematicsOf(a_), kinematicsOf(b_));
        instance_.exitInitializationMode();
        connector_.getLoads(instance_, loadsA_, loadsB_);
        loadScale_ = pack(loadsA_, loadsB_).norm();
        std::vector<std::string> header {"time"};
        for (const std::string& n : bodyColumns("A"))
            header.push_back(n);
        for (const std::string& n : bodyColumns("B"))
            header.push_back(n);
        for (const fmuImport::Variable* v : outputs_)
            header.push_back(csvField(v->name));
        if (c_.scheme == Scheme::implicitTrapezoidal)
            header.push_back("couplingIterations");
        out_.row(header);
        write(c_.startTime);
    }

    // Sets the kinematics at t + h, steps the FMU from t, reads the loads;
    // a non-finite load stops the run (fmuImport::Error) before it moves a
    // body or reaches the output.
    LoadVector evaluate(const BodyState& a1, const BodyState& b1, double t,
                        double h)
    {
        connector_.setKinematics(instance_, kinematicsOf(a1), kinematicsOf(b1));
        ++doSteps_;
        if (!stepOrEnd(instance_, t, h))
            throw SimulationEnded();
        Loads la, lb;
        connector_.getLoads(instance_, la, lb);
        const LoadVector loads = pack(la, lb);
        for (int i = 0; i < loads.size(); ++i)
            if (!std::isfinite(loads[i]))
                throw fmuImport::Error(nonFiniteMessage(
                    instance_, "output '" + loadNames()[i] + "'", loads[i],
                    t + h));
        return loads;
    }

    void explicitStep(double t, double h)
    {
        a_ = advance(c_.A, a_, loadsA_, nullptr, t + h, h);
        b_ = advance(c_.B, b_, loadsB_, nullptr, t + h, h);
        unpack(evaluate(a_, b_, t, h), loadsA_, loadsB_);
    }

    void implicitStep(double t, double h)
    {
        const fmuImport::Instance::State start = instance_.getState();
        const LoadVector l0 = pack(loadsA_, loadsB_);
        // First guess: linear extrapolation of the loads of the last two steps.
        LoadVector guess
            = havePrevious_ ? LoadVector(2 * l0 - previousLoads_) : l0;
        LoadVector residual = LoadVector::Zero(),
                   lastResidual = LoadVector::Zero();
        double relaxation = c_.initialRelaxation;
        for (iterations_ = 1; iterations_ <= c_.maxCouplingIterations;
             ++iterations_) {
            Loads ga, gb;
            unpack(guess, ga, gb);
            const BodyState a1 = advance(c_.A, a_, loadsA_, &ga, t + h, h);
            const BodyState b1 = advance(c_.B, b_, loadsB_, &gb, t + h, h);
            if (iterations_ > 1)
                instance_.setState(start);
            const LoadVector l1 = evaluate(a1, b1, t, h);
            residual = l1 - guess;
            // Relative to this step's loads: a diverging iterate must not
            // loosen the test for the rest of the run.
            loadScale_ = std::max(l0.norm(), l1.norm());
            if (residual.norm() <= c_.couplingTolerance * loadScale_) {
                a_ = a1;
                b_ = b1;
                previousLoads_ = l0;
                havePrevious_ = true;
                unpack(l1, loadsA_, loadsB_);
                return;
            }
            if (iterations_ > 1) {
                const LoadVector change = residual - lastResidual;
                if (change.squaredNorm() > 0)
                    relaxation = -relaxation * lastResidual.dot(change)
                        / change.squaredNorm();
            }
            guess += relaxation * residual;
            lastResidual = residual;
        }
        throw fmuImport::Error(
            "the implicit coupling did not converge at t = " + formatNumber(t)
            + " after " + std::to_string(c_.maxCouplingIterations)
            + " iterations (load change " + formatNumber(residual.norm())
            + ", largest loads " + formatNumber(loadScale_) + ")");
    }

    void write(double t)
    {
        std::vector<std::string> row {formatNumber(t)};
        appendBody(row, c_.A, a_);
        appendBody(row, c_.B, b_);
        const std::vector<std::string> values = readValues(instance_, outputs_);
        row.insert(row.end(), values.begin(), values.end());
        if (c_.scheme == Scheme::implicitTrapezoidal)
            row.push_back(std::to_string(t == c_.startTime ? 0 : iterations_));
        out_.row(row);
    }

    const TwoBodyConfig& c_;
    const fmuImport::Fmu& fmu_;
    const ConnectorIo& connector_;
    fmuImport::Instance instance_;
    CsvWriter out_;
    std::vector<const fmuImport::Variable*> outputs_;
    BodyState a_, b_;
    Loads loadsA_, loadsB_;
    LoadVector previousLoads_ = LoadVector::Zero();
    bool havePrevious_ = false;
    double loadScale_ = 0;
    int iterations_ = 0;
    long doSteps_ = 0;
};

} // namespace

int twoBodyCommand(const std::vector<std::string>& args)
{
    TwoBodyConfig config = parseTwoBodyConfig(args);
    const fmuImport::Fmu fmu = loadFmu(
        config.fmuPath, {config.isolation, config.timeout, std::string()});
    const ConnectorIo connector(fmu);
    const std::vector<std::string> missing
        = connector.variables().missingRequired();
    if (!missing.empty()) {
        std::string list;
        for (const std::string& m : missing)
            list += (list.empty() ? "" : ", ") + m;
        throw LoadError("FMU '" + fmu.path()
                        + "' is not a connector: it does not declare " + list);
    }
    if (!connector.variables().twoBody()) {
        if (config.bMotionGiven && config.B.motion != MotionKind::world)
            throw UsageError(
                "B.motion: FMU '" + fmu.path()
                + "' declares no B. inputs, so body B is the world");
        config.B.motion = MotionKind::world;
    }
    if (config.scheme == Scheme::implicitTrapezoidal
        && !fmu.modelDescription().canGetAndSetFMUstate)
        throw UsageError("scheme implicit: FMU '" + fmu.path()
                         + "' cannot get and set its state");
    Simulation(config, fmu, connector).run();
    return exitOk;
}

} // namespace fmusim
