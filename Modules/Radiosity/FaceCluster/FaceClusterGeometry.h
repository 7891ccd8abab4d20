// The per-cluster geometry of the face cluster hierarchy (Gobbetti et al.
// 2003, section 3.1, after Willmott 2000): a triangle as a leaf cluster, the
// merge of two clusters' areas and materials, the oriented box and the six
// directional projected-area samples over a cluster's triangles, and the
// concavity of a mesh edge (for the convexity flag of section 3.3.3).
#ifndef Radiosity_FaceClusterGeometry_h
#define Radiosity_FaceClusterGeometry_h

#include "Radiosity/FaceCluster/FaceClusterHierarchy.h"

namespace radiosity
{
/// Triangle `t` as a leaf cluster (tree fields left at their defaults).
FaceCluster TriangleCluster(const Scene& scene, std::size_t t);
/// The triangle p[0..2] of material `m` as a leaf cluster (the solver's
/// elements below the input triangles).
FaceCluster TriangleCluster(const Vec3 p[3], const Material& m, int object);

/// Area, area vector and materials (min, max, area-weighted mean) of the
/// union of `a` and `b` into `out`; the convexity flag is the caller's.
void MergeClusterAttributes(const FaceCluster& a, const FaceCluster& b, FaceCluster& out);

/// Box extents along `cluster.Axis` and the D+/D- samples, over the triangles
/// order[First .. First + Count).
void FitBoxAndSamples(const Scene& scene, const std::vector<std::uint32_t>& order, FaceCluster& cluster);

/// The dominant normal direction of triangles order[first .. first + count),
/// the principal eigenvector of sum A_k n_k n_k^T: the box axis of a cluster
/// whose area vector vanishes (a closed surface).
Vec3 DominantNormal(const Scene& scene, const std::vector<std::uint32_t>& order,
  std::uint32_t first, std::uint32_t count);

/// Two unit vectors completing unit `z` to a right-handed frame.
void PerpendicularAxes(const Vec3& z, Vec3& e1, Vec3& e2);

/// Whether the mesh edge shared by triangles s and t folds inward: a vertex
/// of one lies above the other's plane, so the two faces see each other.
bool EdgeIsConcave(const Scene& scene, std::size_t s, std::size_t t);
} // namespace radiosity

#endif
