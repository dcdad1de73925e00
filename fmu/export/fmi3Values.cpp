// The fmi3 get and set functions of every connector FMU. Float64 and
// Boolean variables, a vector or matrix as one array value reference
// (nValues counts the elements, row-major); the other types are declared by
// no connector, and any value reference given for them is refused.
#include <vector>

#include "EntryPoints3.hpp"
#include "fmi3Functions.h"

namespace {

using fmuExport::Fmi3Instance;
using fmuExport::guarded3;
using fmuExport::readableState;
using fmuExport::writableState;
using Elements = std::vector<fmi2ValueReference>;

//- values[k]: the table's Boolean elements as fmi3Boolean
void getBooleans(fmuExport::FmuInstance& core, const Elements& e,
                 fmi3Boolean values[])
{
    std::vector<fmi2Boolean> b(e.size());
    core.getBoolean(e.data(), e.size(), b.data());
    for (std::size_t k = 0; k < b.size(); ++k) {
        values[k] = b[k] != fmi2False;
    }
}

//- The Boolean variables are constants: FmuInstance refuses every one
void setBooleans(fmuExport::FmuInstance& core, const Elements& e,
                 const fmi3Boolean[])
{
    core.setBoolean(e.data(), e.size());
}

} // namespace

extern "C" {

// The types the connectors declare: `call` with `core` (the instance's
// FmuInstance), `e` (the table's value references of the elements) and
// `values`
#define FMU_EXPORT_VALUES(Type, mask, Values, call)                            \
    fmi3Status fmi3##Type(                                                     \
        fmi3Instance instance, const fmi3ValueReference valueReferences[],     \
        size_t nValueReferences, Values values, size_t nValues)                \
    {                                                                          \
        return guarded3(instance, "fmi3" #Type, mask, [&](Fmi3Instance& i) {   \
            fmuExport::FmuInstance& core = i.core();                           \
            const Elements& e                                                  \
                = i.elements(valueReferences, nValueReferences, nValues);      \
            call;                                                              \
        });                                                                    \
    }

FMU_EXPORT_VALUES(GetFloat64, readableState, fmi3Float64*,
                  core.getReal(e.data(), e.size(), values))
FMU_EXPORT_VALUES(SetFloat64, writableState, const fmi3Float64*,
                  core.setReal(e.data(), e.size(), values))
FMU_EXPORT_VALUES(GetBoolean, readableState, fmi3Boolean*,
                  getBooleans(core, e, values))
FMU_EXPORT_VALUES(SetBoolean, writableState, const fmi3Boolean*,
                  setBooleans(core, e, values))

// The types no connector declares: every value reference is refused
#define FMU_EXPORT_NO_VARIABLES(Type, mask, ...)                               \
    fmi3Status fmi3##Type(fmi3Instance instance,                               \
                          const fmi3ValueReference valueReferences[],          \
                          size_t nValueReferences, __VA_ARGS__)                \
    {                                                                          \
        return guarded3(instance, "fmi3" #Type, mask, [&](Fmi3Instance& i) {   \
            i.core().rejectValueReferences(#Type + 3, valueReferences,         \
                                           nValueReferences);                  \
        });                                                                    \
    }

FMU_EXPORT_NO_VARIABLES(GetFloat32, readableState, fmi3Float32[], size_t)
FMU_EXPORT_NO_VARIABLES(GetInt8, readableState, fmi3Int8[], size_t)
FMU_EXPORT_NO_VARIABLES(GetUInt8, readableState, fmi3UInt8[], size_t)
FMU_EXPORT_NO_VARIABLES(GetInt16, readableState, fmi3Int16[], size_t)
FMU_EXPORT_NO_VARIABLES(GetUInt16, readableState, fmi3UInt16[], size_t)
FMU_EXPORT_NO_VARIABLES(GetInt32, readableState, fmi3Int32[], size_t)
FMU_EXPORT_NO_VARIABLES(GetUInt32, readableState, fmi3UInt32[], size_t)
FMU_EXPORT_NO_VARIABLES(GetInt64, readableState, fmi3Int64[], size_t)
FMU_EXPORT_NO_VARIABLES(GetUInt64, readableState, fmi3UInt64[], size_t)
FMU_EXPORT_NO_VARIABLES(GetString, readableState, fmi3String[], size_t)
FMU_EXPORT_NO_VARIABLES(GetBinary, readableState, size_t[], fmi3Binary[],
                        size_t)
FMU_EXPORT_NO_VARIABLES(GetClock, readableState, fmi3Clock[])
FMU_EXPORT_NO_VARIABLES(SetFloat32, writableState, const fmi3Float32[], size_t)
FMU_EXPORT_NO_VARIABLES(SetInt8, writableState, const fmi3Int8[], size_t)
FMU_EXPORT_NO_VARIABLES(SetUInt8, writableState, const fmi3UInt8[], size_t)
FMU_EXPORT_NO_VARIABLES(SetInt16, writableState, const fmi3Int16[], size_t)
FMU_EXPORT_NO_VARIABLES(SetUInt16, writableState, const fmi3UInt16[], size_t)
FMU_EXPORT_NO_VARIABLES(SetInt32, writableState, const fmi3Int32[], size_t)
FMU_EXPORT_NO_VARIABLES(SetUInt32, writableState, const fmi3UInt32[], size_t)
FMU_EXPORT_NO_VARIABLES(SetInt64, writableState, const fmi3Int64[], size_t)
FMU_EXPORT_NO_VARIABLES(SetUInt64, writableState, const fmi3UInt64[], size_t)
FMU_EXPORT_NO_VARIABLES(SetString, writableState, const fmi3String[], size_t)
FMU_EXPORT_NO_VARIABLES(SetBinary, writableState, const size_t[],
                        const fmi3Binary[], size_t)
FMU_EXPORT_NO_VARIABLES(SetClock, writableState, const fmi3Clock[])

} // extern "C"
