/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "wallNusselt.H"
#include "usawOperators.H"
#include "renormalisation.H"
#include "kernelDispatch.H"
#include "checkedEntry.H"
#include "mathematicalConstants.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace SPH
{
namespace functionObjects
{
    defineTypeNameAndDebug(wallNusselt, 0);
    addToRunTimeSelectionTable(functionObject, wallNusselt, dictionary);
}
}
}

const Foam::Enum<Foam::SPH::functionObjects::wallNusselt::wallGradientScheme>
Foam::SPH::functionObjects::wallNusselt::wallGradientSchemeNames
({
    { wallGradientScheme::gamma, "gamma" },
    { wallGradientScheme::renormalised, "renormalised" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::wallNusselt::gradT(List<vector2D>& result)
{
    const sphCloud& c = cloud();
    const label nFluid = c.nFluid();
    const wallMesh& walls = c.walls();
    const vector2DField& x = c.parts().positions();
    if (!usaw_)
    {
        usaw_.reset(new usawWalls(walls, c.W(), nFluid));
    }
    // V_b: dr^2, the vertex particles' share theta_v/(2 pi) of it
    scalarList V(c.size(), sqr(c.dr()));
    forAll(walls.pointAngles(), v)
    {
        V[nFluid + v] *= walls.pointAngles()[v]/constant::mathematical::twoPi;
    }
    nbrs_.build(c.cells(), x, c.W().support(), true);
    usaw_->update(x);
    result.setSize(c.size());
    const scalarField& T = c.parts().field<scalar>("T");
    dispatch(c.W(), [&](const auto& K)
    {
        if (gradScheme_ == wallGradientScheme::gamma)
        {
            usaw::gradMinus(K, nbrs_, *usaw_, V, T, result);
            return;
        }
        R_.setSize(c.size());
        // Below isphFoam's smallest det(G-{r}) a vertex keeps G-{T}
        usaw::renormalisation
        (
            K, nbrs_, *usaw_, V, x, renormalisation::minMomentDet, R_
        );
        usaw::gradMinus(K, nbrs_, *usaw_, V, R_, T, result);
    });
}


void Foam::SPH::functionObjects::wallNusselt::writeLocal() const
{
    const wallMesh& walls = cloud().walls();
    const domain& dom = cloud().dom();
    const fileName dir
    (
        outputDir().path()/time_.timeName()
    );
    mkDir(dir);
    forAll(walls.patchNames(), p)
    {
        if (!selected_[p]) continue;
        OFstream os(dir/walls.patchNames()[p] + ".xy");
        os.precision(writePrecision_);
        os  << "# x y Nu" << nl;
        forAll(walls.segments(), s)
        {
            if (walls.segmentPatch()[s] != p) continue;
            const labelPair& e = walls.segments()[s];
            // Minimum image: a segment may cross a periodic seam
            const vector2D& x1 = walls.points()[e.first()];
            const vector2D mid
            (
                dom.wrap(x1 + 0.5*dom.separation(walls.points()[e.second()], x1))
            );
            os  << mid.x() << ' ' << mid.y() << ' ' << Nu_[s] << nl;
        }
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::SPH::functionObjects::wallNusselt::measure()
{
    const sphCloud& c = cloud();
    const wallMesh& walls = c.walls();
    const label nFluid = c.nFluid();
    const label nPatches = walls.patchNames().size();
    List<vector2D> G;
    gradT(G);

    // Eq. (42) with the segment's gradient the mean of its vertices'
    min_ = scalarList(nPatches, VGREAT);
    max_ = scalarList(nPatches, -VGREAT);
    integral_ = scalarList(nPatches, Zero);
    length_ = scalarList(nPatches, Zero);
    Nu_.setSize(walls.segments().size());
    forAll(walls.segments(), s)
    {
        const labelPair& e = walls.segments()[s];
        const vector2D Gs(0.5*(G[nFluid + e.first()] + G[nFluid + e.second()]));
        Nu_[s] = L_/DeltaT_*mag(Gs & walls.segmentNormals()[s]);
        const label p = walls.segmentPatch()[s];
        const scalar len = mag
        (
            c.dom().separation(walls.points()[e.second()], walls.points()[e.first()])
        );
        min_[p] = Foam::min(min_[p], Nu_[s]);
        max_[p] = Foam::max(max_[p], Nu_[s]);
        integral_[p] += Nu_[s]*len;
        length_[p] += len;
    }
}


void Foam::SPH::functionObjects::wallNusselt::writeLog() const
{
    const wordList& names = cloud().walls().patchNames();
    forAll(names, p)
    {
        if (!selected_[p] || !(length_[p] > 0)) continue;
        Info<< "    patch " << names[p] << " Nu : min = " << min_[p]
            << ", max = " << max_[p] << ", average = "
            << integral_[p]/length_[p] << endl;
    }
}


void Foam::SPH::functionObjects::wallNusselt::writeFiles()
{
    if (!filePtr_.valid())
    {
        filePtr_ = createFile(fileName_);
        OFstream& os = filePtr_();
        writeHeader(os, "Wall Nusselt number");
        writeCommented(os, "Time");
        writeTabbed(os, "patch");
        writeTabbed(os, "min");
        writeTabbed(os, "max");
        writeTabbed(os, "integral");
        writeTabbed(os, "average");
        os  << endl;
    }
    OFstream& os = file();
    const wordList& names = cloud().walls().patchNames();
    forAll(names, p)
    {
        if (!selected_[p] || !(length_[p] > 0)) continue;
        writeCurrentTime(os);
        os  << tab << names[p] << tab << min_[p] << tab << max_[p] << tab
            << integral_[p] << tab << integral_[p]/length_[p] << endl;
    }
    if (time_.writeTime())
    {
        writeLocal();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::functionObjects::wallNusselt::wallNusselt
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    sphFunctionObject(name, runTime, dict, typeName),
    L_(checkedScalar(dict, "L", {0, VGREAT, true}, "reference length of eq. (42)")),
    DeltaT_
    (
        checkedScalar
        (
            dict, "DeltaT", {0, VGREAT, true},
            "reference temperature difference of eq. (42)"
        )
    ),
    gradScheme_
    (
        wallGradientSchemeNames.getOrDefault
        (
            "wallGradient", dict, wallGradientScheme::renormalised
        )
    ),
    nbrs_(true)
{
    read(dict);
    const sphCloud& c = lookupCloud(name, runTime, dict);
    const wordList& names = c.walls().patchNames();
    selected_.setSize(names.size(), true);
    if (dict.found("patches"))
    {
        const wordRes patches(dict.get<wordRes>("patches"));
        forAll(names, p)
        {
            selected_[p] = patches.match(names[p]);
        }
        for (const wordRe& w : patches)
        {
            bool any = false;
            for (const word& n : names) any = any || w.match(n);
            if (!any)
            {
                FatalIOErrorInFunction(dict)
                    << "Function object " << name << ": patches entry " << w
                    << " names no wall patch; the wall patches are "
                    << inParentheses(names) << exit(FatalIOError);
            }
        }
    }
    if (!c.parts().found<scalar>("T"))
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name << " (wallNusselt) needs the"
            << " temperature T: the case has no 0/T" << exit(FatalIOError);
    }
    if (c.size() - c.nFluid() != c.walls().points().size())
    {
        FatalIOErrorInFunction(dict)
            << "Function object " << name << " (wallNusselt) needs USAW wall"
            << " vertex particles (isphFoam)" << exit(FatalIOError);
    }
}


// ************************************************************************* //
