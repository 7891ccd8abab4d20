// Wall-clock seconds since a start, for solver histories (error against run time).
#ifndef Radiosity_Stopwatch_h
#define Radiosity_Stopwatch_h

#include <chrono>

namespace radiosity
{
class Stopwatch
{
public:
  Stopwatch()
    : Start(std::chrono::steady_clock::now())
  {
  }
  double Seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
  }

private:
  std::chrono::steady_clock::time_point Start;
};
} // namespace radiosity

#endif
