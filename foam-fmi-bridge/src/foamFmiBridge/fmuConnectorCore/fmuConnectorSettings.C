// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorSettings.H"
#include "uniqueRestraintNames.H"
#include "Time.H"
#include "error.H"

#include <cctype>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::fmuConnectorSettings::restartMode>
Foam::fmuConnectorSettings::restartModeNames
({
    { restartMode::exact, "exact" },
    { restartMode::fresh, "fresh" },
});

const Foam::Enum<Foam::fmuConnectorSettings::isolationMode>
Foam::fmuConnectorSettings::isolationModeNames
({
    { isolationMode::none, "none" },
    { isolationMode::process, "process" },
});


// * * * * * * * * * * * * * * * * Run settings  * * * * * * * * * * * * * * //

Foam::fmuConnectorSettings::runSettings Foam::fmuConnectorSettings::runSettings::read
(
    const word& restraintName,
    const dictionary& dict
)
{
    runSettings run;
    run.isolation = isolationModeNames.getOrDefault
    (
        "isolation",
        dict,
        isolationMode::none
    );

    run.timeout = dict.getOrDefault<scalar>("timeout", 0);
    if (!(run.timeout >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "restraint " << restraintName << ": entry timeout is "
            << run.timeout << "; expected the longest one call into the FMU"
            << " may take, in seconds, >= 0 (0: no limit)"
            << exit(FatalIOError);
    }

    // A quoted string: unquoted, OpenFOAM reads hexadecimal digits that
    // start with a digit as a number
    if (dict.found("sha256", keyType::LITERAL))
    {
        const ITstream& is = dict.lookup("sha256");
        const bool one =
            is.size() == 1 && (is[0].isWord() || is[0].isString());
        run.sha256 =
            !one ? string()
          : is[0].isWord() ? string(is[0].wordToken())
          : is[0].stringToken();
        bool hex = run.sha256.size() == 64;
        for (char& c : run.sha256)
        {
            c = std::tolower(static_cast<unsigned char>(c));
            hex = hex && std::isxdigit(static_cast<unsigned char>(c));
        }
        if (!hex)
        {
            FatalIOErrorInFunction(dict)
                << "restraint " << restraintName << ": entry sha256 must be"
                << " the 64 hexadecimal digits of the .fmu file's SHA-256"
                << " in double quotes, as sha256sum prints them:"
                << " sha256 \"<digits>\";" << exit(FatalIOError);
        }
    }
    return run;
}


void Foam::fmuConnectorSettings::runSettings::write(Ostream& os) const
{
    if (isolation != isolationMode::none)
    {
        os.writeEntry("isolation", isolationModeNames[isolation]);
    }
    if (timeout > 0)
    {
        os.writeEntry("timeout", timeout);
    }
    if (!sha256.empty())
    {
        os.writeEntry("sha256", sha256);
    }
}


void Foam::fmuConnectorSettings::checkEntries
(
    const word& restraintName,
    const dictionary& dict,
    const word& typeKeyword
)
{
    checkUniqueRestraintNames(dict);

    const wordList keywords
    ({
        typeKeyword, "body", "bodyB", "fmu", "parameters", "report",
        "restart", "isolation", "timeout", "sha256"
    });
    for (const entry& e : dict)
    {
        if (!keywords.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "restraint " << restraintName << ": unknown entry '"
                << e.keyword() << "'; the entries of an fmuConnector"
                << " restraint are " << listed(keywords).c_str()
                << exit(FatalIOError);
        }
    }

    if (dict.found("parameters") && !dict.isDict("parameters"))
    {
        FatalIOErrorInFunction(dict)
            << "restraint " << restraintName << ": entry 'parameters' must"
            << " be a dictionary of the FMU's parameters, e.g."
            << " parameters { stiffness 100; }" << exit(FatalIOError);
    }

    const word bodyB(dict.getOrDefault<word>("bodyB", word::null));
    if (!bodyB.empty() && bodyB == dict.getOrDefault<word>("body", word::null))
    {
        FatalIOErrorInFunction(dict)
            << "restraint " << restraintName << ": body and bodyB are the"
            << " same body " << bodyB << exit(FatalIOError);
    }
}


Foam::string Foam::fmuConnectorSettings::listed(const wordList& words)
{
    string text;
    forAll(words, i)
    {
        text += (i ? ", " : "") + words[i];
    }
    return text;
}


Foam::fileName Foam::fmuConnectorSettings::caseFile
(
    const fileName& fmuFile,
    const Time& runTime
)
{
    fileName file(fmuFile);
    file.expand();
    if (!file.isAbsolute())
    {
        file = runTime.globalPath()/file;
    }
    return file;
}


// * * * * * * * * * * * * * * * Restraint entries * * * * * * * * * * * * * //

Foam::fmuConnectorSettings::restraintEntries::restraintEntries()
:
    report(false),
    restart(restartMode::exact)
{}


void Foam::fmuConnectorSettings::restraintEntries::read
(
    const word& restraintName,
    const dictionary& dict
)
{
    // Read as a string first: a fileName drops what a file name of
    // OpenFOAM's cannot hold (a space, a quote) with a message naming
    // neither the restraint nor the entry
    const string path(dict.get<string>("fmu"));
    for (const char c : path)
    {
        if (!fileName::valid(c))
        {
            FatalIOErrorInFunction(dict)
                << "restraint " << restraintName << ": entry 'fmu' \""
                << path.c_str() << "\" holds "
                << (c == ' ' ? "a space" : "a quote or a blank")
                << ", which an OpenFOAM file name cannot hold: rename the"
                << " file or the folder" << exit(FatalIOError);
        }
    }
    fmu = path;
    parameters = dict.subOrEmptyDict("parameters");
    report = dict.lookupOrDefault<Switch>("report", false);
    restart = restartModeNames.getOrDefault
    (
        "restart",
        dict,
        restartMode::exact
    );
    run = runSettings::read(restraintName, dict);
}


void Foam::fmuConnectorSettings::restraintEntries::write(Ostream& os) const
{
    os.writeEntry("report", report);
    os.writeEntry("restart", restartModeNames[restart]);
    run.write(os);
    os.beginBlock("parameters");
    parameters.write(os, false);
    os.endBlock();
}


// ************************************************************************* //
