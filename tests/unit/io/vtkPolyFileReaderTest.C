/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.

Description
    vtkPolyFileReader: files it cannot read are FatalErrors naming the file,
    and asking for an array that is not there lists the ones that are.

\*---------------------------------------------------------------------------*/

#include "vtkParticleFile.H"
#include "vtkPolyFileReader.H"
#include "vtkTestTools.H"

#include <fstream>

using namespace Foam;
using namespace vtkTest;


TEST(vtkPolyFileReader, missingFileIsFatal)
{
    const fileName file(freshDir()/"none.vtp");

    const std::string message = fatalMessage([&]{ SPH::vtkPolyFileReader{file}; });

    EXPECT_NE(message.find(file), std::string::npos) << message;
}


TEST(vtkPolyFileReader, notVtkIsFatal)
{
    const fileName file(freshDir()/"garbage.vtp");
    std::ofstream(file) << "<?xml version=\"1.0\"?>\n<nothing/>\n";

    throwingErrors guard;
    EXPECT_THROW(SPH::vtkPolyFileReader{file}, Foam::error);
}


TEST(vtkPolyFileReader, truncatedFileIsFatal)
{
    // What a crash while writing straight into the file would have left
    const fileName dir(freshDir());
    SPH::vtkParticleFile particles(List<vector2D>(1000, vector2D(1, 2)));
    particles.addPointField("p", scalarList(1000, 3.0));
    particles.write(dir/"whole.vtp", 0);

    std::ifstream in(dir/"whole.vtp", std::ios::binary);
    const std::string bytes
    (
        (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()
    );
    std::ofstream(dir/"half.vtp", std::ios::binary) << bytes.substr(0, bytes.size()/2);

    throwingErrors guard;
    EXPECT_THROW(SPH::vtkPolyFileReader{dir/"half.vtp"}, Foam::error);
}


TEST(vtkPolyFileReader, missingArrayListsThePresentOnes)
{
    const fileName file(freshDir()/"particles.vtp");
    SPH::vtkParticleFile particles(List<vector2D>({vector2D(0, 0)}));
    particles.addPointField("p", scalarList({1}));
    particles.addPointField("U", List<vector2D>({vector2D(1, 2)}));
    particles.write(file, 0);

    const SPH::vtkPolyFileReader vtp(file);

    const std::string message = fatalMessage([&]{ vtp.pointField("rho"); });
    EXPECT_NE(message.find("rho"), std::string::npos) << message;
    EXPECT_NE(message.find("U"), std::string::npos) << message;

    // Type checks of the accessors
    throwingErrors guard;
    EXPECT_THROW(vtp.pointField("U").scalars(), Foam::error);
    EXPECT_THROW(vtp.pointField("p").labels(), Foam::error);
    EXPECT_THROW(vtp.pointField("p").vector2Ds(), Foam::error);
}


// ************************************************************************* //
