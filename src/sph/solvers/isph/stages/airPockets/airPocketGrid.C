/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "airPocketGrid.H"
#include "error.H"
#include "DynamicList.H"
#include <deque>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::SPH::airPocketGrid::wrappedIndex(label i, label j) const
{
    FixedList<label, 2> ij({i, j});
    for (direction d = 0; d < 2; ++d)
    {
        if (dom_.periodic(d))
        {
            ij[d] = ((ij[d] % n_[d]) + n_[d]) % n_[d];
        }
        else if (ij[d] < 0 || ij[d] >= n_[d])
        {
            return -1;
        }
    }
    return index(ij[0], ij[1]);
}


Foam::label Foam::SPH::airPocketGrid::cellOf(const vector2D& x) const
{
    const vector2D xw(dom_.wrap(x));
    const scalar i = std::floor((xw.x() - origin_.x())/c_.x());
    const scalar j = std::floor((xw.y() - origin_.y())/c_.y());
    if (!(std::abs(i) < labelMax/4 && std::abs(j) < labelMax/4))
    {
        return -1;
    }
    return wrappedIndex(label(i), label(j));
}


Foam::FixedList<Foam::label, 4>
Foam::SPH::airPocketGrid::neighbours(const label k) const
{
    const label i = k % n_[0];
    const label j = k/n_[0];
    return FixedList<label, 4>
    ({
        wrappedIndex(i - 1, j), wrappedIndex(i + 1, j),
        wrappedIndex(i, j - 1), wrappedIndex(i, j + 1)
    });
}


bool Foam::SPH::airPocketGrid::onBorder(const label k) const
{
    const FixedList<label, 2> ij({k % n_[0], k/n_[0]});
    for (direction d = 0; d < 2; ++d)
    {
        if (!dom_.periodic(d) && (ij[d] == 0 || ij[d] == n_[d] - 1))
        {
            return true;
        }
    }
    return false;
}


void Foam::SPH::airPocketGrid::stampDistances(const UList<vector2D>& fluid)
{
    // Each particle lowers the distance of the cells within dr + a cell of
    // it; cell centres are taken unwrapped about the particle's own cell
    dist_ = GREAT;
    const label mi = label(std::ceil(dr_/c_.x())) + 1;
    const label mj = label(std::ceil(dr_/c_.y())) + 1;
    for (const vector2D& x0 : fluid)
    {
        const vector2D x(dom_.wrap(x0) - origin_);
        const scalar fi = std::floor(x.x()/c_.x());
        const scalar fj = std::floor(x.y()/c_.y());
        if (!(fi > -mi - 1 && fi < n_[0] + mi && fj > -mj - 1 && fj < n_[1] + mj))
        {
            continue;
        }
        const label i0 = label(fi);
        const label j0 = label(fj);
        for (label j = j0 - mj; j <= j0 + mj; ++j)
        {
            for (label i = i0 - mi; i <= i0 + mi; ++i)
            {
                const label k = wrappedIndex(i, j);
                if (k < 0) continue;
                const vector2D centre((i + 0.5)*c_.x(), (j + 0.5)*c_.y());
                dist_[k] = min(dist_[k], mag(centre - x));
            }
        }
    }
}


template<class Passes>
Foam::label Foam::SPH::airPocketGrid::flood
(
    labelList& lbl,
    const Passes& passes,
    DynamicList<label>& nCells,
    DynamicList<bool>& border,
    DynamicList<bool>* wet
) const
{
    // lbl: -1 for a cell still to label where passes(k), anything else
    // where not
    std::deque<label> front;
    forAll(lbl, seed)
    {
        if (lbl[seed] != -1) continue;
        const label r = nCells.size();
        nCells.append(0);
        border.append(false);
        if (wet) wet->append(false);
        lbl[seed] = r;
        front.push_back(seed);
        while (!front.empty())
        {
            const label k = front.front();
            front.pop_front();
            ++nCells[r];
            border[r] = border[r] || onBorder(k);
            for (const label nb : neighbours(k))
            {
                if (nb < 0) continue;
                if (wet && label_[nb] == water) (*wet)[r] = true;
                if (lbl[nb] == -1 && passes(nb))
                {
                    lbl[nb] = r;
                    front.push_back(nb);
                }
            }
        }
    }
    return nCells.size();
}


Foam::label Foam::SPH::airPocketGrid::labelRegions
(
    const UList<vector2D>& fluid,
    DynamicList<bool>& border,
    DynamicList<bool>& wet,
    DynamicList<label>& cells
)
{
    // Compartments the fluid is in; the others (an obstacle's inside, the
    // outside of a closed tank) are solid, whatever the distances say
    List<bool>& flooded = compartmentFlooded_;
    flooded = false;
    for (const vector2D& x : fluid)
    {
        const label k = cellOf(x);
        if (k >= 0 && compartment_[k] >= 0) flooded[compartment_[k]] = true;
    }
    forAll(label_, k)
    {
        label_[k] =
            wall_[k] || !flooded[compartment_[k]] ? solid
          : dist_[k] <= dr_ ? water
          : -1;
    }
    const label nRegions = flood
    (
        label_, [&](const label k) { return label_[k] == -1; },
        cells, border, &wet
    );
    regionCompartment_.setSize(nRegions);
    forAll(label_, k)
    {
        if (label_[k] >= 0) regionCompartment_[label_[k]] = compartment_[k];
    }
    return nRegions;
}


void Foam::SPH::airPocketGrid::classifyRegions
(
    const label nRegions,
    const UList<bool>& border,
    const UList<bool>& wet,
    const UList<label>& cells
)
{
    // Per closed compartment its largest wet region, the atmosphere there
    labelList largestWet(compartmentOpen_.size(), -1);
    for (label r = 0; r < nRegions; ++r)
    {
        label& l = largestWet[regionCompartment_[r]];
        if (wet[r] && (l < 0 || cells[r] > cells[l])) l = r;
    }
    const scalar cellArea = c_.x()*c_.y();
    labelList pocketOf(nRegions, label(atmosphere));
    label nPockets = 0;
    for (label r = 0; r < nRegions; ++r)
    {
        const label c = regionCompartment_[r];
        const bool isAtmosphere =
            !wet[r]
         || (compartmentOpen_[c] ? border[r] : r == largestWet[c]);
        if (!isAtmosphere)
        {
            pocketOf[r] = cells[r]*cellArea < minArea_ ? unresolved : nPockets++;
        }
    }
    forAll(label_, k)
    {
        if (label_[k] >= 0)
        {
            label_[k] = pocketOf[label_[k]];
        }
    }
    area_.setSize(nPockets);
}


Foam::scalar Foam::SPH::airPocketGrid::airFraction(const label k) const
{
    const scalar cMin = min(c_.x(), c_.y());
    return min(max((dist_[k] - 0.5*dr_)/cMin + 0.5, scalar(0)), scalar(1));
}


void Foam::SPH::airPocketGrid::addBandAndAreas()
{
    // The band: water cells partly beyond the surface line (distance above
    // dr/2 less half a cell), reached from the pocket within the cells
    // between dr/2 and dr
    std::deque<label> front;
    labelList depth(label_.size(), -1);
    forAll(label_, k)
    {
        if (label_[k] >= 0)
        {
            front.push_back(k);
            depth[k] = 0;
        }
    }
    const scalar cMin = min(c_.x(), c_.y());
    const label maxDepth = label(std::ceil(0.5*dr_/cMin)) + 1;
    while (!front.empty())
    {
        const label k = front.front();
        front.pop_front();
        if (depth[k] >= maxDepth) continue;
        for (const label nb : neighbours(k))
        {
            if
            (
                nb >= 0 && label_[nb] == water && depth[nb] < 0
             && dist_[nb] > 0.5*(dr_ - cMin)
            )
            {
                label_[nb] = label_[k];
                depth[nb] = depth[k] + 1;
                front.push_back(nb);
            }
        }
    }
    area_ = Zero;
    forAll(label_, k)
    {
        if (label_[k] >= 0)
        {
            area_[label_[k]] += airFraction(k)*c_.x()*c_.y();
        }
    }
}


Foam::vector2D Foam::SPH::airPocketGrid::cellsPerDirection
(
    const domain& dom,
    const scalar dr
)
{
    // Cells of about dr/2: a whole number of them over a period, two more
    // on each side where the box is not periodic
    const scalar c0 = 0.5*dr;
    vector2D n;
    for (direction d = 0; d < 2; ++d)
    {
        const scalar span = dom.max()[d] - dom.min()[d];
        n[d] =
            dom.periodic(d)
          ? max(scalar(1), std::round(span/c0))
          : std::ceil(span/c0) + 4;
    }
    return n;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::airPocketGrid::airPocketGrid
(
    const domain& dom,
    const scalar dr,
    const scalar minArea
)
:
    dom_(dom),
    dr_(dr),
    minArea_(minArea)
{
    const vector2D n(cellsPerDirection(dom, dr));
    for (direction d = 0; d < 2; ++d)
    {
        n_[d] = label(n[d]);
        c_[d] = dom.periodic(d) ? (dom.max()[d] - dom.min()[d])/n_[d] : 0.5*dr;
        origin_[d] = dom.min()[d] - (dom.periodic(d) ? 0 : 2*c_[d]);
    }
    wall_.setSize(n_[0]*n_[1], false);
    dist_.setSize(wall_.size());
    label_.setSize(wall_.size());
    compartment_.setSize(wall_.size(), 0);
    compartmentOpen_.setSize(1, true);
    compartmentFlooded_.setSize(1);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::airPocketGrid::setWalls
(
    const UList<vector2D>& points,
    const UList<labelPair>& segments
)
{
    wall_ = false;
    const scalar step = 0.25*min(c_.x(), c_.y());
    for (const labelPair& e : segments)
    {
        const vector2D& a = points[e.first()];
        const vector2D ab(points[e.second()] - a);
        const label nSteps = label(std::ceil(mag(ab)/step)) + 1;
        for (label s = 0; s <= nSteps; ++s)
        {
            const label k = cellOf(a + (scalar(s)/nSteps)*ab);
            if (k >= 0) wall_[k] = true;
        }
    }
    forAll(compartment_, k)
    {
        compartment_[k] = wall_[k] ? -2 : -1;
    }
    DynamicList<label> nCells;
    DynamicList<bool> open;
    flood
    (
        compartment_, [&](const label k) { return !wall_[k]; },
        nCells, open, nullptr
    );
    compartmentOpen_.transfer(open);
    compartmentFlooded_.setSize(compartmentOpen_.size());
}


void Foam::SPH::airPocketGrid::find(const UList<vector2D>& fluid)
{
    stampDistances(fluid);
    DynamicList<bool> border, wet;
    DynamicList<label> cells;
    const label nRegions = labelRegions(fluid, border, wet, cells);
    classifyRegions(nRegions, border, wet, cells);
    addBandAndAreas();
}


Foam::vector2D Foam::SPH::airPocketGrid::centre(const label k) const
{
    vector2D sum(Zero);
    label n = 0;
    forAll(label_, c)
    {
        if (label_[c] == k)
        {
            sum += vector2D(c % n_[0] + 0.5, c/n_[0] + 0.5);
            ++n;
        }
    }
    sum /= max(n, label(1));
    return origin_ + cmptMultiply(sum, c_);
}


Foam::label Foam::SPH::airPocketGrid::at(const vector2D& x) const
{
    const label k = cellOf(x);
    return k < 0 ? label(solid) : label_[k];
}


Foam::label Foam::SPH::airPocketGrid::borderedPocket
(
    const vector2D& x,
    const vector2D& n
) const
{
    const scalar reach = 1.5*dr_ + max(c_.x(), c_.y());
    const scalar step = 0.5*min(c_.x(), c_.y());
    if (n != vector2D::zero)
    {
        for (scalar s = step; s <= reach; s += step)
        {
            const label l = at(x + s*n);
            if (l >= 0) return l;
            if (l == atmosphere || l == unresolved || l == solid) return -1;
        }
        return -1;
    }

    // No normal (a droplet, or the Dirichlet condition): the nearest air
    label nearest = -1;
    scalar dMin = GREAT;
    const label m = label(std::ceil(reach/step));
    for (label j = -m; j <= m; ++j)
    {
        for (label i = -m; i <= m; ++i)
        {
            const vector2D d(i*step, j*step);
            const scalar r = mag(d);
            const label l = r <= reach ? at(x + d) : label(solid);
            if (l != solid && l != water && r < dMin)
            {
                dMin = r;
                nearest = l;
            }
        }
    }
    return nearest >= 0 ? nearest : -1;
}


// ************************************************************************* //
