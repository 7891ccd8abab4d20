// Lambert's contour formula over many edges seen from one point, the angles
// taken in batches (Atan2Batch): each edge (a, b), its ends relative to the
// point, brings theta(a, b) f.(a x b)/|a x b| times its weight, where f is
// the receiver's normal in the edges' frame. The discontinuity mesher's
// samples sum hundreds of edges each (LinkChain.cxx, Backprojection.cxx).
#ifndef Radiosity_ContourSum_h
#define Radiosity_ContourSum_h

#include "Radiosity/Common/Atan2Batch.h"
#include "Radiosity/Common/Types.h"

#include <cstddef>

namespace radiosity
{
/// The weighted sum of Lambert's edge terms (Weight: double or RGB), in the
/// order the edges are added. An edge through the point (a x b = 0) brings
/// nothing.
template <typename Weight>
class ContourSum
{
public:
  void Add(const Vec3& a, const Vec3& b, const Vec3& facing, const Weight& weight)
  {
    const Vec3 c = glm::cross(a, b);
    const double cl = glm::length(c);
    if (!(cl > 0.0))
    {
      return;
    }
    this->Sine[this->Count] = cl;
    this->Cosine[this->Count] = glm::dot(a, b);
    this->Facing[this->Count] = glm::dot(facing, c) / cl;
    this->Weights[this->Count++] = weight;
    if (this->Count == Batch)
    {
      this->Flush();
    }
  }

  /// The sum of every edge added so far.
  Weight Sum()
  {
    this->Flush();
    return this->Total;
  }

private:
  void Flush()
  {
    if (this->Count == 0)
    {
      return;
    }
    Atan2Batch(this->Sine, this->Cosine, this->Sine, this->Count);
    for (std::size_t k = 0; k < this->Count; ++k)
    {
      this->Total += (this->Sine[k] * this->Facing[k]) * this->Weights[k];
    }
    this->Count = 0;
  }

  // On the stack, not thread_local: a TLS lookup per call in a shared
  // library costs more than the buffers.
  static constexpr std::size_t Batch = 64;
  double Sine[Batch], Cosine[Batch], Facing[Batch];
  Weight Weights[Batch];
  Weight Total = Weight(0.0);
  std::size_t Count = 0;
};
} // namespace radiosity

#endif
