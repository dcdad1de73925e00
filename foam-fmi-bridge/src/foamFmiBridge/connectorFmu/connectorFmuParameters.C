/*---------------------------------------------------------------------------*\
  foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics
-------------------------------------------------------------------------------
License
    This file is part of foam-fmi-bridge, free software under the GNU General
    Public License version 3 or later (see LICENSE at the project's top).

Description
    Parameters of connectorFmu: the dictionary's entries checked against
    what the FMU declares and set, and compared with a restored state.

\*---------------------------------------------------------------------------*/

#include "connectorFmu.H"
#include "error.H"
#include "OStringStream.H"
#include "Switch.H"

#include <algorithm>
#include <cmath>
#include <map>

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

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::vector<unsigned int> Foam::connectorFmu::parameterRefs
(
    const dictionary& parameters,
    const entry& e,
    scalarList& values
) const
{
    const std::string key(e.keyword());

    if (!e.isStream())
    {
        FatalIOErrorInFunction(parameters)
            << where().c_str() << "entry '" << key.c_str() << "' is a"
            << " dictionary; a parameter takes a number, or a list of"
            << " numbers for a vector" << exit(FatalIOError);
    }
    const ITstream& is = e.stream();

    // A scalar parameter: one number (or a switch for a Boolean)
    if (fmu_->hasVariable(key))
    {
        const fmuImport::Variable& var = fmu_->variable(key);
        if (var.causality != fmuImport::Causality::parameter)
        {
            FatalIOErrorInFunction(parameters)
                << where().c_str() << "entry '" << key.c_str()
                << "' names a variable of causality "
                << causalityName(var.causality)
                << "; only parameters can be set here"
                << exit(FatalIOError);
        }
        if (var.type == fmuImport::Type::String)
        {
            FatalIOErrorInFunction(parameters)
                << where().c_str() << "string parameter '" << key.c_str()
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
            const Switch sw(is[0].wordToken(), true);
            good = sw.valid();
            value = good && sw ? 1 : 0;
        }
        else
        {
            good = false;
        }

        if (!good)
        {
            FatalIOErrorInFunction(parameters)
                << where().c_str() << "parameter '" << key.c_str()
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
    const bool isMatrix = fmu_->hasVariable(key + "[1,1]");
    if (!isMatrix && !fmu_->hasVariable(key + "[1]"))
    {
        wordList names;
        for (const auto& var : fmu_->modelDescription().variables)
        {
            if (var.causality == fmuImport::Causality::parameter)
            {
                names.append(word(var.name, false));
            }
        }
        FatalIOErrorInFunction(parameters)
            << where().c_str() << "parameter '" << key.c_str()
            << "' is not declared by the FMU; its parameters are "
            << names << exit(FatalIOError);
    }

    label nDeclared = 9;
    if (!isMatrix)
    {
        nDeclared = 0;
        while
        (
            fmu_->hasVariable(key + "[" + std::to_string(nDeclared + 1) + "]")
        )
        {
            ++nDeclared;
        }
    }
    const std::vector<unsigned int> refs =
        vectorRefs(key, nDeclared, "parameter", "");

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
            << where().c_str() << "parameter '" << key.c_str()
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


void Foam::connectorFmu::setParameters(const dictionary& parameters)
{
    // Each FMU variable is set by one entry only: 'A.p (...)' and
    // 'A.p[1] ...' together would leave the result to the entries' order
    std::map<unsigned int, word> setBy;

    for (const entry& e : parameters)
    {
        scalarList values;
        const std::vector<unsigned int> refs =
            parameterRefs(parameters, e, values);

        for (const unsigned int ref : refs)
        {
            const auto previous = setBy.find(ref);
            if (previous != setBy.end())
            {
                std::string variable;
                for (const auto& var : fmu_->modelDescription().variables)
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
                    << where().c_str() << "entries '" << previous->second
                    << "' and '" << e.keyword() << "' both set the FMU"
                    << " parameter " << variable.c_str() << "; give each"
                    << " parameter once, as a vector or by element"
                    << exit(FatalIOError);
            }
            setBy.emplace(ref, e.keyword());
        }

        const fmuImport::Variable* var =
            fmu_->hasVariable(e.keyword()) ? &fmu_->variable(e.keyword())
          : nullptr;
        const fmuImport::Type type = var ? var->type : fmuImport::Type::Real;

        switch (type)
        {
            case fmuImport::Type::Integer:
            case fmuImport::Type::Enumeration:
                instance_->setInteger(refs, {static_cast<int>(values[0])});
                break;
            case fmuImport::Type::Boolean:
                instance_->setBoolean(refs, {values[0] != 0});
                break;
            default:
                instance_->setReal
                (
                    refs,
                    std::vector<double>(values.begin(), values.end())
                );
        }
    }
}


void Foam::connectorFmu::checkRestoredParameters() const
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

    for (const entry& e : parameters_)
    {
        scalarList given;
        const std::vector<unsigned int> refs =
            parameterRefs(parameters_, e, given);

        const fmuImport::Variable* var =
            fmu_->hasVariable(e.keyword()) ? &fmu_->variable(e.keyword())
          : nullptr;
        const fmuImport::Type type = var ? var->type : fmuImport::Type::Real;

        scalarList restored(given.size());
        switch (type)
        {
            case fmuImport::Type::Integer:
            case fmuImport::Type::Enumeration:
                restored[0] = instance_->getInteger(refs)[0];
                break;
            case fmuImport::Type::Boolean:
                restored[0] = instance_->getBoolean(refs)[0];
                break;
            default:
            {
                const std::vector<double> v = instance_->getReal(refs);
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
            << where().c_str() << "parameters differ from the state the run"
            << " restarts from (" << restoreSource_ << "):"
            << changed.str().c_str() << nl
            << "    The FMU continues with the restored values; to apply the"
            << " dictionary's values, start the connector anew with"
            << " 'restart fresh;' in restraint " << restraintName_ << endl;
    }
}


// ************************************************************************* //
