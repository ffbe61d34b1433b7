/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

// VTK first: OpenFOAM's headers define macros (e.g. forAll) that VTK must not see
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkXMLPolyDataWriter.h>

#include "vtkPolyFile.H"

#include <cstring>
#include "vtkAtomicFile.H"
#include "error.H"

#include <cmath>

// * * * * * * * * * * * * * * Private Data Class  * * * * * * * * * * * * * //

struct Foam::SPH::vtkPolyFile::vtkData
{
    vtkSmartPointer<vtkPolyData> poly = vtkSmartPointer<vtkPolyData>::New();
};


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

vtkSmartPointer<vtkDataArray> newArray(const word& name, const UList<scalar>& values)
{
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name.c_str());
    array->SetNumberOfComponents(1);
    array->SetNumberOfTuples(values.size());
    for (label i = 0; i < values.size(); ++i)
    {
        array->SetValue(i, values[i]);
    }
    return array;
}


vtkSmartPointer<vtkDataArray> newArray(const word& name, const UList<vector2D>& values)
{
    // Three components, so ParaView treats the array as a vector (glyphs,
    // magnitude) and it matches OpenFOAM's 3-component U of a 2-D case
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name.c_str());
    array->SetNumberOfComponents(3);
    array->SetNumberOfTuples(values.size());
    for (label i = 0; i < values.size(); ++i)
    {
        array->SetValue(3*i, values[i].x());
        array->SetValue(3*i + 1, values[i].y());
        array->SetValue(3*i + 2, 0);
    }
    return array;
}


vtkSmartPointer<vtkDataArray> newArray(const word& name, const UList<label>& values)
{
    // The build has 32-bit labels (WM_LABEL_SIZE=32); a 64-bit label build
    // would need Int64 here
    static_assert(sizeof(label) == 4, "Int32 arrays assume 32-bit labels");

    auto array = vtkSmartPointer<vtkTypeInt32Array>::New();
    array->SetName(name.c_str());
    array->SetNumberOfComponents(1);
    array->SetNumberOfTuples(values.size());
    for (label i = 0; i < values.size(); ++i)
    {
        array->SetValue(i, values[i]);
    }
    return array;
}


//- Cells from their point lists in VTK's offsets + connectivity form
vtkSmartPointer<vtkCellArray> newCells
(
    const label nCells,
    const label nPointsPerCell,
    const UList<label>& connectivity
)
{
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfTuples(nCells + 1);
    for (label i = 0; i <= nCells; ++i)
    {
        offsets->SetValue(i, vtkIdType(nPointsPerCell)*i);
    }

    auto points = vtkSmartPointer<vtkIdTypeArray>::New();
    points->SetNumberOfTuples(connectivity.size());
    for (label i = 0; i < connectivity.size(); ++i)
    {
        points->SetValue(i, connectivity[i]);
    }

    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(offsets, points);
    return cells;
}


//- Why vtkXMLPolyDataWriter failed, in words (VTK prints its own message too)
std::string writeFailure(const unsigned long code)
{
    switch (code)
    {
        case vtkErrorCode::OutOfDiskSpaceError:
            return "vtkXMLPolyDataWriter ran out of disk space";
        case vtkErrorCode::CannotOpenFileError:
            return "vtkXMLPolyDataWriter could not open the temporary file";
        default:
            // Below VTK's own codes (FirstVTKErrorCode), a system
            // errno: 28 is a full disk
            return
                "vtkXMLPolyDataWriter failed with error code "
              + std::to_string(code)
              + (
                    code < vtkErrorCode::FirstVTKErrorCode
                  ? " (" + std::string(std::strerror(int(code))) + ")"
                  : std::string()
                );
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::vtkPolyFile::checkNewArray
(
    const word& name,
    const label size,
    const bool pointData
) const
{
    const char* kind = pointData ? "point" : "cell";
    const label expected = pointData ? nPoints() : nCells();

    vtkFieldData* data =
        pointData
      ? static_cast<vtkFieldData*>(vtk_->poly->GetPointData())
      : static_cast<vtkFieldData*>(vtk_->poly->GetCellData());

    if (name.empty())
    {
        FatalErrorInFunction
            << "A " << kind << " field needs a name" << exit(FatalError);
    }

    if (data->HasArray(name.c_str()))
    {
        FatalErrorInFunction
            << "The " << kind << " field " << name << " was already added"
            << exit(FatalError);
    }

    if (size != expected)
    {
        FatalErrorInFunction
            << "The " << kind << " field " << name << " has " << size
            << " values for " << expected << ' ' << kind << 's'
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::vtkPolyFile::vtkPolyFile(const UList<vector2D>& points)
:
    vtk_(new vtkData)
{
    // Float64 coordinates, so positions read back are exactly those written
    auto coords = vtkSmartPointer<vtkDoubleArray>::New();
    coords->SetNumberOfComponents(3);
    coords->SetNumberOfTuples(points.size());
    for (label i = 0; i < points.size(); ++i)
    {
        coords->SetValue(3*i, points[i].x());
        coords->SetValue(3*i + 1, points[i].y());
        coords->SetValue(3*i + 2, 0);
    }

    auto vtkPts = vtkSmartPointer<vtkPoints>::New();
    vtkPts->SetData(coords);
    vtk_->poly->SetPoints(vtkPts);
}


Foam::SPH::vtkPolyFile::vtkPolyFile(vtkPolyFile&&) = default;


Foam::SPH::vtkPolyFile& Foam::SPH::vtkPolyFile::operator=(vtkPolyFile&&) = default;


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::SPH::vtkPolyFile::~vtkPolyFile() = default;


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::SPH::vtkPolyFile::insertVertices()
{
    const label n = nPoints();

    labelList connectivity(n);
    for (label i = 0; i < n; ++i)
    {
        connectivity[i] = i;
    }

    vtk_->poly->SetVerts(newCells(n, 1, connectivity));
}


void Foam::SPH::vtkPolyFile::insertLines
(
    const UList<labelPair>& segments,
    const char* what
)
{
    const label n = nPoints();

    labelList connectivity(2*segments.size());
    for (label i = 0; i < segments.size(); ++i)
    {
        const labelPair& s = segments[i];

        if (s.first() < 0 || s.first() >= n || s.second() < 0 || s.second() >= n)
        {
            FatalErrorInFunction
                << what << ' ' << i << " joins points " << s.first() << " and "
                << s.second() << ", but the points are numbered 0 to " << n - 1
                << exit(FatalError);
        }

        connectivity[2*i] = s.first();
        connectivity[2*i + 1] = s.second();
    }

    vtk_->poly->SetLines(newCells(segments.size(), 2, connectivity));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::SPH::vtkPolyFile::nPoints() const
{
    return vtk_->poly->GetNumberOfPoints();
}


Foam::label Foam::SPH::vtkPolyFile::nCells() const
{
    return vtk_->poly->GetNumberOfCells();
}


Foam::wordList Foam::SPH::vtkPolyFile::pointFieldNames() const
{
    vtkPointData* data = vtk_->poly->GetPointData();

    wordList names(data->GetNumberOfArrays());
    forAll(names, i)
    {
        names[i] = data->GetArrayName(i);
    }
    return names;
}


Foam::wordList Foam::SPH::vtkPolyFile::cellFieldNames() const
{
    vtkCellData* data = vtk_->poly->GetCellData();

    wordList names(data->GetNumberOfArrays());
    forAll(names, i)
    {
        names[i] = data->GetArrayName(i);
    }
    return names;
}


template<class Type>
void Foam::SPH::vtkPolyFile::addPointField
(
    const word& name,
    const UList<Type>& values
)
{
    checkNewArray(name, values.size(), true);
    vtk_->poly->GetPointData()->AddArray(newArray(name, values));
}


template<class Type>
void Foam::SPH::vtkPolyFile::addCellField
(
    const word& name,
    const UList<Type>& values
)
{
    checkNewArray(name, values.size(), false);
    vtk_->poly->GetCellData()->AddArray(newArray(name, values));
}


// The three field types a file can hold
#define makeVtkPolyFileFields(Type)                                            \
    template void Foam::SPH::vtkPolyFile::addPointField                        \
    (const word&, const UList<Type>&);                                          \
    template void Foam::SPH::vtkPolyFile::addCellField                         \
    (const word&, const UList<Type>&);

makeVtkPolyFileFields(Foam::scalar)
makeVtkPolyFileFields(Foam::vector2D)
makeVtkPolyFileFields(Foam::label)

#undef makeVtkPolyFileFields


void Foam::SPH::vtkPolyFile::write(const fileName& file, const scalar time) const
{
    if (!std::isfinite(time))
    {
        FatalErrorInFunction
            << "Cannot write " << file << " at time " << time
            << ": the time is not a finite number" << exit(FatalError);
    }

    vtkAtomicFile out(file);

    // TimeValue goes on a shallow copy, so write() leaves this object as it
    // was and the same file may be written at several times
    auto timeValue = vtkSmartPointer<vtkDoubleArray>::New();
    timeValue->SetName("TimeValue");
    timeValue->SetNumberOfTuples(1);
    timeValue->SetValue(0, time);

    auto fieldData = vtkSmartPointer<vtkFieldData>::New();
    fieldData->AddArray(timeValue);

    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->ShallowCopy(vtk_->poly);
    poly->SetFieldData(fieldData);

    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetInputData(poly);
    writer->SetFileName(out.tmpName().c_str());
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToZLib();
    writer->SetHeaderTypeToUInt64();

    if (writer->Write() != 1 || writer->GetErrorCode() != vtkErrorCode::NoError)
    {
        out.fail(writeFailure(writer->GetErrorCode()));
    }

    out.commit();
}


// ************************************************************************* //
