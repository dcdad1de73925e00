// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorParameters.H"
#include "fmuConnectorSettings.H"
#include "error.H"
#include "OStringStream.H"
#include "Switch.H"
#include "Map.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The tokens of an entry as written, for messages
std::string tokensText(const Foam::ITstream& is)
{
    Foam::OStringStream os;
    forAll(is, i)
    {
        os  << (i ? " " : "") << is[i];
    }
    return os.str();
}


//- The log category in which an FMU names a parameter it refuses, with the
//  form "<name> <code>: <message>" (docs/connector-fmu-interface.md)
const char* const refusedParameterCategory = "refusedParameter";


//- The name a refusedParameter message begins with: the parameter's
//  variable name, or the name of a vector refused as a whole
std::string refusedName(const std::string& message)
{
    return message.substr(0, message.find(' '));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fmuConnectorParameters::fmuConnectorParameters
(
    const fmuImport::Fmu& fmu,
    const dictionary& parameters,
    const word& restraintName,
    const fileName& file,
    const std::string& where
)
:
    fmu_(fmu),
    dict_(parameters),
    restraintName_(restraintName),
    file_(file),
    where_(where)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::vector<unsigned int> Foam::fmuConnectorParameters::refs
(
    const entry& e,
    scalarList& values
) const
{
    const dictionary& parameters = dict_;
    const std::string key(e.keyword());

    if (!e.isStream())
    {
        FatalIOErrorInFunction(parameters)
            << where_.c_str() << "entry '" << key.c_str() << "' is a"
            << " dictionary; a parameter takes a number, or a list of"
            << " numbers for a vector" << exit(FatalIOError);
    }
    const ITstream& is = e.stream();

    // A scalar parameter: one number (or a switch for a Boolean)
    if (fmu_.hasVariable(key))
    {
        const fmuImport::Variable& var = fmu_.variable(key);
        if (var.causality != fmuImport::Causality::parameter)
        {
            FatalIOErrorInFunction(parameters)
                << where_.c_str() << "entry '" << key.c_str()
                << "' names a variable of causality "
                << fmuImport::connector::causalityName(var.causality)
                << "; only parameters can be set here"
                << exit(FatalIOError);
        }
        if (var.type == fmuImport::Type::String)
        {
            FatalIOErrorInFunction(parameters)
                << where_.c_str() << "string parameter '" << key.c_str()
                << "' is not supported" << exit(FatalIOError);
        }

        const bool isBoolean = (var.type == fmuImport::Type::Boolean);
        const bool isInteger =
            var.type == fmuImport::Type::Integer
         || var.type == fmuImport::Type::Enumeration;

        scalar value = 0;
        bool good = (is.size() == 1);
        if (good && is[0].isNumber())
        {
            value = is[0].number();
            good = !isInteger || value == std::round(value);
        }
        else if (good && isBoolean && is[0].isWord())
        {
            #if OPENFOAM >= 2312
            const Switch sw(Switch::find(is[0].wordToken()));
            good = sw.good();
            #else
            const Switch sw(is[0].wordToken(), true);
            good = sw.valid();
            #endif
            value = good && sw ? 1 : 0;
        }
        else
        {
            good = false;
        }

        if (!good)
        {
            FatalIOErrorInFunction(parameters)
                << where_.c_str() << "parameter '" << key.c_str()
                << "' expects "
                << (
                       isBoolean ? "a switch (true/false, on/off, 1/0)"
                     : isInteger ? "one integer"
                     : "one number"
                   )
                << ", got '" << tokensText(is).c_str() << "'"
                << exit(FatalIOError);
        }

        values = scalarList(1, value);
        return {var.valueReference};
    }

    // A vector or matrix parameter given as a list for key[1..n]
    const bool isMatrix = fmu_.hasVariable(key + "[1,1]");
    if (!isMatrix && !fmu_.hasVariable(key + "[1]"))
    {
        wordList names;
        for (const auto& var : fmu_.modelDescription().variables)
        {
            if (var.causality == fmuImport::Causality::parameter)
            {
                names.append(word(var.name, false));
            }
        }
        FatalIOErrorInFunction(parameters)
            << where_.c_str() << "parameter '" << key.c_str()
            << "' is not declared by the FMU; its parameters are "
            << fmuConnectorSettings::listed(names).c_str() << exit(FatalIOError);
    }

    // The elements key[1..n], or key[1..3,1..3]: Real parameters
    std::vector<std::string> elements;
    if (isMatrix)
    {
        elements = fmuImport::connector::componentNames
        (
            key,
            fmuImport::connector::Shape::matrix
        );
    }
    for
    (
        label i = 1;
        !isMatrix && fmu_.hasVariable(key + "[" + std::to_string(i) + "]");
        ++i
    )
    {
        elements.push_back(key + "[" + std::to_string(i) + "]");
    }

    std::vector<unsigned int> refs;
    for (const std::string& element : elements)
    {
        if (!fmu_.hasVariable(element))
        {
            FatalIOErrorInFunction(parameters)
                << where_.c_str() << "declares " << refs.size()
                << " elements of " << key.c_str() << " but not "
                << element.c_str() << exit(FatalIOError);
        }
        const fmuImport::Variable& var = fmu_.variable(element);
        if
        (
            var.type != fmuImport::Type::Real
         || var.causality != fmuImport::Causality::parameter
        )
        {
            FatalIOErrorInFunction(parameters)
                << where_.c_str() << "variable " << element.c_str()
                << " must be a Real parameter, it is declared with causality "
                << fmuImport::connector::causalityName(var.causality)
                << exit(FatalIOError);
        }
        refs.push_back(var.valueReference);
    }

    const bool isList =
        is.size()
     && is[0].isPunctuation()
     && is[0].pToken() == token::BEGIN_LIST;

    if (isList)
    {
        values = parameters.get<scalarList>(e.keyword());
    }
    if (!isList || label(refs.size()) != values.size())
    {
        FatalIOErrorInFunction(parameters)
            << where_.c_str() << "parameter '" << key.c_str()
            << "' expects a list of " << refs.size() << " numbers, "
            << key.c_str() << (isMatrix ? "[1,1] to " : "[1] to ")
            << key.c_str() << "["
            << (isMatrix ? std::string("3,3") : std::to_string(refs.size()))
            .c_str()
            << "] in that order, got '" << tokensText(is).c_str() << "'"
            << exit(FatalIOError);
    }

    return refs;
}


void Foam::fmuConnectorParameters::set(fmuImport::Instance& instance) const
{
    const dictionary& parameters = dict_;
    // Each FMU variable is set by one entry only: 'A.p (...)' and
    // 'A.p[1] ...' together would leave the result to the entries' order
    Map<word> setBy;

    for (const entry& e : parameters)
    {
        scalarList values;
        const std::vector<unsigned int> refs =
            this->refs(e, values);

        for (const unsigned int ref : refs)
        {
            const auto previous = setBy.cfind(label(ref));
            if (previous.found())
            {
                std::string variable;
                for (const auto& var : fmu_.modelDescription().variables)
                {
                    if
                    (
                        var.valueReference == ref
                     && var.causality == fmuImport::Causality::parameter
                    )
                    {
                        variable = var.name;
                    }
                }
                FatalIOErrorInFunction(parameters)
                    << where_.c_str() << "entries '" << *previous
                    << "' and '" << e.keyword() << "' both set the FMU"
                    << " parameter " << variable.c_str() << "; give each"
                    << " parameter once, as a vector or by element"
                    << exit(FatalIOError);
            }
            setBy.insert(label(ref), e.keyword());
        }

        const fmuImport::Variable* var =
            fmu_.hasVariable(e.keyword()) ? &fmu_.variable(e.keyword())
          : nullptr;
        const fmuImport::Type type = var ? var->type : fmuImport::Type::Real;

        switch (type)
        {
            case fmuImport::Type::Integer:
            case fmuImport::Type::Enumeration:
                instance.setInteger(refs, {static_cast<int>(values[0])});
                break;
            case fmuImport::Type::Boolean:
                instance.setBoolean(refs, {values[0] != 0});
                break;
            default:
                instance.setReal
                (
                    refs,
                    std::vector<double>(values.begin(), values.end())
                );
        }
    }
}


void Foam::fmuConnectorParameters::check
(
    const dictionary& restraintDict,
    const scalar startTime
) const
{
    const dictionary& parameters = dict_;
    // A probe instance, gone before the connector's own is made (an FMU
    // may allow one instance per process); with debug logging on, of which
    // it keeps only the name of a refused parameter
    std::string refusal;
    std::string refused;
    {
        fmuImport::Instance probe
        (
            fmu_,
            restraintName_,
            [&refused]
            (
                const std::string&,
                int,
                const std::string& category,
                const std::string& message
            )
            {
                if (category == refusedParameterCategory)
                {
                    refused = refusedName(message);
                }
            },
            true
        );
        probe.setupExperiment(startTime);
        probe.enterInitializationMode();
        set(probe);
        try
        {
            probe.exitInitializationMode();
        }
        catch (const fmuImport::LostCall&)
        {
            // A crash or time-out is no refusal: the restraint's error
            throw;
        }
        catch (const fmuImport::Error& err)
        {
            refusal = err.what();
        }
    }
    if (refusal.empty() || refused.empty())
    {
        return;
    }

    // The refused parameter (an element, A.p[1], or its vector, A.p), and
    // the entry that sets it
    for (const fmuImport::Variable& var : fmu_.modelDescription().variables)
    {
        const std::string base(var.name.substr(0, var.name.find('[')));
        if
        (
            var.causality != fmuImport::Causality::parameter
         || !(refused == var.name || refused == base)
        )
        {
            continue;
        }

        for (const entry& e : parameters)
        {
            const std::string key(e.keyword());
            if (key == var.name || key == base)
            {
                FatalIOErrorInFunction(e.stream())
                    << "restraint " << restraintName_ << ": the FMU refuses"
                    << " parameter '" << e.keyword() << "' ("
                    << file_ << "): " << refusal.c_str()
                    << exit(FatalIOError);
            }
        }

        // Not given here: its start value
        FatalIOErrorInFunction
        (
            parameters.empty() ? restraintDict : parameters
        )   << "restraint " << restraintName_ << ": the FMU refuses the"
            << " start value of its parameter " << base.c_str()
            << ", which the parameters do not set (" << file_ << "): "
            << refusal.c_str() << exit(FatalIOError);
    }
}


void Foam::fmuConnectorParameters::checkRestored
(
    fmuImport::Instance& instance,
    const fileName& source
) const
{
    OStringStream changed;

    auto write = [](Ostream& os, const scalarList& values)
    {
        if (values.size() == 1)
        {
            os  << values[0];
            return;
        }
        os  << '(';
        forAll(values, i)
        {
            os  << (i ? " " : "") << values[i];
        }
        os  << ')';
    };

    for (const entry& e : dict_)
    {
        scalarList given;
        const std::vector<unsigned int> refs =
            this->refs(e, given);

        const fmuImport::Variable* var =
            fmu_.hasVariable(e.keyword()) ? &fmu_.variable(e.keyword())
          : nullptr;
        const fmuImport::Type type = var ? var->type : fmuImport::Type::Real;

        scalarList restored(given.size());
        switch (type)
        {
            case fmuImport::Type::Integer:
            case fmuImport::Type::Enumeration:
                restored[0] = instance.getInteger(refs)[0];
                break;
            case fmuImport::Type::Boolean:
                restored[0] = instance.getBoolean(refs)[0];
                break;
            default:
            {
                const std::vector<double> v = instance.getReal(refs);
                std::copy(v.begin(), v.end(), restored.begin());
            }
        }

        if (restored != given)
        {
            changed
                << nl << "        " << e.keyword() << ' ';
            write(changed, given);
            changed
                << " in the dictionary, ";
            write(changed, restored);
            changed
                << " in the restored state";
        }
    }

    if (!changed.str().empty())
    {
        WarningInFunction
            << where_.c_str() << "parameters differ from the state the run"
            << " restarts from (" << source << "):"
            << changed.str().c_str() << nl
            << "    The FMU continues with the restored values; to apply the"
            << " dictionary's values, start the connector anew with"
            << " 'restart fresh;' in restraint " << restraintName_ << endl;
    }
}


// ************************************************************************* //
