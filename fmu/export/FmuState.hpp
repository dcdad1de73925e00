// Saved FMU states (fmi2GetFMUstate) and their serialized form.
//
// Serialized bytes: a fixed header (magic "FOAMFMI", format version, GUID of
// the FMU, instance state, time, number of values) followed by the value
// array as native doubles; for a model with internal state (Model::
// internalState) then its number of values (uint64) and the values. The
// bytes of a model without internal state end after the value array, as
// they always have. Bytes with another magic, version, GUID or size
// are rejected with a message saying which.
#ifndef FMU_EXPORT_FMUSTATE_HPP
#define FMU_EXPORT_FMUSTATE_HPP

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace fmuExport {

//- States of an instance (bit flags, so that a set of states is a mask)
enum ModelState : unsigned {
    instantiated = 1u << 0,
    initializationMode = 1u << 1,
    stepComplete = 1u << 2,
    terminated = 1u << 3,
    error = 1u << 4,
    fatal = 1u << 5,
};

//- "instantiated", "initializationMode", ...
const char* stateName(ModelState state);

//- "instantiated or initializationMode" for a mask of states
std::string stateNames(unsigned mask);

//- Misuse by the caller (wrong state, bad value reference, foreign state):
//  fmi2Error, and the instance keeps its state
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

//- Everything an instance needs to return to a saved point
struct SavedState {
    ModelState state = instantiated;
    double time = 0.0;
    bool outputsValid = false;
    std::vector<double> values;
    //- The model's internal state (Model::internalState), often empty
    std::vector<double> internal;
};

//- Size in bytes of the serialized form of a state with n values and
//  m internal values
std::size_t serializedSize(std::size_t valueCount,
                           std::size_t internalCount = 0);

//- Writes `state` into `buffer` (size serializedSize(values.size(),
//  internal.size()))
void serializeState(const SavedState& state, const std::string& guid,
                    char* buffer, std::size_t size);

//- Reads bytes written by serializeState for the FMU with `guid` and
//  `valueCount` values; throws UsageError for anything else
SavedState deserializeState(const char* bytes, std::size_t size,
                            const std::string& guid, std::size_t valueCount);

} // namespace fmuExport

#endif
