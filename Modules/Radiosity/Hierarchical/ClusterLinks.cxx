#include "Radiosity/Hierarchical/ClusterLinks.h"

#include "Radiosity/Common/Visibility.h"
#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"
#include "Radiosity/Hierarchical/HierarchicalNodeRules.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{
constexpr double HalfPi = 1.57079632679489661923;
/// A cluster receives through a link only when its radius is at most this
/// fraction of the distance: its irradiance is a first-order expansion about
/// its centroid, whose error grows with the square of that ratio.
/// Measured on the 20,480-triangle sphere (rho 0.8): 0.25 and 0.4 gave the
/// same links and error (the normal cone decides there).
constexpr double ReceiverOpening = 0.25;
/// Two elements whose spheres' radii sum to at most this fraction of their
/// distance are linked with sampled visibility, not blockers.
constexpr double DistantElements = 0.25;
/// Two elements too small to split are linked by samples up to this opening.
constexpr double SmallOpening = 1.0;
} // namespace

ClusterLinks::ClusterLinks(const Scene& scene, std::shared_ptr<const FaceClusterHierarchy> hierarchy,
  const Visibility& rays, double diagonal, double planeTolerance, const ElementMesh& mesh, Split split,
  double minEdge, const std::vector<RGB>& radiosity)
  : SourceScene(scene)
  , Clusters(std::move(hierarchy))
  , Rays(rays)
  , Diagonal(diagonal)
  , PlaneTolerance(planeTolerance)
  , Mesh(mesh)
  , SplitElement(std::move(split))
  , MinEdge(minEdge)
  , ElementRadiosity(&radiosity)
  , Triangles(scene.Triangles.size())
{
  this->Frames.resize(this->Triangles);
  tbb::parallel_for(std::size_t(0), this->Triangles, [&](std::size_t t) {
    this->Frames[t] = { scene.Centroid(t), scene.Normal(t), scene.Area(t) };
  });
  const FaceClusterHierarchy& h = *this->Clusters;
  const std::size_t internal = h.NumberOfClusters() - this->Triangles;
  this->InternalBounds.resize(internal);
  const std::vector<double>& cumulative = h.CumulativeArea();
  const std::vector<std::uint32_t>& order = h.TriangleOrder();
  // Each cluster's triangles are a run of TriangleOrder: their normals and
  // corners copied in that order, so that a cluster reads one run of memory
  // (its triangles are scattered in the scene's order).
  std::vector<std::array<Vec3, 4>> laidOut(order.size());
  tbb::parallel_for(std::size_t(0), order.size(), [&](std::size_t k) {
    const std::uint32_t t = order[k];
    laidOut[k] = { this->Frames[t].Normal, scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, internal, 64), [&](const tbb::blocked_range<std::size_t>& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i)
    {
      const FaceCluster& c = *h.InternalCluster(static_cast<std::uint32_t>(this->Triangles + i));
      Bounds& b = this->InternalBounds[i];
      b.Centre = Vec3(c.Centre);
      const double half = glm::length(Vec3(c.HalfSize));
      // The box is stored in single precision: a margin keeps it around its triangles.
      b.Radius = half * (1.0 + 1e-5) + this->PlaneTolerance;
      b.Axis = glm::normalize(Vec3(c.Axis[2]));
      b.Area = cumulative[c.First + c.Count] - cumulative[c.First];
      double minCos = 1.0, offPlane = 0.0;
      const Vec3 origin(c.Centroid);
      for (std::uint32_t k = c.First; k < c.First + c.Count; ++k)
      {
        const std::array<Vec3, 4>& t = laidOut[k];
        minCos = std::min(minCos, glm::dot(t[0], b.Axis));
        for (int v = 1; v <= 3; ++v)
        {
          offPlane = std::max(offPlane, std::fabs(glm::dot(t[v] - origin, b.Axis)));
        }
      }
      b.ConeAngle = std::acos(std::clamp(minCos, -1.0, 1.0));
      b.CosCone = std::cos(b.ConeAngle);
      b.SinCone = std::sin(b.ConeAngle);
      b.Flat = minCos >= 1.0 - 1e-12 && offPlane <= this->PlaneTolerance + 1e-6 * half;
      // No larger than the polygon solver's smallest element: a leaf, as face
      // cluster radiosity's are, so the links stop at a size, not at the
      // input; a curved one clamps its links per triangle (Descend).
      b.Leaf = 2.0 * half <= this->MinEdge;
    }
  });
  this->Radiosity.assign(h.NumberOfClusters(), RGB(0.0));
  // Depth first, the first child's subtree before the second's (Descend).
  this->Preorder.reserve(h.NumberOfClusters());
  std::vector<std::uint32_t> stack;
  for (std::uint32_t root : h.Roots())
  {
    this->RootPositions.push_back(static_cast<std::uint32_t>(this->Preorder.size()));
    stack.assign(1, root);
    while (!stack.empty())
    {
      const std::uint32_t c = stack.back();
      stack.pop_back();
      const auto position = static_cast<std::uint32_t>(this->Preorder.size());
      if (c < this->Triangles)
      {
        this->Preorder.push_back(
          { this->Frames[c].Centroid, this->Frames[c].Normal, this->Frames[c].Area, c, position + 1 });
      }
      else
      {
        const FaceCluster& f = *h.InternalCluster(c);
        this->Preorder.push_back(
          { Vec3(f.Centroid), Vec3(0.0), this->InternalBounds[c - this->Triangles].Area, c, 0 });
        stack.push_back(f.Child[1]);
        stack.push_back(f.Child[0]);
      }
    }
    // Each subtree's end, from the last position back: a node's subtree ends
    // where its second child's does.
    const std::uint32_t first = this->RootPositions.back();
    for (std::uint32_t p = static_cast<std::uint32_t>(this->Preorder.size()); p-- > first;)
    {
      DescentNode& node = this->Preorder[p];
      if (node.Id >= this->Triangles)
      {
        const std::uint32_t second = this->Preorder[p + 1].End; // the first child's subtree ends at the second
        node.End = this->Preorder[second].End;
      }
    }
  }
}

ClusterLinks::~ClusterLinks() = default;

std::size_t ClusterLinks::NumberOfRootPairs() const
{
  const std::size_t r = this->Clusters->Roots().size();
  return r * r;
}

std::size_t ClusterLinks::NumberOfLinks() const
{
  return this->ToElements.size() + this->ToClusters.size();
}

std::size_t ClusterLinks::MemoryBytes() const
{
  std::size_t decisions = this->FacingCursor.capacity() * sizeof(std::uint32_t);
  for (const std::vector<Facing>& d : this->FacingDecisions)
  {
    decisions += sizeof(d) + d.capacity() * sizeof(Facing);
  }
  return decisions + this->ToElements.capacity() * sizeof(ScalarLink) + this->ToClusters.capacity() * sizeof(VectorLink) +
    this->Deferred.capacity() * sizeof(Pair) +
    (this->ElementOffsets.capacity() + this->ClusterOffsets.capacity()) * sizeof(std::uint32_t) +
    this->Preorder.capacity() * sizeof(DescentNode) +
    this->InternalBounds.capacity() * sizeof(Bounds) + this->Radiosity.capacity() * sizeof(RGB) +
    this->Clusters->MemoryBytes();
}

std::uint32_t ClusterLinks::NodeOf(std::uint32_t cluster) const
{
  return cluster < this->Triangles ? (cluster | ElementBit) : cluster;
}

const RGB& ClusterLinks::RadiosityOf(std::uint32_t node) const
{
  return IsElement(node) ? (*this->ElementRadiosity)[ElementOf(node)] : this->Radiosity[node];
}

ClusterLinks::Bounds ClusterLinks::BoundsOf(std::uint32_t node) const
{
  if (!IsElement(node))
  {
    return this->InternalBounds[node - this->Triangles];
  }
  const std::uint32_t e = ElementOf(node);
  const Element& el = this->Mesh[e];
  Bounds b;
  b.Centre = el.Centroid;
  b.Radius = 0.0;
  for (int v = 0; v < 3; ++v)
  {
    b.Radius = std::max(b.Radius, glm::length(this->Mesh.Corner(e, v) - b.Centre));
  }
  b.Radius += this->PlaneTolerance;
  b.Axis = el.Normal;
  b.ConeAngle = 0.0;
  b.CosCone = 1.0;
  b.SinCone = 0.0;
  b.Area = el.Area;
  b.Flat = true;
  b.Leaf = this->Mesh.LongestEdge(e) <= this->MinEdge;
  return b;
}

bool ClusterLinks::CannotExchange(const Bounds& receiver, const Bounds& source, std::uint32_t sourceNode) const
{
  // Everything of the source on or behind a flat receiver's plane.
  if (receiver.Flat)
  {
    double front = -1e300;
    if (IsElement(sourceNode))
    {
      for (int v = 0; v < 3; ++v)
      {
        front = std::max(front, glm::dot(this->Mesh.Corner(ElementOf(sourceNode), v) - receiver.Centre, receiver.Axis));
      }
    }
    else
    {
      const FaceCluster& c = *this->Clusters->InternalCluster(sourceNode);
      front = glm::dot(Vec3(c.Centre) - receiver.Centre, receiver.Axis);
      for (int k = 0; k < 3; ++k)
      {
        front += std::fabs(double(c.HalfSize[k]) * glm::dot(Vec3(c.Axis[k]), receiver.Axis));
      }
      front += 1e-5 * source.Radius;
    }
    if (front <= this->PlaneTolerance)
    {
      return true;
    }
  }
  // Cones: every triangle of one faces away from every point of the other.
  const Vec3 d = source.Centre - receiver.Centre;
  const double distance = glm::length(d);
  if (distance <= receiver.Radius + source.Radius)
  {
    return false;
  }
  const Vec3 w = d / distance;
  const double alpha = std::asin((receiver.Radius + source.Radius) / distance);
  const double towardSource = std::acos(std::clamp(glm::dot(receiver.Axis, w), -1.0, 1.0));
  const double towardReceiver = std::acos(std::clamp(-glm::dot(source.Axis, w), -1.0, 1.0));
  return towardSource - receiver.ConeAngle - alpha >= HalfPi ||
    towardReceiver - source.ConeAngle - alpha >= HalfPi;
}

double ClusterLinks::Bound(const Bounds& r, const Bounds& q, std::uint32_t source) const
{
  const double distance = glm::length(q.Centre - r.Centre);
  const double gap = distance - r.Radius - q.Radius;
  return gap > 0 ? MaxComponent(this->RadiosityOf(source)) * std::max(q.Area, r.Area) / (Pi * distance * distance)
                 : std::numeric_limits<double>::infinity();
}

void ClusterLinks::PullRadiosity()
{
  const std::vector<RGB>& elements = *this->ElementRadiosity;
  std::copy(elements.begin(), elements.begin() + static_cast<std::ptrdiff_t>(this->Triangles),
    this->Radiosity.begin());
  tbb::parallel_for(std::size_t(0), this->RootPositions.size(), [&](std::size_t r) { this->Pull(this->RootPositions[r]); });
}

void ClusterLinks::Pull(std::uint32_t position)
{
  const DescentNode& node = this->Preorder[position];
  if (node.Id < this->Triangles)
  {
    return;
  }
  this->VisitChildren(position, true, [this](std::uint32_t child) { this->Pull(child); });
  RGB sum(0.0);
  double area = 0.0;
  for (std::uint32_t child : this->ChildPositions(position))
  {
    const double a = this->Preorder[child].Area;
    sum += a * this->Radiosity[this->Preorder[child].Id];
    area += a;
  }
  this->Radiosity[node.Id] = area > 0 ? sum / area : RGB(0.0);
}

void ClusterLinks::Refine(
  std::uint32_t r, std::uint32_t q, double epsilon, std::vector<Pair>& out, const ElementPair& elements)
{
  const bool er = IsElement(r), eq = IsElement(q);
  if (r == q)
  {
    // An element does not see itself, nor does a cluster with no concave
    // edge; a leaf's light within itself is below the solution's resolution.
    if (er || this->Clusters->InternalCluster(r)->Convex || this->InternalBounds[r - this->Triangles].Leaf)
    {
      return;
    }
    for (std::uint32_t a : this->Clusters->InternalCluster(r)->Child)
    {
      for (std::uint32_t b : this->Clusters->InternalCluster(r)->Child)
      {
        this->Refine(this->NodeOf(a), this->NodeOf(b), epsilon, out, elements);
      }
    }
    return;
  }
  if (er && eq)
  {
    // Two elements: a sampled link when they are distant, or both too small
    // to split and apart; otherwise the polygon solver's exact link with its
    // blockers (HierarchicalRadiosity::Refine).
    if (MaxComponent(this->RadiosityOf(q)) > 0)
    {
      const Bounds R = this->BoundsOf(r), Q = this->BoundsOf(q);
      const double distance = glm::length(Q.Centre - R.Centre);
      const bool small = R.Leaf && Q.Leaf && R.Radius + Q.Radius <= SmallOpening * distance;
      const bool distant = R.Radius + Q.Radius <= DistantElements * distance && this->Bound(R, Q, q) <= epsilon;
      if (R.Leaf != Q.Leaf && !small && !distant)
      {
        // One element too small to split facing a larger one (apart or not:
        // a large element's sphere holds much that does not touch it): the
        // larger is split here, and its parts sampled, rather than every
        // part's shaft searched for blockers against an element that meshing
        // could not refine; touching parts still reach the polygon solver.
        if (!this->CannotExchange(R, Q, q) && !this->CannotExchange(Q, R, r))
        {
          const bool receiver = !R.Leaf;
          const std::uint32_t c = this->SplitElement(ElementOf(receiver ? r : q));
          for (std::uint32_t i = 0; i < 4; ++i)
          {
            this->Refine(receiver ? (c + i) | ElementBit : r, receiver ? q : (c + i) | ElementBit, epsilon, out, elements);
          }
        }
        return;
      }
      if ((small || distant) && !this->CannotExchange(R, Q, q) && !this->CannotExchange(Q, R, r))
      {
        if (this->BeforeLink)
        {
          this->BeforeLink(this->NumberOfLinks() + out.size());
        }
        out.push_back({ r, q });
        return;
      }
    }
    elements(ElementOf(r), ElementOf(q));
    return;
  }
  const Bounds R = this->BoundsOf(r), Q = this->BoundsOf(q);
  if (this->CannotExchange(R, Q, q) || this->CannotExchange(Q, R, r))
  {
    return;
  }
  const Vec3 d = Q.Centre - R.Centre;
  const double distance = glm::length(d);
  const double bound = this->Bound(R, Q, q);
  // Which to split: the larger while the transfer is too large; the
  // receiver when only its own extent or normal cone stands in the way.
  const bool sr = !R.Leaf, sq = !Q.Leaf;
  bool splitReceiver = sr && (!sq || R.Radius >= Q.Radius);
  if (!(MaxComponent(this->RadiosityOf(q)) > 0))
  {
    // Nothing to send yet: refined when the source has radiosity (RefineAgain).
    this->Deferred.push_back({ r, q });
    return;
  }
  if ((bound <= epsilon && R.Radius + Q.Radius <= SampledOpening * distance) || (!sr && !sq))
  {
    const double alpha = std::asin(std::min(1.0, (R.Radius + Q.Radius) / distance));
    // A cluster receives when every triangle of it faces the whole source,
    // or when it is (nearly) flat: then the source's samples behind its plane
    // are left out of the transfer (Compute), as an element's are.
    // A leaf cluster receives whatever its cone: it is not split, and each
    // triangle takes its own normal's share of the vector (Compute, Descend).
    const bool receives = er || R.Leaf ||
      (R.Radius <= ReceiverOpening * distance &&
        (R.ConeAngle <= NearlyFlatCone ||
          std::acos(std::clamp(glm::dot(R.Axis, d / distance), -1.0, 1.0)) + R.ConeAngle + alpha < HalfPi));
    if (receives)
    {
      if (this->BeforeLink)
      {
        this->BeforeLink(this->NumberOfLinks() + out.size());
      }
      out.push_back({ r, q });
      return;
    }
    splitReceiver = true;
  }
  if (splitReceiver)
  {
    if (er)
    {
      const std::uint32_t c = this->SplitElement(ElementOf(r));
      for (std::uint32_t i = 0; i < 4; ++i)
      {
        this->Refine((c + i) | ElementBit, q, epsilon, out, elements);
      }
    }
    else
    {
      for (std::uint32_t c : this->Clusters->InternalCluster(r)->Child)
      {
        this->Refine(this->NodeOf(c), q, epsilon, out, elements);
      }
    }
  }
  else if (eq)
  {
    const std::uint32_t c = this->SplitElement(ElementOf(q));
    for (std::uint32_t i = 0; i < 4; ++i)
    {
      this->Refine(r, (c + i) | ElementBit, epsilon, out, elements);
    }
  }
  else
  {
    for (std::uint32_t c : this->Clusters->InternalCluster(q)->Child)
    {
      this->Refine(r, this->NodeOf(c), epsilon, out, elements);
    }
  }
}

bool ClusterLinks::LinkRoots(double epsilon, std::vector<Pair>& out, const ElementPair& elements,
  const std::function<bool()>& keepGoing)
{
  const std::vector<std::uint32_t>& roots = this->Clusters->Roots();
  for (std::uint32_t r : roots)
  {
    if (!keepGoing())
    {
      return false;
    }
    for (std::uint32_t q : roots)
    {
      this->Refine(this->NodeOf(r), this->NodeOf(q), epsilon, out, elements);
    }
  }
  return true;
}

std::size_t ClusterLinks::RefineAgain(double epsilon, std::vector<Pair>& out, const ElementPair& elements)
{
  std::vector<Pair> again;
  const auto tooLarge = [&](std::uint32_t r, std::uint32_t q) {
    if (this->Bound(this->BoundsOf(r), this->BoundsOf(q), q) > epsilon)
    {
      again.push_back({ r, q });
      return true;
    }
    return false;
  };
  this->ToElements.erase(std::remove_if(this->ToElements.begin(), this->ToElements.end(),
                           [&](const ScalarLink& l) { return tooLarge(l.Receiver | ElementBit, l.Source); }),
    this->ToElements.end());
  this->ToClusters.erase(std::remove_if(this->ToClusters.begin(), this->ToClusters.end(),
                           [&](const VectorLink& l) { return tooLarge(l.Receiver, l.Source); }),
    this->ToClusters.end());
  for (const Pair& p : again)
  {
    this->Refine(p.Receiver, p.Source, epsilon, out, elements);
  }
  const std::size_t changed = again.size() + this->RefineLitDeferred(epsilon, out, elements);
  this->Index();
  return changed;
}

std::size_t ClusterLinks::RefineLitDeferred(double epsilon, std::vector<Pair>& out, const ElementPair& elements)
{
  std::vector<Pair> deferred;
  deferred.swap(this->Deferred);
  std::size_t linked = 0;
  for (const Pair& p : deferred)
  {
    if (MaxComponent(this->RadiosityOf(p.Source)) > 0)
    {
      this->Refine(p.Receiver, p.Source, epsilon, out, elements);
      ++linked;
    }
    else
    {
      this->Deferred.push_back(p); // still dark: Refine would defer it again
    }
  }
  return linked;
}

std::size_t ClusterLinks::LinkDeferred(double epsilon, std::vector<Pair>& out, const ElementPair& elements)
{
  const std::size_t linked = this->RefineLitDeferred(epsilon, out, elements);
  this->Index();
  return linked;
}

void ClusterLinks::Index()
{
  std::stable_sort(this->ToElements.begin(), this->ToElements.end(),
    [](const ScalarLink& a, const ScalarLink& b) { return a.Receiver < b.Receiver; });
  std::stable_sort(this->ToClusters.begin(), this->ToClusters.end(),
    [](const VectorLink& a, const VectorLink& b) { return a.Receiver < b.Receiver; });
  const std::size_t elements = this->Mesh.Elements().size();
  this->ElementOffsets.assign(elements + 1, 0);
  for (const ScalarLink& l : this->ToElements)
  {
    ++this->ElementOffsets[l.Receiver + 1];
  }
  for (std::size_t i = 0; i < elements; ++i)
  {
    this->ElementOffsets[i + 1] += this->ElementOffsets[i];
  }
  // The links changed: their FacingOf decisions are recorded again.
  std::uint32_t straddling = 0;
  for (VectorLink& l : this->ToClusters)
  {
    l.Straddling = l.Straddles ? straddling++ : 0;
  }
  this->FacingDecisions.assign(straddling, {});
  this->FacingCursor.assign(straddling, 0);
  this->FacingRecorded = false;
  const std::size_t internal = this->InternalBounds.size();
  this->ClusterOffsets.assign(internal + 1, 0);
  for (const VectorLink& l : this->ToClusters)
  {
    ++this->ClusterOffsets[l.Receiver - this->Triangles + 1];
  }
  for (std::size_t i = 0; i < internal; ++i)
  {
    this->ClusterOffsets[i + 1] += this->ClusterOffsets[i];
  }
}
} // namespace radiosity
