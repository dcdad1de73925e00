// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "implicitNewmark.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace rigidBodySolvers
{
    defineTypeNameAndDebug(implicitNewmark, 0);
    addToRunTimeSelectionTable(rigidBodySolver, implicitNewmark, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodySolvers::implicitNewmark::setCoefficients()
{
    // Chung and Hulbert (1993): second-order, unconditionally stable for
    // linear problems, spectral radius rhoInf as omega h -> infinity
    alphaM_ = (2*rhoInf_ - 1)/(rhoInf_ + 1);
    alphaF_ = rhoInf_/(rhoInf_ + 1);
    gamma_ = 0.5 + alphaF_ - alphaM_;
    beta_ = 0.25*sqr(gamma_ + 0.5);
}


void Foam::RBD::rigidBodySolvers::implicitNewmark::read
(
    const dictionary& dict
)
{
    rhoInf_ = dict.lookupOrDefault<scalar>("rhoInf", 1);
    tolerance_ = dict.lookupOrDefault<scalar>("tolerance", 1e-10);
    maxIter_ = dict.lookupOrDefault<label>("maxIter", 20);
    fdStep_ = dict.lookupOrDefault<scalar>("fdStep", 1e-6);
    maxFailedSteps_ = dict.lookupOrDefault<label>("maxFailedSteps", 3);
    report_ = dict.lookupOrDefault<Switch>("report", false);
    const word restart(dict.lookupOrDefault<word>("restart", "exact"));
    restartFresh_ = (restart == "fresh");

    if (!(rhoInf_ >= 0 && rhoInf_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "rhoInf = " << rhoInf_ << ": the spectral radius at infinite"
            << " frequency must be in [0, 1] (1: trapezoidal, no damping)"
            << exit(FatalIOError);
    }
    if (!(tolerance_ > 0 && tolerance_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "tolerance = " << tolerance_ << ": the relative tolerance of"
            << " the Newton iterations must be in (0, 1)"
            << exit(FatalIOError);
    }
    if (maxIter_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "maxIter = " << maxIter_ << ": at least one Newton iteration"
            << " per solve is needed" << exit(FatalIOError);
    }
    if (!(fdStep_ > 0 && fdStep_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "fdStep = " << fdStep_ << ": the relative finite-difference"
            << " step must be in (0, 1); about the square root of the"
            << " restraints' relative accuracy (1e-6 for double precision)"
            << exit(FatalIOError);
    }
    if (restart != "exact" && restart != "fresh")
    {
        FatalIOErrorInFunction(dict)
            << "restart " << restart << ": exact (restore the solver's"
            << " memory written with the time the run starts from) or fresh"
            << " (start it anew)" << exit(FatalIOError);
    }
    if (maxFailedSteps_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "maxFailedSteps = " << maxFailedSteps_ << ": must be at least"
            << " 1 (1 stops at the first unconverged step)"
            << exit(FatalIOError);
    }

    setCoefficients();
}


void Foam::RBD::rigidBodySolvers::implicitNewmark::newStep
(
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    if (!stepFailed_)
    {
        nFailedSteps_ = 0;
    }
    stepFailed_ = false;

    // rigidBodyMotion::solve sets the old time to the new one on the first
    // step of a run that did not start from a written state
    const bool firstStep = (state0().t() == state().t());

    if (firstStep)
    {
        // The stored acceleration of an initial state is zero, not the
        // acceleration of that state: compute it, with the loads given
        q() = q0();
        qDot() = qDot0();
        model_.forwardDynamicsCorrection(state());

        scalarField rtau(tau);
        Field<spatialVector> rfx(fx);
        model_.applyRestraints(rtau, rfx, state());
        model_.rigidBodyModel::forwardDynamics(state(), rtau, rfx);
        ++nEvaluations_;

        a0_ = qDdot();
    }
    else
    {
        a0_ = qDdot0();
    }

    // The algorithmic acceleration carries over from the previous step of
    // this run; after a restart it starts from the acceleration
    if (!firstStep && aBar_.size() == a0_.size() && tSolve_ == state0().t())
    {
        aBar0_ = aBar_;
    }
    else
    {
        aBar0_ = a0_;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodySolvers::implicitNewmark::implicitNewmark
(
    rigidBodyMotion& body,
    const dictionary& dict
)
:
    rigidBodySolver(body),
    restartFresh_(false),
    tSolve_(-GREAT),
    converged_(true),
    stepFailed_(false),
    nFailedSteps_(0),
    jacobianDeltaT_(0),
    nSolves_(0),
    nIterations_(0),
    nEvaluations_(0),
    nJacobians_(0)
{
    read(dict);

    memory_.reset(new implicitNewmarkState(model_.time(), *this, restartFresh_));

    Info<< "Rigid-body solver " << typeName << ": generalized-alpha with"
        << " alphaM " << alphaM_ << ", alphaF " << alphaF_ << ", gamma "
        << gamma_ << ", beta " << beta_ << nl;
    write(Info);
    Info<< endl;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::RBD::rigidBodySolvers::implicitNewmark::~implicitNewmark()
{
    if (nSolves_)
    {
        Info<< "Rigid-body solver " << typeName << ": " << nSolves_
            << " solves, " << nIterations_ << " Newton iterations, "
            << nEvaluations_ << " evaluations of the restraints, "
            << nJacobians_ << " Jacobians" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::rigidBodySolvers::implicitNewmark::solve
(
    const scalarField& tau,
    const Field<spatialVector>& fx
)
{
    const bool firstSolve = (state().t() != tSolve_);
    if (firstSolve)
    {
        newStep(tau, fx);
    }
    tSolve_ = state().t();

    // Base of the model's acceleration relaxation: the previous solve
    const scalarField qDdotPrev(qDdot());

    // Start from the previous solve of this step when it converged, else
    // from the acceleration that keeps the bodies at q0: the first trial
    // state is then the old configuration, where every restraint is known
    // to be defined. Predictors that move the bodies (a = a0, or constant
    // velocity) overshoot by (omega h)^2 or omega h with a stiff restraint
    // and can leave the basin of the solution of a geometrically nonlinear
    // one (a spring pushed through its anchor has a second root).
    scalarField a(qDdotPrev);
    if (!converged_ || firstSolve)
    {
        const scalarField aBarPredicted
        (
            -(qDot0()/deltaT() + (0.5 - beta_)*aBar0_)/beta_
        );
        a =
            ((1 - alphaM_)*aBarPredicted + alphaM_*aBar0_ - alphaF_*a0_)
           /(1 - alphaF_);
    }

    scalar residualNorm = 0;
    label nIter = 0;
    converged_ = newton(a, {tau, fx, qDdotPrev}, residualNorm, nIter);

    // The end-of-step state of the last iterate
    setTrialState(a);
    qDdot() = a;

    ++nSolves_;
    nIterations_ += nIter;

    if (report_)
    {
        Info<< typeName << ": t = " << state().t() << ", " << nIter
            << " iterations, residual " << residualNorm << endl;
    }

    if (!converged_)
    {
        if (!stepFailed_)
        {
            stepFailed_ = true;
            ++nFailedSteps_;
        }

        WarningInFunction
            << "Newton iterations not converged at t = " << state().t()
            << " after " << nIter << " iterations: residual " << residualNorm
            << " (relative tolerance " << tolerance_ << "); "
            << nFailedSteps_ << " consecutive step(s) with an unconverged"
            << " solve, at most " << maxFailedSteps_ << endl;

        if (nFailedSteps_ >= maxFailedSteps_)
        {
            FatalErrorInFunction
                << "Newton iterations not converged in " << nFailedSteps_
                << " consecutive time steps (maxFailedSteps "
                << maxFailedSteps_ << "); last residual " << residualNorm
                << " after " << nIter << " iterations at t = " << state().t()
                << ". Reduce the time step, raise maxIter or rhoInf < 1"
                << exit(FatalError);
        }
    }
}


void Foam::RBD::rigidBodySolvers::implicitNewmark::write(Ostream& os) const
{
    os.writeEntry("type", typeName);
    os.writeEntry("rhoInf", rhoInf_);
    os.writeEntry("tolerance", tolerance_);
    os.writeEntry("maxIter", maxIter_);
    os.writeEntry("fdStep", fdStep_);
    os.writeEntry("maxFailedSteps", maxFailedSteps_);
    os.writeEntry("report", report_);
    os.writeEntry("restart", word(restartFresh_ ? "fresh" : "exact"));
}


// ************************************************************************* //
