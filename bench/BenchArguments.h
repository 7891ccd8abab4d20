// The command line and heading shared by the method benchmarks:
//   <program> <output dir> [--quick] [--bunny index.js]
#ifndef BenchArguments_h
#define BenchArguments_h

#include "Radiosity/Common/SystemInfo.h"

#include <filesystem>
#include <iostream>
#include <ostream>
#include <string>
#include <thread>

struct BenchArguments
{
  std::string Directory;
  bool Quick = false;
  std::string BunnyJs;

  /// False (after printing why) when the output directory is not given or
  /// cannot be made: a bench that runs for minutes must not find out at the
  /// end that its table has nowhere to go.
  bool Parse(int argc, char* argv[])
  {
    // An option where the directory goes (--help, or options first) gets the
    // usage, not a full run writing into a directory named like the option.
    if (argc < 2 || argv[1][0] == '-')
    {
      std::cerr << "usage: " << argv[0] << " <output dir> [--quick] [--bunny index.js]\n";
      return false;
    }
    this->Directory = argv[1];
    std::error_code error;
    std::filesystem::create_directories(this->Directory, error);
    if (error || !std::filesystem::is_directory(this->Directory))
    {
      std::cerr << argv[0] << ": cannot make the output directory " << this->Directory << ": "
                << error.message() << "\n";
      return false;
    }
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
