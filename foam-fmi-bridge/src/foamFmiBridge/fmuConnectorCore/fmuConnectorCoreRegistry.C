// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Description
    Where a connector is kept in the run: registered on the Time database
    under its restraint's name, where the flow sampling and the other parts
    of the bridge find it.
\*---------------------------------------------------------------------------*/

#include "fmuConnectorCore.H"
#include "Time.H"

// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::word Foam::fmuConnectorCore::registryName(const word& restraintName)
{
    return typeName + '.' + restraintName;
}


Foam::IOobject Foam::fmuConnectorCore::registryIO
(
    const Time& runTime,
    const word& restraintName
)
{
    return IOobject
    (
        registryName(restraintName),
        runTime.timeName(),
        runTime,
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
}


Foam::fmuConnectorCore* Foam::fmuConnectorCore::find
(
    const objectRegistry& obr,
    const word& restraintName
)
{
    return obr.time().getObjectPtr<fmuConnectorCore>
    (
        registryName(restraintName)
    );
}


Foam::wordList Foam::fmuConnectorCore::names(const objectRegistry& obr)
{
    wordList names(obr.time().sortedNames<fmuConnectorCore>());
    for (word& name : names)
    {
        name = name.substr(typeName.size() + 1);
    }
    return names;
}


// ************************************************************************* //
