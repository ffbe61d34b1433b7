/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

// VTK first: OpenFOAM's headers define macros (e.g. forAll) that VTK must not see
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>
#include <vtkXMLPolyDataReader.h>

#include "vtkPolyFileReader.H"
#include "DynamicList.H"
#include "OSspecific.H"
#include "error.H"

#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using dataArray = Foam::SPH::vtkPolyFileReader::dataArray;

//- Collects the reader's error messages, so they end up in our FatalError
//  (and are not printed a second time by VTK)
class errorCollector
:
    public vtkCommand
{
public:

    static errorCollector* New()
    {
        return new errorCollector;
    }

    void Execute(vtkObject*, unsigned long, void* callData) override
    {
        if (callData)
        {
            messages += static_cast<const char*>(callData);
        }
    }

    std::string messages;
};


//- The VTK XML name of an array's value type (Float64, Int32, UInt8, ...)
word xmlTypeName(vtkDataArray* array)
{
    const int type = array->GetDataType();
    const std::string bits = std::to_string(8*array->GetDataTypeSize());

    if (type == VTK_FLOAT || type == VTK_DOUBLE)
    {
        return "Float" + bits;
    }

    const bool isUnsigned =
        type == VTK_UNSIGNED_CHAR || type == VTK_UNSIGNED_SHORT
     || type == VTK_UNSIGNED_INT || type == VTK_UNSIGNED_LONG
     || type == VTK_UNSIGNED_LONG_LONG || type == VTK_BIT;

    return (isUnsigned ? "UInt" : "Int") + bits;
}


//- All numeric arrays of point or cell data; string arrays are skipped
List<dataArray> readArrays(vtkFieldData* data)
{
    DynamicList<dataArray> arrays;

    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
        vtkDataArray* array = data->GetArray(a);
        if (!array)
        {
            continue;
        }

        dataArray result;
        result.name = array->GetName() ? array->GetName() : "";
        result.type = xmlTypeName(array);

        const int nComp = array->GetNumberOfComponents();
        const label n = array->GetNumberOfTuples();

        result.components.setSize(nComp);
        for (int c = 0; c < nComp; ++c)
        {
            scalarList& values = result.components[c];
            values.setSize(n);
            for (label i = 0; i < n; ++i)
            {
                values[i] = array->GetComponent(i, c);
            }
        }

        arrays.append(result);
    }

    return List<dataArray>(std::move(arrays));
}


wordList namesOf(const UList<dataArray>& arrays)
{
    wordList names(arrays.size());
    forAll(arrays, i)
    {
        names[i] = arrays[i].name;
    }
    return names;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * dataArray  * * * * * * * * * * * * * * * * //

Foam::label Foam::SPH::vtkPolyFileReader::dataArray::size() const
{
    return components.empty() ? 0 : components[0].size();
}


Foam::scalarList Foam::SPH::vtkPolyFileReader::dataArray::scalars() const
{
    if (nComponents() != 1)
    {
        FatalErrorInFunction
            << "Array " << name << " has " << nComponents()
            << " components, not 1" << exit(FatalError);
    }
    return components[0];
}


Foam::labelList Foam::SPH::vtkPolyFileReader::dataArray::labels() const
{
    if (nComponents() != 1 || type.substr(0, 5) == "Float")
    {
        FatalErrorInFunction
            << "Array " << name << " is " << type << " with " << nComponents()
            << " components, not a 1-component integer array" << exit(FatalError);
    }

    labelList values(size());
    forAll(values, i)
    {
        values[i] = label(components[0][i]);
    }
    return values;
}


Foam::List<Foam::vector2D>
Foam::SPH::vtkPolyFileReader::dataArray::vector2Ds() const
{
    if (nComponents() != 2 && nComponents() != 3)
    {
        FatalErrorInFunction
            << "Array " << name << " has " << nComponents()
            << " components, not 2 or 3" << exit(FatalError);
    }

    List<vector2D> values(size());
    forAll(values, i)
    {
        values[i] = vector2D(components[0][i], components[1][i]);
    }
    return values;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::SPH::vtkPolyFileReader::dataArray& Foam::SPH::vtkPolyFileReader::find
(
    const UList<dataArray>& arrays,
    const word& name,
    const char* kind
) const
{
    forAll(arrays, i)
    {
        if (arrays[i].name == name)
        {
            return arrays[i];
        }
    }

    FatalErrorInFunction
        << "No " << kind << " data array " << name << " in " << file_ << nl
        << "    It has " << namesOf(arrays) << exit(FatalError);

    return arrays[0];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::vtkPolyFileReader::vtkPolyFileReader(const fileName& file)
:
    file_(file),
    points_(),
    nVertices_(0),
    lines_(),
    hasTime_(false),
    time_(0),
    pointData_(),
    cellData_()
{
    if (!isFile(file_, false))
    {
        FatalErrorInFunction
            << "Cannot read " << file_ << ": no such file" << exit(FatalError);
    }

    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();

    if (!reader->CanReadFile(file_.c_str()))
    {
        FatalErrorInFunction
            << "Cannot read " << file_ << ": not a VTK XML PolyData file"
            << exit(FatalError);
    }

    auto errors = vtkSmartPointer<errorCollector>::New();
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(file_.c_str());
    reader->Update();

    if (!errors->messages.empty() || reader->GetErrorCode() != 0)
    {
        FatalErrorInFunction
            << "Cannot read " << file_ << nl
            << "    VTK says: " << errors->messages.c_str() << exit(FatalError);
    }

    vtkPolyData* poly = reader->GetOutput();

    if (vtkPoints* pts = poly->GetPoints())
    {
        points_.setSize(pts->GetNumberOfPoints());
        forAll(points_, i)
        {
            double x[3];
            pts->GetPoint(i, x);
            points_[i] = vector2D(x[0], x[1]);
        }
    }

    nVertices_ = poly->GetNumberOfVerts();

    vtkCellArray* lines = poly->GetLines();
    lines_.setSize(lines ? lines->GetNumberOfCells() : 0);
    vtkNew<vtkIdList> ids;
    forAll(lines_, i)
    {
        lines->GetCellAtId(i, ids);
        if (ids->GetNumberOfIds() != 2)
        {
            FatalErrorInFunction
                << "Line cell " << i << " in " << file_ << " has "
                << label(ids->GetNumberOfIds())
                << " points; only 2-point lines are read" << exit(FatalError);
        }
        lines_[i] = labelPair(ids->GetId(0), ids->GetId(1));
    }

    if (vtkFieldData* fd = poly->GetFieldData())
    {
        vtkDataArray* t = fd->GetArray("TimeValue");
        if (t && t->GetNumberOfTuples() > 0)
        {
            hasTime_ = true;
            time_ = t->GetComponent(0, 0);
        }
    }

    pointData_ = readArrays(poly->GetPointData());
    cellData_ = readArrays(poly->GetCellData());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::SPH::vtkPolyFileReader::time() const
{
    if (!hasTime_)
    {
        FatalErrorInFunction
            << "No FieldData TimeValue in " << file_ << exit(FatalError);
    }
    return time_;
}


Foam::wordList Foam::SPH::vtkPolyFileReader::pointFieldNames() const
{
    return namesOf(pointData_);
}


Foam::wordList Foam::SPH::vtkPolyFileReader::cellFieldNames() const
{
    return namesOf(cellData_);
}


const Foam::SPH::vtkPolyFileReader::dataArray&
Foam::SPH::vtkPolyFileReader::pointField(const word& name) const
{
    return find(pointData_, name, "point");
}


const Foam::SPH::vtkPolyFileReader::dataArray&
Foam::SPH::vtkPolyFileReader::cellField(const word& name) const
{
    return find(cellData_, name, "cell");
}


// ************************************************************************* //
