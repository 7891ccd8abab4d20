#include "SceneFileCheck.h"
#include "SceneFileCheckText.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <sys/stat.h>
#include <vector>

namespace radiosity
{
namespace cli
{
using namespace text;


std::string ByteSize(double bytes)
{
  std::ostringstream s;
  if (bytes < 1e4)
  {
    s << static_cast<long long>(bytes) << " bytes";
  }
  else
  {
    const char* units[] = { "kB", "MB", "GB", "TB", "PB" };
    int u = 0;
    bytes /= 1e3;
    while (bytes >= 1e3 && u < 4)
    {
      bytes /= 1e3;
      ++u;
    }
    s.precision(3);
    s << bytes << " " << units[u];
  }
  return s.str();
}

bool ReadFileBytes(const std::string& file, std::string& bytes, std::string& error)
{
  struct stat info;
  if (::stat(file.c_str(), &info) != 0)
  {
    error = file + ": cannot be opened: " + std::strerror(errno);
    return false;
  }
  if (!S_ISREG(info.st_mode))
  {
    error = file + ": not a regular file";
    return false;
  }
  std::ifstream in(file, std::ios::binary);
  if (!in)
  {
    error = file + ": cannot be opened for reading";
    return false;
  }
  bytes.assign(static_cast<std::size_t>(info.st_size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (static_cast<std::size_t>(in.gcount()) != bytes.size())
  {
    error = file + ": read " + std::to_string(in.gcount()) + " of its " +
      std::to_string(bytes.size()) + " bytes";
    return false;
  }
  return true;
}

bool CheckObjText(const std::string& file, const std::string& bytes, std::string& error)
{
  const auto at = [&bytes](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  if (bytes.size() >= 2 && ((at(0) == 0xFE && at(1) == 0xFF) || (at(0) == 0xFF && at(1) == 0xFE)))
  {
    error = file + ": UTF-16 text (byte order mark " + Hex(at(0)) + " " + Hex(at(1)) +
      " at offset 0); save it as UTF-8 or ASCII";
    return false;
  }
  for (std::size_t i = 0; i < bytes.size(); ++i)
  {
    const unsigned char c = at(i);
    if (c == 0)
    {
      // NUL between ASCII characters: UTF-16 (or UTF-32) without a byte order mark.
      const bool wide = (i > 0 && at(i - 1) >= 0x20 && at(i - 1) < 0x7F) ||
        (i + 1 < bytes.size() && at(i + 1) >= 0x20 && at(i + 1) < 0x7F);
      error = file + ": " + (wide ? "UTF-16 or UTF-32 text" : "binary content") +
        " (a NUL byte at offset " + std::to_string(i) + "), not an 8-bit text OBJ file";
      return false;
    }
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v')
    {
      error = file + ": binary content (control byte " + Hex(c) + " at offset " +
        std::to_string(i) + "), not a text OBJ file";
      return false;
    }
  }
  return true;
}

bool CheckStl(const std::string& file, const std::string& bytes, std::string& error)
{
  if (vtksys::SystemTools::DetectFileType(file.c_str()) == vtksys::SystemTools::FileTypeText)
  {
    return true; // vtkSTLReader's ASCII parser reports its own errors
  }
  if (bytes.size() < 84)
  {
    error = file + ": binary STL of " + std::to_string(bytes.size()) +
      " bytes, shorter than its 84-byte header";
    return false;
  }
  std::uint32_t count = 0;
  for (int i = 3; i >= 0; --i)
  {
    count = (count << 8) | static_cast<unsigned char>(bytes[80 + i]);
  }
  const double expected = 84.0 + 50.0 * count;
  if (expected != static_cast<double>(bytes.size()))
  {
    std::ostringstream s;
    s << file << ": binary STL header declares " << count << " triangles (" << ByteSize(expected)
      << " with the 84-byte header) but the file holds " << bytes.size() << " bytes";
    if ((bytes.size() - 84) % 50 == 0)
    {
      s << " (" << (bytes.size() - 84) / 50 << " triangles)";
    }
    error = s.str();
    return false;
  }
  return true;
}
} // namespace cli
} // namespace radiosity
