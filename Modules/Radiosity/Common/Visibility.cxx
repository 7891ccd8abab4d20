#include "Radiosity/Common/Visibility.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace radiosity
{
namespace
{
// One Embree device for the process, never released: a solution held by a
// VTK object until the process exits (ParaView keeps its pipelines to the
// end) would otherwise release its device after Embree's own statics are
// gone, and rtcReleaseDevice then waits forever on a destroyed mutex.
RTCDevice SharedDevice()
{
  static RTCDevice device = rtcNewDevice("threads=0");
  return device;
}
}

struct Visibility::Internals
{
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  std::vector<unsigned> GeometryToTriangle; // Embree primitive id -> scene triangle
  Vec3 Origin{ 0.0 }; // scene centre: float coordinates relative to it lose less
  mutable std::atomic<std::size_t> Rays{ 0 };
  /// An Embree point query of the sphere (centre, radius) in the BVH's frame.
  RTCPointQuery PointQuery(const Vec3& centre, float radius) const;
};

Visibility::Visibility(const Scene& scene, const std::vector<unsigned char>& canOcclude)
  : Impl(new Internals)
{
  Vec3 lo(0.0), hi(0.0);
  if (!scene.Triangles.empty())
  {
    scene.BoundingBox(lo, hi);
  }
  const double diag = glm::length(hi - lo);
  this->Impl->Origin = 0.5 * (lo + hi);
  // Single precision BVH: 1e-5 of the extent is ~100 ulps of a float there.
  this->Epsilon = 1e-5 * (diag > 0 ? diag : 1.0);

  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (canOcclude[t])
    {
      this->Impl->GeometryToTriangle.push_back(static_cast<unsigned>(t));
    }
  }
  this->NumberOfOccluders = this->Impl->GeometryToTriangle.size();

  this->Impl->Device = SharedDevice();
  if (!this->Impl->Device)
  {
    throw std::runtime_error("Embree: cannot create a device");
  }
  this->Impl->Scene = rtcNewScene(this->Impl->Device);
  // The context filter lets CollectOccluders see every hit along a segment.
  rtcSetSceneFlags(
    this->Impl->Scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(this->Impl->Scene, RTC_BUILD_QUALITY_HIGH);
  if (this->NumberOfOccluders > 0)
  {
    RTCGeometry geom = rtcNewGeometry(this->Impl->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const std::size_t nt = this->NumberOfOccluders;
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * nt));
    auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
    for (std::size_t i = 0; i < nt; ++i)
    {
      const unsigned t = this->Impl->GeometryToTriangle[i];
      for (int k = 0; k < 3; ++k)
      {
        const Vec3 p = scene.Vertex(t, k) - this->Impl->Origin;
        vb[9 * i + 3 * k + 0] = static_cast<float>(p.x);
        vb[9 * i + 3 * k + 1] = static_cast<float>(p.y);
        vb[9 * i + 3 * k + 2] = static_cast<float>(p.z);
        ib[3 * i + k] = static_cast<unsigned>(3 * i + k);
      }
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(this->Impl->Scene, geom);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(this->Impl->Scene);
}

bool Visibility::Occludes(std::uint32_t t) const
{
  // In scene order: the occluders were listed as the scene's triangles were walked.
  return std::binary_search(this->Impl->GeometryToTriangle.begin(), this->Impl->GeometryToTriangle.end(), t);
}

Visibility::~Visibility()
{
  if (this->Impl->Scene)
  {
    rtcReleaseScene(this->Impl->Scene);
  }
}

std::size_t Visibility::RaysCast() const
{
  return this->Impl->Rays.load();
}

namespace
{
// The intersect context comes first so that Embree's context pointer is ours.
struct PassingContext
{
  RTCIntersectContext Context;
  const std::vector<unsigned>* GeometryToTriangle;
  const std::function<bool(std::uint32_t)>* Passes;
};

void PassThrough(const RTCFilterFunctionNArguments* args)
{
  const auto* ctx = reinterpret_cast<const PassingContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i)
  {
    if (args->valid[i] != 0 &&
      (*ctx->Passes)((*ctx->GeometryToTriangle)[RTCHitN_primID(args->hit, args->N, i)]))
    {
      args->valid[i] = 0; // not an occluder of this segment: traversal goes on
    }
  }
}
}

namespace
{
/// The Embree ray of the segment from -> to (coordinates relative to
/// `origin`), shortened by `epsilon` at both ends; false when nothing fits
/// between the ends.
bool SegmentRay(const Vec3& origin, const Vec3& from, const Vec3& to, double epsilon, RTCRay& r)
{
  const Vec3 o = from - origin;
  const Vec3 d = to - from;
  const double len = glm::length(d);
  if (len <= 2.0 * epsilon)
  {
    return false;
  }
  r.org_x = static_cast<float>(o.x);
  r.org_y = static_cast<float>(o.y);
  r.org_z = static_cast<float>(o.z);
  r.dir_x = static_cast<float>(d.x / len);
  r.dir_y = static_cast<float>(d.y / len);
  r.dir_z = static_cast<float>(d.z / len);
  r.tnear = static_cast<float>(epsilon);
  r.tfar = static_cast<float>(len - epsilon);
  r.time = 0.f;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
  return true;
}
} // namespace

void Visibility::TestSegments(
  const Vec3* from, const Vec3* to, std::size_t n, unsigned char* visible) const
{
  this->TestSegmentsPassing(from, to, n, {}, visible);
}

void Visibility::TestSegmentsPassing(const Vec3* from, const Vec3* to, std::size_t n,
  const std::function<bool(std::uint32_t)>& passes, unsigned char* visible) const
{
  if (this->Empty())
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      visible[i] = 1;
    }
    return;
  }
  constexpr std::size_t Batch = 64;
  RTCRay rays[Batch];
  PassingContext passing;
  rtcInitIntersectContext(&passing.Context);
  passing.GeometryToTriangle = &this->Impl->GeometryToTriangle;
  passing.Passes = &passes;
  if (passes)
  {
    passing.Context.filter = &PassThrough;
  }
  std::size_t cast = 0;
  for (std::size_t start = 0; start < n; start += Batch)
  {
    const std::size_t count = std::min(Batch, n - start);
    std::size_t k = 0;
    unsigned char* out = visible + start;
    std::size_t slot[Batch];
    for (std::size_t i = 0; i < count; ++i)
    {
      if (!SegmentRay(this->Impl->Origin, from[start + i], to[start + i], this->Epsilon, rays[k]))
      {
        out[i] = 1; // endpoints closer than the offset: nothing fits between
        continue;
      }
      slot[k++] = i;
    }
    if (k > 0)
    {
      rtcOccluded1M(this->Impl->Scene, &passing.Context, rays, static_cast<unsigned>(k), sizeof(RTCRay));
      for (std::size_t j = 0; j < k; ++j)
      {
        // Embree marks an occluded ray by setting tfar to -inf.
        out[slot[j]] = rays[j].tfar >= 0.f ? 1 : 0;
      }
      cast += k;
    }
  }
  this->Impl->Rays += cast;
}

void Visibility::FirstHits(const Vec3* from, const Vec3* to, std::size_t n, std::uint32_t* triangle) const
{
  std::fill(triangle, triangle + n, NoHit);
  if (this->Empty())
  {
    return;
  }
  constexpr std::size_t Batch = 64;
  RTCRayHit rays[Batch];
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  std::size_t cast = 0;
  for (std::size_t start = 0; start < n; start += Batch)
  {
    const std::size_t count = std::min(Batch, n - start);
    std::size_t k = 0;
    std::size_t slot[Batch];
    for (std::size_t i = 0; i < count; ++i)
    {
      if (!SegmentRay(this->Impl->Origin, from[start + i], to[start + i], this->Epsilon, rays[k].ray))
      {
        continue; // as TestSegments: nothing fits between
      }
      rays[k].hit.geomID = RTC_INVALID_GEOMETRY_ID;
      slot[k++] = start + i;
    }
    if (k > 0)
    {
      rtcIntersect1M(this->Impl->Scene, &context, rays, static_cast<unsigned>(k), sizeof(RTCRayHit));
      for (std::size_t j = 0; j < k; ++j)
      {
        if (rays[j].hit.geomID != RTC_INVALID_GEOMETRY_ID)
        {
          triangle[slot[j]] = this->Impl->GeometryToTriangle[rays[j].hit.primID];
        }
      }
      cast += k;
    }
  }
  this->Impl->Rays += cast;
}

namespace
{
// The intersect context comes first so that Embree's context pointer is ours.
struct CollectingContext
{
  RTCIntersectContext Context;
  const std::vector<unsigned>* GeometryToTriangle;
  std::vector<std::uint32_t>* Hits;
};

void CollectHit(const RTCFilterFunctionNArguments* args)
{
  auto* ctx = reinterpret_cast<CollectingContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i)
  {
    if (args->valid[i] == 0)
    {
      continue;
    }
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    ctx->Hits->push_back((*ctx->GeometryToTriangle)[prim]);
    args->valid[i] = 0; // reject, so that traversal goes on to farther hits
  }
}
}

void Visibility::CollectOccluders(
  const Vec3* from, const Vec3* to, std::size_t n, std::vector<std::uint32_t>& triangles) const
{
  if (this->Empty())
  {
    return;
  }
  const std::size_t first = triangles.size();
  CollectingContext ctx;
  rtcInitIntersectContext(&ctx.Context);
  ctx.Context.filter = &CollectHit;
  ctx.GeometryToTriangle = &this->Impl->GeometryToTriangle;
  ctx.Hits = &triangles;
  for (std::size_t i = 0; i < n; ++i)
  {
    RTCRayHit rh;
    if (!SegmentRay(this->Impl->Origin, from[i], to[i], this->Epsilon, rh.ray))
    {
      continue;
    }
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(this->Impl->Scene, &ctx.Context, &rh);
  }
  this->Impl->Rays += n;
  std::sort(triangles.begin() + static_cast<std::ptrdiff_t>(first), triangles.end());
  triangles.erase(std::unique(triangles.begin() + static_cast<std::ptrdiff_t>(first), triangles.end()),
    triangles.end());
}

namespace
{
struct SphereQuery
{
  const std::vector<unsigned>* GeometryToTriangle;
  std::vector<std::uint32_t>* Hits;
};

bool CollectInSphere(RTCPointQueryFunctionArguments* args)
{
  auto* q = static_cast<SphereQuery*>(args->userPtr);
  q->Hits->push_back((*q->GeometryToTriangle)[args->primID]);
  return false; // the query sphere stays as it is
}

struct FilteredSphereQuery
{
  const std::vector<unsigned>* GeometryToTriangle;
  const std::function<bool(std::uint32_t)>* Keep;
  std::size_t Most;
  std::vector<std::uint32_t>* Hits;
  std::size_t Kept;
};

bool CollectKeptInSphere(RTCPointQueryFunctionArguments* args)
{
  auto* q = static_cast<FilteredSphereQuery*>(args->userPtr);
  if (q->Kept > q->Most)
  {
    return false;
  }
  const std::uint32_t t = (*q->GeometryToTriangle)[args->primID];
  // A triangle the BVH split over several leaves is met more than once.
  if (std::find(q->Hits->end() - static_cast<std::ptrdiff_t>(q->Kept), q->Hits->end(), t) != q->Hits->end() ||
    !(*q->Keep)(t))
  {
    return false;
  }
  q->Hits->push_back(t);
  if (++q->Kept > q->Most)
  {
    args->query->radius = 0.f; // enough: the traversal ends
    return true;
  }
  return false;
}
}

namespace
{
struct NearestQuery
{
  const std::vector<unsigned>* GeometryToTriangle;
  const std::function<double(std::uint32_t)>* Distance;
  double Best;
  std::int64_t Triangle;
  double Margin; ///< the float BVH's bounds against the double triangles
  bool Shrink;
};

bool NearestInSphere(RTCPointQueryFunctionArguments* args)
{
  auto* q = static_cast<NearestQuery*>(args->userPtr);
  const std::uint32_t t = (*q->GeometryToTriangle)[args->primID];
  const double d = (*q->Distance)(t);
  if (!(d < q->Best || (d == q->Best && q->Triangle >= 0 && t < q->Triangle)))
  {
    return false;
  }
  q->Best = d;
  q->Triangle = t;
  const float r = static_cast<float>(d + q->Margin);
  if (q->Shrink && r < args->query->radius)
  {
    args->query->radius = r;
    return true; // the sphere shrank
  }
  return false;
}
}

RTCPointQuery Visibility::Internals::PointQuery(const Vec3& centre, float radius) const
{
  const Vec3 c = centre - this->Origin; // the BVH's float coordinates are relative to it
  RTCPointQuery query;
  query.x = static_cast<float>(c.x);
  query.y = static_cast<float>(c.y);
  query.z = static_cast<float>(c.z);
  query.time = 0.f;
  query.radius = radius;
  return query;
}

std::int64_t Visibility::NearestTriangle(const Vec3& p, double radius,
  const std::function<double(std::uint32_t)>& distance, bool shrink) const
{
  if (this->Empty())
  {
    return -1;
  }
  RTCPointQuery query = this->Impl->PointQuery(p, std::isfinite(radius)
      ? static_cast<float>(radius + this->Epsilon)
      : std::numeric_limits<float>::infinity());
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  NearestQuery user{ &this->Impl->GeometryToTriangle, &distance, std::numeric_limits<double>::infinity(), -1,
    this->Epsilon, shrink };
  rtcPointQuery(this->Impl->Scene, &query, &context, &NearestInSphere, &user);
  return user.Best <= radius ? user.Triangle : -1;
}

void Visibility::OccludersInSphere(
  const Vec3& centre, double radius, std::vector<std::uint32_t>& triangles) const
{
  if (this->Empty())
  {
    return;
  }
  RTCPointQuery query = this->Impl->PointQuery(centre, static_cast<float>(radius * (1.0 + 1e-6) + this->Epsilon));
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  SphereQuery user{ &this->Impl->GeometryToTriangle, &triangles };
  rtcPointQuery(this->Impl->Scene, &query, &context, &CollectInSphere, &user);
}

bool Visibility::OccludersInSphere(const Vec3& centre, double radius,
  const std::function<bool(std::uint32_t)>& keep, std::size_t most, std::vector<std::uint32_t>& triangles) const
{
  if (this->Empty())
  {
    return true;
  }
  RTCPointQuery query = this->Impl->PointQuery(centre, static_cast<float>(radius * (1.0 + 1e-6) + this->Epsilon));
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  FilteredSphereQuery user{ &this->Impl->GeometryToTriangle, &keep, most, &triangles, 0 };
  rtcPointQuery(this->Impl->Scene, &query, &context, &CollectKeptInSphere, &user);
  return user.Kept <= most;
}

bool Visibility::Intersect(const Vec3& origin, const Vec3& direction, double& t,
  unsigned& triangle, double& u, double& v) const
{
  if (this->Empty())
  {
    return false;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  const Vec3 o = origin - this->Impl->Origin;
  const Vec3 d = glm::normalize(direction);
  rh.ray.org_x = static_cast<float>(o.x);
  rh.ray.org_y = static_cast<float>(o.y);
  rh.ray.org_z = static_cast<float>(o.z);
  rh.ray.dir_x = static_cast<float>(d.x);
  rh.ray.dir_y = static_cast<float>(d.y);
  rh.ray.dir_z = static_cast<float>(d.z);
  rh.ray.tnear = 0.f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.time = 0.f;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(this->Impl->Scene, &context, &rh);
  ++this->Impl->Rays;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
  {
    return false;
  }
  t = rh.ray.tfar;
  triangle = this->Impl->GeometryToTriangle[rh.hit.primID];
  u = rh.hit.u;
  v = rh.hit.v;
  return true;
}
} // namespace radiosity
