// Sensor files of the command-line program (SPEC: --probes, --probe-output).
#ifndef vtkradiosity_ProbeIO_h
#define vtkradiosity_ProbeIO_h

#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Types.h"

#include <string>
#include <vector>

namespace radiosity
{
namespace cli
{
/**
 * Reads a sensor CSV: the header `x,y,z,nx,ny,nz` (spaces around fields, a
 * UTF-8 byte order mark and CRLF line ends tolerated), then one row of 6 finite
 * numbers per sensor; blank lines are skipped. Normals are returned
 * normalized; a zero normal is an error. On failure returns false, `probes` is
 * left empty and `error` names the file, the line and its text.
 */
bool ReadProbes(const std::string& csv, std::vector<Probe>& probes, std::string& error);

/**
 * Reads reference values in the --probe-output format `x,y,z,E_r,E_g,E_b`
 * (or `x,y,z,E_r,E_g,E_b,DF`, as written with a sky; DF is ignored), one row
 * per probe, in the order of `probes` and at their positions (else an error
 * naming the line).
 */
bool ReadProbeValues(const std::string& csv, const std::vector<Probe>& probes,
  std::vector<RGB>& values, std::string& error);

/**
 * Writes `x,y,z,E_r,E_g,E_b`, one row per probe in input order, with 17
 * significant digits (doubles round-trip exactly). Refuses mismatched sizes and
 * non-finite values; written to a temporary file in the same directory and
 * renamed, so no half-written file is ever left. With `skyUnobstructed` (the
 * unobstructed horizontal irradiance of the scene's sky, SPEC "Lights and
 * sky") a seventh column `DF`, the daylight factor
 * luminance(E) / luminance(E_unobstructed) (DaylightFactor).
 */
/// `standardErrors` (instead of a sky): a seventh column SE, each value's
/// relative standard error (a path-traced reference, --reference-output).
bool WriteProbeValues(const std::string& csv, const std::vector<Probe>& probes,
  const std::vector<RGB>& values, std::string& error, const RGB* skyUnobstructed = nullptr,
  const std::vector<double>* standardErrors = nullptr);

/// The daylight factor (CIE/Radiance convention): the ratio of the
/// luminance-weighted channels 0.2126 R + 0.7152 G + 0.0722 B of E and of
/// the unobstructed sky's horizontal irradiance (0 when that is 0).
double DaylightFactor(const RGB& irradiance, const RGB& unobstructed);
} // namespace cli
} // namespace radiosity

#endif
