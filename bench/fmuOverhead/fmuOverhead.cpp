// fmuOverhead [<unzipped linearSpring FMU directory>]
//
// Cost of one communication step of linearSpring.fmu through its C API
// (fmi2SetReal of the 36 inputs, fmi2DoStep, fmi2GetReal of the 17 outputs)
// against one direct connectors::LinearSpring::evaluate, measured in the
// same run on the same inputs. The two are timed alternately, several runs
// of many cycles each (steady_clock), and each figure is its best run, to
// damp noise from other load on the machine.
#include <dlfcn.h>

#include <pugixml.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "fmi2Functions.h"
#include "linearSpring/LinearSpring.hpp"

namespace {

constexpr int cycles = 200000;
constexpr int repetitions = 7;

using Clock = std::chrono::steady_clock;

void quietLogger(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String,
                 fmi2String message, ...)
{
    std::fprintf(stderr, "fmu: %s\n", message);
}

template <class Function> Function* symbol(void* library, const char* name)
{
    void* s = dlsym(library, name);
    if (s == nullptr) {
        std::fprintf(stderr, "fmuOverhead: missing %s\n", name);
        std::exit(1);
    }
    return reinterpret_cast<Function*>(s);
}

//- Time per cycle [ns] of `body(i)` over one run of `cycles` cycles
template <class Body> double nanosecondsPerCycle(Body&& body)
{
    const Clock::time_point start = Clock::now();
    for (int i = 0; i < cycles; ++i) {
        body(i);
    }
    const std::chrono::duration<double, std::nano> elapsed
        = Clock::now() - start;
    return elapsed.count() / cycles;
}

} // namespace

int main(int argc, char** argv)
{
    const std::string dir = argc > 1 ? argv[1] : FOAMFMI_STAGED_SPRING;
    pugi::xml_document xml;
    if (!xml.load_file((dir + "/modelDescription.xml").c_str())) {
        std::fprintf(stderr,
                     "fmuOverhead: cannot read %s/modelDescription.xml\n",
                     dir.c_str());
        return 1;
    }
    const pugi::xml_node root = xml.child("fmiModelDescription");
    std::vector<fmi2ValueReference> in, out;
    std::vector<std::string> inputNames;
    std::map<std::string, fmi2ValueReference> vr;
    for (const pugi::xml_node v :
         root.child("ModelVariables").children("ScalarVariable")) {
        const std::string causality = v.attribute("causality").value();
        vr[v.attribute("name").value()]
            = v.attribute("valueReference").as_uint();
        if (causality == "input") {
            in.push_back(v.attribute("valueReference").as_uint());
            inputNames.push_back(v.attribute("name").value());
        } else if (causality == "output") {
            out.push_back(v.attribute("valueReference").as_uint());
        }
    }

    void* lib
        = dlopen((dir + "/binaries/linux64/linearSpring.so").c_str(), RTLD_NOW);
    if (lib == nullptr) {
        std::fprintf(stderr, "fmuOverhead: %s\n", dlerror());
        return 1;
    }
    auto instantiate = symbol<fmi2InstantiateTYPE>(lib, "fmi2Instantiate");
    auto enterInit = symbol<fmi2EnterInitializationModeTYPE>(
        lib, "fmi2EnterInitializationMode");
    auto exitInit = symbol<fmi2ExitInitializationModeTYPE>(
        lib, "fmi2ExitInitializationMode");
    auto setReal = symbol<fmi2SetRealTYPE>(lib, "fmi2SetReal");
    auto getReal = symbol<fmi2GetRealTYPE>(lib, "fmi2GetReal");
    auto doStep = symbol<fmi2DoStepTYPE>(lib, "fmi2DoStep");
    auto freeInstance = symbol<fmi2FreeInstanceTYPE>(lib, "fmi2FreeInstance");

    // Same configuration for both: rotated bodies, offset attachment
    // points, moving bodies, damping on.
    connectors::LinearSpringParameters p;
    p.p_AoP_A = {0.1, -0.2, 0.3};
    p.p_BoQ_B = {-0.4, 0.05, 0.2};
    p.stiffness = 250.0;
    p.restLength = 0.7;
    p.damping = 15.0;
    connectors::BodyKinematics A, B;
    A.p_WKo_W = {0.2, -0.4, 1.1};
    A.R_WK = Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, -2, 0.5).normalized())
                 .toRotationMatrix();
    A.v_WKo_W = {0.3, 0.1, -0.2};
    A.w_WK_W = {0.05, -0.3, 0.2};
    B.p_WKo_W = {1.9, 0.7, 0.4};
    B.R_WK = Eigen::AngleAxisd(-1.3, Eigen::Vector3d(0.2, 1, 1).normalized())
                 .toRotationMatrix();
    B.v_WKo_W = {-0.6, 0.4, 0.25};
    B.w_WK_W = {-0.1, 0.2, 0.4};

    fmi2CallbackFunctions callbacks {quietLogger, nullptr, nullptr, nullptr,
                                     nullptr};
    const fmi2Component c
        = instantiate("bench", fmi2CoSimulation, root.attribute("guid").value(),
                      "", &callbacks, fmi2False, fmi2False);
    if (c == nullptr || enterInit(c) != fmi2OK) {
        return 1;
    }
    const std::map<std::string, double> parameters
        = {{"A.p[1]", 0.1},      {"A.p[2]", -0.2},    {"A.p[3]", 0.3},
           {"B.p[1]", -0.4},     {"B.p[2]", 0.05},    {"B.p[3]", 0.2},
           {"stiffness", 250.0}, {"restLength", 0.7}, {"damping", 15.0}};
    for (const auto& [name, value] : parameters) {
        setReal(c, &vr.at(name), 1, &value);
    }
    if (exitInit(c) != fmi2OK) {
        return 1;
    }

    // Input vector in the FMU's declaration order (A.r, A.R, A.v, A.omega,
    // B...)
    std::vector<double> inputs;
    for (const connectors::BodyKinematics* k : {&A, &B}) {
        inputs.insert(inputs.end(), k->p_WKo_W.data(), k->p_WKo_W.data() + 3);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                inputs.push_back(k->R_WK(i, j));
            }
        }
        inputs.insert(inputs.end(), k->v_WKo_W.data(), k->v_WKo_W.data() + 3);
        inputs.insert(inputs.end(), k->w_WK_W.data(), k->w_WK_W.data() + 3);
    }
    if (inputs.size() != in.size() || inputNames.front() != "A.r[1]") {
        std::fprintf(stderr, "fmuOverhead: unexpected input layout\n");
        return 1;
    }
    const std::size_t xIndex = 18; // B.r[1]: A has 3 + 9 + 3 + 3 inputs

    std::vector<double> outputs(out.size());
    double checksum = 0.0;
    double t = 0.0;
    const double h = 1e-3;
    const auto fmiCycle = [&](int i) {
        inputs[xIndex] = 1.9 + 1e-7 * i;
        setReal(c, in.data(), in.size(), inputs.data());
        if (doStep(c, t, h, fmi2True) != fmi2OK) {
            std::exit(1);
        }
        t += h;
        getReal(c, out.data(), out.size(), outputs.data());
        checksum += outputs[0];
    };
    const connectors::LinearSpring law(p);
    const auto lawCycle = [&](int i) {
        B.p_WKo_W[0] = 1.9 + 1e-7 * i;
        const connectors::ConnectorResult r = law.evaluate(A, B);
        checksum += r.A.f_W[0];
    };
    // Alternate the two so that both see the same load from other
    // processes; keep the best run of each.
    double fmiNs = 1e300, lawNs = 1e300;
    for (int r = 0; r < repetitions; ++r) {
        fmiNs = std::min(fmiNs, nanosecondsPerCycle(fmiCycle));
        lawNs = std::min(lawNs, nanosecondsPerCycle(lawCycle));
    }
    freeInstance(c);
    dlclose(lib);

    std::printf("fmuOverhead: linearSpring, best of %d runs of %d cycles\n",
                repetitions, cycles);
    std::printf(
        "  direct: LinearSpring::evaluate                    %8.1f ns\n",
        lawNs);
    std::printf(
        "  FMI:    SetReal(%zu) + DoStep + GetReal(%zu)        %8.1f ns\n",
        in.size(), out.size(), fmiNs);
    std::printf("  ratio FMI / direct                                %8.2f\n",
                fmiNs / lawNs);
    std::printf("  (checksum %.6g)\n", checksum);
    return 0;
}
