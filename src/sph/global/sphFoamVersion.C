#include "sphFoamVersion.H"

const char* const Foam::SPH::version = "0.1";
