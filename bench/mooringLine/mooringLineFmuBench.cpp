// mooringLineFmuBench: mooringLine.fmu stepped through the project's
// importer (fmuImport) as foam-fmi-bridge's fmuConnectorCore steps it, on
// mooringLineBench's two reference lines (lab chain, OC4 line) with its
// motion, harmonic and clock: per coupling step the FMU state is saved
// (fmi2GetFMUstate into the one of the step before, as the bridge does
// when a repeated solve can follow), the inputs of A and B are set, the
// FMU steps, and the loads A.F, A.M, B.F, B.M are read; with `all`, every
// Real output instead (the bridge's reads before it asked for the line's
// shape only at write times); with `unsaved`, the loads and no state
// saved (what the saves cost). The fairlead tension of the harmonic is
// |A.F|, the law's fairleadTension.
//
// Usage: mooringLineFmuBench FMU lab|oc4 N h [loads|all|unsaved]
//                            [energyAccount]
//   FMU            mooringLine.fmu (build/fmus/mooringLine.fmu)
//   loads|all|unsaved  what is read after each step (default loads)
//   energyAccount  the FMU parameter, 0 or 1 (default: the FMU's start
//                  value)
// Prints one row as mooringLineBench does: amplitude [N], wall and CPU
// time per simulated second (the start not counted).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "MooringLineReferences.hpp"
#include "fmuImport/fmuImport.hpp"

namespace {

using connectors::Vector3;
using Clock = std::chrono::steady_clock;
constexpr double pi = 3.14159265358979323846;

double cpuSeconds()
{
    timespec t {};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Case {
    connectors::references::ReferenceLine line;
    double amplitude, period;
};

//- The fairlead's position and velocity at t (mooringLineBench's surge,
//  ramped in over the first period)
void fairleadAt(const Case& c, double t, Vector3& r, Vector3& v)
{
    const double w = 2.0 * pi / c.period;
    const double ramp
        = t < c.period ? 0.5 * (1.0 - std::cos(pi * t / c.period)) : 1.0;
    const double dRamp = t < c.period
        ? 0.5 * pi / c.period * std::sin(pi * t / c.period)
        : 0.0;
    r = c.line.fairlead + Vector3(c.amplitude * ramp * std::sin(w * t), 0, 0);
    v = Vector3(c.amplitude
                    * (dRamp * std::sin(w * t) + ramp * w * std::cos(w * t)),
                0, 0);
}

//- The law's parameters as the FMU's, by name
std::vector<std::pair<std::string, double>>
fmuParameters(const connectors::MooringLineParameters& p)
{
    std::vector<std::pair<std::string, double>> v = {
        {"unstretchedLength", p.length},
        {"EA", p.EA},
        {"axialDamping", p.axialDamping},
        {"massPerLength", p.massPerLength},
        {"diameter", p.diameter},
        {"waterDensity", p.waterDensity},
        {"gravity", p.gravity},
        {"normalDrag", p.normalDrag},
        {"tangentialDrag", p.tangentialDrag},
        {"normalAddedMass", p.normalAddedMass},
        {"tangentialAddedMass", p.tangentialAddedMass},
        {"seabedContact", p.seabedContact ? 1.0 : 0.0},
        {"seabedStiffness", p.seabedStiffness},
        {"seabedDamping", p.seabedDamping},
        {"segments", double(p.segments)},
        {"hermiteEnds", p.hermiteEnds ? 1.0 : 0.0},
        {"endInertia", p.endInertia ? 1.0 : 0.0},
    };
    for (int i = 0; i < 3; ++i) {
        const std::string k = "[" + std::to_string(i + 1) + "]";
        v.push_back({"A.p" + k, p.p_AoP_A[i]});
        v.push_back({"B.p" + k, p.p_BoQ_B[i]});
    }
    return v;
}

int run(const std::string& path, const Case& c, int N, double h, bool all,
        bool save, int energyAccount)
{
    connectors::MooringLineParameters p = c.line.p;
    p.segments = N;
    const fmuImport::Fmu fmu(path);
    const fmuImport::connector::Variables vars(fmu);
    fmuImport::Instance in(fmu, "line");
    in.setupExperiment(0.0);
    in.enterInitializationMode();
    std::vector<unsigned> refs;
    std::vector<double> values;
    for (const auto& [name, value] : fmuParameters(p)) {
        refs.push_back(fmu.variable(name).valueReference);
        values.push_back(value);
    }
    if (energyAccount >= 0) {
        refs.push_back(fmu.variable("energyAccount").valueReference);
        values.push_back(energyAccount);
    }
    in.setReal(refs, values);

    // the inputs as the bridge sets them: A and B, r R v omega each
    std::vector<unsigned> inputRefs;
    for (const char* body : {"A", "B"}) {
        for (const char* term : {".r", ".R", ".v", ".omega"}) {
            const std::vector<unsigned>& r
                = vars.refs(body + std::string(term));
            inputRefs.insert(inputRefs.end(), r.begin(), r.end());
        }
    }
    std::vector<double> inputs(inputRefs.size(), 0.0);
    const auto setInputs = [&](double t) {
        Vector3 r, v;
        fairleadAt(c, t, r, v);
        double* x = inputs.data();
        const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        // A: r, R, v, omega; then B: the anchor at rest
        for (int i = 0; i < 3; ++i) {
            x[i] = r[i];
        }
        std::copy(identity, identity + 9, x + 3);
        for (int i = 0; i < 3; ++i) {
            x[12 + i] = v[i];
            x[15 + i] = 0.0;
            x[18 + i] = c.line.anchor[i];
            x[30 + i] = x[33 + i] = 0.0;
        }
        std::copy(identity, identity + 9, x + 21);
        in.setReal(inputRefs, inputs);
    };
    std::vector<unsigned> readRefs;
    if (all) {
        for (const fmuImport::Variable& v : fmu.modelDescription().variables) {
            if (v.causality == fmuImport::Causality::output
                && v.type == fmuImport::Type::Real) {
                readRefs.push_back(v.valueReference);
            }
        }
    } else {
        for (const char* term : {"A.F", "A.M", "B.F", "B.M"}) {
            const std::vector<unsigned>& r = vars.refs(term);
            readRefs.insert(readRefs.end(), r.begin(), r.end());
        }
    }
    const std::vector<unsigned>& AF = vars.refs("A.F");
    std::vector<std::size_t> at;
    for (const unsigned r : AF) {
        at.push_back(std::size_t(std::find(readRefs.begin(), readRefs.end(), r)
                                 - readRefs.begin()));
    }
    setInputs(0.0);
    in.exitInitializationMode();

    const int perPeriod = int(std::lround(c.period / h));
    fmuImport::Instance::State saved;
    std::vector<double> read;
    const auto start = Clock::now();
    const double cpuStart = cpuSeconds();
    std::complex<double> a1 = 0.0;
    for (int k = 1; k <= 3 * perPeriod; ++k) {
        const double t = k * h;
        if (save) {
            in.getState(saved);
        }
        setInputs(t);
        in.doStep(t - h, h);
        in.getReal(readRefs, read);
        const double T
            = std::sqrt(read[at[0]] * read[at[0]] + read[at[1]] * read[at[1]]
                        + read[at[2]] * read[at[2]]);
        if (k > 2 * perPeriod) {
            a1 += T
                * std::exp(std::complex<double>(0.0, -2.0 * pi * t / c.period));
        }
    }
    const double wall
        = std::chrono::duration<double>(Clock::now() - start).count()
        / (3.0 * c.period);
    const double cpu = (cpuSeconds() - cpuStart) / (3.0 * c.period);
    std::printf("%s N = %d h = %g (FMU, %s read, %s, energyAccount %s): "
                "amplitude %.9g N, wall %.4g s (CPU %.4g s) per simulated "
                "second\n",
                c.line.name, N, h, all ? "every output" : "the loads",
                save ? "state saved" : "no state saved",
                energyAccount < 0 ? "default" : (energyAccount ? "1" : "0"),
                2.0 * std::abs(a1) / perPeriod, wall, cpu);
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 5 || argc > 7
        || (std::strcmp(argv[2], "lab") != 0
            && std::strcmp(argv[2], "oc4") != 0)) {
        std::fprintf(stderr,
                     "usage: %s FMU lab|oc4 N h [loads|all|unsaved] "
                     "[energyAccount 0|1]\n",
                     argv[0]);
        return 2;
    }
    const bool lab = std::strcmp(argv[2], "lab") == 0;
    const Case c = lab ? Case {connectors::references::lab(20), 0.01, 1.0}
                       : Case {connectors::references::oc4(20), 1.0, 10.0};
    const bool all = argc >= 6 && std::strcmp(argv[5], "all") == 0;
    const bool save = !(argc >= 6 && std::strcmp(argv[5], "unsaved") == 0);
    const int account = argc == 7 ? std::atoi(argv[6]) : -1;
    try {
        return run(argv[1], c, std::atoi(argv[3]), std::atof(argv[4]), all,
                   save, account);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mooringLineFmuBench: %s\n", e.what());
        return 1;
    }
}
