// The built-in lit room `office` (SPEC "Lights and sky"): a 5 x 4 x 3 m room
// with a window opening in one wall, a desk, a ceiling lamp as a spot and
// the CIE overcast sky seen through the window. No triangle emits: the lamp
// and the daylight light it. The daylighting scene of the demo and the bench.
#ifndef Radiosity_OfficeScene_h
#define Radiosity_OfficeScene_h

#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Scene.h"

#include <vector>

namespace radiosity
{
namespace office
{
constexpr double Width = 5.0, Depth = 4.0, Height = 3.0; ///< x, y, z in metres
/// The window in the wall y = 0: x in [WindowX0, WindowX1], z in [Sill, Head].
constexpr double WindowX0 = 1.0, WindowX1 = 4.0, Sill = 0.9, Head = 2.4;
constexpr double DeskHeight = 0.75;
constexpr double SkyZenithRadiance = 1000.0; ///< L_z, W/(m^2 sr): E_unobstructed = 7/9 pi L_z
constexpr double LampIntensity = 150.0;      ///< W/sr on the axis
} // namespace office

/// The office with its spot and sky; `lamp` and `sky` switch each off.
Scene MakeOfficeScene(bool lamp = true, bool sky = true);

/// A daylighting sensor grid: 0.75 m above the floor (the desk's working
/// plane), facing up, on a 0.5 m grid clear of the desk and the walls.
std::vector<Probe> OfficeSensorGrid();
} // namespace radiosity

#endif
