// The Neumann series b = e + Te + T^2 e + ... of Lehtinen et al. 2007,
// section 6.3 (lines 1 to 5), summed bounce by bounce with the geometric
// tail added at once (Aitken) once the ratio of successive bounces is
// steady: what the solve (MeshlessRadiosity::Solve) and the precomputed
// transfer (MeshlessTransfer, section 6.5) share, so that a relit field
// stops where a fresh solve would.
#ifndef Radiosity_BounceSeries_h
#define Radiosity_BounceSeries_h

#include <cmath>

namespace radiosity
{
class BounceSeries
{
public:
  struct Step
  {
    double Ratio = 0.0;     ///< this bounce's magnitude over the previous one's
    double Gain = 1.0;      ///< what to add this bounce with: 1, or 1/(1 - ratio) with the tail
    double Remaining = 0.0; ///< the estimated rest of the series after this bounce
    bool Steady = false;    ///< the tail was added: the series is summed
  };

  /// The next bounce, of `magnitude`, after one of `previousMagnitude`.
  Step Next(double previousMagnitude, double magnitude)
  {
    Step s;
    s.Ratio = previousMagnitude > 0 ? magnitude / previousMagnitude : 0.0;
    // Steady over three bounces, not two: the first bounces of an open room
    // fall faster than its last (light leaving by the window early), and a
    // ratio that held for one bounce by chance (the office: 0.58 twice at
    // bounce 3) put the tail 2% under at the back of the room.
    const bool held = s.Ratio > 0.3 && s.Ratio < 1.0 && this->PreviousRatio > 0 &&
      std::fabs(s.Ratio - this->PreviousRatio) < 0.01 * (1.0 - s.Ratio);
    this->SteadyBounces = held ? this->SteadyBounces + 1 : 0;
    s.Steady = this->SteadyBounces >= 2;
    s.Gain = s.Steady ? 1.0 / (1.0 - s.Ratio) : 1.0;
    s.Remaining = s.Steady ? 0.0 : magnitude * (s.Ratio < 1 ? s.Ratio / (1 - s.Ratio) : 1.0);
    this->PreviousRatio = s.Ratio;
    return s;
  }

private:
  double PreviousRatio = -1.0;
  int SteadyBounces = 0;
};
} // namespace radiosity

#endif
