// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
//
// What a connector tells the user when it starts: the FMU it loaded and
// the value of every parameter it uses, given in the case or the FMU's
// default (a parameter left out silently takes the default otherwise);
// and, at its first evaluation, where the bodies are: each body's
// reference point (rigidBodyMotion: the origin of the body's frame, which
// its transform sets; sixDoF: the centre of rotation) and its attachment
// point, global coordinates, so that a point given in the wrong frame or
// from the wrong origin shows at once.

#include "fmuConnectorCore.H"
#include "Map.H"

#include <sstream>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fmuConnectorCore::reportSetup(fmuImport::Instance& instance) const
{
    const fmuImport::ModelDescription& md = fmu_->modelDescription();

    // The value references the case's entries set
    Map<bool> given;
    for (const entry& e : parameters_->dict())
    {
        scalarList values;
        for (const unsigned int ref : parameters_->refs(e, values))
        {
            given.set(label(ref), true);
        }
    }

    // The parameters in the FMU's order, the elements of a vector ("A.p[1]",
    // "A.p[2]", ...) as one line
    struct line
    {
        std::string name;
        fmuImport::Type type;
        std::vector<unsigned int> refs;
        bool given = false;
    };
    std::vector<line> lines;
    for (const fmuImport::Variable& var : md.variables)
    {
        if
        (
            var.causality != fmuImport::Causality::parameter
         || var.type == fmuImport::Type::String
        )
        {
            continue;
        }
        const std::string::size_type bracket = var.name.rfind('[');
        const std::string name
        (
            bracket != std::string::npos && var.name.back() == ']'
          ? var.name.substr(0, bracket) : var.name
        );
        if (lines.empty() || lines.back().name != name)
        {
            lines.push_back({name, var.type, {}, false});
        }
        lines.back().refs.push_back(var.valueReference);
        lines.back().given =
            lines.back().given || given.found(label(var.valueReference));
    }

    Info<< "Restraint " << restraintName_ << ": FMU " << file_ << " (FMI "
        << md.fmiVersion.c_str() << ", " << md.modelName.c_str()
        << ", SHA-256 " << fmuImport::fileSha256(file_).c_str() << ")"
        << nl;
    for (const line& l : lines)
    {
        std::vector<double> values;
        switch (l.type)
        {
            case fmuImport::Type::Integer:
            case fmuImport::Type::Enumeration:
                for (const int v : instance.getInteger(l.refs))
                {
                    values.push_back(v);
                }
                break;
            case fmuImport::Type::Boolean:
                for (const bool v : instance.getBoolean(l.refs))
                {
                    values.push_back(v);
                }
                break;
            default:
                values = instance.getReal(l.refs);
        }
        std::ostringstream text;
        text.precision(12);
        if (values.size() == 1)
        {
            text << values[0];
        }
        else
        {
            text << '(';
            for (std::size_t i = 0; i < values.size(); ++i)
            {
                text << (i ? " " : "") << values[i];
            }
            text << ')';
        }
        Info<< "    " << l.name.c_str() << ' ' << text.str().c_str()
            << (l.given ? "" : "  (not given: the FMU's default)") << nl;
    }
    Info<< endl;
}


void Foam::fmuConnectorCore::reportStart
(
    const kinematics& A,
    const kinematics& B
) const
{
    Info<< "Restraint " << restraintName_ << ": the bodies at its first"
        << " evaluation, global coordinates (a body's reference point: the"
        << " origin of its frame; under sixDoF the centre of rotation; the"
        << " world's: the origin)" << nl;

    const kinematics* bodies[2] = {&A, &B};
    forAll(bodyNames_, i)
    {
        const kinematics& body = *bodies[i];
        const std::string side(i == 0 ? "A" : "B");
        Info<< "    body " << side.c_str() << ' ' << bodyNames_[i]
            << ": reference point " << body.r;

        // The attachment, where the FMU declares one
        std::vector<unsigned int> refs;
        for (label d = 1; d <= 3; ++d)
        {
            const std::string name(side + ".p[" + std::to_string(d) + ']');
            if (fmu_->hasVariable(name))
            {
                refs.push_back(fmu_->variable(name).valueReference);
            }
        }
        if (refs.size() == 3)
        {
            const std::vector<double> p(instance_->getReal(refs));
            const vector local(p[0], p[1], p[2]);
            Info<< ", attachment " << side.c_str() << ".p " << local
                << " (its frame) at " << (body.r + (body.R & local));
        }
        Info<< nl;
    }
    Info<< endl;
}


// ************************************************************************* //
