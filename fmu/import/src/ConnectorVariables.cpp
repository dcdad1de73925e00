// The connector FMU interface's vocabulary and a connector FMU's variables
// resolved against it (fmuImport.hpp, namespace connector).
#include "fmuImport/fmuImport.hpp"

#include <algorithm>

namespace fmuImport {
namespace connector {

const std::vector<Term>& vocabulary()
{
    using C = Causality;
    using V = Variability;
    using R = Requirement;
    static const std::vector<Term> terms = [] {
        std::vector<Term> all;
        auto add = [&all](const std::string& base, Shape shape, C causality,
                          std::vector<std::string> units, R requirement) {
            all.push_back({base, shape, causality,
                           causality == C::parameter ? V::fixed : V::continuous,
                           std::move(units), requirement});
        };
        for (const std::string body : {"A", "B"}) {
            const R core = body == "A" ? R::always : R::twoBody;
            add(body + ".r", Shape::vector, C::input, {"m"}, core);
            // A rotation matrix has no other unit: none declared is as good
            add(body + ".R", Shape::matrix, C::input, {"1", ""}, core);
            add(body + ".v", Shape::vector, C::input, {"m/s"}, R::optional);
            add(body + ".omega", Shape::vector, C::input, {"rad/s"},
                R::optional);
            add(body + ".m", Shape::scalar, C::input, {"kg"}, R::optional);
            add(body + ".c", Shape::vector, C::input, {"m"}, R::optional);
            add(body + ".J", Shape::matrix, C::input, {"kg.m2"}, R::optional);
            add(body + ".F", Shape::vector, C::output, {"N"}, core);
            add(body + ".M", Shape::vector, C::output, {"N.m"}, core);
            add(body + ".p", Shape::vector, C::parameter, {"m"}, R::optional);
        }
        add("length", Shape::scalar, C::output, {"m"}, R::optional);
        add("lengthRate", Shape::scalar, C::output, {"m/s"}, R::optional);
        add("tension", Shape::scalar, C::output, {"N"}, R::optional);
        add("potentialEnergy", Shape::scalar, C::output, {"J"}, R::optional);
        add("dissipatedPower", Shape::scalar, C::output, {"W"}, R::optional);
        return all;
    }();
    return terms;
}

std::vector<std::string> componentNames(const std::string& base, Shape shape)
{
    if (shape == Shape::scalar)
        return {base};
    std::vector<std::string> names;
    for (int i = 1; i <= 3; ++i) {
        if (shape == Shape::vector) {
            names.push_back(base + "[" + std::to_string(i) + "]");
            continue;
        }
        for (int j = 1; j <= 3; ++j)
            names.push_back(base + "[" + std::to_string(i) + ","
                            + std::to_string(j) + "]");
    }
    return names;
}

const char* causalityName(Causality c)
{
    static const char* const names[]
        = {"parameter",   "calculatedParameter", "input", "output", "local",
           "independent", "structuralParameter"};
    return names[static_cast<int>(c)];
}

const char* variabilityName(Variability v)
{
    static const char* const names[]
        = {"constant", "fixed", "tunable", "discrete", "continuous"};
    return names[static_cast<int>(v)];
}

namespace {

std::string dimensionsText(const std::vector<std::size_t>& dimensions)
{
    std::string text = "[";
    for (std::size_t d = 0; d < dimensions.size(); ++d)
        text += (d ? ", " : "") + std::to_string(dimensions[d]);
    return text + "]";
}

const char* shapeText(Shape shape)
{
    return shape == Shape::scalar ? "a scalar"
        : shape == Shape::vector  ? "an array of dimensions [3]"
                                  : "an array of dimensions [3, 3] (row-major)";
}

// FMI 3.0: how a term's variable departs from the term's shape (A.r a
// Float64 array of dimensions [3], A.R [3, 3], A.m a scalar), or empty.
std::string shapeProblem(const Fmu& fmu, const Term& term)
{
    const std::vector<std::size_t> expected = term.shape == Shape::scalar
        ? std::vector<std::size_t>()
        : term.shape == Shape::vector ? std::vector<std::size_t> {3}
                                      : std::vector<std::size_t> {3, 3};
    const char* what = shapeText(term.shape);
    const std::vector<std::size_t>* declared = nullptr;
    const Variable* found = nullptr;
    for (const Variable& v : fmu.modelDescription().variables) {
        if (v.arrayName == term.base) {
            declared = &v.dimensions;
            found = &v;
            break;
        }
        if (v.name == term.base && v.arrayName.empty()) {
            found = &v;
            break;
        }
    }
    if (!found)
        return std::string();
    const std::vector<std::size_t> none;
    const std::vector<std::size_t>& has = declared ? *declared : none;
    if (has == expected)
        return std::string();
    return term.base + " is "
        + (declared ? "an array of dimensions " + dimensionsText(has)
                    : std::string("a scalar"))
        + ", expected " + what;
}

} // namespace

Variables::Variables(const Fmu& fmu) : twoBody_(false)
{
    const bool v3 = fmu.modelDescription().fmiMajorVersion == 3;
    for (const Variable& v : fmu.modelDescription().variables)
        if (v.causality == Causality::input && v.name.compare(0, 2, "B.") == 0)
            twoBody_ = true;

    for (const Term& term : vocabulary()) {
        const std::vector<std::string> names
            = componentNames(term.base, term.shape);

        std::vector<unsigned int> refs;
        for (const std::string& name : names) {
            if (!fmu.hasVariable(name)
                || fmu.variable(name).type != Type::Real) {
                refs.clear();
                break;
            }
            refs.push_back(fmu.variable(name).valueReference);
        }
        refs_.push_back(refs);

        const bool isRequired = required(term);
        auto problem = [&](Problem::Kind kind, const std::string& name,
                           const std::string& text) {
            problems_.push_back({kind, isRequired, &term, name, text});
        };
        if (v3) {
            // One FMI 3.0 variable per term: its dimensions first
            const std::string wrongShape = shapeProblem(fmu, term);
            if (!wrongShape.empty()) {
                refs_.back().clear();
                problem(Problem::Kind::dimensions, term.base, wrongShape);
                continue;
            }
        }
        const bool anyDeclared = std::any_of(
            names.begin(), names.end(),
            [&](const std::string& n) { return fmu.hasVariable(n); });
        if (!anyDeclared && !isRequired)
            continue;
        if (v3 && !anyDeclared) {
            problem(Problem::Kind::missing, term.base,
                    "missing " + term.base + ": expected an "
                        + causalityName(term.causality) + " Float64 "
                        + term.base + ", " + shapeText(term.shape));
            continue;
        }

        for (const std::string& name : names) {
            if (!fmu.hasVariable(name)) {
                problem(Problem::Kind::missing, name,
                        isRequired ? "missing " + name
                                   : name
                                + " is missing while other "
                                  "components of "
                                + term.base + " are declared");
                continue;
            }
            const Variable& v = fmu.variable(name);
            if (v.type != Type::Real)
                problem(Problem::Kind::type, name, name + " is not Real");
            else if (v3 && v.typeName != "Float64")
                problem(Problem::Kind::type, name,
                        name + " is " + v.typeName + ", expected Float64");
            if (v.causality != term.causality)
                problem(Problem::Kind::causality, name,
                        name + " has causality " + causalityName(v.causality)
                            + ", expected " + causalityName(term.causality));
            if (v.variability != term.variability)
                problem(Problem::Kind::variability, name,
                        name + " has variability "
                            + variabilityName(v.variability) + ", expected "
                            + variabilityName(term.variability));
            if (std::find(term.units.begin(), term.units.end(), v.unit)
                == term.units.end())
                problem(Problem::Kind::unit, name,
                        name + " has unit '" + v.unit + "', expected '"
                            + term.units.front() + "'");
        }
    }
}

bool Variables::required(const Term& term) const
{
    return term.requirement == Requirement::always
        || (term.requirement == Requirement::twoBody && twoBody_);
}

const std::vector<unsigned int>& Variables::refs(const std::string& base) const
{
    static const std::vector<unsigned int> none;
    const std::vector<Term>& terms = vocabulary();
    for (std::size_t i = 0; i < terms.size(); ++i)
        if (terms[i].base == base)
            return refs_[i];
    return none;
}

std::vector<std::string> Variables::missingRequired() const
{
    std::vector<std::string> missing;
    const std::vector<Term>& terms = vocabulary();
    for (std::size_t i = 0; i < terms.size(); ++i)
        if (required(terms[i]) && refs_[i].empty())
            missing.push_back(terms[i].base);
    return missing;
}

} // namespace connector
} // namespace fmuImport
