#include "Radiosity/Common/ElementMesh.h"

#include <algorithm>

namespace radiosity
{
ElementMesh::ElementMesh(
  const Scene& scene, double shooterEdge, double initialEdge, int maxLevel)
  : SourceScene(&scene)
  , Pool(scene.Points)
{
  this->Nodes.reserve(scene.Triangles.size() * 4);
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    this->AddElement(scene.Triangles[t].V, -1, static_cast<std::uint32_t>(t), 0);
  }
  // Breadth-first uniform refinement to the initial element size; children
  // inherit their parent's shooter, so the first node small enough shoots.
  for (std::size_t i = 0; i < this->Nodes.size(); ++i)
  {
    const auto e = static_cast<std::uint32_t>(i);
    const double edge = this->LongestEdge(e);
    const bool atMaxLevel = this->Nodes[e].Level >= maxLevel;
    if (this->Nodes[e].ShooterNode == NoShooter && (edge <= shooterEdge || atMaxLevel))
    {
      this->Nodes[e].ShooterNode = e;
      this->ShooterNodes.push_back(e);
    }
    if (!atMaxLevel && (edge > initialEdge || this->Nodes[e].ShooterNode == NoShooter))
    {
      this->Subdivide(e);
    }
  }
}

std::uint32_t ElementMesh::AddElement(const std::array<std::uint32_t, 3>& v, std::int32_t parent,
  std::uint32_t source, std::uint16_t level)
{
  Element el;
  el.V = v;
  el.Parent = parent;
  el.Source = source;
  el.Level = level;
  const Vec3 a = this->Pool[v[0]], b = this->Pool[v[1]], c = this->Pool[v[2]];
  const Vec3 av = AreaVector(a, b, c);
  el.Area = glm::length(av);
  el.Normal = el.Area > 0 ? av / el.Area : this->SourceScene->Normal(source);
  el.Centroid = (a + b + c) / 3.0;
  el.Unshot = this->SourceScene->Materials[source].Emission;
  this->Nodes.push_back(el);
  ++this->LeafCount;
  return static_cast<std::uint32_t>(this->Nodes.size() - 1);
}

std::uint32_t ElementMesh::Midpoint(std::uint32_t a, std::uint32_t b)
{
  const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
  auto it = this->Midpoints.find(key);
  if (it != this->Midpoints.end())
  {
    return it->second;
  }
  this->Pool.push_back(0.5 * (this->Pool[a] + this->Pool[b]));
  const auto index = static_cast<std::uint32_t>(this->Pool.size() - 1);
  this->Midpoints.emplace(key, index);
  return index;
}

double ElementMesh::LongestEdge(std::uint32_t e) const
{
  const Element& el = this->Nodes[e];
  double m = 0;
  for (int k = 0; k < 3; ++k)
  {
    m = std::max(m, glm::length(this->Pool[el.V[(k + 1) % 3]] - this->Pool[el.V[k]]));
  }
  return m;
}

std::uint32_t ElementMesh::Subdivide(std::uint32_t e)
{
  const std::array<std::uint32_t, 3> v = this->Nodes[e].V;
  const std::uint32_t ab = this->Midpoint(v[0], v[1]);
  const std::uint32_t bc = this->Midpoint(v[1], v[2]);
  const std::uint32_t ca = this->Midpoint(v[2], v[0]);
  const std::uint32_t source = this->Nodes[e].Source;
  const auto level = static_cast<std::uint16_t>(this->Nodes[e].Level + 1);
  const auto parent = static_cast<std::int32_t>(e);

  const std::uint32_t first = this->AddElement({ v[0], ab, ca }, parent, source, level);
  this->AddElement({ ab, v[1], bc }, parent, source, level);
  this->AddElement({ ca, bc, v[2] }, parent, source, level);
  this->AddElement({ ab, bc, ca }, parent, source, level);
  --this->LeafCount; // the parent stops being a leaf

  Element& p = this->Nodes[e];
  p.FirstChild = static_cast<std::int32_t>(first);
  // Linear field through the parent's corners, evaluated at the children's
  // corners and centroids, plus the offset that keeps the parent's mean.
  const RGB h0 = p.Irradiance.Corner[0], h1 = p.Irradiance.Corner[1], h2 = p.Irradiance.Corner[2];
  const RGB offset = p.Irradiance.Mean() - (h0 + h1 + h2) / 3.0;
  const RGB m01 = 0.5 * (h0 + h1), m12 = 0.5 * (h1 + h2), m20 = 0.5 * (h2 + h0);
  const std::array<std::array<RGB, 3>, 4> corners = { { { h0, m01, m20 }, { m01, h1, m12 },
    { m20, m12, h2 }, { m01, m12, m20 } } };
  for (int c = 0; c < 4; ++c)
  {
    Element& child = this->Nodes[first + c];
    for (int k = 0; k < 3; ++k)
    {
      child.Irradiance.Corner[k] = corners[c][k] + offset;
    }
    child.Irradiance.Centre =
      (corners[c][0] + corners[c][1] + corners[c][2]) / 3.0 + offset;
    child.Unshot = p.Unshot;
    child.ShooterNode = p.ShooterNode;
  }
  p.Unshot = RGB(0.0);
  return first;
}

std::vector<std::uint16_t> ElementMesh::MaxLevels(int levels) const
{
  std::vector<std::uint16_t> deepest(this->SourceScene->Triangles.size(), 0);
  for (const Element& e : this->Nodes)
  {
    deepest[e.Source] = std::max(deepest[e.Source], e.Level);
  }
  for (auto& level : deepest)
  {
    level = static_cast<std::uint16_t>(level + std::max(0, levels));
  }
  return deepest;
}

std::vector<std::uint32_t> ElementMesh::Leaves() const
{
  std::vector<std::uint32_t> leaves;
  leaves.reserve(this->LeafCount);
  for (std::size_t e = 0; e < this->Nodes.size(); ++e)
  {
    if (this->Nodes[e].IsLeaf())
    {
      leaves.push_back(static_cast<std::uint32_t>(e));
    }
  }
  return leaves;
}
} // namespace radiosity
