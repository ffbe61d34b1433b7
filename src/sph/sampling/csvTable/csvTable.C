/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "csvTable.H"
#include "stringOps.H"
#include "DynamicList.H"

#include <cstdlib>
#include <fstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- Split a line at the delimiter (',') or at white space (' ')
    Foam::List<Foam::string> splitLine(const std::string& line, const char delim)
    {
        Foam::DynamicList<Foam::string> items;
        if (delim == ',')
        {
            std::string::size_type start = 0;
            while (true)
            {
                const auto end = line.find(',', start);
                Foam::string item(line.substr(start, end - start));
                Foam::stringOps::inplaceTrim(item);
                items.append(item);
                if (end == std::string::npos) break;
                start = end + 1;
            }
        }
        else
        {
            for (const auto& sub : Foam::stringOps::splitSpace(line))
            {
                items.append(Foam::string(sub.str()));
            }
        }
        return items;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::csvTable::csvTable(const fileName& file)
:
    file_(file),
    nRows_(0)
{
    std::ifstream is(file_);
    if (!is)
    {
        FatalErrorInFunction
            << "Cannot open the table file " << file_ << nl
            << exit(FatalError);
    }

    List<DynamicList<scalar>> values;
    char delim = ' ';
    label lineNo = 0;
    std::string line;
    while (std::getline(is, line))
    {
        ++lineNo;
        string trimmed(line);
        stringOps::inplaceTrim(trimmed);
        if (trimmed.empty() || trimmed[0] == '#')
        {
            continue;
        }

        if (names_.empty())
        {
            delim = (trimmed.find(',') != std::string::npos) ? ',' : ' ';
            names_ = splitLine(trimmed, delim);
            values.setSize(names_.size());
        }
        else
        {
            const List<string> items(splitLine(trimmed, delim));
            if (items.size() != names_.size())
            {
                FatalErrorInFunction
                    << "Line " << lineNo << " of " << file_ << " holds "
                    << items.size() << " values but the header names "
                    << names_.size() << " columns" << nl
                    << exit(FatalError);
            }
            forAll(items, c)
            {
                char* end = nullptr;
                const scalar v = std::strtod(items[c].c_str(), &end);
                if (items[c].empty() || *end != '\0')
                {
                    FatalErrorInFunction
                        << "Line " << lineNo << " of " << file_
                        << ": value '" << items[c] << "' of column "
                        << names_[c] << " is not a number" << nl
                        << exit(FatalError);
                }
                values[c].append(v);
            }
            ++nRows_;
        }
    }

    if (names_.empty())
    {
        FatalErrorInFunction
            << "The table file " << file_ << " holds no header line (column"
            << " names) after its '#' comments" << nl
            << exit(FatalError);
    }

    forAll(names_, c)
    {
        columns_.set(names_[c], scalarField(std::move(values[c])));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::SPH::csvTable::namesLine() const
{
    string line;
    for (const string& name : names_)
    {
        line += (line.empty() ? "" : " ") + name;
    }
    return line;
}


const Foam::scalarField& Foam::SPH::csvTable::column(const string& name) const
{
    const auto iter = columns_.cfind(name);
    if (!iter.found())
    {
        FatalErrorInFunction
            << "No column '" << name.c_str() << "' in " << file_ << nl
            << "Columns: " << namesLine().c_str() << nl
            << exit(FatalError);
    }
    return *iter;
}


// ************************************************************************* //
