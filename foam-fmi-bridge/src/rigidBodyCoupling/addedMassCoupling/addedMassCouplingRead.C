// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Description
    The coupling dictionary of addedMassCoupling and the coefficients
    around it, read strictly. A
    misspelt keyword would silently keep a default (a 'tolerence' the
    Newton iterations never see), so:

      - the coupling sub-dictionary holds its own entries, each of its
        type: any other entry, or one of another type, is a FatalIOError
        that lists the valid entries or says what is expected;
      - the coefficients hold the motion's OpenFOAM entries, the
        coupling (a dictionary) and the user's own entries for $-expansion
        (the tutorials keep a restraint's parameters there): an entry that
        is a coupling entry out of its place, or that differs from one of
        the known keywords by a letter or two (a quarter of its length, or
        its case: 'couplng', 'addedMassInteval', 'accelerationRelaxaton')
        is a FatalIOError that names the keyword it resembles and lists
        the valid ones.
\*---------------------------------------------------------------------------*/

#include "addedMassCoupling.H"
#include "Switch.H"

#include <cctype>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- dynamicMeshDict's own entries, when the coefficients are its top level
//  (no <type>Coeffs: motionSolver::coeffDict), besides other solvers'
//  <type>Coeffs
const Foam::wordList meshDictEntries
({
    "dynamicFvMesh", "motionSolverLibs", "motionSolver"
});

//- The coupling's entries
const Foam::wordList couplingEntries
({
    "addedMass", "pressure", "residual", "addedMassInterval", "maxIter",
    "tolerance"
});


Foam::string listed(const Foam::wordList& words)
{
    Foam::string text;
    forAll(words, i)
    {
        text += (i ? ", " : "") + words[i];
    }
    return text;
}


//- Edit distance between two words, letters compared without their case
Foam::label distance(const std::string& a, const std::string& b)
{
    std::vector<Foam::label> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
    {
        row[j] = Foam::label(j);
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        Foam::label diagonal = row[0];
        row[0] = Foam::label(i);
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const Foam::label above = row[j];
            const bool same =
                std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
            row[j] = Foam::min
            (
                Foam::min(row[j] + 1, row[j - 1] + 1),
                diagonal + (same ? 0 : 1)
            );
            diagonal = above;
        }
    }
    return row[b.size()];
}


//- The known keyword that key differs from by a letter or two (at most a
//  quarter of the known keyword's length, or only in case), or empty
Foam::word resembles(const Foam::word& key, const Foam::wordList& known)
{
    for (const Foam::word& k : known)
    {
        const Foam::label d = distance(key, k);
        if (key != k && d <= Foam::label(k.size()/4))
        {
            return k;
        }
    }
    return Foam::word::null;
}


//- Whether a keyword names some solver's coefficients, <type>Coeffs
bool isCoeffs(const Foam::word& key)
{
    const std::string suffix("Coeffs");
    return
        key.size() > suffix.size()
     && key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0;
}


//- The entry's only token; FatalIOError naming the entry and what it
//  expects when it is a dictionary or not one token
const Foam::token& oneToken
(
    const Foam::word& solverType,
    const Foam::dictionary& dict,
    const Foam::word& key,
    const char* expected
)
{
    using namespace Foam;

    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e->isStream() || e->stream().size() != 1)
    {
        FatalIOErrorInFunction(dict)
            << solverType << ": coupling entry '" << key
            << "' expects " << expected << ", got "
            << (e->isStream() ? "several tokens" : "a dictionary")
            << exit(FatalIOError);
    }
    return e->stream()[0];
}


//- FatalIOError: the entry holds a token of the wrong kind
void wrongType
(
    const Foam::word& solverType,
    const Foam::dictionary& dict,
    const Foam::word& key,
    const char* expected,
    const Foam::token& tok
)
{
    FatalIOErrorInFunction(dict)
        << solverType << ": coupling entry '" << key
        << "' expects " << expected << ", got '" << tok << "'"
        << Foam::exit(Foam::FatalIOError);
}


//- A coupling entry: its only token, of the kind accepts takes, read by
//  value; deflt when absent. FatalIOError naming the entry and what it
//  expects for any other token
template<class Type, class Accepts, class Value>
Type couplingEntry
(
    const Foam::word& solverType,
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Type& deflt,
    const char* expected,
    const Accepts& accepts,
    const Value& value
)
{
    if (!dict.found(key, Foam::keyType::LITERAL))
    {
        return deflt;
    }
    const Foam::token& tok = oneToken(solverType, dict, key, expected);
    if (!accepts(tok))
    {
        wrongType(solverType, dict, key, expected, tok);
    }
    return value(tok);
}


//- A switch's value, or an invalid switch for any other word
Foam::Switch switchOf(const Foam::token& tok)
{
    #if OPENFOAM >= 2312
    return Foam::Switch::find(tok.wordToken());
    #else
    return Foam::Switch(tok.wordToken(), true);
    #endif
}


bool isSwitch(const Foam::token& tok)
{
    #if OPENFOAM >= 2312
    return tok.isWord() && switchOf(tok).good();
    #else
    return tok.isWord() && switchOf(tok).valid();
    #endif
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::addedMassCoupling::checkEntries
(
    const dictionary& coeffs,
    const word& openFoamName,
    const wordList& openFoamEntries,
    const wordList& otherEntries,
    const bool otherCoeffs
) const
{
    wordList known(openFoamEntries);
    known.append("coupling");
    known.append(otherEntries);

    for (const entry& e : coeffs)
    {
        const word& key = e.keyword();
        if (known.found(key) || (otherCoeffs && isCoeffs(key)))
        {
            continue;
        }

        // Anything else is the user's (for $-expansion) unless it is a
        // coupling entry out of its place or a misspelt keyword
        const word like(resembles(key, known));
        const word likeCoupling(resembles(key, couplingEntries));
        if (!couplingEntries.found(key) && like.empty() && likeCoupling.empty())
        {
            continue;
        }

        FatalIOErrorInFunction(coeffs)
            << solverType_ << ": unknown entry '" << key << "'";
        if (couplingEntries.found(key))
        {
            FatalIOError
                << ", which belongs in the coupling sub-dictionary:"
                << " coupling { " << key << " ...; }";
        }
        else if (like.size())
        {
            FatalIOError<< " (did you mean '" << like << "'?)";
        }
        else
        {
            FatalIOError
                << " (did you mean the coupling entry '" << likeCoupling
                << "', in the coupling sub-dictionary?)";
        }
        FatalIOError
            << ". The entries are OpenFOAM's " << openFoamName << "'s ("
            << listed(openFoamEntries).c_str() << ") and coupling, a"
            << " dictionary of " << listed(couplingEntries).c_str()
            << exit(FatalIOError);
    }

    if (coeffs.found("coupling", keyType::LITERAL) && !coeffs.isDict("coupling"))
    {
        FatalIOErrorInFunction(coeffs)
            << solverType_ << ": entry 'coupling' must be a"
            << " dictionary of " << listed(couplingEntries).c_str()
            << ", e.g. coupling { addedMass on; addedMassInterval 10; }"
            << exit(FatalIOError);
    }

    for (const entry& e : coeffs.subOrEmptyDict("coupling"))
    {
        if (!couplingEntries.found(e.keyword()))
        {
            FatalIOErrorInFunction(coeffs.subDict("coupling"))
                << solverType_ << ": unknown coupling entry '"
                << e.keyword() << "'; the entries of coupling are "
                << listed(couplingEntries).c_str() << exit(FatalIOError);
        }
    }
}


void Foam::addedMassCoupling::read
(
    const dictionary& coeffs,
    const word& openFoamName,
    const wordList& openFoamEntries,
    const wordList& otherEntries,
    const bool otherCoeffs
)
{
    checkEntries
    (
        coeffs, openFoamName, openFoamEntries, otherEntries, otherCoeffs
    );

    const dictionary& dict = coeffs.subOrEmptyDict("coupling");

    const auto isWord = [](const token& t) { return t.isWord(); };
    const auto isLabel = [](const token& t) { return t.isLabel(); };
    const auto isNumber = [](const token& t) { return t.isNumber(); };
    const auto wordOf = [](const token& t) { return t.wordToken(); };
    const auto labelOf = [](const token& t) { return t.labelToken(); };
    const auto numberOf = [](const token& t) { return t.number(); };

    addedMass_ = couplingEntry<bool>
    (
        solverType_, dict, "addedMass", true,
        "a switch (on/off, true/false, yes/no)", isSwitch,
        [](const token& t) { return bool(switchOf(t)); }
    );
    pName_ = couplingEntry<word>
    (
        solverType_, dict, "pressure", "p_rgh", "the pressure field's name",
        isWord, wordOf
    );
    residualName_ = couplingEntry<word>
    (
        solverType_, dict, "residual", defaultResidual_, "a field name",
        isWord, wordOf
    );
    maxIter_ = couplingEntry<label>
    (
        solverType_, dict, "maxIter", 10, "an integer", isLabel, labelOf
    );
    addedMassInterval_ = couplingEntry<label>
    (
        solverType_, dict, "addedMassInterval", 10, "an integer", isLabel,
        labelOf
    );
    tolerance_ = couplingEntry<scalar>
    (
        solverType_, dict, "tolerance", 1e-9, "a number", isNumber, numberOf
    );

    if (maxIter_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "maxIter = " << maxIter_ << ": at least one Newton iteration"
            << " per outer corrector is needed" << exit(FatalIOError);
    }
    if (addedMassInterval_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "addedMassInterval = " << addedMassInterval_ << ": the"
            << " number of time steps between two added-mass estimates must"
            << " be at least 1" << exit(FatalIOError);
    }
    if (!(tolerance_ > 0 && tolerance_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "tolerance = " << tolerance_ << ": the relative tolerance of"
            << " the Newton iterations must be in (0, 1)"
            << exit(FatalIOError);
    }
    // Stable with one outer corrector, but far from converged there
    const dictionary& solution = mesh_.solutionDict();
    if
    (
        addedMass_
     && solution.found("PIMPLE")
     && solution.subDict("PIMPLE").lookupOrDefault<label>
        (
            "nOuterCorrectors", 1
        ) < 2
    )
    {
        WarningInFunction
            << solverType_ << ": PIMPLE nOuterCorrectors 1: the coupling is"
            << " stable, but one outer corrector leaves the flow, and so the"
            << " motion, far from converged (OpenFOAM's floatingObject box"
            << " at 100 and 30 kg/m^3: sway off by 69 % of its range"
            << " against a converged run, 11-12 % with 3 correctors); use 3"
            << " or more, or end the steps by the coupling residual"
            << " (docs/floating-stability.md, \"How many outer correctors\")"
            << endl;
    }

    if (addedMass_ && coeffs.found("accelerationRelaxation"))
    {
        const scalar aRelax =
            coeffs.get<scalar>("accelerationRelaxation");
        if (aRelax != 1)
        {
            FatalIOErrorInFunction(coeffs)
                << "accelerationRelaxation " << aRelax << " with the"
                << " added-mass coupling: the coupling converges without"
                << " relaxation, which would only slow it down; remove the"
                << " entry (or set coupling { addedMass off; } to run"
                << " OpenFOAM's relaxed coupling)" << exit(FatalIOError);
        }
    }
}



void Foam::addedMassCoupling::readSolver
(
    const dictionary& solverDict,
    const dictionary& coeffs,
    const word& openFoamName,
    const wordList& openFoamEntries
)
{
    const bool topLevel =
        !solverDict.found(word(solverType_ + "Coeffs"));

    read
    (
        coeffs,
        openFoamName,
        openFoamEntries,
        topLevel ? meshDictEntries : wordList(),
        topLevel
    );
}


// ************************************************************************* //
