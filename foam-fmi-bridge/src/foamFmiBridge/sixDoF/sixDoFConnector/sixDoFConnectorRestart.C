// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

// sixDoFConnector at a restart: the restraints of the copy of the motion
// the run restarts from compared with the case's own dictionary

#include "sixDoFConnector.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- An entry's value as text, numbers at the precision of written files
//  (the copy holds the case's numbers at that precision)
std::string valueText(const Foam::entry& e)
{
    Foam::OStringStream os;
    os.precision(Foam::IOstream::defaultPrecision());
    if (e.isDict())
    {
        os  << e.dict();
        return os.str();
    }
    const Foam::ITstream& is = e.stream();
    forAll(is, i)
    {
        os  << (i ? " " : "");
        if (is[i].isNumber())
        {
            os  << is[i].number();
        }
        else
        {
            os  << is[i];
        }
    }
    return os.str();
}


//- Lines "key: <case> in the case's dictionary, <copy> in the restored
//  copy" for every entry of the case's dictionary that differs from the
//  copy; parameters entry by entry, both ways
void differences
(
    const Foam::dictionary& caseDict,
    const Foam::dictionary& copy,
    const std::string& prefix,
    std::string& out
)
{
    for (const Foam::entry& e : caseDict)
    {
        const Foam::word& key = e.keyword();
        const Foam::entry* c = copy.findEntry(key, Foam::keyType::LITERAL);
        if (key == "parameters" && e.isDict() && c && c->isDict())
        {
            differences(e.dict(), c->dict(), prefix + key + '.', out);
            continue;
        }
        const std::string given(valueText(e));
        const std::string restored(c ? valueText(*c) : "nothing");
        if (given != restored)
        {
            out +=
                "\n        " + prefix + key + ": " + given
              + " in the case's dictionary, " + restored
              + " in the restored copy";
        }
    }
    if (prefix.size())
    {
        // A parameter removed from the case's dictionary
        for (const Foam::entry& c : copy)
        {
            if (!caseDict.found(c.keyword(), Foam::keyType::LITERAL))
            {
                out +=
                    "\n        " + prefix + c.keyword()
                  + ": nothing in the case's dictionary, " + valueText(c)
                  + " in the restored copy";
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::sixDoFConnector::compareWithCase
(
    const dictionary& caseDict,
    const fileName& caseFile,
    const fileName& copyFile
)
{
    if (compared_ || !Pstream::master())
    {
        return;
    }
    compared_ = true;

    std::string changed;
    differences(caseDict, dict_, "", changed);
    if (changed.empty())
    {
        return;
    }

    WarningInFunction
        << "restraint " << name_ << ": the run restarts from " << copyFile
        << ", the copy of the motion written by the earlier run, which"
        << " holds the restraint as it was; the case's dictionary "
        << caseFile << " differs:" << changed.c_str() << nl
        << "    The connector continues with the restored copy's entries;"
        << " to apply the case's, edit them in " << copyFile
        << " (with 'restart fresh;' in the restraint when the FMU's state"
        << " carries its parameters)" << endl;
}


void Foam::sixDoFConnector::compareRestraints
(
    const dictionary& caseRestraints,
    const dictionary& copyRestraints,
    const fileName& caseFile,
    const fileName& copyFile
)
{
    std::string changed;

    // Added to the case: not constructed, as OpenFOAM reads the copy
    for (const entry& e : caseRestraints)
    {
        if (e.isDict() && !copyRestraints.isDict(e.keyword()))
        {
            changed +=
                "\n        " + e.keyword() + " (added): in the case's"
                " dictionary, not in the restored copy, so not applied";
        }
    }

    for (const entry& c : copyRestraints)
    {
        if (!c.isDict())
        {
            continue;
        }
        if (!caseRestraints.isDict(c.keyword()))
        {
            changed +=
                "\n        " + c.keyword() + " (removed): in the restored"
                " copy, not in the case's dictionary, so still applied";
        }
        else if
        (
            c.dict().getOrDefault<word>("sixDoFRigidBodyMotionRestraint", word::null)
         != "fmuConnector"
        )
        {
            // A connector's own entries are compared by the connector
            differences
            (
                caseRestraints.subDict(c.keyword()),
                c.dict(),
                c.keyword() + '.',
                changed
            );
        }
    }

    if (changed.empty())
    {
        return;
    }

    WarningInFunction
        << "the run restarts from " << copyFile << ", the copy of the"
        << " motion written by the earlier run, which holds the restraints"
        << " as they were; those of the case's dictionary " << caseFile
        << " differ:" << changed.c_str() << nl
        << "    The run continues with the restored copy's restraints; to"
        << " apply the case's, edit them in " << copyFile << endl;
}


// ************************************************************************* //
