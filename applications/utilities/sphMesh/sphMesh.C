#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "sphFoamVersion.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::addNote("Generate SPH particles and walls");
    #include "setRootCase.H"
    #include "createTime.H"
    Info<< "sphFoam " << SPH::version << nl << endl;
    Info<< "End" << nl << endl;
    return 0;
}
