/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of OpenFOAM.

    OpenFOAM is free software: you can redistribute it and/or modify it
    under the terms of the GNU General Public License as published by
    the Free Software Foundation, either version 3 of the License, or
    (at your option) any later version.

    OpenFOAM is distributed in the hope that it will be useful, but WITHOUT
    ANY WARRANTY; without even the implied warranty of MERCHANTABILITY or
    FITNESS FOR A PARTICULAR PURPOSE.  See the GNU General Public License
    for more details.

    You should have received a copy of the GNU General Public License
    along with OpenFOAM.  If not, see <http://www.gnu.org/licenses/>.

Application
    interFoamAliasSafe

Group
    grpMultiphaseSolvers grpMovingMeshSolvers

Description
    OpenFOAM v1912 interFoam, compiled from the unmodified v1912 sources
    without the __restrict__ qualifiers of the field-loop macros.

    The field algebra of v1912 (ListLoopM.H, FieldM.H) declares every
    operand pointer of an element-wise loop __restrict__, while the tmp
    operators reuse the storage of a temporary operand for the result.  An
    expression such as inv(tmp<volTensorField>) & tmp<volVectorField>
    therefore writes the result over an operand that the compiler has been
    told it does not alias.  GCC 12 at -O3 (the flags of Debian's build)
    vectorises these loops and computes the later vector components from
    already overwritten ones.  In interFoam this corrupts fvc::reconstruct,
    which rebuilds the cell velocity from the face fluxes in the pressure
    corrector: on cells whose faces are not aligned with the axes the
    reconstructed velocity is wrong by O(1).  A Cartesian mesh hides the
    defect (the tensor inverted in fvc::reconstruct is then diagonal); a
    deforming mesh around a floating body exposes it within a few time
    steps.

    The solver algorithm is that of interFoam v1912; see
    $FOAM_SOLVERS/multiphase/interFoam/interFoam.C.  The only change is the
    compilation: Make/options defines __restrict__ away, so every template
    instantiated in this application (fvc::reconstruct, the tmp field
    operators, CorrectPhi, MULES) is compiled without the false no-alias
    promise.

Usage
    Run it in place of interFoam, in the same case:
    \verbatim
        interFoamAliasSafe
        mpirun -np 2 interFoamAliasSafe -parallel
    \endverbatim

\*---------------------------------------------------------------------------*/

#ifdef __restrict__
    // Make/options defines __restrict__ to nothing; see the description
#else
    #error "interFoamAliasSafe must be compiled with -D__restrict__= (Make/options)"
#endif

#include "interFoam.C"

// ************************************************************************* //
