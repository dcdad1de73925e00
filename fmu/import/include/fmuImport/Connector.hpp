// fmuImport: the connector FMU interface (docs/connector-fmu-interface.md):
// its vocabulary, and a connector FMU's variables resolved against it.
// Part of the importer's public interface (fmuImport.hpp includes every
// part), C++11 like the rest of it.
#ifndef FMUIMPORT_CONNECTOR_HPP
#define FMUIMPORT_CONNECTOR_HPP

#include "fmuImport/Fmu.hpp"
#include "fmuImport/ModelDescription.hpp"
#include <string>
#include <vector>

namespace fmuImport {

// The connector FMU interface (docs/connector-fmu-interface.md) as every
// importer of connectors sees it: the vocabulary of interface variables with
// their rules, and a connector FMU's variables resolved against it. fmusim
// check reports what departs from it; the OpenFOAM bridge refuses such an
// FMU; both from the same list.
namespace connector {

enum class Shape { scalar, vector, matrix };
enum class Requirement { always, twoBody, optional };

// One name of the interface: base "A.r" with shape vector stands for
// A.r[1], A.r[2], A.r[3].
struct Term {
    std::string base;
    Shape shape;
    Causality causality;
    Variability variability;
    std::vector<std::string>
        units; // accepted units; the first is the documented one
    Requirement requirement;
};

// Every term of the interface: A's, B's, then the diagnostics.
const std::vector<Term>& vocabulary();

// The scalar names of a term: "A.r[1]".."A.r[3]", "A.R[1,1]".."A.R[3,3]".
std::vector<std::string> componentNames(const std::string& base, Shape shape);

// "input", "fixed", ...: the names modelDescription.xml uses.
const char* causalityName(Causality c);
const char* variabilityName(Variability v);

// One way in which a connector FMU departs from the vocabulary.
struct Problem {
    enum class Kind {
        missing, // a component of a required term, or of an optional term
        // of which other components are declared
        type, // not Real (FMI 3.0: not Float64)
        causality,
        variability,
        unit,
        // FMI 3.0: the term's variable has other dimensions than its
        // shape's ("A.r is an array of dimensions [4], expected an array
        // of dimensions [3]"); variable is the term's base, and its other
        // problems are not looked for
        dimensions
    };
    Kind kind;
    bool required; // a problem of a term the FMU must declare
    const Term* term; // into vocabulary()
    std::string variable; // the component: "A.r[2]"
    std::string text; // "missing A.r[2]", "A.F[1] has unit 'kN', expected 'N'"
};

// A connector FMU's interface variables. It is a two-body connector when it
// declares an input of B; a term counts as declared when all its components
// are declared Real variables. It follows the interface when problems() is
// empty.
class Variables {
public:
    explicit Variables(const Fmu& fmu);

    bool twoBody() const { return twoBody_; }
    bool required(const Term& term) const;

    // Value references of a term's components, in componentNames() order,
    // when it is declared; empty otherwise (also for a name that is not a
    // term).
    const std::vector<unsigned int>& refs(const std::string& base) const;
    bool declared(const std::string& base) const { return !refs(base).empty(); }

    // The required terms not declared ("A.F", ...): empty for a usable
    // connector.
    std::vector<std::string> missingRequired() const;

    // In vocabulary order, each term's components in order.
    const std::vector<Problem>& problems() const { return problems_; }

private:
    bool twoBody_;
    std::vector<std::vector<unsigned int>> refs_; // by vocabulary() index
    std::vector<Problem> problems_;
};

} // namespace connector

} // namespace fmuImport

#endif
