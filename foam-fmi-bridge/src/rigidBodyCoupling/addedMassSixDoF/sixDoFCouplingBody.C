// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "sixDoFCouplingBody.H"
#include "Time.H"
#include "forces.H"
#include "quaternion.H"
#include "restartFiles.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::sixDoFCouplingBody::motionStateEntries
({
    "centreOfRotation", "orientation", "velocity", "acceleration",
    "angularMomentum", "torque"
});


const Foam::wordList Foam::sixDoFCouplingBody::meanEntries
({
    "meanAngularVelocity", "meanVelocity", "meanAngularAcceleration",
    "meanAcceleration"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::sixDoFCouplingBody::rotationVector(const tensor& R)
{
    // OpenFOAM's quaternion of R, w = cos(angle/2) and v = sin(angle/2)
    // times the axis, taken with w >= 0 for the angle in [0, pi]. Near pi
    // its axis comes from the symmetric part of R, where the antisymmetric
    // part, sin(angle) times the axis, is lost to round-off
    quaternion q(R);
    if (q.w() < 0)
    {
        q = -q;
    }

    const scalar sinHalfAngle = mag(q.v());
    if (sinHalfAngle < VSMALL)
    {
        return Zero;
    }
    return 2*atan2(sinHalfAngle, q.w())/sinHalfAngle*q.v();
}


void Foam::sixDoFCouplingBody::meanVelocities
(
    const sixDoFRigidBodyMotionState& s,
    const scalar dt,
    vector& omega,
    vector& v
) const
{
    omega = rotationVector(s.Q() & state0_.Q().T())/dt;
    v = (s.centreOfRotation() - state0_.centreOfRotation())/dt;
}


bool Foam::sixDoFCouplingBody::nextMeans
(
    const scalar dt,
    FixedList<vector, 4>& means
) const
{
    if (solved_)
    {
        meanVelocities(motion_.state(), dt, means[0], means[1]);
        means[2] = (means[0] - omegaMean0_)/dt;
        means[3] = (means[1] - vMean0_)/dt;
        return true;
    }

    means = FixedList<vector, 4>({omegaMean0_, vMean0_, alphaPrev_, aPrev_});
    return meansKnown_;
}


void Foam::sixDoFCouplingBody::setMeans(const FixedList<vector, 4>& means)
{
    omegaMean0_ = means[0];
    vMean0_ = means[1];
    alphaPrev_ = means[2];
    aPrev_ = means[3];
}


void Foam::sixDoFCouplingBody::update
(
    const vector& force,
    const vector& moment
)
{
    const Time& t = motion_.time();
    const vector gravity(motion_.mass()*g_);

    motion_.update
    (
        firstIter_,
        force_ + force + gravity,
        moment_ + moment + (motion_.momentArm() ^ gravity),
        t.deltaTValue(),
        t.deltaT0Value()
    );
    solved_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sixDoFCouplingBody::sixDoFCouplingBody
(
    sixDoFRigidBodyMotion& motion,
    const word& name
)
:
    motion_(motion),
    name_(name),
    force_(Zero),
    moment_(Zero),
    g_(Zero),
    firstIter_(false),
    state0_(motion.state()),
    start_(motion.state()),
    solved_(false),
    alphaPrev_(Zero),
    aPrev_(Zero),
    omegaMean0_(Zero),
    vMean0_(Zero),
    momentAdd_(Zero),
    forceAdd_(Zero),
    originAdd_(Zero),
    meansKnown_(false),
    meansRead_(false)
{}


Foam::sixDoFCouplingBody::sixDoFCouplingBody
(
    sixDoFRigidBodyMotion& motion,
    const word& name,
    const sixDoFCouplingBody& b
)
:
    sixDoFCouplingBody(motion, name)
{
    // The means the next time step of b starts from, as a restart reads
    // them
    FixedList<vector, 4> means;
    meansKnown_ = b.nextMeans(b.motion_.time().deltaTValue(), means);
    meansRead_ = meansKnown_;
    setMeans(means);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::sixDoFCouplingBody::newTime()
{
    if (solved_)
    {
        FixedList<vector, 4> means;
        nextMeans(motion_.time().deltaT0Value(), means);
        setMeans(means);
    }
    else if (!meansRead_)
    {
        // No step before: the velocities of the state
        const sixDoFRigidBodyMotionState& s = motion_.state();
        omegaMean0_ = s.Q() & (inv(motion_.momentOfInertia()) & s.pi());
        vMean0_ = s.v();
    }
    meansKnown_ = true;
    meansRead_ = false;

    motion_.newTime();
    state0_ = motion_.state();
    solved_ = false;
}


void Foam::sixDoFCouplingBody::setLoads
(
    const vector& force,
    const vector& moment,
    const vector& g,
    const bool firstIter
)
{
    force_ = force;
    moment_ = moment;
    g_ = g;
    firstIter_ = firstIter;
}


void Foam::sixDoFCouplingBody::setFluidLoads
(
    const objectRegistry& db,
    const List<wordRe>& patches,
    const word& rhoName,
    const scalar rhoInf,
    const vector& g,
    const bool firstIter
)
{
    dictionary forcesDict;

    forcesDict.add("type", functionObjects::forces::typeName);
    forcesDict.add("patches", patches);
    forcesDict.add("rhoInf", rhoInf);
    forcesDict.add("rho", rhoName);
    forcesDict.add("CofR", motion_.centreOfRotation());

    functionObjects::forces f("forces", db, forcesDict);
    #if OPENFOAM >= 2206
    f.calcForcesMoments();
    #else
    f.calcForcesMoment();
    #endif

    setLoads(f.forceEff(), f.momentEff(), g, firstIter);
}


void Foam::sixDoFCouplingBody::reportSolve()
{
    if (!motion_.report())
    {
        return;
    }

    const_cast<sixDoFRigidBodyMotionState&>(motion_.state()) = start_;
    update
    (
        forceAdd_,
        momentAdd_ + ((originAdd_ - motion_.centreOfRotation()) ^ forceAdd_)
    );
}


bool Foam::sixDoFCouplingBody::readState(const dictionary& state)
{
    label nFound = 0;
    for (const word& key : meanEntries)
    {
        nFound += state.found(key, keyType::LITERAL);
    }
    if (nFound == 0)
    {
        return false;
    }

    // All or none: readEntry names the one missing
    FixedList<vector, 4> means;
    forAll(meanEntries, i)
    {
        state.readEntry(meanEntries[i], means[i], keyType::LITERAL);
    }
    setMeans(means);
    meansKnown_ = true;
    meansRead_ = true;
    return true;
}


void Foam::sixDoFCouplingBody::readRestartState
(
    const dictionary& state,
    const fileName& file
)
{
    const Time& t = motion_.time();
    if (!readState(state) && restartFiles::restarted(t, t.timeName()))
    {
        Info<< name_ << ": the restart state " << file << " has no "
            << meanEntries[0] << ", " << meanEntries[1] << ", "
            << meanEntries[2] << ", " << meanEntries[3]
            << " (written before the coupling kept them): the first time"
            << " step takes the state's velocities for the previous step's"
            << " mean velocities and zero for its accelerations, so the"
            << " restart is not exact" << endl;
    }
}


void Foam::sixDoFCouplingBody::writeState(dictionary& state) const
{
    FixedList<vector, 4> means;
    if (nextMeans(motion_.time().deltaTValue(), means))
    {
        forAll(meanEntries, i)
        {
            state.add(meanEntries[i], means[i]);
        }
    }
}


Foam::List<Foam::vector> Foam::sixDoFCouplingBody::origins() const
{
    return List<vector>(1, motion_.centreOfRotation());
}


Foam::tensorField Foam::sixDoFCouplingBody::axes() const
{
    // Q takes body to global axes
    return tensorField(1, motion_.orientation().T());
}


Foam::scalar Foam::sixDoFCouplingBody::mass(const label) const
{
    return motion_.mass();
}


Foam::scalar Foam::sixDoFCouplingBody::inertiaTrace(const label) const
{
    // About the centre of rotation, where the motion turns
    return tr(motion_.momentOfInertia());
}


void Foam::sixDoFCouplingBody::saveState()
{
    start_ = motion_.state();

    // A restraint shared with another body (sixDoFConnector) hands over, in
    // the first solve of a round, the loads the other body's solve left;
    // it is made here, so that every coupling solve evaluates the same
    solveWith(List<vector>(1, motion_.centreOfRotation()), scalarField(6, 0));
}


void Foam::sixDoFCouplingBody::solveWith
(
    const List<vector>& origins,
    const scalarField& fAdd
)
{
    momentAdd_ = vector(fAdd[0], fAdd[1], fAdd[2]);
    forceAdd_ = vector(fAdd[3], fAdd[4], fAdd[5]);
    originAdd_ = origins[0];

    // From the corrector's start: the restraints read the motion's state
    const_cast<sixDoFRigidBodyMotionState&>(motion_.state()) = start_;

    const int level = messageStream::level;
    messageStream::level = 0;
    update
    (
        forceAdd_,
        momentAdd_ + ((originAdd_ - motion_.centreOfRotation()) ^ forceAdd_)
    );
    messageStream::level = level;
}


void Foam::sixDoFCouplingBody::solveFluidLoads()
{
    update(Zero, Zero);
}


Foam::scalarField Foam::sixDoFCouplingBody::accelerations
(
    const List<vector>& origins
) const
{
    const sixDoFRigidBodyMotionState& s = motion_.state();

    vector alpha(alphaPrev_);
    vector a(aPrev_);
    if (solved_)
    {
        const scalar dt = motion_.time().deltaTValue();
        vector omegaMean, vMean;
        meanVelocities(s, dt, omegaMean, vMean);
        alpha = (omegaMean - omegaMean0_)/dt;
        a = (vMean - vMean0_)/dt;
    }

    // Linear acceleration at the origin, rigidly with the body
    const vector linear(a + (alpha ^ (origins[0] - s.centreOfRotation())));

    scalarField c(6);
    for (direction r = 0; r < 3; ++r)
    {
        c[r] = alpha[r];
        c[3 + r] = linear[r];
    }
    return c;
}


// ************************************************************************* //
