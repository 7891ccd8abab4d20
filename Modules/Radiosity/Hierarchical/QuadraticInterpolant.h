// Hardt & Teller section 2.2: a quadratic irradiance interpolant over a
// triangle in its barycentric frame x = p0 + s (p1 - p0) + t (p2 - p0),
//   R(s,t) = A s^2 + 2B st + 2C s + D t^2 + 2E t + F,
// fitted to six samples r0..r5 at (0,0), (1/2,0), (1,0), (1/2,1/2), (0,1),
// (0,1/2). Stored, as the paper stores it, as (A, 2B, 2C, D, 2E, F) so that
// the evaluation takes eight multiplies and five adds.
//
// The paper's printed closed form has E = -3/2 r0 - 1/2 r4 + r5; solving its
// own 6x6 system gives E = -3/2 r0 - 1/2 r4 + 2 r5 (the t-axis twin of
// C = -3/2 r0 + 2 r1 - 1/2 r2), which is what is used here; the unit tests
// check that the interpolant reproduces all six samples.
#ifndef Radiosity_QuadraticInterpolant_h
#define Radiosity_QuadraticInterpolant_h

#include "Radiosity/Common/Types.h"

#include <array>

namespace radiosity
{
struct QuadraticInterpolant
{
  /// (A, 2B, 2C, D, 2E, F), each RGB.
  std::array<RGB, 6> Coefficients{};

  /// Samples in the order r0..r5 above: corners p0, p1, p2 are r0, r2, r4;
  /// the midpoints of p0p1, p1p2, p2p0 are r1, r3, r5.
  static QuadraticInterpolant FromSamples(const std::array<RGB, 6>& r)
  {
    QuadraticInterpolant q;
    const RGB A = 2.0 * r[0] - 4.0 * r[1] + 2.0 * r[2];
    const RGB B = 2.0 * r[0] - 2.0 * r[1] + 2.0 * r[3] - 2.0 * r[5];
    const RGB C = -1.5 * r[0] + 2.0 * r[1] - 0.5 * r[2];
    const RGB D = 2.0 * r[0] + 2.0 * r[4] - 4.0 * r[5];
    const RGB E = -1.5 * r[0] - 0.5 * r[4] + 2.0 * r[5];
    q.Coefficients = { A, 2.0 * B, 2.0 * C, D, 2.0 * E, r[0] };
    return q;
  }

  RGB Evaluate(double s, double t) const
  {
    const auto& k = this->Coefficients;
    return s * (k[0] * s + k[1] * t + k[2]) + t * (k[3] * t + k[4]) + k[5];
  }

  /// Area mean over the triangle (exact for a quadratic): the mean of the
  /// three edge-midpoint values.
  RGB Mean() const
  {
    return (this->Evaluate(0.5, 0.0) + this->Evaluate(0.5, 0.5) + this->Evaluate(0.0, 0.5)) / 3.0;
  }
};
} // namespace radiosity

#endif
