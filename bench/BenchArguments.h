// The command line and heading shared by the method benchmarks:
//   <program> <output dir> [--quick] [--bunny index.js]
#ifndef BenchArguments_h
#define BenchArguments_h

#include "Radiosity/Common/SystemInfo.h"

#include <iostream>
#include <ostream>
#include <string>
#include <thread>

struct BenchArguments
{
  std::string Directory;
  bool Quick = false;
  std::string BunnyJs;

  /// False (after printing the usage) when the output directory is missing.
  bool Parse(int argc, char* argv[])
  {
    if (argc < 2)
    {
      std::cerr << "usage: " << argv[0] << " <output dir> [--quick] [--bunny index.js]\n";
      return false;
    }
    this->Directory = argv[1];
    for (int i = 2; i < argc; ++i)
    {
      const std::string a = argv[i];
      if (a == "--quick")
      {
        this->Quick = true;
      }
      else if (a == "--bunny" && i + 1 < argc)
      {
        this->BunnyJs = argv[++i];
      }
    }
    return true;
  }

  /// "# <title>", the machine and the mode.
  void WriteHeading(std::ostream& md, const std::string& title) const
  {
    md << "# " << title << "\n\nMachine: " << radiosity::CpuModel() << ", "
       << std::thread::hardware_concurrency() << " hardware threads. Mode: "
       << (this->Quick ? "quick" : "full") << ".\n\n";
  }
};

#endif
