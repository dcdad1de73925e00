// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "sixDoFFmuConnector.H"
#include "sixDoFRigidBodyMotion.H"
#include "regIOobject.H"
#include "Time.H"
#include "wordRes.H"
#include "fmuConnectorCore.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace sixDoFRigidBodyMotionRestraints
{
    defineTypeNameAndDebug(fmuConnector, 0);

    addToRunTimeSelectionTable
    (
        sixDoFRigidBodyMotionRestraint,
        fmuConnector,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The dictionary of the motion that holds the restraint dictionary
//  (restraint -> restraints -> motion; a sixDoFRigidBodyMotionCoeffs
//  sub-dictionary of a motion solver's dictionary counts as the solver's)
const Foam::dictionary& motionDict(const Foam::dictionary& restraintDict)
{
    return restraintDict.parent().parent();
}


//- The name of the body a motion dictionary moves
Foam::word motionName(const Foam::dictionary& motion)
{
    if
    (
        motion.dictName() == "sixDoFRigidBodyMotionCoeffs"
     && &motion.parent() != &Foam::dictionary::null
    )
    {
        return motion.parent().dictName();
    }
    return motion.dictName();
}


//- Whether a dictionary is a motion's: it, or its sub-dictionary
//  sixDoFRigidBodyMotionCoeffs, has a mass and a momentOfInertia
bool isMotion(const Foam::dictionary& dict)
{
    const Foam::dictionary& coeffs =
        dict.optionalSubDict("sixDoFRigidBodyMotionCoeffs");
    return
        coeffs.found("mass", Foam::keyType::LITERAL)
     && coeffs.found("momentOfInertia", Foam::keyType::LITERAL);
}


//- The names of the motion's own body: the name of its dictionary (unless
//  that is a copy of sixDoFRigidBodyMotionCoeffs, which names nothing) and
//  the patches it moves (a sixDoFRigidBodyMotion solver's)
Foam::wordList ownBodyNames(const Foam::dictionary& motion)
{
    Foam::wordList names;
    const Foam::word name(motionName(motion));
    if (name != "sixDoFRigidBodyMotionCoeffs")
    {
        names.append(name);
    }
    if (motion.found("patches", Foam::keyType::LITERAL))
    {
        for (const Foam::wordRe& patch : motion.get<Foam::wordRes>("patches"))
        {
            if (patch.isLiteral() && !names.found(patch))
            {
                names.append(patch);
            }
        }
    }
    return names;
}


//- The dictionary of the body a motion moves: the motion's, or its
//  parent's for a sixDoFRigidBodyMotionCoeffs sub-dictionary
const Foam::dictionary& bodyDict(const Foam::dictionary& motion)
{
    return
        motion.dictName() == "sixDoFRigidBodyMotionCoeffs"
     && &motion.parent() != &Foam::dictionary::null
      ? motion.parent() : motion;
}


//- The bodies of the case a restraint in the motion can name: the motions
//  beside it in the dictionary that holds it (the patches of
//  pointDisplacement's boundaryField with a sixDoF condition, the solvers
//  of dynamicMotionSolverListFvMesh, sixDoFSim's bodies) by their keywords,
//  with the motion's own names (where it is a copy, only those)
Foam::wordList caseBodyNames(const Foam::dictionary& motion)
{
    using namespace Foam;

    const dictionary& body = bodyDict(motion);

    wordList names;
    if (&body.parent() != &dictionary::null)
    {
        for (const entry& e : body.parent())
        {
            if (e.isDict() && isMotion(e.dict()))
            {
                names.append(e.keyword());
            }
        }
    }
    for (const word& name : ownBodyNames(motion))
    {
        if (!names.found(name))
        {
            names.append(name);
        }
    }
    return names;
}


//- FatalIOError unless the restraint's entry key names one of the valid
//  bodies; which those are is said in the message
void checkBody
(
    const Foam::word& restraintName,
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::wordList& valid,
    const char* which
)
{
    using namespace Foam;

    const bool given = dict.found(key, keyType::LITERAL);
    const word body(given ? dict.get<word>(key) : word::null);
    if (given && valid.found(body))
    {
        return;
    }
    FatalIOErrorInFunction(dict)
        << "restraint " << restraintName << ": entry " << key;
    if (given)
    {
        FatalIOError<< " names " << body << ", which is not a body of the case";
    }
    else
    {
        FatalIOError<< " is missing";
    }
    FatalIOError
        << ". A sixDoF body is named by its motion: the patch of its"
        << " sixDoFRigidBodyDisplacement condition, the solver's name in"
        << " dynamicMotionSolverListFvMesh, a patch a sixDoFRigidBodyMotion"
        << " solver moves. " << which << ": "
        << (valid.empty() ? string("none found") : fmuConnectorCore::listed(valid)).c_str()
        << exit(FatalIOError);
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sixDoFRigidBodyMotionRestraints::fmuConnector::fmuConnector
(
    const word& name,
    const dictionary& sDoFRBMRDict
)
:
    sixDoFRigidBodyMotionRestraint(name, sDoFRBMRDict),
    side_(0)
{
    read(sDoFRBMRDict);

    // The case's time: the motion dictionary is part of a file of the case
    // (a field's boundary condition, dynamicMeshDict, a solver's
    // dictionary of dynamicMotionSolverListFvMesh): the nearest enclosing
    // dictionary that is a registered object
    const regIOobject* top = nullptr;
    const dictionary* topDict = nullptr;
    for
    (
        const dictionary* d = &sDoFRBMRDict;
        !top && d != &dictionary::null && d != &d->parent();
        d = &d->parent()
    )
    {
        top = dynamic_cast<const regIOobject*>(d);
        topDict = d;
    }
    if (!top)
    {
        if (!bodyB_.empty())
        {
            FatalIOErrorInFunction(sDoFRBMRDict)
                << "restraint " << name_ << ": a connector between two"
                << " sixDoF bodies needs each body moved by its own"
                << " sixDoFRigidBodyDisplacement patch condition (the"
                << " restraint in the patch's dictionary of"
                << " pointDisplacement); in a sixDoFRigidBodyMotion solver"
                << " only a connector to the fixed world is supported"
                << " (docs/sixdof-connectors.md)" << exit(FatalIOError);
        }
        // Loaded at the first evaluation, which knows the time
        return;
    }
    const Time& runTime = top->db().time();

    const dictionary& motion = motionDict(sDoFRBMRDict);
    const word motionBody = motionName(motion);
    fmuConnectorCore::kinematics start(fmuConnectorCore::kinematics::world());
    fmuConnectorCore::massProperties mass{0, Zero, Zero};

    if (!bodyB_.empty())
    {
        if (motionBody == body_)
        {
            side_ = 0;
        }
        else if (motionBody == bodyB_)
        {
            side_ = 1;
        }
        else
        {
            FatalIOErrorInFunction(sDoFRBMRDict)
                << "restraint " << name_ << " connects " << body_ << " and "
                << bodyB_ << " but is in the motion of " << motionBody
                << ". A sixDoF body is named by the dictionary of its"
                << " motion: the patch of a sixDoFRigidBodyDisplacement"
                << " condition, the solver's name in"
                << " dynamicMotionSolverListFvMesh" << exit(FatalIOError);
        }
    }

    // The kinematics the body starts from (a line's start shape, the other
    // body's evaluations before this one's first solve) and its mass
    // properties
    {
        dictionary startDict(motion);
        startDict.remove("restraints");
        const sixDoFRigidBodyMotion startMotion
        (
            startDict,
            startDict,
            runTime
        );
        start = sixDoFConnector::kinematics(startMotion);
        mass = sixDoFConnector::massProperties(startMotion);
    }

    connector_ = sixDoFConnector::New(name_, sDoFRBMRCoeffs_, runTime);
    connector_->registerSide(side_, start, mass, sDoFRBMRCoeffs_);

    // A restart reads the restraint from the copy the earlier run wrote:
    // report what the case's own dictionary changed since (master rank,
    // where the connector lives)
    if (Pstream::master())
    {
        compareWithCase(*top, *topDict, sDoFRBMRDict);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::sixDoFRigidBodyMotionRestraints::fmuConnector::~fmuConnector()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::sixDoFRigidBodyMotionRestraints::fmuConnector::restrain
(
    const sixDoFRigidBodyMotion& motion,
    vector& restraintPosition,
    vector& restraintForce,
    vector& restraintMoment
) const
{
    if (!connector_)
    {
        // The FMU starts at the start time, as if loaded at construction
        const Time& runTime = motion.time();
        const scalar startTime = runTime.startTime().value();
        connector_ = sixDoFConnector::New
        (
            name_,
            sDoFRBMRCoeffs_,
            runTime,
            runTime.timeName(startTime),
            startTime
        );
    }

    const fmuConnectorCore::loads loads(connector_->restrain(side_, motion));

    restraintPosition = motion.centreOfRotation();
    restraintForce = loads.F;
    restraintMoment = loads.M;
}


bool Foam::sixDoFRigidBodyMotionRestraints::fmuConnector::read
(
    const dictionary& sDoFRBMRDict
)
{
    sixDoFRigidBodyMotionRestraint::read(sDoFRBMRDict);

    // The bodies named must be the case's: a connector to the world has
    // its restraint in its body's motion, one between two bodies in the
    // motions of both (checked at construction, where the dictionary is
    // still in the case's; a motion built from a copy of its dictionary
    // knows no other body, and the constructor refuses a connector between
    // two bodies there)
    const dictionary& motion = motionDict(sDoFRBMRDict);
    const bool twoBody = sDoFRBMRDict.found("bodyB", keyType::LITERAL);
    if
    (
        &motion != &dictionary::null
     && (!twoBody || &bodyDict(motion).parent() != &dictionary::null)
    )
    {
        const wordList valid
        (
            twoBody ? caseBodyNames(motion) : ownBodyNames(motion)
        );
        checkBody
        (
            name_,
            sDoFRBMRDict,
            "body",
            valid,
            twoBody
          ? "The bodies of the case"
          : "A connector to the fixed world is in its body's motion, here"
        );
        if (twoBody)
        {
            checkBody
            (
                name_, sDoFRBMRDict, "bodyB", valid, "The bodies of the case"
            );
        }
    }

    fmuConnectorCore::checkEntries
    (
        name_,
        sDoFRBMRCoeffs_,
        "sixDoFRigidBodyMotionRestraint"
    );

    entries_.read(name_, sDoFRBMRCoeffs_);
    sDoFRBMRCoeffs_.readEntry("body", body_);
    bodyB_ = sDoFRBMRCoeffs_.lookupOrDefault<word>("bodyB", word::null);

    return true;
}


void Foam::sixDoFRigidBodyMotionRestraints::fmuConnector::write
(
    Ostream& os
) const
{
    os.writeEntry("fmu", entries_.fmu);
    os.writeEntry("body", body_);
    if (!bodyB_.empty())
    {
        os.writeEntry("bodyB", bodyB_);
    }
    entries_.write(os);
}


// ************************************************************************* //
