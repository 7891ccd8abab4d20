#include "Radiosity/SystemInfo.h"

#include <sys/resource.h>

#include <fstream>

namespace radiosity
{
std::string CpuModel()
{
  std::ifstream info("/proc/cpuinfo");
  std::string line;
  while (std::getline(info, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      return line.substr(line.find(':') + 2);
    }
  }
  return "unknown CPU";
}

double PeakMemoryBytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0; // Linux reports kilobytes
}
} // namespace radiosity
