// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
//
// What a connector tells the user when it starts: the FMU it loaded and
// the value of every parameter it uses, given in the case or the FMU's
// default (a parameter left out silently takes the default otherwise).

#include "fmuConnectorCore.H"
#include "Map.H"

#include <sstream>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fmuConnectorCore::reportSetup(fmuImport::Instance& instance) const
{
    const fmuImport::ModelDescription& md = fmu_->modelDescription();

    // The value references the case's entries set
    Map<bool> given;
    for (const entry& e : parameters_)
    {
        scalarList values;
        for (const unsigned int ref : parameterRefs(parameters_, e, values))
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


// ************************************************************************* //
