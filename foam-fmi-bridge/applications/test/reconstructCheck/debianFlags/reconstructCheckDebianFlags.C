// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Application
    reconstructCheckDebianFlags

Group
    grpTest

Description
    reconstructCheck compiled with the flags of Debian's own OpenFOAM build
    (see ../reconstructCheck.C and Make/options).
\*---------------------------------------------------------------------------*/

#include "reconstructCheck.C"

// ************************************************************************* //
