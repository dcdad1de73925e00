// Options of `fmusim twobody`, from a `key = value` configuration file
// and/or `--key value` on the command line (the command line wins).
#ifndef FMUSIM_TWOBODY_TWOBODYCONFIG_HPP
#define FMUSIM_TWOBODY_TWOBODYCONFIG_HPP

#include "twobody/RigidBody.hpp"
#include "io/Settings.hpp"

#include <optional>
#include <string>
#include <vector>

namespace fmusim {

enum class Scheme { explicitEuler, implicitTrapezoidal };

struct TwoBodyConfig {
    std::string fmuPath;
    double startTime = 0, stopTime = 10, stepSize = 1e-3; // [s]
    Scheme scheme = Scheme::explicitEuler;
    Eigen::Vector3d gravity = Eigen::Vector3d::Zero(); // [m/s2]
    Body A, B;
    bool bMotionGiven
        = false; // else B is free for a two-body connector, the world otherwise
    std::string outputFile; // empty: standard output
    int writeEvery = 1; // write every n-th step
    double couplingTolerance = 1e-10; // implicit: relative change of the loads
    int maxCouplingIterations = 50;
    double initialRelaxation
        = 0.5; // implicit: first Aitken factor of each step
    std::vector<Setting> fmuSettings; // --set, --parameters
    bool logging = false;
    double timeout
        = 0; // the longest one call into the FMU may take [s], 0: no limit
    fmuImport::Isolation isolation
        = fmuImport::Isolation::none; // where the FMU runs
};

// The configuration keys, for the help text and the option parser.
const std::vector<std::string>& twoBodyKeys();

// args: everything after "twobody".
TwoBodyConfig parseTwoBodyConfig(const std::vector<std::string>& args);

} // namespace fmusim

#endif
