// RECEIVER-ORACLE of Lehtinen et al. 2007, section 6.3: which receivers of
// a bounce (or of the direct light) get their coefficient computed. The
// coarsest level is computed whole; a coarsest function is refined (its
// children, the next level's functions centred in its support, computed)
// when its value differs from a neighbour's by more than epsilon_E; a finer
// one when its coefficient (a difference to the coarser levels, eq. 10)
// exceeds epsilon_E; the coarser functions non-zero at a child are computed
// before it. Shared by the solve (MeshlessRadiosity::Refine, over points)
// and the relight (MeshlessTransfer::Indirect, over the transfer's rows),
// so that the two choose the same receivers.
#ifndef Radiosity_ReceiverOracle_h
#define Radiosity_ReceiverOracle_h

#include "Radiosity/Common/Types.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace radiosity
{
/**
 * `coarsest`: the coarsest level's indices (computed first). `compute(set)`
 * computes a set's values and coefficients (into `value` and `alpha`) and
 * marks them in `computed`. `neighbours(j, out)`, `children(k, out)` and
 * `ancestors(c, out)` append the facing neighbours of a coarsest j, the
 * children of k and the coarser functions non-zero at c, all in the same
 * index space as the vectors.
 */
template <typename Compute, typename Neighbours, typename Children, typename Ancestors>
void RunReceiverOracle(std::vector<std::uint32_t> coarsest, double threshold, const std::vector<RGB>& value,
  const std::vector<RGB>& alpha, const std::vector<unsigned char>& computed, Compute&& compute,
  Neighbours&& neighbours, Children&& children, Ancestors&& ancestors)
{
  compute(coarsest);
  std::vector<std::uint32_t> refine, near, next, missing;
  for (std::uint32_t j : coarsest)
  {
    near.clear();
    neighbours(j, near);
    double variation = 0.0;
    for (std::uint32_t k : near)
    {
      variation = std::max(variation, MaxComponent(glm::abs(value[k] - value[j])));
    }
    if (variation > threshold)
    {
      refine.push_back(j);
    }
  }
  while (!refine.empty())
  {
    next.clear();
    for (std::uint32_t k : refine)
    {
      near.clear();
      children(k, near);
      for (std::uint32_t c : near)
      {
        if (!computed[c])
        {
          next.push_back(c);
        }
      }
    }
    missing.clear();
    for (std::uint32_t c : next)
    {
      near.clear();
      ancestors(c, near);
      for (std::uint32_t q : near)
      {
        if (!computed[q])
        {
          missing.push_back(q);
        }
      }
    }
    if (!missing.empty())
    {
      compute(missing);
    }
    compute(next);
    refine.clear();
    for (std::uint32_t c : next)
    {
      if (MaxComponent(glm::abs(alpha[c])) > threshold)
      {
        refine.push_back(c);
      }
    }
  }
}
} // namespace radiosity

#endif
