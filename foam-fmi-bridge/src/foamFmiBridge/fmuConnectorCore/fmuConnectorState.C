// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorState.H"
#include "Time.H"
#include "IOstreams.H"
#include "stringList.H"
#include "IFstream.H"

#include <cstring>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(fmuConnectorState, 0);
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

const char* const hexDigits = "0123456789abcdef";

//- Hex digits per line of the written state
const std::string::size_type hexLine = 64;

Foam::string toHex(const std::vector<char>& bytes)
{
    std::string hex;
    hex.reserve(2*bytes.size());
    for (const char c : bytes)
    {
        const unsigned char u = static_cast<unsigned char>(c);
        hex += hexDigits[u >> 4];
        hex += hexDigits[u & 0xf];
    }
    return hex;
}

int hexValue(const char c)
{
    const char* p = std::strchr(hexDigits, c);
    return (c && p) ? int(p - hexDigits) : -1;
}


//- Names joined by ", ", as a message lists them
std::string joined(const Foam::wordList& names)
{
    std::string text;
    for (const Foam::word& name : names)
    {
        text += (text.empty() ? "" : ", ") + name;
    }
    return text;
}


//- The entry connectors of a complete state file, or an empty list (a
//  file cut short, or written without the entry)
Foam::wordList connectorsIn(const Foam::fileName& file)
{
    using namespace Foam;

    const wordList entries({"fmu", "time", "state", "connectors"});
    if (restartFiles::problem(file, entries).size())
    {
        return wordList();
    }
    IFstream is(file);
    return dictionary(is).get<wordList>("connectors");
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::fmuConnectorState::folder() const
{
    return time().path()/instance()/local();
}


void Foam::fmuConnectorState::readWritten()
{
    // Every complete file lists the same connectors; files of states
    // written before the entry existed list none
    for (const fileName& f : readDir(folder(), fileName::FILE))
    {
        if (f.ext() != "tmp" && written_.empty())
        {
            written_ = connectorsIn(folder()/f);
        }
    }
}


void Foam::fmuConnectorState::refuseNew(const dictionary& restraintDict) const
{
    FatalIOErrorInFunction(restraintDict)
        << "restraint " << name() << ": the run starts from t = "
        << instance().c_str() << ", written by an earlier run whose"
        << " connectors were " << joined(written_).c_str() << " (their states"
        << " are in " << folder() << "); " << name() << " is not one of"
        << " them, so it has no state to restore: it is new since, or one"
        << " of them renamed. A new restraint: set 'restart fresh;' in it"
        << " to start its connector from its initial state. A renamed one:"
        << " give it its old name for this restart, so that its state is"
        << " restored" << exit(FatalIOError);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fmuConnectorState::fmuConnectorState
(
    const word& name,
    const objectRegistry& time,
    fmuConnectorCore& fmu,
    const bool fresh,
    const dictionary& restraintDict,
    const word& startTimeName
)
:
    restartFiles::stateFile
    (
        IOobject
        (
            name,
            startTimeName.empty() ? time.time().timeName() : startTimeName,
            "uniform/fmuConnectors",
            time,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        )
    ),
    fmu_(fmu),
    unusedChecked_(false)
{
    // A time written by an earlier run (restartFiles::restarted); a case's
    // initial time is none, even when it gives the bodies' state
    const Time& runTime = time.time();
    const bool restarted = restartFiles::restarted(runTime, instance());
    const bool stateFile = isFile(objectPath());

    if (restarted)
    {
        readWritten();
    }

    if (fresh)
    {
        if (stateFile)
        {
            Info<< "Connector " << name << ": restart fresh: the FMU starts"
                << " from its initial state, " << objectPath()
                << " is not read" << endl;
        }
        return;
    }

    if (stateFile && !fmu_.canSerialize())
    {
        FatalIOErrorInFunction(restraintDict)
            << "restraint " << name << ": " << objectPath() << " holds a"
            << " connector state, but FMU " << fmu_.file() << " cannot"
            << " restore a serialized state (canGetAndSetFMUstate and"
            << " canSerializeFMUstate must both be true). Set 'restart"
            << " fresh;' in the restraint to start the connector from its"
            << " initial state" << exit(FatalIOError);
    }

    if (restarted && !stateFile && !fmu_.canSerialize())
    {
        FatalIOErrorInFunction(restraintDict)
            << "restraint " << name << ": the run starts from t = "
            << instance().c_str() << ", written by an earlier run, but the"
            << " connector's state " << objectPath() << " is missing (FMU"
            << " cannot serialize its state, so none was written). The"
            << " connector would start from its initial state while the"
            << " bodies continue. Set 'restart fresh;' in the restraint to"
            << " accept that" << exit(FatalIOError);
    }

    if
    (
        restarted
     && !stateFile
     && written_.size()
     && !written_.found(name)
    )
    {
        refuseNew(restraintDict);
    }

    // Missing, cut short or incomplete: the time was not written to the
    // end
    restartFiles::require
    (
        runTime,
        instance(),
        local()/name,
        wordList({"fmu", "time", "state"}),
        "restraint " + name + ": the connector's state",
        " (or set 'restart fresh;' in the restraint to start the connector"
        " from its initial state while the bodies continue)"
    );

    if (stateFile)
    {
        readData(readStream(typeName));
        close();
    }

    if (!fmu_.canSerialize())
    {
        WarningInFunction
            << "restraint " << name << ": FMU " << fmu_.file() << " cannot"
            << " serialize its state, so none is written for restarts; a"
            << " run restarted from a written time needs 'restart fresh;'"
            << " in this restraint" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fmuConnectorState::readData(Istream& is)
{
    const dictionary dict(is);

    const scalar time = dict.get<scalar>("time");
    // Hex digits in lines: OpenFOAM limits a string to 1024 characters
    string hex;
    for (const string& line : dict.get<List<string>>("state"))
    {
        hex += line;
    }

    if (hex.size() % 2)
    {
        FatalIOErrorInFunction(dict)
            << "entry 'state' must hold an even number of hex digits"
            << exit(FatalIOError);
    }

    std::vector<char> bytes(hex.size()/2);
    for (size_t i = 0; i < bytes.size(); ++i)
    {
        const int hi = hexValue(hex[2*i]);
        const int lo = hexValue(hex[2*i + 1]);
        if (hi < 0 || lo < 0)
        {
            FatalIOErrorInFunction(dict)
                << "entry 'state' is not a hex string at character "
                << 2*i << exit(FatalIOError);
        }
        bytes[i] = static_cast<char>(16*hi + lo);
    }

    fmu_.deserialize(bytes, time, objectPath());

    return true;
}


bool Foam::fmuConnectorState::writeData(Ostream& os) const
{
    scalar time = 0;
    const std::vector<char> bytes = fmu_.serialize(time);

    os.writeEntry("fmu", fmu_.file());

    // Every digit of the FMU's time: a restart continues its time line
    const label precision = os.precision(17);
    os.writeEntry("time", time);
    os.precision(precision);
    const string hex(toHex(bytes));
    List<string> lines((hex.size() + hexLine - 1)/hexLine);
    forAll(lines, i)
    {
        lines[i] = hex.substr(i*hexLine, hexLine);
    }
    os.writeEntry("state", lines);

    // The connectors whose states this time holds, for a restart to tell a
    // time written in part from a restraint added since
    const HashTable<const fmuConnectorState*> states
    (
        db().lookupClass<fmuConnectorState>()
    );
    wordList connectors;
    forAllConstIters(states, iter)
    {
        if (iter.val()->writable())
        {
            connectors.append(iter.key());
        }
    }
    Foam::sort(connectors);
    os.writeEntry("connectors", connectors);

    return os.good();
}


void Foam::fmuConnectorState::reportUnused() const
{
    if (unusedChecked_)
    {
        return;
    }
    unusedChecked_ = true;

    const wordList current
    (
        db().lookupClass<fmuConnectorState>().sortedToc()
    );
    if (written_.empty() || current.empty() || current.first() != name())
    {
        return;
    }

    wordList unused;
    for (const word& w : written_)
    {
        if (!current.found(w))
        {
            unused.append(w);
        }
    }
    if (unused.size())
    {
        WarningInFunction
            << "the run starts from t = " << instance().c_str() << ", which"
            << " holds the states of connectors " << joined(unused).c_str()
            << " in " << folder() << ": no restraint of the case has those"
            << " names (removed or renamed since), so they are not used."
            << " A renamed restraint restores its state only under its old"
            << " name" << endl;
    }
}


// ************************************************************************* //
