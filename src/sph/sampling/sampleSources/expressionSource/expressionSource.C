/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "expressionSource.H"
#include "fieldExprDriver.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(expressionSource, 0);
    addToRunTimeSelectionTable(sampleSource, expressionSource, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Classes * * * * * * * * * * * * * * * //

namespace
{
    //- OpenFOAM's field expression driver with the coordinates x and y as
    //- field variables
    class pointExprDriver
    :
        public Foam::expressions::fieldExpr::parseDriver
    {
    public:

        explicit pointExprDriver(const Foam::UList<Foam::vector2D>& points)
        :
            parseDriver(points.size())
        {
            Foam::scalarField x(points.size()), y(points.size());
            forAll(points, i)
            {
                x[i] = points[i].x();
                y[i] = points[i].y();
            }
            variables_.set("x", Foam::expressions::exprResult(x));
            variables_.set("y", Foam::expressions::exprResult(y));
        }
    };
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::expressionSource::expressionSource
(
    const word& name,
    const dictionary& dict,
    const options& opts
)
:
    sampleSource(name, dict)
{
    const dictionary& fieldsDict = dict_.subDict("fields");
    for (const entry& e : fieldsDict)
    {
        names_.append(e.keyword());
        expressions_.append(readText(fieldsDict, e.keyword()));
    }
    if (names_.empty())
    {
        FatalIOErrorInFunction(fieldsDict)
            << "Source " << name_ << ": entry 'fields' holds no expression"
            << " (e.g. fields { Ux \"y*(1 - y)\"; })" << nl
            << exit(FatalIOError);
    }

    // Parse each once now, so that a syntax error names the entry
    const List<vector2D> probe(1, vector2D(0.5, 0.5));
    forAll(names_, i)
    {
        const bool throwing = FatalError.throwExceptions();
        try
        {
            evaluate(expressions_[i], probe);
            FatalError.throwExceptions(throwing);
        }
        catch (const Foam::error& err)
        {
            FatalError.throwExceptions(throwing);
            FatalIOErrorInFunction(fieldsDict)
                << "Source " << name_ << ": cannot evaluate the expression of "
                << names_[i] << ", \"" << expressions_[i] << "\":" << nl
                << "    " << err.message().c_str() << nl
                << "(the variables are x and y)" << nl
                << exit(FatalIOError);
        }
    }

    Info<< "    expressions of x and y for " << names_ << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField> Foam::SPH::expressionSource::evaluate
(
    const string& expression,
    const UList<vector2D>& points
)
{
    pointExprDriver driver(points);
    driver.parse(expression);
    const expressions::exprResult& result = driver.result();
    if (!result.isType<scalar>())
    {
        FatalErrorInFunction
            << "Expression \"" << expression << "\" is not a scalar: give"
            << " each component on its own (Ux, Uy)" << nl
            << exit(FatalError);
    }

    const scalarField& values = result.cref<scalar>();
    if (values.size() == points.size())
    {
        return tmp<scalarField>::New(values);
    }
    // A constant expression gives one value
    return tmp<scalarField>::New(points.size(), values.empty() ? 0 : values[0]);
}


Foam::wordList Foam::SPH::expressionSource::components(const word& field) const
{
    return namedComponents(names_, field);
}


Foam::List<Foam::scalarField> Foam::SPH::expressionSource::sample
(
    const word& field,
    const UList<vector2D>& points
) const
{
    const wordList cmpts(components(field));
    List<scalarField> result(cmpts.size());
    forAll(cmpts, c)
    {
        const label i = names_.find(cmpts[c]);
        result[c] = scaleFactor(cmpts[c])*evaluate(expressions_[i], points);
    }
    return result;
}


// ************************************************************************* //
