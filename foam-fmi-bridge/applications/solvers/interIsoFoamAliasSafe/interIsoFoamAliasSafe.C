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
    interIsoFoamAliasSafe

Group
    grpMultiphaseSolvers grpMovingMeshSolvers

Description
    OpenFOAM's interIsoFoam (the phase fraction advected geometrically by
    isoAdvector), compiled from the unmodified sources of the OpenFOAM it is
    built against without the __restrict__ qualifiers of the field-loop
    macros, as interFoamAliasSafe is interFoam: see
    ../interFoamAliasSafe/interFoamAliasSafe.C for the defect (a wrong
    fvc::reconstruct on cells whose faces are not aligned with the axes),
    which interIsoFoam meets on a moving mesh in its alpha equation and in
    its pressure corrector.

    The solver algorithm is that of interIsoFoam; see
    $FOAM_SOLVERS/multiphase/interIsoFoam/interIsoFoam.C.

Usage
    Run it in place of interIsoFoam, in the same case:
    \verbatim
        interIsoFoamAliasSafe
        mpirun -np 2 interIsoFoamAliasSafe -parallel
    \endverbatim

\*---------------------------------------------------------------------------*/

#ifdef __restrict__
    // Make/options defines __restrict__ to nothing; see the description
#else
    #error "interIsoFoamAliasSafe must be compiled with -D__restrict__= (Make/options)"
#endif

#include "interIsoFoam.C"

// ************************************************************************* //
