#include "ProgressiveGPUAtlas.h"

#include <algorithm>

namespace radiosity
{
namespace
{
void Put(std::vector<float>& texels, std::size_t i, const Vec3& xyz, double w)
{
  texels[4 * i + 0] = static_cast<float>(xyz.x);
  texels[4 * i + 1] = static_cast<float>(xyz.y);
  texels[4 * i + 2] = static_cast<float>(xyz.z);
  texels[4 * i + 3] = static_cast<float>(w);
}

/// A two-float position: `xyz` as float (hi) and what rounding dropped (lo).
void PutSplit(std::vector<float>& hi, std::vector<float>& lo, std::size_t i, const Vec3& xyz, double w)
{
  Put(hi, i, xyz, w);
  const Vec3 rounded(hi[4 * i], hi[4 * i + 1], hi[4 * i + 2]);
  Put(lo, i, xyz - rounded, 0.0);
}

RGB Get(const std::vector<float>& texels, std::size_t i)
{
  return RGB(texels[4 * i], texels[4 * i + 1], texels[4 * i + 2]);
}
} // namespace

std::array<float, 3> ToFloat(const Vec3& v)
{
  return { static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z) };
}

void SplitFloat(const Vec3& v, std::array<float, 3>& hi, std::array<float, 3>& lo)
{
  hi = ToFloat(v);
  lo = ToFloat(v - Vec3(hi[0], hi[1], hi[2]));
}

GPUAtlas LayOutAtlas(const ElementMesh& mesh, const GPUFrame& frame, const std::vector<std::uint16_t>& maxLevel)
{
  GPUAtlas atlas;
  const std::vector<std::uint32_t>& shooters = mesh.Shooters();
  std::vector<std::uint32_t> slot(mesh.Elements().size(), 0);
  for (std::size_t k = 0; k < shooters.size(); ++k)
  {
    slot[shooters[k]] = static_cast<std::uint32_t>(k);
  }
  atlas.Leaves = mesh.Leaves();
  std::stable_sort(atlas.Leaves.begin(), atlas.Leaves.end(),
    [&](std::uint32_t a, std::uint32_t b) { return slot[mesh[a].ShooterNode] < slot[mesh[b].ShooterNode]; });

  GPUElementTexels& elements = atlas.Elements;
  elements.Count = atlas.Leaves.size();
  elements.Width = static_cast<int>(std::min<std::size_t>(2048, std::max<std::size_t>(1, elements.Count)));
  elements.Height = static_cast<int>((elements.Count + elements.Width - 1) / elements.Width);
  const std::size_t texels = 4 * static_cast<std::size_t>(elements.Width) * elements.Height;
  for (std::vector<float>* v : { &elements.Centre, &elements.Corner0, &elements.Corner1, &elements.Corner2,
         &elements.CentreLo, &elements.Corner0Lo, &elements.Corner1Lo, &elements.Corner2Lo, &elements.Normal,
         &elements.Reflectance, &elements.Irradiance0, &elements.Irradiance1, &elements.Irradiance2,
         &elements.IrradianceCentre, &elements.Unshot })
  {
    v->assign(texels, 0.0f);
  }
  atlas.NodeFirst.assign(shooters.size(), 0);
  atlas.NodeCount.assign(shooters.size(), 0);
  for (std::size_t i = 0; i < atlas.Leaves.size(); ++i)
  {
    const std::uint32_t l = atlas.Leaves[i];
    const Element& e = mesh[l];
    const Material& m = mesh.MaterialOf(l);
    PutSplit(elements.Centre, elements.CentreLo, i, frame.Scaled(e.Centroid), frame.ScaledArea(e.Area));
    PutSplit(elements.Corner0, elements.Corner0Lo, i, frame.Scaled(mesh.Corner(l, 0)), 0.0);
    PutSplit(elements.Corner1, elements.Corner1Lo, i, frame.Scaled(mesh.Corner(l, 1)), 0.0);
    PutSplit(elements.Corner2, elements.Corner2Lo, i, frame.Scaled(mesh.Corner(l, 2)), 0.0);
    Put(elements.Normal, i, e.Normal, static_cast<double>(e.Source));
    // w: 1 where the element may still split (section 4.4's maximum depth).
    Put(elements.Reflectance, i, m.Reflectance, e.Level < maxLevel[e.Source] ? 1.0 : 0.0);
    Put(elements.Irradiance0, i, e.Irradiance.Corner[0], 0.0);
    Put(elements.Irradiance1, i, e.Irradiance.Corner[1], 0.0);
    Put(elements.Irradiance2, i, e.Irradiance.Corner[2], 0.0);
    Put(elements.IrradianceCentre, i, e.Irradiance.Centre, 0.0);
    Put(elements.Unshot, i, e.Unshot, 0.0);
    const std::uint32_t k = slot[e.ShooterNode];
    if (atlas.NodeCount[k]++ == 0)
    {
      atlas.NodeFirst[k] = i;
    }
  }

  GPUNodeTexels& nodes = atlas.Nodes;
  nodes.Count = shooters.size();
  nodes.Width = 1;
  while (static_cast<std::size_t>(nodes.Width) * nodes.Width < nodes.Count)
  {
    nodes.Width *= 2;
  }
  nodes.Range.assign(4 * static_cast<std::size_t>(nodes.Width) * nodes.Width, 0.0f);
  nodes.Reflectance = nodes.Range;
  for (std::size_t k = 0; k < shooters.size(); ++k)
  {
    const Element& n = mesh[shooters[k]];
    Put(nodes.Range, k,
      Vec3(static_cast<double>(atlas.NodeFirst[k]), static_cast<double>(atlas.NodeCount[k]), frame.ScaledArea(n.Area)),
      0.0);
    Put(nodes.Reflectance, k, mesh.MaterialOf(shooters[k]).Reflectance, 0.0);
  }
  return atlas;
}

void ReadBackAtlas(ElementMesh& mesh, const GPUAtlas& atlas, const std::array<std::vector<float>, 5>& targets)
{
  for (std::size_t i = 0; i < atlas.Leaves.size(); ++i)
  {
    Element& e = mesh[atlas.Leaves[i]];
    for (int c = 0; c < 3; ++c)
    {
      e.Irradiance.Corner[c] = Get(targets[c], i);
    }
    e.Irradiance.Centre = Get(targets[3], i);
    e.Unshot = Get(targets[4], i);
  }
}
} // namespace radiosity
