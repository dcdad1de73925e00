// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Description
    The Newton iterations of implicitNewmark: trial states, residual,
    finite-difference Jacobian.
\*---------------------------------------------------------------------------*/

#include "implicitNewmark.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- Largest magnitude of a field, 0 for an empty one
Foam::scalar normInf(const Foam::scalarField& f)
{
    Foam::scalar n = 0;
    for (const Foam::scalar x : f)
    {
        n = Foam::max(n, Foam::mag(x));
    }
    return n;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::RBD::rigidBodySolvers::implicitNewmark::setTrialState
(
    const scalarField& a
)
{
    const scalar h = deltaT();

    aBar_ = ((1 - alphaF_)*a + alphaF_*a0_ - alphaM_*aBar0_)/(1 - alphaM_);

    qDot() = qDot0() + h*((1 - gamma_)*aBar0_ + gamma_*aBar_);
    q() = q0() + h*qDot0() + sqr(h)*((0.5 - beta_)*aBar0_ + beta_*aBar_);

    // q - q0 of a quaternion joint is its rotation vector: rotate q0 by it
    correctQuaternionJoints();
}


void Foam::RBD::rigidBodySolvers::implicitNewmark::residual
(
    const scalarField& a,
    const stepLoads& loads,
    scalarField& R
)
{
    setTrialState(a);

    // Body kinematics of the trial state, for the restraints
    qDdot() = loads.qDdotPrev;
    model_.forwardDynamicsCorrection(state());

    scalarField rtau(loads.tau);
    Field<spatialVector> rfx(loads.fx);
    model_.applyRestraints(rtau, rfx, state());

    // Accelerations, relaxed towards qDdotPrev as the model specifies
    model_.forwardDynamics(state(), rtau, rfx);
    ++nEvaluations_;

    R = a - qDdot();
}


bool Foam::RBD::rigidBodySolvers::implicitNewmark::updateJacobian
(
    const scalarField& a,
    const scalarField& R,
    const stepLoads& loads,
    const scalar aScale
)
{
    const label n = a.size();
    jacobian_ = scalarSquareMatrix(n, Zero);

    scalarField ap(a);
    scalarField Rp(n);

    // One column per degree of freedom: a_j moves q_j and qDot_j together
    for (label j = 0; j < n; ++j)
    {
        ap[j] = a[j] + fdStep_*max(mag(a[j]), aScale);
        const scalar da = ap[j] - a[j];

        residual(ap, loads, Rp);

        for (label i = 0; i < n; ++i)
        {
            jacobian_(i, j) = (Rp[i] - R[i])/da;
        }
        ap[j] = a[j];
    }

    scalar maxCoeff = 0;
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            maxCoeff = max(maxCoeff, mag(jacobian_(i, j)));
        }
    }
    if (!(maxCoeff > 0) || !std::isfinite(maxCoeff))
    {
        return false;
    }

    pivots_.setSize(n);
    LUDecompose(jacobian_, pivots_);
    ++nJacobians_;
    jacobianDeltaT_ = deltaT();

    for (label i = 0; i < n; ++i)
    {
        if (!(mag(jacobian_(i, i)) > SMALL*maxCoeff))
        {
            jacobianDeltaT_ = 0;
            return false;
        }
    }

    return true;
}


bool Foam::RBD::rigidBodySolvers::implicitNewmark::newton
(
    scalarField& a,
    const stepLoads& loads,
    scalar& residualNorm,
    label& nIter
)
{
    const label n = a.size();
    const scalar gScale = mag(model_.g());

    scalarField R(n);
    residual(a, loads, R);

    // Acceleration scale of the convergence test and of the FD step
    auto scale = [&]()
    {
        return max
        (
            max(max(normInf(a), normInf(a - R)), max(normInf(a0_), gScale)),
            ROOTVSMALL
        );
    };

    // Position change per unit change of a [s^2]
    const scalar dqda = beta_*sqr(deltaT())*(1 - alphaF_)/(1 - alphaM_);

    // Converged: the residual is small against the accelerations, or the
    // last correction moved q by less than tolerance of max(|q|, 1) (m or
    // rad). The second test ends the iterations at the round-off floor of
    // a stiff restraint near rest, where |R| ~ eps k |x|/m need not be
    // small against the net acceleration.
    scalar correctionNorm = GREAT;
    auto converged = [&]()
    {
        return
            residualNorm <= tolerance_*scale()
         || correctionNorm <= tolerance_*max(normInf(q()), scalar(1));
    };

    residualNorm = normInf(R);
    nIter = 0;

    while (true)
    {
        if (!std::isfinite(residualNorm))
        {
            FatalErrorInFunction
                << "Non-finite residual " << residualNorm << " at t = "
                << state().t() << " after " << nIter << " Newton iterations:"
                << " a restraint or the dynamics returned a non-finite load"
                << " at the trial state q = " << q() << ", qDot = " << qDot()
                << exit(FatalError);
        }

        if (converged() || nIter >= maxIter_)
        {
            break;
        }

        // Rebuild the Jacobian for a new time step or when the last
        // iteration did not contract
        bool fresh = false;
        if (jacobianDeltaT_ != deltaT() || jacobian_.m() != n)
        {
            if (!updateJacobian(a, R, loads, scale()))
            {
                FatalErrorInFunction
                    << "Singular Newton matrix dR/da at t = " << state().t()
                    << " (finite-difference step " << fdStep_ << "): check"
                    << " that every degree of freedom has inertia"
                    << exit(FatalError);
            }
            fresh = true;
        }

        scalarField da(-R);
        LUBacksubstitute(jacobian_, pivots_, da);

        const scalarField R0(R);
        a += da;
        residual(a, loads, R);
        ++nIter;

        const scalar newNorm = normInf(R);

        DebugInfo
            << typeName << ": iteration " << nIter << ", residual "
            << newNorm << ", correction " << dqda*normInf(da)
            << (fresh ? ", new Jacobian" : "") << endl;

        if (std::isfinite(newNorm) && newNorm > residualNorm && !fresh)
        {
            // A stale Jacobian made things worse: undo and rebuild
            a -= da;
            R = R0;
            jacobianDeltaT_ = 0;
            if (nIter >= maxIter_)
            {
                // Leave the restraints evaluated at the final iterate
                residual(a, loads, R);
            }
            continue;
        }
        if (!(newNorm <= 0.1*residualNorm))
        {
            jacobianDeltaT_ = 0;
        }
        residualNorm = newNorm;
        correctionNorm = dqda*normInf(da);
    }

    return converged();
}


// ************************************************************************* //
