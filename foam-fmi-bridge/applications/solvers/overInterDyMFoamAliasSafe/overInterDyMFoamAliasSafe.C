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
    overInterDyMFoamAliasSafe

Group
    grpMultiphaseSolvers grpMovingMeshSolvers

Description
    OpenFOAM v1912 overInterDyMFoam (interFoam on overset meshes), compiled
    from the unmodified v1912 sources without the __restrict__ qualifiers of
    the field-loop macros.

    The field algebra of v1912 (ListLoopM.H, FieldM.H) declares every
    operand pointer of an element-wise loop __restrict__, while the tmp
    operators reuse the storage of a temporary operand for the result.  GCC
    12 at -O3 (the flags of Debian's build) vectorises these loops and
    computes the later vector components of inv(T) & b from already
    overwritten ones.  overInterDyMFoam calls fvc::reconstruct in its
    pressure corrector, as interFoam does, and its overset meshes rotate
    with the body: every cell of a tilted component mesh has faces off the
    axes, where Debian's build reconstructs a wrong velocity.  See
    interFoamAliasSafe and docs/floating-stability.md.

    The solver algorithm is that of overInterDyMFoam v1912; see
    $FOAM_SOLVERS/multiphase/interFoam/overInterDyMFoam/overInterDyMFoam.C.
    The only change is the compilation: Make/options defines __restrict__
    away, so every template instantiated in this application is compiled
    without the false no-alias promise.

Usage
    Run it in place of overInterDyMFoam, in the same case:
    \verbatim
        overInterDyMFoamAliasSafe
        mpirun -np 2 overInterDyMFoamAliasSafe -parallel
    \endverbatim

\*---------------------------------------------------------------------------*/

#ifdef __restrict__
    // Make/options defines __restrict__ to nothing; see the description
#else
    #error "overInterDyMFoamAliasSafe must be compiled with -D__restrict__= (Make/options)"
#endif

#include "overInterDyMFoam.C"

// ************************************************************************* //
