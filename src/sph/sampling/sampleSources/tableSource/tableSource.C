/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "tableSource.H"
#include "errorNorms.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(tableSource, 0);
    addToRunTimeSelectionTable(sampleSource, tableSource, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::scalarField& Foam::SPH::tableSource::column
(
    const dictionary& dict,
    const word& key
) const
{
    const string name(readText(dict, key));
    if (!table_->found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "': no column '" << name.c_str() << "' in "
            << file_ << nl
            << "Columns: " << table_->namesLine().c_str() << nl
            << exit(FatalIOError);
    }
    return table_->column(name);
}


Foam::scalarField Foam::SPH::tableSource::coordinate(const word& key) const
{
    ITstream& is = dict_.lookup(key);
    const token t(is);
    if (t.isNumber())
    {
        return scalarField(table_->nRows(), t.number());
    }
    return column(dict_, key);
}


Foam::labelList Foam::SPH::tableSource::findRows
(
    const UList<vector2D>& points
) const
{
    // A point is on a row when they agree to round-off of the table's size
    scalar span = 0;
    for (const vector2D& p : points_)
    {
        span = max(span, cmptMax(cmptMag(p)));
    }
    const scalar tol = 1e-9*max(span, scalar(1));

    labelList rows(points.size(), -1);
    forAll(points, i)
    {
        forAll(points_, r)
        {
            if (cmptMax(cmptMag(points[i] - points_[r])) <= tol)
            {
                rows[i] = r;
                break;
            }
        }
    }
    return rows;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::tableSource::tableSource
(
    const word& name,
    const dictionary& dict,
    const options& opts
)
:
    sampleSource(name, dict),
    file_(readPath("file", opts.baseDir))
{
    if (file_.empty() || !isFile(file_))
    {
        FatalIOErrorInFunction(dict_)
            << "Source " << name_ << ": entry 'file': cannot read the table "
            << (file_.empty() ? fileName("(none given)") : file_) << nl
            << exit(FatalIOError);
    }
    table_.reset(new csvTable(file_));

    const scalarField x(coordinate("x"));
    const scalarField y(coordinate("y"));
    points_.setSize(table_->nRows());
    forAll(points_, r)
    {
        points_[r] = vector2D(x[r], y[r]);
    }

    const dictionary& columnsDict = dict_.subDict("columns");
    for (const entry& e : columnsDict)
    {
        const word& cmpt = e.keyword();
        values_.set(cmpt, scalarField(scaleFactor(cmpt)*column(columnsDict, cmpt)));
        names_.append(cmpt);
    }
    if (names_.empty())
    {
        FatalIOErrorInFunction(columnsDict)
            << "Source " << name_ << ": entry 'columns' names no column"
            << " (e.g. columns { Ux Re100; })" << nl << exit(FatalIOError);
    }

    Info<< "    table " << file_.name() << ": " << points_.size()
        << " rows, " << names_ << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::wordList Foam::SPH::tableSource::components(const word& field) const
{
    return namedComponents(names_, field);
}


Foam::List<Foam::scalarField> Foam::SPH::tableSource::sample
(
    const word& field,
    const UList<vector2D>& points
) const
{
    const labelList rows(findRows(points));
    const wordList cmpts(components(field));

    List<scalarField> result(cmpts.size());
    forAll(cmpts, c)
    {
        const scalarField& v = values_[cmpts[c]];
        result[c].setSize(points.size());
        forAll(points, i)
        {
            result[c][i] = rows[i] < 0 ? errorNorms::missing() : v[rows[i]];
        }
    }
    return result;
}


void Foam::SPH::tableSource::ownPoints
(
    List<vector2D>& points,
    scalarField& weights
) const
{
    points = points_;
    weights = scalarField(points_.size(), 1.0);
}


// ************************************************************************* //
