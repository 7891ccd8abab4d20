// The sky directions hidden from every point of a leaf, for the
// discontinuity mesher's samples (DiscontinuityMeshWork.h).
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/Hierarchical/DiscontinuityMeshWork.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace radiosity
{
namespace discontinuity_mesh_detail
{
std::vector<std::uint64_t> SkyHiddenOverLeaves(const HierarchicalRadiosity& s, const DirectLighting& lights,
  const std::vector<std::uint32_t>& leaves, const std::vector<std::uint32_t>& order, std::size_t begin,
  std::size_t end)
{
  const ElementMesh& mesh = s.Mesh();
  const std::size_t words = lights.SkyMaskWords();
  const std::size_t stride = 64 * words;
  // A corner's rays are those of a point of the element mesh's pool and a
  // normal, to the bit: the quadrature's frame turns with the normal's
  // signs (-0 included), and the elements of one input triangle may
  // differ in its last bits.
  using Key = std::array<std::uint64_t, 4>;
  auto key = [&](std::uint32_t leaf, int k) {
    const Vec3& n = mesh[leaf].Normal;
    Key out{ mesh[leaf].V[k], 0, 0, 0 };
    std::memcpy(&out[1], &n.x, sizeof(double));
    std::memcpy(&out[2], &n.y, sizeof(double));
    std::memcpy(&out[3], &n.z, sizeof(double));
    return out;
  };
  std::vector<Key> keys;
  keys.reserve(3 * (end - begin));
  for (std::size_t j = begin; j < end; ++j)
  {
    for (int k = 0; k < 3; ++k)
    {
      keys.push_back(key(leaves[order[j]], k));
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<std::uint32_t> hits(keys.size() * stride);
  tbb::parallel_for(std::size_t(0), keys.size(), [&](std::size_t i) {
    Vec3 n;
    std::memcpy(&n.x, &keys[i][1], sizeof(double));
    std::memcpy(&n.y, &keys[i][2], sizeof(double));
    std::memcpy(&n.z, &keys[i][3], sizeof(double));
    lights.SkyFirstHits(mesh.Points()[keys[i][0]], n, hits.data() + i * stride);
  });
  std::vector<std::uint64_t> hidden((end - begin) * words, 0);
  const auto m = static_cast<std::size_t>(lights.SkySamples());
  tbb::parallel_for(begin, end, [&](std::size_t j) {
    const std::uint32_t* corner[3];
    for (int k = 0; k < 3; ++k)
    {
      const auto at = std::lower_bound(keys.begin(), keys.end(), key(leaves[order[j]], k)) - keys.begin();
      corner[k] = hits.data() + static_cast<std::size_t>(at) * stride;
    }
    std::uint64_t* mask = hidden.data() + (j - begin) * words;
    for (std::size_t i = 0; i < m; ++i)
    {
      if (corner[0][i] != Visibility::NoHit && corner[0][i] == corner[1][i] && corner[0][i] == corner[2][i])
      {
        mask[i / 64] |= std::uint64_t(1) << (i % 64);
      }
    }
  });
  return hidden;
}
} // namespace discontinuity_mesh_detail
} // namespace radiosity
