// What the discontinuity mesher leaves out or shares per leaf, checked
// against what it replaces: a leaf's chain of links brought by their merged
// edges (MergedLinkEdges, LinkChain.h) against the source-by-source contour
// sums at three scales; a link whose source one blocker hides wholly
// (HidesWholly) against the backprojection inside the leaf; the sky
// directions hidden over a whole leaf against rays from inside it.
#include "Radiosity/Hierarchical/Backprojection.h"
#include "Radiosity/Hierarchical/DiscontinuityMeshWork.h"
#include "Radiosity/Hierarchical/EdgeTopology.h"
#include "Radiosity/Hierarchical/HierarchicalRadiosity.h"
#include "Radiosity/Hierarchical/LinkChain.h"
#include "Radiosity/Scenes/OfficeScene.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace radiosity;

namespace
{
struct ChainComparison
{
  double WorstRelative = 0.0; ///< inside the leaves
  double WorstOnBoundary = 0.0; ///< 1e-7 inside their corners and edge midpoints
  std::size_t Points = 0, MergedLinks = 0, Edges = 0;
};

ChainComparison CompareChains(Scene scene, double scale)
{
  for (Vec3& p : scene.Points)
  {
    p *= scale;
  }
  HierarchicalRadiosity solver(scene, HierarchicalOptions());
  solver.Solve();
  const MergedLinkEdges merged(solver);
  const std::vector<std::uint32_t> leaves = solver.Mesh().Leaves();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ChainComparison out;
  out.MergedLinks = merged.NumberOfMergedLinks();
  out.Edges = merged.NumberOfEdges();
  double peak = 0.0;
  std::vector<std::pair<RGB, RGB>> values;
  std::vector<bool> boundary;
  for (std::size_t i = 0; i < leaves.size(); i += 1 + leaves.size() / 400)
  {
    const std::uint32_t leaf = leaves[i];
    const TriangleCorners c = solver.Corners(leaf);
    const Vec3& n = solver.Mesh()[leaf].Normal;
    const std::vector<ChainSource> whole = GatherChain(solver, leaf);
    const std::vector<ChainSource> rest = GatherChain(solver, leaf, false, &merged);
    const std::vector<ChainEdge> edges = merged.ChainEdges(solver, leaf);
    // The mesher's samples: corners and edge midpoints moved 1e-7 inside, and inner points.
    const Vec3 centroid = (c[0] + c[1] + c[2]) / 3.0;
    std::vector<Vec3> points;
    for (int k = 0; k < 3; ++k)
    {
      points.push_back(c[k] + 1e-7 * (centroid - c[k]));
      const Vec3 mid = 0.5 * (c[k] + c[(k + 1) % 3]);
      points.push_back(mid + 1e-7 * (centroid - mid));
    }
    for (int k = 0; k < 3; ++k)
    {
      double a = u(rng), b = u(rng);
      if (a + b > 1.0)
      {
        a = 1.0 - a;
        b = 1.0 - b;
      }
      points.push_back(c[0] + a * (c[1] - c[0]) + b * (c[2] - c[0]));
    }
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      const Vec3& x = points[k];
      boundary.push_back(k < 6);
      values.emplace_back(ChainIrradiance(whole, x, n), ChainIrradiance(rest, edges, x, n));
      peak = std::max(peak, MaxComponent(values.back().first));
    }
  }
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    double& worst = boundary[k] ? out.WorstOnBoundary : out.WorstRelative;
    worst = std::max(worst, MaxComponent(glm::abs(values[k].second - values[k].first)) / peak);
  }
  out.Points = values.size();
  return out;
}
} // namespace

TEST(LinkChain, MergedEdgesEqualTheSourceBySourceSums)
{
  for (const double scale : { 1e-4, 1.0, 1e4 })
  {
    for (const bool cornell : { true, false })
    {
      const ChainComparison r = CompareChains(cornell ? MakeCornellBox() : MakeContactScene(4, 0.5, 1.0), scale);
      std::cout << (cornell ? "Cornell box" : "contact scene") << " at scale " << scale << ": " << r.Points
                << " points, worst difference " << r.WorstRelative << " of the peak inside, "
                << r.WorstOnBoundary << " on the boundary; " << r.MergedLinks
                << " links merged into " << r.Edges << " edges\n";
      EXPECT_LT(r.WorstRelative, 1e-13) << "scale " << scale; // measured 1.4e-15 at most
      // 1e-7 of a leaf from a contact edge (the Cornell box's tilted wall
      // under the ceiling) the source-by-source sum clips a corner of a
      // ceiling source whose height over the wall's plane is a rounding
      // (-1e-21 at 1e-4 m), which moves it by such a sliver: 1.6e-10 of the
      // peak at 1e-4 m, 7.4e-13 at 1e4 m, 1.4e-15 at 1 m. The merged edges
      // take the limit those corners are on the plane.
      EXPECT_LT(r.WorstOnBoundary, 1e-9) << "scale " << scale;
      // Merging must find shared edges: fewer than the three per link taken alone.
      EXPECT_GT(r.MergedLinks, 1000u);
      EXPECT_LT(r.Edges, 2.5 * r.MergedLinks);
    }
  }
}

TEST(Backprojection, HidesWhollyOnlyInTheUmbra)
{
  // A square source (two triangles) at height 1 over a floor, a square
  // blocker at height 0.5: its umbra on the floor is the square of half-width
  // 0.2 - 0.1 = 0.1 around the axis (the blocker's 0.2 projected from the
  // source's far side, 2 x 0.2 - 0.3). Exact form factors by backprojection
  // check the claim at points inside each receiver.
  for (const double scale : { 1e-4, 1.0, 1e4 })
  {
    auto at = [&](double x, double y, double z) { return scale * Vec3(x, y, z); };
    const TriangleCorners source[2] = { { at(-0.3, -0.3, 1), at(0.3, 0.3, 1), at(0.3, -0.3, 1) },
      { at(-0.3, -0.3, 1), at(-0.3, 0.3, 1), at(0.3, 0.3, 1) } };
    BlockerPolygon blocker;
    blocker.Corners = { at(-0.2, -0.2, 0.5), at(0.2, -0.2, 0.5), at(0.2, 0.2, 0.5), at(-0.2, 0.2, 0.5) };
    blocker.Size = 4;
    const TriangleCorners inUmbra = { at(-0.09, -0.09, 0), at(0.09, -0.09, 0), at(0, 0.09, 0) };
    const TriangleCorners acrossPenumbra = { at(-0.09, -0.09, 0), at(0.3, -0.09, 0), at(0, 0.09, 0) };
    // The umbra's edge through a corner: still wholly hidden (the closed umbra).
    const TriangleCorners toTheEdge = { at(-0.1, -0.1, 0), at(0.1, -0.1, 0), at(0, 0.1, 0) };
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto worstSeen = [&](const TriangleCorners& r, const TriangleCorners& s) {
      double worst = 0.0;
      for (int i = 0; i < 200; ++i)
      {
        double a = u(rng), b = u(rng);
        if (a + b > 1.0)
        {
          a = 1.0 - a;
          b = 1.0 - b;
        }
        const Vec3 x = r[0] + a * (r[1] - r[0]) + b * (r[2] - r[0]);
        const TriangleCorners blockers[2] = { { blocker.Corners[0], blocker.Corners[1], blocker.Corners[2] },
          { blocker.Corners[0], blocker.Corners[2], blocker.Corners[3] } };
        worst = std::max(worst, VisibleFormFactor(x, Vec3(0, 0, 1), s, blockers, 2));
      }
      return worst;
    };
    for (const TriangleCorners& s : source)
    {
      EXPECT_TRUE(HidesWholly(inUmbra, s, blocker)) << "scale " << scale;
      EXPECT_TRUE(HidesWholly(toTheEdge, s, blocker)) << "scale " << scale;
      EXPECT_LT(worstSeen(inUmbra, s), 1e-15) << "scale " << scale; // measured 0
      EXPECT_FALSE(HidesWholly(acrossPenumbra, s, blocker)) << "scale " << scale;
    }
    // Across the penumbra some of the source shows (the check above is not vacuous).
    EXPECT_GT(worstSeen(acrossPenumbra, source[0]) + worstSeen(acrossPenumbra, source[1]), 1e-3);
    // A blocker above the source, or a receiver above the blocker, hides nothing.
    BlockerPolygon above = blocker;
    for (Vec3& c : above.Corners)
    {
      c.z = 2.0 * scale;
    }
    EXPECT_FALSE(HidesWholly(inUmbra, source[0], above));
    const TriangleCorners high = { at(-0.09, -0.09, 0.7), at(0.09, -0.09, 0.7), at(0, 0.09, 0.7) };
    EXPECT_FALSE(HidesWholly(high, source[0], blocker));
  }
}

TEST(DiscontinuityMesh, SkyDirectionsHiddenOverALeafAreHiddenInside)
{
  // The office under its overcast sky (the lamp off): the directions that
  // SkyHiddenOverLeaves takes as hidden from a whole leaf, since its three
  // corners' rays meet one occluder first, are hidden at points inside it.
  Scene scene = MakeOfficeScene();
  scene.Lighting.Lights.clear();
  HierarchicalOptions options;
  options.RelativeLinkTolerance = 0.5;
  options.MaxRefinementRounds = 0;
  options.SkySamples = 256;
  HierarchicalRadiosity solver(scene, options);
  solver.Solve();
  const DirectLighting& lights = *solver.GetDirectLighting();
  const std::vector<std::uint32_t> leaves = solver.Mesh().Leaves();
  std::vector<std::uint32_t> order(leaves.size());
  for (std::uint32_t i = 0; i < order.size(); ++i)
  {
    order[i] = i;
  }
  const std::vector<std::uint64_t> hidden =
    discontinuity_mesh_detail::SkyHiddenOverLeaves(solver, lights,
      discontinuity_mesh_detail::ConvexCoplanarNeighbours(
        scene, discontinuity_mesh_detail::EdgeTopology(scene), *lights.ShadowRays()),
      leaves, order, 0, order.size());
  const std::size_t words = lights.SkyMaskWords();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::size_t hiddenDirections = 0, checked = 0, seen = 0;
  std::vector<std::uint64_t> visible(words);
  for (std::size_t k = 0; k < leaves.size(); k += 1 + leaves.size() / 300)
  {
    const TriangleCorners c = solver.Corners(leaves[k]);
    const Vec3& n = solver.Mesh()[leaves[k]].Normal;
    for (int p = 0; p < 4; ++p)
    {
      double a = u(rng), b = u(rng);
      if (a + b > 1.0)
      {
        a = 1.0 - a;
        b = 1.0 - b;
      }
      lights.SkyVisibility(c[0] + a * (c[1] - c[0]) + b * (c[2] - c[0]), n, visible.data());
      for (std::size_t w = 0; w < words; ++w)
      {
        const std::uint64_t mask = hidden[k * words + w];
        hiddenDirections += static_cast<std::size_t>(__builtin_popcountll(mask));
        seen += static_cast<std::size_t>(__builtin_popcountll(mask & visible[w]));
      }
      ++checked;
    }
  }
  std::cout << checked << " points: " << hiddenDirections << " hidden directions, " << seen << " of them seen\n";
  EXPECT_EQ(seen, 0u);
  EXPECT_GT(hiddenDirections, 20u * checked); // measured: see the output
}
