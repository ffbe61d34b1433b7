/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "stageList.H"
#include "Ostream.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::SPH::stage* Foam::SPH::stageList::find(const word& name) const
{
    for (const stage& s : *this)
    {
        if (s.name() == name)
        {
            return &s;
        }
    }
    return nullptr;
}


void Foam::SPH::stageList::print(Ostream& os) const
{
    for (const stage& s : *this)
    {
        os  << "    " << s.title().c_str();
        for (label pad = s.title().size(); pad < 20; ++pad)
        {
            os  << ' ';
        }
        s.describe(os);
        os  << nl;
    }
}


void Foam::SPH::stageList::printStep(Ostream& os) const
{
    for (const stage& s : *this)
    {
        s.printStep(os);
    }
}


void Foam::SPH::stageList::expireReuse() const
{
    for (const stage& s : *this)
    {
        s.expireReuse();
    }
}


Foam::scalar Foam::SPH::stageList::seconds() const
{
    scalar total = 0;
    for (const stage& s : *this)
    {
        total += s.seconds();
    }
    return total;
}


void Foam::SPH::stageList::printTimes(Ostream& os) const
{
    const scalar total = seconds();
    if (total <= 0)
    {
        return;
    }
    os  << "Time in the steps: " << total << " s, of which";
    forAll(*this, i)
    {
        const stage& s = operator[](i);
        os  << (i ? ", " : " ") << s.name().c_str() << ' ' << s.seconds()
            << " s (" << label(100*s.seconds()/total + 0.5) << "%)";
    }
    os  << nl;
}


// ************************************************************************* //
