// EvaluateOnNearestTriangles: the triangle a probe lies on (or, off the
// surface, the one nearest it) answers for it, whoever's edges and
// diagonals run through the probe.
#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Scenes/SceneGenerators.h"

#include <gtest/gtest.h>

using namespace radiosity;

TEST(EvaluateOnNearestTriangles, EachProbeOnTheTriangleHoldingIt)
{
  // The contact scene's floor: 2 x 1 in 4 x 4 quads split along their
  // diagonals, so probes on a diagonal have far triangles whose planes'
  // barycentrics are large but mixed in sign.
  const Scene scene = MakeContactScene(4, 0.0, 10.0);
  std::vector<Probe> probes;
  for (double x = 0.05; x < 2.0; x += 0.1)
  {
    for (double y = 0.02; y < 1.0; y += 0.07)
    {
      probes.push_back({ Vec3(x, y, 1e-9), Vec3(0, 0, 1) });
    }
  }
  probes.push_back({ Vec3(0.3, 0.4, 0.0), Vec3(0, 0, 1) }); // on a diagonal
  probes.push_back({ Vec3(2.5, 0.5, 0.0), Vec3(0, 0, 1) }); // off the floor
  const std::vector<RGB> found = EvaluateOnNearestTriangles(scene, probes,
    [](std::uint32_t t, const Vec3&, const Vec3&) { return RGB(static_cast<double>(t)); });
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const auto t = static_cast<std::size_t>(found[i].x);
    ASSERT_LT(t, scene.Triangles.size());
    const Vec3 p = probes[i].Position;
    // The answering triangle holds the probe's projection (within 1e-9), or
    // for the probe off the floor, touches the floor's edge x = 2 nearest it.
    const Vec3 a = scene.Vertex(t, 0), b = scene.Vertex(t, 1), c = scene.Vertex(t, 2);
    const Vec3 n = glm::cross(b - a, c - a);
    const Vec3 q = p - glm::dot(p - a, n) / glm::dot(n, n) * n;
    double least = 1.0;
    for (int k = 0; k < 3; ++k)
    {
      const Vec3 e0 = scene.Vertex(t, k), e1 = scene.Vertex(t, (k + 1) % 3);
      least = std::min(least, glm::dot(glm::cross(e1 - e0, q - e0), n) / glm::dot(n, n));
    }
    if (p.x < 2.0)
    {
      EXPECT_GT(least, -1e-9) << "probe (" << p.x << ", " << p.y << ") answered by triangle " << t;
    }
    else
    {
      double nearest = 1e300;
      for (int k = 0; k < 3; ++k)
      {
        nearest = std::min(nearest, std::abs(scene.Vertex(t, k).x - 2.0));
      }
      EXPECT_LT(nearest, 1e-12) << "triangle " << t;
    }
  }
}
