// The behavioural part of `fmusim check`: probes that drive instances of a
// connector FMU with random and special kinematics.
#ifndef FMUSIM_CHECK_CHECKPROBES_HPP
#define FMUSIM_CHECK_CHECKPROBES_HPP

#include "check/Check.hpp"
#include "io/ConnectorIo.hpp"

#include <functional>
#include <random>

namespace fmusim {

struct ProbeOptions {
    unsigned int seed = 1;
    int samples = 20; // random configurations
    double stepSize = 1e-3; // communication step of every probe [s]
    bool verbose = false; // print the FMU's log messages
};

// Runs every probe, handing each result to report as soon as it is known.
void runProbes(const fmuImport::Fmu& fmu, const ConnectorIo& connector,
               const ProbeOptions& options,
               const std::function<void(const CheckResult&)>& report);

} // namespace fmusim

#endif
