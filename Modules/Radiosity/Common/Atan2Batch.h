// atan2 over arrays, two lanes at a time with SLEEF's vectorised atan2
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
} // namespace radiosity

#endif
