#include "Radiosity/Common/Atan2Batch.h"

#include <emmintrin.h>
#include <sleef.h>

namespace radiosity
{
void Atan2Batch(const double* y, const double* x, double* out, std::size_t count)
{
  std::size_t k = 0;
  // Sleef_atan2d2_u10 picks the SSE2, SSE4.1 or AVX2 (128-bit) kernel for
  // the machine it runs on; SSE2 is every x86-64's baseline.
  for (; k + 2 <= count; k += 2)
  {
    _mm_storeu_pd(out + k, Sleef_atan2d2_u10(_mm_loadu_pd(y + k), _mm_loadu_pd(x + k)));
  }
  // An odd last one in both lanes: SLEEF's scalar atan2 takes twice libm's
  // time, the two-lane one half of it.
  if (k < count)
  {
    _mm_store_sd(out + k, Sleef_atan2d2_u10(_mm_set1_pd(y[k]), _mm_set1_pd(x[k])));
  }
}
} // namespace radiosity
