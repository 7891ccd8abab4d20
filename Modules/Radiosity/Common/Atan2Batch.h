// atan2 over arrays, four lanes at a time with SLEEF's vectorised atan2
// where the processor has AVX2 and FMA, else two
// (Shibata & Petrogalli 2020, "SLEEF: A Portable Vectorized Library of C
// Standard Mathematical Functions"; the 1-ulp variant, as accurate as libm's).
// Lambert's contour formula takes one angle per polygon edge: where many
// edges are summed at one point (the discontinuity mesher's samples) the
// angles dominate, and libm's scalar atan2 (which saves and restores the
// rounding mode per call) costs several times SLEEF's per lane.
#ifndef Radiosity_Atan2Batch_h
#define Radiosity_Atan2Batch_h

#include <cstddef>

namespace radiosity
{
/// out[k] = atan2(y[k], x[k]) for k < count, to 1 ulp (out may alias y or x).
void Atan2Batch(const double* y, const double* x, double* out, std::size_t count);

namespace atan2_batch_detail
{
/// The kernels Atan2Batch picks from, for its test: two lanes (any x86-64)
/// and four (AVX2 and FMA: only where Avx2Available()).
void Atan2BatchTwoLanes(const double* y, const double* x, double* out, std::size_t count);
void Atan2BatchAvx2(const double* y, const double* x, double* out, std::size_t count);
bool Avx2Available();
} // namespace atan2_batch_detail
} // namespace radiosity

#endif
