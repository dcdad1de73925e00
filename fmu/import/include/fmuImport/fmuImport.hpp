// fmuImport: load an FMI 2.0 or FMI 3.0 co-simulation FMU and drive its
// instances.
//
// Public interface, C++11 (it is included by OpenFOAM code built with
// -std=c++11); the implementation is C++17. Every failure throws
// fmuImport::Error with a message naming the FMU file and the variable,
// function or archive entry involved.
//
// One header per part, each included here: MaskFpTraps.hpp (the host's
// floating-point traps around FMU calls), Error.hpp (Error, LostCall),
// ModelDescription.hpp (variables and capabilities), Reports.hpp (reports
// of calls that do not come back, the ending hook), Fmu.hpp (an FMU
// loaded, isolation, SHA-256), Instance.hpp (an instance and its calls),
// Connector.hpp (the connector interface's vocabulary).
#ifndef FMUIMPORT_FMUIMPORT_HPP
#define FMUIMPORT_FMUIMPORT_HPP

#include "fmuImport/MaskFpTraps.hpp"
#include "fmuImport/Error.hpp"
#include "fmuImport/ModelDescription.hpp"
#include "fmuImport/Reports.hpp"
#include "fmuImport/Fmu.hpp"
#include "fmuImport/Instance.hpp"
#include "fmuImport/Connector.hpp"

#endif
