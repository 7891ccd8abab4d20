// The machine a measurement ran on and what it cost: benchmark results are
// committed with them.
#ifndef Radiosity_SystemInfo_h
#define Radiosity_SystemInfo_h

#include <string>

namespace radiosity
{
/// The processor's model name (from /proc/cpuinfo), or "unknown CPU".
std::string CpuModel();

/// Peak resident memory of this process so far, bytes.
double PeakMemoryBytes();

/// Physical memory of this machine (sysconf), bytes; 0 when unknown.
double PhysicalMemoryBytes();
} // namespace radiosity

#endif
