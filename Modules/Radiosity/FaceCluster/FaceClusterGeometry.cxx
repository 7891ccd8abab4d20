#include "Radiosity/FaceCluster/FaceClusterGeometry.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace radiosity
{
namespace
{
glm::vec3 ToFloat(const RGB& c)
{
  return glm::vec3(c);
}

void AccumulateSamples(const Vec3& areaVector, const FaceCluster& c, double dPlus[3], double dMinus[3])
{
  for (int j = 0; j < 3; ++j)
  {
    const double d = glm::dot(areaVector, Vec3(c.Axis[j]));
    dPlus[j] += std::max(d, 0.0);
    dMinus[j] += std::max(-d, 0.0);
  }
}
}

double FaceCluster::NormalProjectedArea() const
{
  return glm::length(Vec3(this->AreaVector));
}

double FaceCluster::MinProjectedArea(const Vec3& r) const
{
  return this->NormalProjectedArea() * std::max(glm::dot(this->MeanNormal(), r), 0.0);
}

double FaceCluster::MaxProjectedArea(const Vec3& r) const
{
  double a = 0.0;
  for (int j = 0; j < 3; ++j)
  {
    const double d = glm::dot(Vec3(this->Axis[j]), r);
    a += std::max(d, 0.0) * this->DPlus[j] + std::max(-d, 0.0) * this->DMinus[j];
  }
  return a;
}

double FaceCluster::SelfFormFactorLower() const
{
  if (this->Convex || !(this->Area > 0.0f))
  {
    return 0.0;
  }
  double samples = 0.0;
  for (int j = 0; j < 3; ++j)
  {
    samples += this->DPlus[j] + this->DMinus[j];
  }
  return std::clamp(1.0 - samples / this->Area, 0.0, 1.0);
}

double FaceCluster::SelfFormFactorUpper() const
{
  if (this->Convex || !(this->Area > 0.0f))
  {
    return 0.0;
  }
  return std::clamp(1.0 - this->NormalProjectedArea() / this->Area, 0.0, 1.0);
}

double FaceCluster::BoxProjectedArea(const Vec3& r) const
{
  const Vec3 h(this->HalfSize);
  const double faces[3] = { 4.0 * h.y * h.z, 4.0 * h.x * h.z, 4.0 * h.x * h.y };
  double a = 0.0;
  for (int j = 0; j < 3; ++j)
  {
    a += faces[j] * std::abs(glm::dot(Vec3(this->Axis[j]), r));
  }
  return a;
}

FaceCluster TriangleCluster(const Scene& scene, std::size_t t)
{
  const Vec3 p[3] = { scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
  return TriangleCluster(p, scene.Materials[t], scene.ObjectIds[t]);
}

FaceCluster TriangleCluster(const Vec3 p[3], const Material& m, int object)
{
  FaceCluster c;
  const Vec3 areaVector = 0.5 * glm::cross(p[1] - p[0], p[2] - p[0]);
  const double area = glm::length(areaVector);
  c.Area = static_cast<float>(area);
  c.AreaVector = glm::vec3(areaVector);
  c.Centroid = glm::vec3((p[0] + p[1] + p[2]) / 3.0);
  c.Object = object;
  Vec3 z = area > 0.0 ? areaVector / area : Vec3(0.0, 0.0, 1.0);
  int longest = 0;
  double length = -1.0;
  for (int k = 0; k < 3; ++k)
  {
    const double l = glm::length(p[(k + 1) % 3] - p[k]);
    if (l > length)
    {
      length = l;
      longest = k;
    }
  }
  Vec3 x = p[(longest + 1) % 3] - p[longest];
  x -= glm::dot(x, z) * z;
  if (glm::length(x) > 0.0)
  {
    x = glm::normalize(x);
  }
  else
  {
    Vec3 e2;
    PerpendicularAxes(z, x, e2);
  }
  c.Axis[0] = glm::vec3(x);
  c.Axis[1] = glm::vec3(glm::cross(z, x));
  c.Axis[2] = glm::vec3(z);
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (int k = 0; k < 3; ++k)
  {
    const Vec3& q = p[k];
    const Vec3 local(glm::dot(q, x), glm::dot(q, Vec3(c.Axis[1])), glm::dot(q, z));
    lo = glm::min(lo, local);
    hi = glm::max(hi, local);
  }
  const Vec3 mid = 0.5 * (lo + hi);
  c.Centre = glm::vec3(mid.x * x + mid.y * Vec3(c.Axis[1]) + mid.z * z);
  c.HalfSize = glm::vec3(0.5 * (hi - lo));
  double dPlus[3] = { 0, 0, 0 }, dMinus[3] = { 0, 0, 0 };
  AccumulateSamples(areaVector, c, dPlus, dMinus);
  for (int j = 0; j < 3; ++j)
  {
    c.DPlus[j] = static_cast<float>(dPlus[j]);
    c.DMinus[j] = static_cast<float>(dMinus[j]);
  }
  c.ReflectanceMin = c.ReflectanceMax = c.ReflectanceMean = ToFloat(m.Reflectance);
  c.EmissionMin = c.EmissionMax = c.EmissionMean = ToFloat(m.Emission);
  return c;
}

void MergeClusterAttributes(const FaceCluster& a, const FaceCluster& b, FaceCluster& out)
{
  out.Area = a.Area + b.Area;
  out.AreaVector = a.AreaVector + b.AreaVector;
  const float wa = out.Area > 0.0f ? a.Area / out.Area : 0.5f;
  const float wb = 1.0f - wa;
  out.Centroid = wa * a.Centroid + wb * b.Centroid;
  out.ReflectanceMin = glm::min(a.ReflectanceMin, b.ReflectanceMin);
  out.ReflectanceMax = glm::max(a.ReflectanceMax, b.ReflectanceMax);
  out.ReflectanceMean = wa * a.ReflectanceMean + wb * b.ReflectanceMean;
  out.EmissionMin = glm::min(a.EmissionMin, b.EmissionMin);
  out.EmissionMax = glm::max(a.EmissionMax, b.EmissionMax);
  out.EmissionMean = wa * a.EmissionMean + wb * b.EmissionMean;
}

void FitBoxAndSamples(const Scene& scene, const std::vector<std::uint32_t>& order, FaceCluster& c)
{
  const Vec3 axis[3] = { Vec3(c.Axis[0]), Vec3(c.Axis[1]), Vec3(c.Axis[2]) };
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  double dPlus[3] = { 0, 0, 0 }, dMinus[3] = { 0, 0, 0 };
  for (std::uint32_t i = c.First; i < c.First + c.Count; ++i)
  {
    const std::uint32_t t = order[i];
    const Vec3 p[3] = { scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) };
    for (const Vec3& q : p)
    {
      const Vec3 local(glm::dot(q, axis[0]), glm::dot(q, axis[1]), glm::dot(q, axis[2]));
      lo = glm::min(lo, local);
      hi = glm::max(hi, local);
    }
    AccumulateSamples(0.5 * glm::cross(p[1] - p[0], p[2] - p[0]), c, dPlus, dMinus);
  }
  const Vec3 mid = 0.5 * (lo + hi);
  c.Centre = glm::vec3(mid.x * axis[0] + mid.y * axis[1] + mid.z * axis[2]);
  c.HalfSize = glm::vec3(0.5 * (hi - lo));
  for (int j = 0; j < 3; ++j)
  {
    c.DPlus[j] = static_cast<float>(dPlus[j]);
    c.DMinus[j] = static_cast<float>(dMinus[j]);
  }
}

Vec3 DominantNormal(const Scene& scene, const std::vector<std::uint32_t>& order,
  std::uint32_t first, std::uint32_t count)
{
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  for (std::uint32_t i = first; i < first + count; ++i)
  {
    const std::uint32_t t = order[i];
    const Vec3 n = scene.Normal(t);
    const Eigen::Vector3d e(n.x, n.y, n.z);
    s += scene.Area(t) * e * e.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(s);
  const Eigen::Vector3d v = eigen.eigenvectors().col(2);
  const Vec3 d(v.x(), v.y(), v.z());
  return glm::length(d) > 0.0 ? glm::normalize(d) : Vec3(0.0, 0.0, 1.0);
}

void PerpendicularAxes(const Vec3& z, Vec3& e1, Vec3& e2)
{
  const Vec3 helper = std::abs(z.x) < 0.6 ? Vec3(1, 0, 0) : (std::abs(z.y) < 0.6 ? Vec3(0, 1, 0) : Vec3(0, 0, 1));
  e1 = glm::normalize(glm::cross(helper, z));
  e2 = glm::cross(z, e1);
}

bool EdgeIsConcave(const Scene& scene, std::size_t s, std::size_t t)
{
  auto above = [&](std::size_t a, std::size_t b) {
    const Vec3 n = scene.Normal(a);
    const Vec3 origin = scene.Vertex(a, 0);
    double size = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      size = std::max(size, glm::length(scene.Vertex(a, (k + 1) % 3) - scene.Vertex(a, k)));
    }
    for (int k = 0; k < 3; ++k)
    {
      if (glm::dot(n, scene.Vertex(b, k) - origin) > 1e-9 * size)
      {
        return true;
      }
    }
    return false;
  };
  return above(s, t) || above(t, s);
}
} // namespace radiosity
