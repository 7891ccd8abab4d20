// Shaft culling between two triangles (Haines & Wallace 1991, "Shaft
// Culling for Efficient Ray-Traced Radiosity"): the convex hull of the two
// triangles, as the planes of its faces. Hanrahan, Salzman & Aupperle's links
// record the blockers that their shaft meets; Hardt & Teller reuse them per
// leaf, where the narrower shaft of the leaf leaves most of them out.
#ifndef Radiosity_Shaft_h
#define Radiosity_Shaft_h

#include "Radiosity/Hierarchical/Backprojection.h"

#include <algorithm>

namespace radiosity
{
/// The shaft between two triangles: the face planes of the convex hull of
/// their six corners (shaft culling, Haines & Wallace 1991). A blocker with
/// every vertex outside one of these planes cannot hide any part of one
/// triangle from any point of the other.
class Shaft
{
public:
  Shaft(const TriangleCorners& receiver, const TriangleCorners& source)
  {
    const Vec3 p[6] = { receiver[0], receiver[1], receiver[2], source[0], source[1], source[2] };
    double scale = 0.0;
    for (const Vec3& v : p)
    {
      scale = std::max(scale, glm::length(v - p[0]));
    }
    const double tolerance = 1e-9 * scale;
    for (int i = 0; i < 6; ++i)
    {
      for (int j = i + 1; j < 6; ++j)
      {
        for (int k = j + 1; k < 6; ++k)
        {
          Vec3 n = glm::cross(p[j] - p[i], p[k] - p[i]);
          const double len = glm::length(n);
          if (!(len > 1e-12 * scale * scale))
          {
            continue;
          }
          // Which side each corner is on, against the unit normal's
          // tolerance scaled by |n|: most of the 20 planes through three
          // corners are not faces, and are dropped before the division.
          const double scaledTolerance = tolerance * len;
          int above = 0, below = 0;
          for (const Vec3& v : p)
          {
            const double d = glm::dot(v - p[i], n);
            above += d > scaledTolerance;
            below += d < -scaledTolerance;
          }
          if (above > 0 && below > 0)
          {
            continue;
          }
          n /= len;
          if (above > 0)
          {
            n = -n; // outward
          }
          if (this->Count < MaxPlanes)
          {
            this->Normal[this->Count] = n;
            this->Offset[this->Count++] = glm::dot(p[i], n) + tolerance;
          }
        }
      }
    }
  }

  bool Excludes(const TriangleCorners& b) const { return this->Excludes(b.data(), 3); }

  /// Whether every one of the `count` points lies outside one face plane
  /// (then nothing they span, a triangle or a box, meets the shaft).
  bool Excludes(const Vec3* points, int count) const
  {
    for (int f = 0; f < this->Count; ++f)
    {
      bool outside = true;
      for (int k = 0; k < count && outside; ++k)
      {
        outside = glm::dot(points[k], this->Normal[f]) > this->Offset[f];
      }
      if (outside)
      {
        return true;
      }
    }
    return false;
  }

private:
  static constexpr int MaxPlanes = 20;
  Vec3 Normal[MaxPlanes];
  double Offset[MaxPlanes];
  int Count = 0;
};
} // namespace radiosity

#endif
