// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Description
    Variable handling of fmuConnectorCore: its interface variables by
    fmuImport's vocabulary, inputs and outputs (parameters:
    fmuConnectorParameters; a line's variables: fmuConnectorLine).
\*---------------------------------------------------------------------------*/

#include "fmuConnectorCore.H"
#include "error.H"
#include "OStringStream.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fmuConnectorCore::lookupVariables()
{
    variables_.reset(new fmuImport::connector::Variables(*fmu_));

    // The FMU follows the interface as fmusim check has it, or is refused
    // with every departure; a required term not declared at all takes one
    // line, not one per component
    namespace connector = fmuImport::connector;
    OStringStream problems;
    const connector::Term* undeclared = nullptr;
    for (const connector::Problem& p : variables_->problems())
    {
        const connector::Term& term = *p.term;
        const std::vector<std::string> names
        (
            connector::componentNames(term.base, term.shape)
        );
        const bool noneDeclared = std::none_of
        (
            names.begin(),
            names.end(),
            [this](const std::string& n) { return fmu_->hasVariable(n); }
        );

        if (p.required && noneDeclared)
        {
            if (&term != undeclared)
            {
                undeclared = &term;
                problems
                    << nl << "    the connector interface requires the "
                    << connector::causalityName(term.causality) << ' '
                    << term.base.c_str()
                    << (
                           term.shape == connector::Shape::scalar ? ""
                         : term.shape == connector::Shape::vector ? "[1..3]"
                         : "[1..3,1..3]"
                       )
                    << " but the FMU does not declare it";
            }
        }
        else
        {
            problems<< nl << "    " << p.text.c_str();
        }
    }
    if (!problems.str().empty())
    {
        FatalErrorInFunction
            << where().c_str() << "the FMU does not follow the connector"
            << " interface (docs/connector-fmu-interface.md), as fmusim check"
            << " reports it:" << problems.str().c_str()
            << exit(FatalError);
    }

    auto lookupBody = [this](const std::string& body, bodyVariables& vars)
    {
        const fmuImport::connector::Variables& found = variables_();
        vars.r = found.refs(body + ".r");
        vars.R = found.refs(body + ".R");
        vars.v = found.refs(body + ".v");
        vars.omega = found.refs(body + ".omega");
        vars.m = found.refs(body + ".m");
        vars.c = found.refs(body + ".c");
        vars.J = found.refs(body + ".J");
    };

    lookupBody("A", A_);
    lookupBody("B", B_);

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
    auto positions = [this](const std::string& term)
    {
        const std::vector<unsigned int>& refs = variables_->refs(term);
        labelList pos(refs.size());
        forAll(pos, i)
        {
            pos[i] =
                std::find(outputRefs_.begin(), outputRefs_.end(), refs[i])
              - outputRefs_.begin();
        }
        return pos;
    };

    A_.Fout = positions("A.F");
    A_.Mout = positions("A.M");
    B_.Fout = positions("B.F");
    B_.Mout = positions("B.M");

    line_.lookup(outputNames_, fmu_(), where());
}


void Foam::fmuConnectorCore::setInputs
(
    const kinematics& A,
    const kinematics& B
)
{
    // In the order of inputRefs_ (lookupVariables); OpenFOAM's tensor
    // stores its components row by row, as A.R[i,j] does. An FMU declares
    // all of a term's components or none (fmuImport::ConnectorVariables);
    // each is copied on its own, as a library call (memmove) for each
    // block would cost more than the copy
    double* value = inputValues_.data();
    auto add = [&value](const std::vector<unsigned int>& refs, const auto& x)
    {
        using Type = std::decay_t<decltype(x)>;
        if (!refs.empty())
        {
            for (direction c = 0; c < pTraits<Type>::nComponents; ++c)
            {
                *value++ = x[c];
            }
        }
    };

    for (const auto& body : {std::make_pair(&A_, &A), std::make_pair(&B_, &B)})
    {
        add(body.first->r, body.second->r);
        add(body.first->R, body.second->R);
        add(body.first->v, body.second->v);
        add(body.first->omega, body.second->omega);
    }

    if (!inputRefs_.empty())
    {
        instance_->setReal(inputRefs_, inputValues_);
    }
    if (!massRefs_.empty())
    {
        instance_->setReal(massRefs_, massValues_);
    }
    line_.setInputs(*instance_);
}


void Foam::fmuConnectorCore::setMassProperties
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

    add(A_.m, &A.m);
    add(A_.c, A.c.cdata());
    add(A_.J, A.J.cdata());
    if (setB)
    {
        add(B_.m, &B.m);
        add(B_.c, B.c.cdata());
        add(B_.J, B.J.cdata());
    }
}


void Foam::fmuConnectorCore::readOutputs()
{
    const std::vector<double>& values = outputValues_;
    instance_->getReal(outputRefs_, outputValues_);

    // Checked in one pass; the output to name is searched for only when
    // one is not finite
    bool finite = true;
    for (const double v : values)
    {
        finite &= std::isfinite(v);
    }
    if (!finite)
    {
        forAll(outputs_, i)
        {
            if (!std::isfinite(values[i]))
            {
                FatalErrorInFunction
                    << where().c_str() << "output " << outputNames_[i]
                    << " is not finite (" << values[i] << ") at t = "
                    << stepEndTime_ << exit(FatalError);
            }
        }
    }
    std::copy(values.cbegin(), values.cend(), outputs_.begin());
    line_.readOutputs(*instance_);
}


Foam::fmuConnectorCore::loads Foam::fmuConnectorCore::loadsOf
(
    const bodyVariables& vars
) const
{
    loads l{Zero, Zero};

    forAll(vars.Fout, i)
    {
        l.F[i] = outputs_[vars.Fout[i]];
        l.M[i] = outputs_[vars.Mout[i]];
    }

    return l;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fmuConnectorCore::output
(
    const word& name,
    const scalar deflt
) const
{
    const label i = outputNames_.find(name);
    return i < 0 ? deflt : outputs_[i];
}


void Foam::fmuConnectorCore::setFlow(const vectorField& U)
{
    line_.setFlow(U, where());
}


void Foam::fmuConnectorCore::setAcceleration(const vectorField& a)
{
    line_.setAcceleration(a, where());
}


void Foam::fmuConnectorCore::setStartKinematics
(
    const std::function<std::pair<kinematics, kinematics>()>& start
)
{
    startKinematics_ = start;
}


Foam::pointField Foam::fmuConnectorCore::startShapePoints()
{
    if
    (
        initialised_
     || !restoreBytes_.empty()
     || !startKinematics_
     || line_.nPoints() == 0
    )
    {
        return pointField();
    }

    const std::pair<kinematics, kinematics> start(startKinematics_());
    const fmuImport::MaskFpTraps masked;
    try
    {
        // Still in initialisation mode: the outputs of the start shape
        setInputs(start.first, start.second);
        readOutputs();
    }
    catch (const fmuImport::Error& err)
    {
        FatalErrorInFunction
            << "restraint " << restraintName_ << ", the start shape: "
            << err.what() << exit(FatalError);
    }
    return line_.points(outputs_);
}


void Foam::fmuConnectorCore::writeDiagnostics(Ostream& os) const
{
    for (const word diagnostic : {"length", "tension"})
    {
        if (outputNames_.found(diagnostic))
        {
            os  << ' ' << diagnostic << ' ' << output(diagnostic, 0);
        }
    }
    os  << " (global frame; each moment about its body's reference point,"
        << " the world's about the origin)";
}


// ************************************************************************* //
