// The GLSL programs of progressive radiosity on the GPU (Coombe, Harris &
// Lastra 2004, "Radiosity on Graphics Hardware"), one per pass:
//
// - HemicubeItem*: section 3.2's visibility pass: the scene drawn from the
//   shooter onto the five faces of a hemicube with each input triangle's id
//   (and its distance, for the shadow-map test the paper likens it to) as
//   colour: the item buffer.
// - Shot*: sections 3.2 and 3.3, the reconstruction pass: one fragment per
//   element texel; each of the element's four samples back-projects itself
//   onto the item buffer (visible where it finds its own triangle, or a
//   surface no nearer than its plane), takes the disc form factor of eq. 2,
//   or the exact contour formula where the shooter is close, and the texel
//   adds the shot's irradiance to four delta targets (blended over the
//   shooter's parts).
// - Split*: section 4.1's gradient test on the shot's deltas; an occlusion
//   query counts the elements to subdivide.
// - Commit*: eq. 1's update, the deltas added to the irradiance and rho
//   times their mean to the residual.
// - NodePower*: section 3.4's mipmapped residual: the unshot power of every
//   shooter node, summed over its elements, in a power-of-two texture whose
//   top mipmap level is the total (and the signed total for overshooting).
// - Selection*: section 3.4's z-buffer maximum: every node drawn as a point
//   into a one-pixel frame buffer at a depth decreasing with its power,
//   its id as colour; the pixel read back is the next shooter.
#ifndef Radiosity_ProgressiveGPUShaders_h
#define Radiosity_ProgressiveGPUShaders_h

namespace radiosity
{
namespace gpu_shaders
{
extern const char* const HemicubeItemVertex;
extern const char* const HemicubeItemFragment;
extern const char* const ShotFragment;
extern const char* const CommitFragment;
extern const char* const SplitFragment;
extern const char* const NodePowerFragment;
extern const char* const SelectionVertex;
extern const char* const SelectionFragment;
} // namespace gpu_shaders
} // namespace radiosity

#endif
