/*---------------------------------------------------------------------------*\
  sphFoam: 2-D SPH on OpenFOAM v1912.  GPL-3.0-or-later.
\*---------------------------------------------------------------------------*/

#include "ILU0.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::SPH::ILU0::ILU0()
:
    nZeroPivots_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::SPH::ILU0::factorise()
{
    if (LU_.rows() != LU_.cols())
    {
        FatalErrorInFunction
            << "ILU0 needs a square matrix, not " << label(LU_.rows()) << " x "
            << label(LU_.cols()) << exit(FatalError);
    }
    LU_.makeCompressed();

    const int n = LU_.rows();
    const int* start = LU_.outerIndexPtr();
    const int* col = LU_.innerIndexPtr();
    scalar* a = LU_.valuePtr();

    diag_.assign(n, -1);
    for (int i = 0; i < n; ++i)
    {
        for (int k = start[i]; k < start[i + 1]; ++k)
        {
            if (col[k] == i)
            {
                diag_[i] = k;
                break;
            }
        }
        if (diag_[i] < 0)
        {
            FatalErrorInFunction
                << "Row " << i << " of the matrix has no diagonal entry"
                << exit(FatalError);
        }
    }

    // Saad's IKJ ILU(0): position of each column of row i in iw
    std::vector<int> iw(n, -1);
    nZeroPivots_ = 0;
    for (int i = 0; i < n; ++i)
    {
        for (int k = start[i]; k < start[i + 1]; ++k)
        {
            iw[col[k]] = k;
        }
        for (int k = start[i]; k < diag_[i]; ++k)
        {
            const int kk = col[k];
            const scalar lik = a[k]/a[diag_[kk]];
            a[k] = lik;
            for (int j = diag_[kk] + 1; j < start[kk + 1]; ++j)
            {
                const int at = iw[col[j]];
                if (at >= 0)
                {
                    a[at] -= lik*a[j];
                }
            }
        }
        if (a[diag_[i]] == 0)
        {
            a[diag_[i]] = 1;
            ++nZeroPivots_;
        }
        for (int k = start[i]; k < start[i + 1]; ++k)
        {
            iw[col[k]] = -1;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::SPH::ILU0::solveInPlace(vectorN& x) const
{
    const int n = LU_.rows();
    const int* start = LU_.outerIndexPtr();
    const int* col = LU_.innerIndexPtr();
    const scalar* a = LU_.valuePtr();

    // Forward: L y = b (unit diagonal)
    for (int i = 0; i < n; ++i)
    {
        scalar s = x[i];
        for (int k = start[i]; k < diag_[i]; ++k)
        {
            s -= a[k]*x[col[k]];
        }
        x[i] = s;
    }

    // Backward: U x = y
    for (int i = n - 1; i >= 0; --i)
    {
        scalar s = x[i];
        for (int k = diag_[i] + 1; k < start[i + 1]; ++k)
        {
            s -= a[k]*x[col[k]];
        }
        x[i] = s/a[diag_[i]];
    }
}


// ************************************************************************* //
