/*---------------------------------------------------------------------------*\
  foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics
-------------------------------------------------------------------------------
License
    This file is part of foam-fmi-bridge, free software under the GNU General
    Public License version 3 or later (see LICENSE at the project's top).

Description
    Variable handling of connectorFmu: lookup of the interface vocabulary,
    inputs and outputs (parameters: connectorFmuParameters.C).

\*---------------------------------------------------------------------------*/

#include "connectorFmu.H"
#include "error.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::string Foam::connectorFmu::causalityName
(
    const fmuImport::Causality c
)
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
