#include "Radiosity/Hierarchical/Backprojection.h"

#include "Radiosity/Common/ContourSum.h"
#include "Radiosity/Common/FormFactor.h"

#include <algorithm>
#include <type_traits>
#include <cmath>
#include <vector>

namespace radiosity
{
namespace backprojection_detail
{
SourceFrame::SourceFrame(const Vec3* corners, int count)
  : Source{ corners[0], corners[1], corners[2] }
  , Corners(std::min(count, MaxSourceCorners))
{
  std::copy(corners, corners + this->Corners, this->Outline.begin());
  Vec3 cross(0.0); // twice the area along the normal (Newell)
  for (int i = 1; i + 1 < this->Corners; ++i)
  {
    cross += glm::cross(corners[i] - corners[0], corners[i + 1] - corners[0]);
  }
  const double twiceArea = glm::length(cross);
  const Vec3 e1 = corners[1] - corners[0];
  if (!(twiceArea > 0) || !(glm::length(e1) > 0) || count > MaxSourceCorners)
  {
    return;
  }
  this->Valid = true;
  this->M = cross / twiceArea;
  this->PlaneOffset = glm::dot(corners[0], this->M);
  this->U = e1 / glm::length(e1);
  this->V = glm::cross(this->M, this->U);
  this->MinArea = 1e-14 * 0.5 * twiceArea;
  for (int i = 0; i < this->Corners; ++i)
  {
    this->Whole.Push(this->To2(corners[i]));
    for (int j = 0; j < i; ++j)
    {
      this->Size = std::max(this->Size, glm::length(corners[i] - corners[j]));
    }
  }
}

SourceFrame::SourceFrame(const TriangleCorners& source)
  : SourceFrame(source.data(), 3)
{
}

void BlockerLevels::FindLevels(const SourceFrame& frame)
{
  double lowest = 1e300, highest = -1e300;
  for (int i = 0; i < this->Size; ++i)
  {
    const double l = glm::dot(this->Corner[i], frame.M);
    this->Level[i] = l;
    this->Flat[i] = frame.To2(this->Corner[i]);
    lowest = std::min(lowest, l);
    highest = std::max(highest, l);
  }
  this->Lowest = lowest;
  this->Highest = highest;
}
} // namespace backprojection_detail

namespace
{
using backprojection_detail::BlockerLevels;
using backprojection_detail::Point2;
using backprojection_detail::Polygon2;
using backprojection_detail::SourceFrame;

double Cross(const Point2& o, const Point2& a, const Point2& b)
{
  return (a.X - o.X) * (b.Y - o.Y) - (a.Y - o.Y) * (b.X - o.X);
}

double SignedArea(const Polygon2& p)
{
  double a = 0.0;
  for (int i = 0; i < p.N; ++i)
  {
    const Point2& u = p.V[i];
    const Point2& v = p.V[i + 1 < p.N ? i + 1 : 0];
    a += u.X * v.Y - v.X * u.Y;
  }
  return 0.5 * a;
}

// Sutherland-Hodgman split by a line into its left and right parts in one
// pass, `side[i]` being corner i's Cross against the line (computed once:
// the pass visits each corner as both ends of an edge); false when a part
// would not fit (the caller stops subtracting).
bool SplitBySides(const Polygon2& in, const double* side, Polygon2& left, Polygon2& right)
{
  left.N = right.N = 0;
  for (int i = 0; i < in.N; ++i)
  {
    const int j = i + 1 < in.N ? i + 1 : 0;
    const Point2& p = in.V[i];
    const Point2& q = in.V[j];
    const double dp = side[i];
    const double dq = side[j];
    if (left.N + 2 > Polygon2::Capacity || right.N + 2 > Polygon2::Capacity)
    {
      return false;
    }
    if (dp >= 0)
    {
      left.Push(p);
    }
    if (dp <= 0)
    {
      right.Push(p);
    }
    if ((dp > 0 && dq < 0) || (dp < 0 && dq > 0))
    {
      const double t = dp / (dp - dq);
      const Point2 x{ p.X + t * (q.X - p.X), p.Y + t * (q.Y - p.Y) };
      left.Push(x);
      right.Push(x);
    }
  }
  return true;
}

// The same split by the line a->b.
bool SplitByLine(const Polygon2& in, const Point2& a, const Point2& b, Polygon2& left, Polygon2& right)
{
  double side[Polygon2::Capacity];
  for (int i = 0; i < in.N; ++i)
  {
    side[i] = Cross(a, b, in.V[i]);
  }
  return SplitBySides(in, side, left, right);
}

// Clip of a small 3D polygon to the half-space dot(p, m) - offset >= 0.
int ClipPlane(const Vec3* in, int n, const Vec3& m, double offset, Vec3* out)
{
  int k = 0;
  for (int i = 0; i < n; ++i)
  {
    const Vec3& p = in[i];
    const Vec3& q = in[(i + 1) % n];
    const double dp = glm::dot(p, m) - offset;
    const double dq = glm::dot(q, m) - offset;
    if (dp >= 0)
    {
      out[k++] = p;
    }
    if ((dp >= 0) != (dq >= 0))
    {
      out[k++] = p + (dp / (dp - dq)) * (q - p);
    }
  }
  return k;
}

struct Box2
{
  double X0 = 1e300, Y0 = 1e300, X1 = -1e300, Y1 = -1e300;
  explicit Box2(const Polygon2& p)
  {
    for (int i = 0; i < p.N; ++i)
    {
      X0 = std::min(X0, p.V[i].X);
      Y0 = std::min(Y0, p.V[i].Y);
      X1 = std::max(X1, p.V[i].X);
      Y1 = std::max(Y1, p.V[i].Y);
    }
  }
  bool Overlaps(const Box2& o) const
  {
    return X0 < o.X1 && o.X0 < X1 && Y0 < o.Y1 && o.Y0 < Y1;
  }
};

// Fragment minus a convex counter-clockwise polygon: the parts of `piece`
// outside each edge of `hole` in turn (disjoint by construction). False when
// a fragment outgrew its capacity (then `piece` is kept whole).
bool Subtract(const Polygon2& piece, const Polygon2& hole, double minArea, std::vector<Polygon2>& out)
{
  const std::size_t first = out.size();
  // What is left inside the hole's edges so far: the piece, then one of two
  // buffers in turn (no copy per edge).
  Polygon2 buffers[2], outside;
  const Polygon2* rest = &piece;
  for (int i = 0; i < hole.N && rest->N >= 3; ++i)
  {
    const Point2& a = hole.V[i];
    const Point2& b = hole.V[i + 1 < hole.N ? i + 1 : 0];
    // A piece wholly on one side of the edge's line needs no split (most
    // are: the hole's edges are few and the pieces small).
    double side[Polygon2::Capacity];
    bool left = true, right = true;
    for (int k = 0; k < rest->N; ++k)
    {
      side[k] = Cross(a, b, rest->V[k]);
      left = left && side[k] >= 0;
      right = right && side[k] <= 0;
    }
    if (left)
    {
      continue; // all of it still inside this edge
    }
    if (right)
    {
      // Wholly outside the hole: kept whole (as the split would keep it).
      if (std::abs(SignedArea(*rest)) > minArea)
      {
        out.push_back(*rest);
      }
      return true;
    }
    Polygon2& inside = rest == &buffers[0] ? buffers[1] : buffers[0]; // not the one read
    if (!SplitBySides(*rest, side, inside, outside))
    {
      out.resize(first);
      out.push_back(piece);
      return false;
    }
    if (outside.N >= 3 && std::abs(SignedArea(outside)) > minArea)
    {
      out.push_back(outside);
    }
    rest = &inside;
  }
  return true;
}
// Blocker parts within this distance of either plane cast no shadow worth a
// fragment (and would project to infinity at the receiver's plane): 1e-9 of
// x's height, and no less than a clip's rounding far above the coordinates'
// (a corner clipped 1e-14 below x's level at a height of 1e-5 and 5e3 from
// the origin came out above it and was projected behind x).
double SlabSlack(const SourceFrame& frame, const Vec3& x, double height)
{
  const double coordinates = glm::length(x) + glm::length(frame.Source[0]) + frame.Size;
  return std::max(1e-9 * height, 1e-13 * coordinates);
}

// The shadow of `blocker` on the source's plane seen from x (at `height`
// above it, at `xLevel` along its normal, at `flatX` in its frame),
// counter-clockwise in the source's frame: the blocker clipped to the slab
// between the two planes (less `slack`) and projected centrally from x. A
// corner c projects to x + t (c - x), t = height / (xLevel - level of c),
// found in the frame (an affine map) from the corner's 2D coordinates. False
// when it casts none (outside the slab, or seen edge-on).
bool ShadowOf(const SourceFrame& frame, const Point2& flatX, double height, double xLevel,
  double slack, const BlockerLevels& blocker, Polygon2& shadow)
{
  const Vec3& m = frame.M;
  const double lo = frame.PlaneOffset + slack, hi = xLevel - slack;
  if (blocker.Highest <= lo || blocker.Lowest >= hi)
  {
    return false; // wholly behind the source or behind the point
  }
  const double* level = blocker.Level;
  const Point2* flat = blocker.Flat;
  int n3 = blocker.Size;
  // Up to four corners, two more after each of the two clips; a blocker
  // wholly between the planes is its own clip.
  double clippedLevel[8];
  Point2 clippedFlat[8];
  if (!(blocker.Lowest > lo && blocker.Highest < hi))
  {
    Vec3 clipped[8], poly[8];
    n3 = ClipPlane(blocker.Corner, blocker.Size, m, lo, clipped);
    n3 = ClipPlane(clipped, n3, -m, -hi, poly);
    for (int i = 0; i < n3; ++i)
    {
      clippedLevel[i] = glm::dot(poly[i], m);
      clippedFlat[i] = frame.To2(poly[i]);
    }
    level = clippedLevel;
    flat = clippedFlat;
  }
  if (n3 < 3)
  {
    return false;
  }
  shadow.N = 0;
  for (int i = 0; i < n3; ++i)
  {
    const double t = height / (xLevel - level[i]);
    shadow.Push(Point2{ flatX.X + t * (flat[i].X - flatX.X), flatX.Y + t * (flat[i].Y - flatX.Y) });
  }
  const double area = SignedArea(shadow);
  if (std::abs(area) <= frame.MinArea)
  {
    return false; // seen edge-on from x
  }
  if (area < 0)
  {
    std::reverse(shadow.V, shadow.V + shadow.N);
  }
  return true;
}

// The intersection of p and the convex counter-clockwise polygon q; false
// when it would not fit. An empty intersection has fewer than 3 corners.
bool Intersect(const Polygon2& p, const Polygon2& q, Polygon2& out)
{
  Polygon2 buffers[2], outside;
  const Polygon2* in = &p;
  for (int i = 0; i < q.N && in->N >= 3; ++i)
  {
    Polygon2& next = buffers[i & 1];
    if (!SplitByLine(*in, q.V[i], q.V[i + 1 < q.N ? i + 1 : 0], next, outside))
    {
      return false;
    }
    in = &next;
  }
  out = *in;
  return true;
}

// What the backprojection sums over the visible part: the form factor
// (Scalar), or the vector form factor whose dot product with n is it
// (Vector: the irradiance vector of vector radiosity, what a glossy display
// reads). Both are Lambert's contour integral clipped to x's horizon, so
// both are additive over the fragments.
struct ScalarFactor
{
  using Value = double;
  static double Of(const Vec3& x, const Vec3& n, const Vec3* poly, std::size_t count)
  {
    return PointToPolygonFormFactor(x, n, poly, count);
  }
  static double NonNegative(double f) { return std::max(0.0, f); }
};

struct VectorFactor
{
  using Value = Vec3;
  static Vec3 Of(const Vec3& x, const Vec3& n, const Vec3* poly, std::size_t count)
  {
    return PointToPolygonVectorFormFactor(x, poly, count, &n);
  }
  static Vec3 NonNegative(const Vec3& f) { return f; }
};

// Lambert's contour formula over a convex polygon of the source's plane
// (fans beyond 8 corners, the contour kernel's stack size).
template <typename Factor = ScalarFactor>
typename Factor::Value FormFactorOf(const SourceFrame& frame, const Vec3& x, const Vec3& n, const Polygon2& piece)
{
  Vec3 poly3[Polygon2::Capacity];
  for (int i = 0; i < piece.N; ++i)
  {
    poly3[i] = frame.To3(piece.V[i]);
  }
  if (piece.N <= 8)
  {
    return Factor::Of(x, n, poly3, static_cast<std::size_t>(piece.N));
  }
  typename Factor::Value factor(0.0);
  for (int i = 1; i + 1 < piece.N; ++i)
  {
    const Vec3 fan[3] = { poly3[0], poly3[i], poly3[i + 1] };
    factor += Factor::Of(x, n, fan, 3);
  }
  return factor;
}

// Lambert's contour formula over fragments of a source that lies wholly
// above x's horizon, x `height` in front of it: the sum in the source's
// frame, without FormFactorOf's corners in 3D, horizon clip or facing test.
// The fragments turn counter-clockwise about the source's normal, towards
// x, so each one's sum has the same sign.
double PlainFragmentsFactor(
  const SourceFrame& frame, const Vec3& x, const Vec3& n, double height, const std::vector<Polygon2>& pieces)
{
  const Point2 foot = frame.To2(x);
  const Vec3 m(glm::dot(n, frame.U), glm::dot(n, frame.V), glm::dot(n, frame.M));
  ContourSum<double> sum;
  for (const Polygon2& piece : pieces)
  {
    Vec3 a(piece.V[0].X - foot.X, piece.V[0].Y - foot.Y, -height);
    const Vec3 first = a;
    for (int i = 0; i < piece.N; ++i)
    {
      const Vec3 b = i + 1 < piece.N ? Vec3(piece.V[i + 1].X - foot.X, piece.V[i + 1].Y - foot.Y, -height) : first;
      sum.Add(a, b, m, 1.0);
      a = b;
    }
  }
  return std::fabs(sum.Sum()) / (2.0 * Pi);
}

// The visible form factor as the source's less that of the union of the
// shadows on it, the union as disjoint convex pieces: shadow j's part on the
// source less the shadows before it,
//   F(S - U A_i) = F(S) - sum_j F((A_j n S) - A_1 - ... - A_(j-1)).
// Equal to VisibleFromPoint's sum over the visible fragments (the form
// factor is additive over regions), but better conditioned where x nearly
// touches the source's plane: there the form factor gathers at the foot of
// x, and cutting the whole source along the lines of the shadows' edges
// (which pass through that foot when a blocker stands on the source's
// plane) moved it by 1e-3 at 1e-8 above the plane, where the shadows change
// it by 2e-9. Here only the shadows are cut, and they lie away from the
// foot. False when a piece outgrew Polygon2's capacity (then nothing is
// computed).
template <typename Factor = ScalarFactor>
bool SourceLessShadows(const SourceFrame& frame, const Vec3& x, const Vec3& n,
  const std::vector<BlockerLevels>& blockers, typename Factor::Value& factor)
{
  const double height = glm::dot(x, frame.M) - frame.PlaneOffset;
  const double slack = SlabSlack(frame, x, height);
  const double xLevel = glm::dot(x, frame.M);
  const Point2 flatX = frame.To2(x);
  thread_local std::vector<Polygon2> shadows, pieces, next;
  shadows.clear();
  const Box2 sourceBox(frame.Whole);
  factor = Factor::Of(x, n, frame.Outline.data(), static_cast<std::size_t>(frame.Corners));
  for (const BlockerLevels& blocker : blockers)
  {
    Polygon2 shadow, part;
    if (!ShadowOf(frame, flatX, height, xLevel, slack, blocker, shadow) || !Box2(shadow).Overlaps(sourceBox))
    {
      continue;
    }
    if (!Intersect(frame.Whole, shadow, part))
    {
      return false;
    }
    if (part.N < 3 || !(SignedArea(part) > frame.MinArea))
    {
      continue; // beside the source
    }
    // What of this part the shadows before it have not covered yet.
    pieces.assign(1, part);
    for (const Polygon2& earlier : shadows)
    {
      const Box2 earlierBox(earlier);
      next.clear();
      for (const Polygon2& piece : pieces)
      {
        if (!Box2(piece).Overlaps(earlierBox))
        {
          next.push_back(piece);
        }
        else if (!Subtract(piece, earlier, frame.MinArea, next))
        {
          return false;
        }
      }
      pieces.swap(next);
      if (pieces.empty())
      {
        break;
      }
    }
    for (const Polygon2& piece : pieces)
    {
      factor -= FormFactorOf<Factor>(frame, x, n, piece);
    }
    shadows.push_back(part);
  }
  return true;
}

/// Below this height above the source's plane, relative to the source's
/// size, the visible part is found as the source less the shadows
/// (SourceLessShadows), not as fragments cut from the whole source.
constexpr double NearPlane = 1e-3;

// The visible form factor at x through the blockers that blockerAt(b)
// returns (BlockerLevels), for the source of `frame`: the source less each
// shadow in turn, as disjoint convex fragments (and near its plane,
// SourceLessShadows).
template <typename Factor = ScalarFactor, typename BlockerAt>
typename Factor::Value VisibleFromPoint(const SourceFrame& frame, const Vec3& x, const Vec3& n,
  std::size_t blockerCount, const BlockerAt& blockerAt, bool* exact, std::size_t fragmentsLimit)
{
  using Value = typename Factor::Value;
  if (exact)
  {
    *exact = true;
  }
  if (!frame.Valid)
  {
    return Value(0.0);
  }
  const Vec3& m = frame.M;
  const double planeOffset = frame.PlaneOffset;
  const double height = glm::dot(x, m) - planeOffset;
  if (!(height > 0))
  {
    return Value(0.0); // behind the one-sided source
  }
  if (blockerCount == 0)
  {
    return Factor::Of(x, n, frame.Outline.data(), static_cast<std::size_t>(frame.Corners));
  }

  if (height < NearPlane * frame.Size)
  {
    thread_local std::vector<BlockerLevels> near;
    near.clear();
    for (std::size_t b = 0; b < blockerCount; ++b)
    {
      near.push_back(blockerAt(b));
    }
    Value factor(0.0);
    if (SourceLessShadows<Factor>(frame, x, n, near, factor))
    {
      return Factor::NonNegative(factor);
    }
  }

  const double minArea = frame.MinArea;
  thread_local std::vector<Polygon2> visible, next;
  visible.clear();
  visible.push_back(frame.Whole);
  const double slack = SlabSlack(frame, x, height);
  const double xLevel = glm::dot(x, m);
  const Point2 flatX = frame.To2(x);

  for (std::size_t b = 0; b < blockerCount && !visible.empty(); ++b)
  {
    Polygon2 shadow;
    if (!ShadowOf(frame, flatX, height, xLevel, slack, blockerAt(b), shadow))
    {
      continue;
    }
    const Box2 shadowBox(shadow);
    next.clear();
    for (const Polygon2& piece : visible)
    {
      if (!Box2(piece).Overlaps(shadowBox))
      {
        next.push_back(piece);
        continue;
      }
      if (!Subtract(piece, shadow, minArea, next) && exact)
      {
        *exact = false;
      }
    }
    visible.swap(next);
    if (visible.size() > fragmentsLimit)
    {
      if (exact)
      {
        *exact = false;
      }
      break;
    }
  }

  if constexpr (std::is_same_v<Factor, ScalarFactor>)
  {
    bool above = true; // the whole source above x's horizon: no clip
    for (int i = 0; i < frame.Corners && above; ++i)
    {
      above = glm::dot(frame.Outline[static_cast<std::size_t>(i)] - x, n) >= 0.0;
    }
    if (above)
    {
      return PlainFragmentsFactor(frame, x, n, height, visible);
    }
  }
  Value factor(0.0);
  for (const Polygon2& piece : visible)
  {
    factor += FormFactorOf<Factor>(frame, x, n, piece);
  }
  return Factor::NonNegative(factor);
}

// The backprojection for blockers of up to four corners; corners(b, out)
// writes blocker b's corners to out and returns how many. Each blocker's
// levels are found when the loop reaches it (it stops once nothing is left).
template <typename Factor = ScalarFactor, typename Corners>
typename Factor::Value VisibleFormFactorOf(const Vec3& x, const Vec3& n, const SourceFrame& frame,
  std::size_t blockerCount, const Corners& corners, bool* exact, std::size_t fragmentsLimit)
{
  BlockerLevels current;
  return VisibleFromPoint<Factor>(frame, x, n, blockerCount,
    [&](std::size_t b) -> const BlockerLevels& {
      current.Size = corners(b, current.Corner);
      current.FindLevels(frame);
      return current;
    },
    exact, fragmentsLimit);
}
} // namespace

PreparedVisibleFormFactor::PreparedVisibleFormFactor(
  const TriangleCorners& source, const BlockerPolygon* blockers, std::size_t count)
  : Frame(source)
  , Blockers(count)
{
  for (std::size_t b = 0; b < count; ++b)
  {
    BlockerLevels& levels = this->Blockers[b];
    std::copy(blockers[b].Corners.begin(), blockers[b].Corners.begin() + blockers[b].Size, levels.Corner);
    levels.Size = blockers[b].Size;
    levels.FindLevels(this->Frame);
  }
}

double PreparedVisibleFormFactor::operator()(const Vec3& x, const Vec3& n) const
{
  return VisibleFromPoint(this->Frame, x, n, this->Blockers.size(),
    [this](std::size_t b) -> const BlockerLevels& { return this->Blockers[b]; }, nullptr, 4096);
}

double VisibleFormFactor(const Vec3& x, const Vec3& n, const TriangleCorners& source,
  const TriangleCorners* blockers, std::size_t blockerCount, bool* exact, std::size_t fragmentsLimit)
{
  return VisibleFormFactorOf(x, n, SourceFrame(source), blockerCount,
    [blockers](std::size_t b, Vec3* out) {
      std::copy(blockers[b].begin(), blockers[b].end(), out);
      return 3;
    },
    exact, fragmentsLimit);
}

double VisibleFormFactor(const Vec3& x, const Vec3& n, const TriangleCorners& source,
  const BlockerPolygon* blockers, std::size_t blockerCount, bool* exact, std::size_t fragmentsLimit)
{
  return VisibleFormFactorOf(x, n, SourceFrame(source), blockerCount,
    [blockers](std::size_t b, Vec3* out) {
      std::copy(blockers[b].Corners.begin(), blockers[b].Corners.begin() + blockers[b].Size, out);
      return blockers[b].Size;
    },
    exact, fragmentsLimit);
}

Vec3 VisibleVectorFormFactor(const Vec3& x, const Vec3& n, const TriangleCorners& source,
  const TriangleCorners* blockers, std::size_t blockerCount, bool* exact, std::size_t fragmentsLimit)
{
  return VisibleFormFactorOf<VectorFactor>(x, n, SourceFrame(source), blockerCount,
    [blockers](std::size_t b, Vec3* out) {
      std::copy(blockers[b].begin(), blockers[b].end(), out);
      return 3;
    },
    exact, fragmentsLimit);
}

Vec3 VisibleVectorFormFactor(const Vec3& x, const Vec3& n, const Vec3* source, int corners,
  const TriangleCorners* blockers, std::size_t blockerCount, bool* exact, std::size_t fragmentsLimit)
{
  return VisibleFormFactorOf<VectorFactor>(x, n, SourceFrame(source, corners), blockerCount,
    [blockers](std::size_t b, Vec3* out) {
      std::copy(blockers[b].begin(), blockers[b].end(), out);
      return 3;
    },
    exact, fragmentsLimit);
}

bool HidesWholly(const TriangleCorners& receiver, const TriangleCorners& source, const BlockerPolygon& blocker)
{
  const Vec3* b = blocker.Corners.data();
  Vec3 normal(0.0); // Newell: along the blocker's normal whatever its turn
  for (int i = 1; i + 1 < blocker.Size; ++i)
  {
    normal += glm::cross(b[i] - b[0], b[i + 1] - b[0]);
  }
  if (!(glm::dot(normal, normal) > 0.0))
  {
    return false;
  }
  for (const Vec3& r : receiver)
  {
    const double dr = glm::dot(r - b[0], normal);
    for (const Vec3& s : source)
    {
      const double ds = glm::dot(s - b[0], normal);
      // The segment must reach the blocker's plane: from either side, or
      // from a receiver corner on it (a contact edge).
      if (!((dr > 0.0 && ds < 0.0) || (dr < 0.0 && ds > 0.0) || (dr == 0.0 && ds != 0.0)))
      {
        return false;
      }
      const Vec3 p = r + (dr / (dr - ds)) * (s - r);
      for (int i = 0; i < blocker.Size; ++i)
      {
        const Vec3& e0 = b[i];
        const Vec3& e1 = b[(i + 1) % blocker.Size];
        if (glm::dot(glm::cross(e1 - e0, p - e0), normal) < 0.0)
        {
          return false;
        }
      }
    }
  }
  return true;
}

bool ConvexQuad(const Vec3 (&quad)[4], const Vec3& normal)
{
  for (int k = 0; k < 4; ++k)
  {
    const Vec3 turn = glm::cross(quad[(k + 1) % 4] - quad[k], quad[(k + 2) % 4] - quad[(k + 1) % 4]);
    if (!(glm::dot(turn, normal) > 0.0))
    {
      return false;
    }
  }
  return true;
}

std::vector<BlockerPolygon> MergeCoplanarPairs(
  const std::vector<TriangleCorners>& corners, const std::vector<std::array<std::uint32_t, 3>>& vertexIds)
{
  const std::size_t count = corners.size();
  std::vector<Vec3> normal(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    const Vec3 c = glm::cross(corners[i][1] - corners[i][0], corners[i][2] - corners[i][0]);
    const double length = glm::length(c);
    normal[i] = length > 0 ? c / length : Vec3(0.0);
  }
  // Edges by their two point indices: blocker lists are short (at most
  // MaxBlockersPerLink), so a sorted list does.
  struct Edge
  {
    std::uint64_t Key;
    std::uint32_t Triangle;
    int Side; ///< the edge from corner Side to corner Side + 1
  };
  std::vector<Edge> edges;
  edges.reserve(3 * count);
  for (std::size_t i = 0; i < count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = vertexIds[i][k], b = vertexIds[i][(k + 1) % 3];
      edges.push_back({ (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b),
        static_cast<std::uint32_t>(i), k });
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.Key < b.Key; });
  std::vector<char> used(count, 0);
  std::vector<BlockerPolygon> out;
  out.reserve(count);
  for (std::size_t e = 0; e + 1 < edges.size(); ++e)
  {
    const Edge& p = edges[e];
    const Edge& q = edges[e + 1];
    if (p.Key != q.Key || p.Triangle == q.Triangle || used[p.Triangle] || used[q.Triangle] ||
      !(glm::dot(normal[p.Triangle], normal[q.Triangle]) > 1.0 - 1e-9))
    {
      continue;
    }
    // Around the quad: p's corners a -> b -> c in p's winding, with q's
    // third corner d spliced in between a and b (across the shared edge):
    // a -> d -> b -> c keeps p's winding, so every turn of a convex quad is
    // along p's normal.
    const TriangleCorners& tp = corners[p.Triangle];
    const Vec3& a = tp[p.Side];
    const Vec3& b = tp[(p.Side + 1) % 3];
    const Vec3& c = tp[(p.Side + 2) % 3];
    const Vec3& d = corners[q.Triangle][(q.Side + 2) % 3];
    const Vec3 quad[4] = { a, d, b, c };
    if (!ConvexQuad(quad, normal[p.Triangle]))
    {
      continue;
    }
    used[p.Triangle] = used[q.Triangle] = 1;
    BlockerPolygon merged;
    std::copy(quad, quad + 4, merged.Corners.begin());
    merged.Size = 4;
    out.push_back(merged);
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    if (!used[i])
    {
      BlockerPolygon single;
      std::copy(corners[i].begin(), corners[i].end(), single.Corners.begin());
      out.push_back(single);
    }
  }
  return out;
}
} // namespace radiosity
