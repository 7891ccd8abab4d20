#include "Radiosity/Common/SystemInfo.h"

#include <sys/resource.h>
#include <unistd.h>

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

double PhysicalMemoryBytes()
{
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long size = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && size > 0 ? static_cast<double>(pages) * static_cast<double>(size) : 0.0;
}
} // namespace radiosity
