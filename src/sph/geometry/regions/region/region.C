/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "region.H"
#include "scalarList.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
    defineTypeNameAndDebug(region, 0);
    defineRunTimeSelectionTable(region, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- True if the components xy make a point: (x y), or (x y z) with z ignored
bool isPoint(const Foam::scalarList& xy)
{
    return xy.size() == 2 || xy.size() == 3;
}

} // End anonymous namespace


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::vector2D Foam::SPH::region::readPoint
(
    const dictionary& dict,
    const word& key
)
{
    const scalarList xy(dict.get<scalarList>(key));

    if (!isPoint(xy))
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << key << " is " << xy << " with " << xy.size()
            << " components: expected a 2-D point (x y), or (x y z) with z"
            << " ignored" << nl
            << exit(FatalIOError);
    }

    return vector2D(xy[0], xy[1]);
}


Foam::List<Foam::vector2D> Foam::SPH::region::readPoints
(
    const dictionary& dict,
    const word& key
)
{
    const List<scalarList> xys(dict.get<List<scalarList>>(key));

    List<vector2D> points(xys.size());

    forAll(xys, i)
    {
        if (!isPoint(xys[i]))
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << key << ": point " << i << " is " << xys[i]
                << " with " << xys[i].size() << " components: expected 2-D"
                << " points ((x y) (x y) ...), or (x y z) with z ignored" << nl
                << exit(FatalIOError);
        }

        points[i] = vector2D(xys[i][0], xys[i][1]);
    }

    return points;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::region::region(const word& name)
:
    name_(name)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::word& Foam::SPH::region::name() const
{
    return name_;
}


// ************************************************************************* //
