// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

// sixDoF fmuConnector at a restart: the restraints of the copy of the
// motion the run restarts from compared with the case's own dictionary

#include "sixDoFFmuConnector.H"
#include "Time.H"
#include "IFstream.H"
#include "restartFiles.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- At a restart from a motion dictionary written by an earlier run (the
//  file top, at the start time): the case's own copy of that file,
//  constant/<name> (sixDoFSim's constant/sixDoFBodies) or else the file in
//  the case's earliest time directory (the point-patch condition's
//  0/pointDisplacement); empty when there is none or top is it
Foam::fileName caseFileOf(const Foam::regIOobject& top)
{
    using namespace Foam;

    const Time& runTime = top.time();
    if (!restartFiles::restarted(runTime, top.instance()))
    {
        return fileName::null;
    }

    fileName file(runTime.path()/runTime.constant()/top.name());
    if (!isFile(file))
    {
        file.clear();
        for (const instant& t : Time::findTimes(runTime.path()))
        {
            const fileName f(runTime.path()/t.name()/top.local()/top.name());
            if (file.empty() && t.name() != runTime.constant() && isFile(f))
            {
                file = f;
            }
        }
    }
    return file == top.objectPath() ? fileName::null : file;
}


//- The restraint dictionary at the same place in another dictionary of the
//  same file (the keys from top down to dict), or nullptr
const Foam::dictionary* samePlace
(
    const Foam::dictionary& top,
    const Foam::dictionary& dict,
    const Foam::dictionary& other
)
{
    Foam::wordList keys;
    for
    (
        const Foam::dictionary* d = &dict;
        d != &top && d != &Foam::dictionary::null;
        d = &d->parent()
    )
    {
        keys.append(d->dictName());
    }

    const Foam::dictionary* found = &other;
    forAllReverse(keys, i)
    {
        found =
            found->isDict(keys[i]) ? &found->subDict(keys[i]) : nullptr;
        if (!found)
        {
            break;
        }
    }
    return found;
}


//- The first fmuConnector restraint of a restraints dictionary
Foam::word firstConnector(const Foam::dictionary& restraints)
{
    for (const Foam::entry& e : restraints)
    {
        if
        (
            e.isDict()
         && e.dict().getOrDefault<Foam::word>
            (
                "sixDoFRigidBodyMotionRestraint",
                Foam::word::null
            ) == "fmuConnector"
        )
        {
            return e.keyword();
        }
    }
    return Foam::word::null;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::sixDoFRigidBodyMotionRestraints::fmuConnector::compareWithCase
(
    const regIOobject& top,
    const dictionary& topDict,
    const dictionary& sDoFRBMRDict
) const
{
    const Time& runTime = top.time();
    const fileName caseFile(caseFileOf(top));
    if (caseFile.size())
    {
        // Read as a field file is read (its header sets the format: binary
        // lists); a file that does not read is not compared
        const bool throwing = FatalError.throwExceptions();
        const bool ioThrowing = FatalIOError.throwExceptions();
        try
        {
            IFstream is(caseFile);
            IOobject header(caseFile.name(), runTime.timeName(), runTime);
            const dictionary caseDict
            (
                header.readHeader(is) ? dictionary(is) : dictionary()
            );
            const dictionary* caseRestraint =
                samePlace(topDict, sDoFRBMRDict, caseDict);
            if (caseRestraint)
            {
                connector_->compareWithCase
                (
                    *caseRestraint,
                    caseFile,
                    top.objectPath()
                );
            }

            // Every restraint of the body, once: by its first connector
            const dictionary& copyRestraints = sDoFRBMRDict.parent();
            const dictionary* caseRestraints =
                samePlace(topDict, copyRestraints, caseDict);
            if (caseRestraints && firstConnector(copyRestraints) == name_)
            {
                sixDoFConnector::compareRestraints
                (
                    *caseRestraints,
                    copyRestraints,
                    caseFile,
                    top.objectPath()
                );
            }
        }
        catch (const Foam::error& err)
        {
            Info<< "Restraint " << name_ << ": " << caseFile << " does not"
                << " read, so it is not compared with the copy the run"
                << " restarts from: " << err.message().c_str() << endl;
        }
        FatalError.throwExceptions(throwing);
        FatalIOError.throwExceptions(ioThrowing);
    }
}


// ************************************************************************* //
