// The sky directions hidden from every point of a leaf, for the
// discontinuity mesher's samples (DiscontinuityMeshWork.h).
#include "Radiosity/Common/Visibility.h"
#include "Radiosity/Hierarchical/Backprojection.h"
#include "Radiosity/Hierarchical/DiscontinuityMeshWork.h"
#include "Radiosity/Hierarchical/EdgeTopology.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstring>

namespace radiosity
{
namespace discontinuity_mesh_detail
{
namespace
{
/// Whether the segment from `origin` to `origin + d`, less `near` at
/// both ends, crosses triangle (a, b, c) inside it by a margin (barycentric
/// coordinates of at least 1e-9, `near` doubled): Moller & Trumbore's test
/// in double precision, without a division. `length`: |d|.
bool CrossesInside(const Vec3& origin, const Vec3& d, double length, double near, const Vec3& a, const Vec3& e1,
  const Vec3& e2)
{
  constexpr double Margin = 1e-9;
  const Vec3 p = glm::cross(d, e2);
  double det = glm::dot(e1, p);
  const Vec3 s = origin - a;
  const Vec3 q = glm::cross(s, e1);
  double u = glm::dot(s, p), v = glm::dot(d, q), t = glm::dot(e2, q);
  if (det < 0.0)
  {
    det = -det;
    u = -u;
    v = -v;
    t = -t;
  }
  // det = 0 (d parallel to the plane) fails the first test.
  const double along = 2.0 * near / length; // of d
  return u >= Margin * det && v >= Margin * det && u + v <= (1.0 - Margin) * det && t >= along * det &&
    t <= (1.0 - along) * det && det > 0.0;
}

/// Whether triangle t and its coplanar neighbour u across t's side k form
/// a convex quad (then a segment between two points of their union stays in it).
bool ConvexWithNeighbour(const Scene& scene, std::uint32_t t, int k, std::uint32_t u)
{
  const auto& tv = scene.Triangles[t].V;
  const auto& uv = scene.Triangles[u].V;
  const std::uint32_t p = tv[k], q = tv[(k + 1) % 3];
  std::uint32_t far = uv[0];
  for (std::uint32_t v : uv)
  {
    far = v != p && v != q ? v : far;
  }
  // t's winding with u's far corner between the shared edge's ends.
  const Vec3 quad[4] = { scene.Points[p], scene.Points[far], scene.Points[q], scene.Points[tv[(k + 2) % 3]] };
  return ConvexQuad(quad, glm::cross(quad[2] - quad[0], quad[3] - quad[0]));
}
} // namespace

std::vector<std::array<std::uint32_t, 3>> ConvexCoplanarNeighbours(
  const Scene& scene, const EdgeTopology& topology, const Visibility& occluders)
{
  std::vector<std::array<std::uint32_t, 3>> quads(scene.Triangles.size());
  tbb::parallel_for(std::size_t(0), scene.Triangles.size(), [&](std::size_t i) {
    const auto t = static_cast<std::uint32_t>(i);
    for (int side = 0; side < 3; ++side)
    {
      const std::uint32_t u = topology.CoplanarNeighbour(t, side);
      quads[i][side] = u != EdgeTopology::None && occluders.Occludes(t) && occluders.Occludes(u) &&
          ConvexWithNeighbour(scene, t, side, u)
        ? u
        : EdgeTopology::None;
    }
  });
  return quads;
}

std::vector<std::uint64_t> SkyHiddenOverLeaves(const HierarchicalRadiosity& s, const DirectLighting& lights,
  const std::vector<std::array<std::uint32_t, 3>>& quads, const std::vector<std::uint32_t>& leaves,
  const std::vector<std::uint32_t>& order, std::size_t begin,
  std::size_t end)
{
  const ElementMesh& mesh = s.Mesh();
  const Scene& scene = s.GetScene();
  const std::size_t words = lights.SkyMaskWords();
  const std::size_t stride = 64 * words;
  const double offset = lights.ShadowRays()->Offset();
  // A direction is hidden from the whole leaf where the rays from its three
  // corners all cross one occluder: the parallel rays from its points cross
  // that occluder's plane at the same convex combination of the corners'
  // crossings, inside it and no farther than the farthest (each ray starts
  // at its point moved by the same offset along n). The occluder is the one
  // that the ray from one corner meets first (Embree); the three crossings
  // are then tested in double precision against it alone, with a margin,
  // and where one misses it, against its union with a coplanar neighbour
  // when that union is convex (`quads`).
  // The rays are traced from the corner of lowest point index, so that the
  // leaves meeting there share them: a corner's rays are
  // those of a point of the element mesh's pool and a normal, to the bit
  // (the quadrature's frame turns with the normal's signs, -0 included, and
  // the elements of one input triangle may differ in its last bits).
  using Key = std::array<std::uint64_t, 4>;
  auto traced = [&](std::uint32_t leaf) {
    const auto& v = mesh[leaf].V;
    return static_cast<int>(v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2));
  };
  auto key = [&](std::uint32_t leaf) {
    const Vec3& n = mesh[leaf].Normal;
    Key out{ mesh[leaf].V[traced(leaf)], 0, 0, 0 };
    std::memcpy(&out[1], &n.x, sizeof(double));
    std::memcpy(&out[2], &n.y, sizeof(double));
    std::memcpy(&out[3], &n.z, sizeof(double));
    return out;
  };
  std::vector<Key> keys;
  keys.reserve(end - begin);
  for (std::size_t j = begin; j < end; ++j)
  {
    keys.push_back(key(leaves[order[j]]));
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
  tbb::parallel_for(begin, end, [&](std::size_t j) {
    const std::uint32_t leaf = leaves[order[j]];
    const std::uint32_t* first =
      hits.data() + static_cast<std::size_t>(std::lower_bound(keys.begin(), keys.end(), key(leaf)) - keys.begin()) * stride;
    const Vec3& n = mesh[leaf].Normal;
    // The segments TestSegments casts from the corners (SegmentRay): from
    // RayOrigin to the corner plus FarDistance along the direction.
    std::array<Vec3, 3> origin, lift;
    std::array<double, 3> far;
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& corner = mesh.Points()[mesh[leaf].V[k]];
      origin[k] = lights.RayOrigin(corner, n);
      lift[k] = corner - origin[k];
      far[k] = lights.FarDistance(corner);
    }
    thread_local std::vector<Vec3> directions;
    lights.SkyQuadrature(n, directions);
    std::uint64_t* mask = hidden.data() + (j - begin) * words;
    for (std::size_t i = 0; i < directions.size(); ++i)
    {
      const std::uint32_t t = first[i];
      if (t == Visibility::NoHit)
      {
        continue;
      }
      std::array<Vec3, 3> d;
      for (int k = 0; k < 3; ++k)
      {
        // |d| is far[k] to a part in 1e7 (lift is a hundredth of the
        // offset, far at least twice the scene's size): ample for the bounds on t.
        d[k] = lift[k] + far[k] * directions[i];
      }
      // Tests against `triangle` the corners whose rays are not yet known
      // to cross an occluder (inside[k] false), marking those that cross
      // it; with `stopAtMiss`, stops at the first miss. True when all of
      // them cross it.
      auto crosses = [&](std::uint32_t triangle, bool* inside, bool stopAtMiss) {
        const Vec3 a = scene.Vertex(triangle, 0);
        const Vec3 e1 = scene.Vertex(triangle, 1) - a, e2 = scene.Vertex(triangle, 2) - a;
        bool every = true;
        for (int k = 0; k < 3 && (every || !stopAtMiss); ++k)
        {
          if (!inside[k])
          {
            inside[k] = CrossesInside(origin[k], d[k], far[k], offset, a, e1, e2);
            every = every && inside[k];
          }
        }
        return every;
      };
      const std::array<std::uint32_t, 3>& quad = quads[t];
      const bool neighbours = quad[0] != EdgeTopology::None || quad[1] != EdgeTopology::None ||
        quad[2] != EdgeTopology::None;
      bool inside[3] = { false, false, false };
      bool all = crosses(t, inside, !neighbours);
      // Else the crossings may still lie in the union of t and a coplanar
      // neighbour across one of its sides (a wall's other triangle), where
      // that union is convex: the convex combinations stay in it.
      for (int side = 0; side < 3 && !all; ++side)
      {
        if (quad[side] != EdgeTopology::None)
        {
          bool either[3] = { inside[0], inside[1], inside[2] };
          all = crosses(quad[side], either, true);
        }
      }
      if (all)
      {
        mask[i / 64] |= std::uint64_t(1) << (i % 64);
      }
    }
  });
  return hidden;
}
} // namespace discontinuity_mesh_detail
} // namespace radiosity
