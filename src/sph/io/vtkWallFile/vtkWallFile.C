/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "vtkWallFile.H"
#include "error.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

Foam::List<Foam::labelPair> pairs
(
    const Foam::UList<Foam::label>& start,
    const Foam::UList<Foam::label>& end
)
{
    if (start.size() != end.size())
    {
        FatalErrorInFunction
            << "Wall segments have " << start.size() << " start and "
            << end.size() << " end indices" << Foam::exit(Foam::FatalError);
    }

    Foam::List<Foam::labelPair> segments(start.size());
    forAll(segments, i)
    {
        segments[i] = Foam::labelPair(start[i], end[i]);
    }
    return segments;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::vtkWallFile::vtkWallFile
(
    const UList<vector2D>& vertices,
    const UList<labelPair>& segments
)
:
    vtkPolyFile(vertices)
{
    insertLines(segments, "Wall segment");
}


Foam::SPH::vtkWallFile::vtkWallFile
(
    const UList<vector2D>& vertices,
    const UList<label>& segmentStart,
    const UList<label>& segmentEnd
)
:
    vtkWallFile(vertices, pairs(segmentStart, segmentEnd))
{}


// ************************************************************************* //
