// Morton (Z-order) codes: points sorted by them lie near their neighbours
// in the sorted order, so that consecutive runs are compact tiles.
#ifndef Radiosity_Morton_h
#define Radiosity_Morton_h

#include "Radiosity/Common/Types.h"

#include <algorithm>
#include <cstdint>

namespace radiosity
{
/// The 63-bit Morton code of a point of the unit cube (21 bits an axis;
/// coordinates outside [0, 1] are clamped).
inline std::uint64_t Morton(const Vec3& unit)
{
  auto spread = [](std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffull;
    v = (v | v << 16) & 0x1f0000ff0000ffull;
    v = (v | v << 8) & 0x100f00f00f00f00full;
    v = (v | v << 4) & 0x10c30c30c30c30c3ull;
    v = (v | v << 2) & 0x1249249249249249ull;
    return v;
  };
  auto q = [](double x) { return static_cast<std::uint64_t>(std::clamp(x, 0.0, 1.0) * 2097151.0); };
  return spread(q(unit.x)) | spread(q(unit.y)) << 1 | spread(q(unit.z)) << 2;
}
} // namespace radiosity

#endif
