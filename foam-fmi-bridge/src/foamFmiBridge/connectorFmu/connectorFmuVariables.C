/*---------------------------------------------------------------------------*\
  foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics
-------------------------------------------------------------------------------
License
    This file is part of foam-fmi-bridge, free software under the GNU General
    Public License version 3 or later (see LICENSE at the project's top).

Description
    Variable handling of connectorFmu: lookup of the interface vocabulary,
    parameters, inputs and outputs.

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

std::string causalityName(const fmuImport::Causality c)
{
    switch (c)
    {
        case fmuImport::Causality::parameter: return "parameter";
        case fmuImport::Causality::calculatedParameter:
            return "calculatedParameter";
        case fmuImport::Causality::input: return "input";
        case fmuImport::Causality::output: return "output";
        case fmuImport::Causality::local: return "local";
        case fmuImport::Causality::independent: return "independent";
    }
    return "unknown";
}


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

std::vector<unsigned int> Foam::connectorFmu::vectorRefs
(
    const std::string& name,
    const label n,
    const std::string& causality,
    const std::string& unit
) const
{
    std::vector<unsigned int> refs;

    const bool matrix = (n == 9);
    const label nRows = matrix ? 3 : n;
    const label nCols = matrix ? 3 : 1;

    for (label i = 1; i <= nRows; ++i)
    {
        for (label j = 1; j <= nCols; ++j)
        {
            const std::string element =
                name + "[" + std::to_string(i)
              + (matrix ? "," + std::to_string(j) : std::string()) + "]";

            if (!fmu_->hasVariable(element))
            {
                if (refs.empty())
                {
                    return refs;
                }
                FatalErrorInFunction
                    << where().c_str() << "declares " << refs.size()
                    << " elements of " << name.c_str() << " but not " << element.c_str()
                    << exit(FatalError);
            }

            const fmuImport::Variable& var = fmu_->variable(element);

            if
            (
                var.type != fmuImport::Type::Real
             || causalityName(var.causality) != causality
            )
            {
                FatalErrorInFunction
                    << where().c_str() << "variable " << element.c_str()
                    << " must be a Real " << causality
                    << ", it is declared with causality "
                    << causalityName(var.causality)
                    << exit(FatalError);
            }

            // The interface fixes the units; an FMU in other units would
            // put loads off by a factor without any other sign
            if (!unit.empty() && var.unit != unit)
            {
                FatalErrorInFunction
                    << where().c_str() << "variable " << element.c_str()
                    << " has unit '" << var.unit.c_str()
                    << "'; the connector interface expects '" << unit.c_str()
                    << "' (docs/connector-fmu-interface.md)"
                    << exit(FatalError);
            }

            refs.push_back(var.valueReference);
        }
    }

    return refs;
}


void Foam::connectorFmu::lookupVariables()
{
    auto lookupBody = [this](const std::string& body, bodyVariables& vars)
    {
        vars.r = vectorRefs(body + ".r", 3, "input", "m");
        vars.R = vectorRefs(body + ".R", 9, "input", "1");
        vars.v = vectorRefs(body + ".v", 3, "input", "m/s");
        vars.omega = vectorRefs(body + ".omega", 3, "input", "rad/s");
        vars.F = vectorRefs(body + ".F", 3, "output", "N");
        vars.M = vectorRefs(body + ".M", 3, "output", "N.m");
    };

    lookupBody("A", A_);
    lookupBody("B", B_);

    // Required: the A inputs and loads; for a two-body connector the same
    // for B (docs/connector-fmu-interface.md)
    auto require = [this]
    (
        const std::vector<unsigned int>& refs,
        const char* name,
        const char* role
    )
    {
        if (refs.empty())
        {
            FatalErrorInFunction
                << where().c_str() << "the connector interface requires the "
                << role << " " << name << " but the FMU does not declare it"
                << exit(FatalError);
        }
    };

    require(A_.r, "A.r[1..3]", "input");
    require(A_.R, "A.R[1..3,1..3]", "input");
    require(A_.F, "A.F[1..3]", "output");
    require(A_.M, "A.M[1..3]", "output");

    if (declaresBodyB())
    {
        require(B_.R, "B.R[1..3,1..3]", "input");
        require(B_.F, "B.F[1..3]", "output");
        require(B_.M, "B.M[1..3]", "output");
    }

    for (const bodyVariables* vars : {&A_, &B_})
    {
        for (const auto* refs : {&vars->r, &vars->R, &vars->v, &vars->omega})
        {
            inputRefs_.insert(inputRefs_.end(), refs->begin(), refs->end());
        }
    }
    inputValues_.resize(inputRefs_.size());

    for (const fmuImport::Variable& var : fmu_->modelDescription().variables)
    {
        if
        (
            var.causality == fmuImport::Causality::output
         && var.type == fmuImport::Type::Real
        )
        {
            outputNames_.append(word(var.name, false));
            outputRefs_.push_back(var.valueReference);
        }
    }
    outputs_.setSize(outputNames_.size(), Zero);

    // Positions of the loads among the outputs
    auto positions = [this](const std::vector<unsigned int>& refs)
    {
        std::vector<label> pos;
        for (const unsigned int ref : refs)
        {
            pos.push_back
            (
                std::find(outputRefs_.begin(), outputRefs_.end(), ref)
              - outputRefs_.begin()
            );
        }
        return pos;
    };

    for (bodyVariables* vars : {&A_, &B_})
    {
        vars->Fout = positions(vars->F);
        vars->Mout = positions(vars->M);
    }
}


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


void Foam::connectorFmu::setInputs
(
    const kinematics& A,
    const kinematics& B
)
{
    // In the order of inputRefs_ (lookupVariables); OpenFOAM's tensor
    // stores its components row by row, as A.R[i,j] does
    double* value = inputValues_.data();
    auto add = [&value](const std::vector<unsigned int>& refs, const double* v)
    {
        value = std::copy(v, v + refs.size(), value);
    };

    for (const auto& body : {std::make_pair(&A_, &A), std::make_pair(&B_, &B)})
    {
        add(body.first->r, body.second->r.cdata());
        add(body.first->R, body.second->R.cdata());
        add(body.first->v, body.second->v.cdata());
        add(body.first->omega, body.second->omega.cdata());
    }

    if (!inputRefs_.empty())
    {
        instance_->setReal(inputRefs_, inputValues_);
    }
    if (!massRefs_.empty())
    {
        instance_->setReal(massRefs_, massValues_);
    }
}


void Foam::connectorFmu::setMassProperties
(
    const massProperties& A,
    const massProperties& B,
    const bool setB
)
{
    massRefs_.clear();
    massValues_.clear();

    auto add = [this](const std::vector<unsigned int>& refs, const double* v)
    {
        massRefs_.insert(massRefs_.end(), refs.begin(), refs.end());
        massValues_.insert(massValues_.end(), v, v + refs.size());
    };

    for (const char* body : {"A", "B"})
    {
        if (body[0] == 'B' && !setB)
        {
            break;
        }
        const massProperties& p = (body[0] == 'A') ? A : B;
        const std::string prefix(body);

        if (fmu_->hasVariable(prefix + ".m"))
        {
            const fmuImport::Variable& var = fmu_->variable(prefix + ".m");
            if
            (
                var.type != fmuImport::Type::Real
             || causalityName(var.causality) != "input"
             || var.unit != "kg"
            )
            {
                FatalErrorInFunction
                    << where().c_str() << "variable " << prefix.c_str()
                    << ".m must be a Real input in kg"
                    << " (docs/connector-fmu-interface.md)" << exit(FatalError);
            }
            add({var.valueReference}, &p.m);
        }
        add(vectorRefs(prefix + ".c", 3, "input", "m"), p.c.cdata());
        add(vectorRefs(prefix + ".J", 9, "input", "kg.m2"), p.J.cdata());
    }
}


void Foam::connectorFmu::readOutputs()
{
    const std::vector<double> values = instance_->getReal(outputRefs_);

    forAll(outputs_, i)
    {
        if (!std::isfinite(values[i]))
        {
            FatalErrorInFunction
                << where().c_str() << "output " << outputNames_[i]
                << " is not finite (" << values[i] << ") at t = "
                << stepEndTime_ << exit(FatalError);
        }
        outputs_[i] = values[i];
    }
}


Foam::connectorFmu::loads Foam::connectorFmu::loadsOf
(
    const bodyVariables& vars
) const
{
    loads l{Zero, Zero};

    for (size_t i = 0; i < vars.Fout.size(); ++i)
    {
        l.F[i] = outputs_[vars.Fout[i]];
        l.M[i] = outputs_[vars.Mout[i]];
    }

    return l;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::connectorFmu::output
(
    const word& name,
    const scalar deflt
) const
{
    const label i = outputNames_.find(name);
    return i < 0 ? deflt : outputs_[i];
}


// ************************************************************************* //
