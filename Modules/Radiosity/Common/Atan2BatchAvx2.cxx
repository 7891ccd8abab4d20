// Atan2Batch's four-lane kernel (Common/Atan2Batch.h), in a translation unit
// of its own compiled for AVX2 and FMA: Atan2Batch calls it only where the
// processor has both (__builtin_cpu_supports), so the library still runs on
// any x86-64.
#include "Radiosity/Common/Atan2Batch.h"

#include <immintrin.h>
#include <sleef.h>

namespace radiosity
{
namespace atan2_batch_detail
{
void Atan2BatchAvx2(const double* y, const double* x, double* out, std::size_t count)
{
  std::size_t k = 0;
  for (; k + 4 <= count; k += 4)
  {
    _mm256_storeu_pd(out + k, Sleef_atan2d4_u10avx2(_mm256_loadu_pd(y + k), _mm256_loadu_pd(x + k)));
  }
  if (k < count)
  {
    // The last one to three in one call, the empty lanes repeating the last.
    double ys[4], xs[4], r[4];
    for (std::size_t i = 0; i < 4; ++i)
    {
      const std::size_t j = k + i < count ? k + i : count - 1;
      ys[i] = y[j];
      xs[i] = x[j];
    }
    _mm256_storeu_pd(r, Sleef_atan2d4_u10avx2(_mm256_loadu_pd(ys), _mm256_loadu_pd(xs)));
    for (std::size_t i = 0; k + i < count; ++i)
    {
      out[k + i] = r[i];
    }
  }
}
} // namespace atan2_batch_detail
} // namespace radiosity
