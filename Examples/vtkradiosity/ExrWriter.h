// OpenEXR output of the linear radiance image (SPEC: --exr).
#ifndef vtkradiosity_ExrWriter_h
#define vtkradiosity_ExrWriter_h

#include "Radiosity/Common/RadianceImage.h"

#include <string>

namespace radiosity
{
namespace cli
{
/**
 * Writes `image` as a half-float RGB OpenEXR file (linear radiance, no tone
 * mapping: the point of EXR is to keep the physical values).
 *
 * The file is written under a temporary name in the same directory and renamed
 * on success, so a failure never leaves a half-written `file` (SPEC: exit
 * status 2 leaves no output behind). Refused, with nothing written: an image of
 * the wrong size, a NaN or infinite pixel, and a value beyond the half-float
 * range (65504), which half would silently turn into infinity. On failure
 * returns false and `error` names the file and the reason.
 */
bool WriteExrHalf(const std::string& file, const RadianceImage& image, std::string& error);
} // namespace cli
} // namespace radiosity

#endif
