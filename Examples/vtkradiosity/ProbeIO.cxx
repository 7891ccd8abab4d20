#include "ProbeIO.h"

#include "TextTrim.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

#include <unistd.h>

namespace radiosity
{
namespace cli
{
namespace
{

std::vector<std::string> SplitFields(const std::string& line)
{
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true)
  {
    const auto comma = line.find(',', start);
    fields.push_back(Trim(line.substr(start, comma == std::string::npos ? comma : comma - start)));
    if (comma == std::string::npos)
    {
      return fields;
    }
    start = comma + 1;
  }
}

// Locale independent and strict: "1.5abc" or "" is not a number.
bool ParseFinite(const std::string& field, double& value)
{
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (begin != end && *begin == '+')
  {
    ++begin;
  }
  const auto result = std::from_chars(begin, end, value);
  return begin != end && result.ec == std::errc() && result.ptr == end && std::isfinite(value);
}

// Same directory as the target, so that the rename is atomic.
std::string TemporarySibling(const std::string& file)
{
  return file + ".part" + std::to_string(static_cast<long>(::getpid()));
}
} // namespace

bool ReadProbes(const std::string& csv, std::vector<Probe>& probes, std::string& error)
{
  probes.clear();
  std::ifstream in(csv);
  if (!in)
  {
    error = "cannot read probe file '" + csv + "'";
    return false;
  }
  static const char* const expected[6] = { "x", "y", "z", "nx", "ny", "nz" };
  std::string line;
  int number = 0;
  bool header = false;
  auto fail = [&](const std::string& reason) {
    error = csv + ":" + std::to_string(number) + ": " + reason + ": '" + Trim(line) + "'";
    probes.clear();
    return false;
  };
  while (std::getline(in, line))
  {
    ++number;
    if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
    {
      line.erase(0, 3); // byte order mark, as spreadsheets write it
    }
    if (Trim(line).empty())
    {
      continue;
    }
    const std::vector<std::string> fields = SplitFields(line);
    if (!header)
    {
      bool ok = fields.size() == 6;
      for (std::size_t i = 0; ok && i < 6; ++i)
      {
        ok = fields[i] == expected[i];
      }
      if (!ok)
      {
        return fail("expected the header 'x,y,z,nx,ny,nz'");
      }
      header = true;
      continue;
    }
    if (fields.size() != 6)
    {
      return fail("expected 6 values, found " + std::to_string(fields.size()));
    }
    double v[6];
    for (int i = 0; i < 6; ++i)
    {
      if (!ParseFinite(fields[i], v[i]))
      {
        return fail(std::string("column ") + expected[i] + " is not a finite number ('" +
          fields[i] + "')");
      }
    }
    Probe probe;
    probe.Position = Vec3(v[0], v[1], v[2]);
    const Vec3 normal(v[3], v[4], v[5]);
    const double length = glm::length(normal);
    // length is finite (each component is), but may underflow to 0 or overflow.
    if (!(length > 0.0) || !std::isfinite(length))
    {
      return fail("the normal (nx, ny, nz) has zero or unrepresentable length");
    }
    probe.Normal = normal / length;
    probes.push_back(probe);
  }
  if (!header)
  {
    number = 0;
    line.clear();
    error = csv + ": empty file, expected the header 'x,y,z,nx,ny,nz'";
    return false;
  }
  return true;
}

bool WriteProbeValues(const std::string& csv, const std::vector<Probe>& probes,
  const std::vector<RGB>& values, std::string& error)
{
  const std::string prefix = "cannot write probe values '" + csv + "': ";
  if (probes.size() != values.size())
  {
    error = prefix + std::to_string(probes.size()) + " probes but " +
      std::to_string(values.size()) + " values";
    return false;
  }
  // Checked before anything touches the disk: a refused output leaves no file.
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const Vec3& p = probes[i].Position;
    const RGB& e = values[i];
    for (int c = 0; c < 3; ++c)
    {
      if (!std::isfinite(p[c]) || !std::isfinite(e[c]))
      {
        error = prefix + "probe " + std::to_string(i) + " (row " + std::to_string(i + 2) +
          ") has a non-finite position or value";
        return false;
      }
    }
  }

  const std::string temporary = TemporarySibling(csv);
  std::FILE* out = std::fopen(temporary.c_str(), "w");
  if (out == nullptr)
  {
    error = prefix + std::strerror(errno);
    return false;
  }
  // %.17g: every double prints so that it reads back to the same bits.
  bool ok = std::fputs("x,y,z,E_r,E_g,E_b\n", out) >= 0;
  for (std::size_t i = 0; ok && i < probes.size(); ++i)
  {
    const Vec3& p = probes[i].Position;
    const RGB& e = values[i];
    ok = std::fprintf(out, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", p.x, p.y, p.z, e.r, e.g,
           e.b) > 0;
  }
  int code = ok ? 0 : errno;
  // fclose flushes: a full disk shows up here, not before.
  if (std::fclose(out) != 0 && ok)
  {
    ok = false;
    code = errno;
  }
  if (ok && std::rename(temporary.c_str(), csv.c_str()) != 0)
  {
    ok = false;
    code = errno;
  }
  if (!ok)
  {
    std::remove(temporary.c_str());
    error = prefix + (code != 0 ? std::strerror(code) : "write failed");
    return false;
  }
  return true;
}
} // namespace cli
} // namespace radiosity
