// Compiled as C++11 with -pedantic-errors: the importer's public header must
// build in OpenFOAM's wmake (g++ -std=c++11).
#include "fmuImport/fmuImport.hpp"

#if __cplusplus != 201103L
#error "this translation unit must be compiled as C++11"
#endif

namespace {

fmuImport::Variable exampleVariable()
{
    fmuImport::Variable v;
    v.name = "A.F[1]";
    v.causality = fmuImport::Causality::output;
    return v;
}

} // namespace

bool fmuImportHeaderIsCxx11()
{
    return exampleVariable().causality == fmuImport::Causality::output;
}
