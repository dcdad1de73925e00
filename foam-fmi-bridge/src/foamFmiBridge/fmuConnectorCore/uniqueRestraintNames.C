// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "uniqueRestraintNames.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "HashTable.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The file a dictionary name starts with (the longest leading part that
//  is a file, ending before a '.' or '/') and the keywords after it; an
//  empty file when no part is a file
void splitName
(
    const Foam::string& name,
    Foam::fileName& file,
    Foam::wordList& keywords
)
{
    file.clear();
    keywords.clear();
    std::string::size_type end = std::string::npos;
    for (std::string::size_type i = 1; i < name.size(); ++i)
    {
        if ((name[i] == '.' || name[i] == '/') && Foam::isFile(name.substr(0, i)))
        {
            end = i;
        }
    }
    if (end == std::string::npos)
    {
        return;
    }
    file = name.substr(0, end);

    const char separator = name[end];
    std::string::size_type start = end + 1;
    while (start <= name.size())
    {
        const std::string::size_type next = name.find(separator, start);
        const std::string::size_type stop =
            next == std::string::npos ? name.size() : next;
        keywords.append(Foam::word(name.substr(start, stop - start), false));
        start = stop + 1;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::checkUniqueRestraintNames(const dictionary& restraintDict)
{
    fileName file;
    wordList scope;
    splitName(restraintDict.name(), file, scope);
    if (file.empty() || scope.size() < 2)
    {
        return;
    }
    // The keywords down to the restraints dictionary
    scope.resize(scope.size() - 1);

    // Keywords of the open blocks, the last word read (a keyword when a
    // '{' follows), and the line of each restraint in the restraints
    // dictionary
    wordList open;
    word lastWord;
    label lastLine = 0;
    HashTable<label> lines;

    IFstream is(file);
    token t;
    while (is.good() && !is.read(t).bad() && t.good())
    {
        if (t.isPunctuation() && t.pToken() == token::BEGIN_BLOCK)
        {
            if (open == scope && lastWord.size())
            {
                if (lines.found(lastWord))
                {
                    FatalIOErrorInFunction(restraintDict)
                        << "restraint " << lastWord << " is given twice in "
                        << file << " (lines " << lines[lastWord] << " and "
                        << lastLine << "): OpenFOAM would keep the"
                        << " last one's entries only, merged into the"
                        << " first. Give each restraint a name of its own"
                        << exit(FatalIOError);
                }
                lines.insert(lastWord, lastLine);
            }
            open.append(lastWord);
            lastWord.clear();
        }
        else if (t.isPunctuation() && t.pToken() == token::END_BLOCK)
        {
            if (open.size())
            {
                open.resize(open.size() - 1);
            }
            lastWord.clear();
        }
        else if (t.isWord() || t.isString())
        {
            // The header's format: a binary file's lists (a field file's
            // initialPoints) are read as OpenFOAM reads them
            if
            (
                t.isWord()
             && lastWord == "format"
             && open.size() == 1
             && open.first() == "FoamFile"
            )
            {
                is.format(t.wordToken());
            }
            lastWord =
                t.isWord() ? t.wordToken() : word(t.stringToken(), false);
            lastLine = t.lineNumber();
        }
        else
        {
            lastWord.clear();
        }
    }
}


// ************************************************************************* //
