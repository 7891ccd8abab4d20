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

namespace
{
struct CsvRow
{
  int Line = 0;
  std::string Text;
  double Values[6];
};

/// Reads a CSV with exactly the header `names` (spaces around fields, a UTF-8
/// byte order mark and CRLF line ends tolerated) and rows of 6 finite numbers;
/// blank lines are skipped. `error` names the file, the line and its text.
/// With `seventh`, a header of the six and `seventh` is accepted too, its
/// rows of 7 finite numbers, the seventh checked and ignored.
bool ReadSixColumns(const std::string& csv, const char* const names[6], const std::string& what,
  std::vector<CsvRow>& rows, std::string& error, const char* seventh = nullptr)
{
  std::size_t columns = 6;
  rows.clear();
  std::ifstream in(csv);
  std::string headerText;
  for (int i = 0; i < 6; ++i)
  {
    headerText += std::string(i ? "," : "") + names[i];
  }
  if (!in)
  {
    error = "cannot read " + what + " file '" + csv + "'";
    return false;
  }
  std::string line;
  int number = 0;
  bool header = false;
  auto fail = [&](const std::string& reason) {
    error = csv + ":" + std::to_string(number) + ": " + reason + ": '" + Trim(line) + "'";
    rows.clear();
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
      // `seventh`: the names a seventh column may have, '|' between them.
      bool ok = fields.size() == 6 ||
        (seventh && fields.size() == 7 &&
          ("|" + std::string(seventh) + "|").find("|" + fields[6] + "|") != std::string::npos);
      for (std::size_t i = 0; ok && i < 6; ++i)
      {
        ok = fields[i] == names[i];
      }
      columns = fields.size();
      if (!ok)
      {
        return fail("expected the header '" + headerText + "'");
      }
      header = true;
      continue;
    }
    if (fields.size() != columns)
    {
      return fail("expected " + std::to_string(columns) + " values, found " + std::to_string(fields.size()));
    }
    double ignored = 0.0;
    if (columns == 7 && !ParseFinite(fields[6], ignored))
    {
      return fail(std::string("column ") + seventh + " is not a finite number ('" + fields[6] + "')");
    }
    CsvRow row;
    row.Line = number;
    row.Text = Trim(line);
    for (int i = 0; i < 6; ++i)
    {
      if (!ParseFinite(fields[i], row.Values[i]))
      {
        return fail(std::string("column ") + names[i] + " is not a finite number ('" +
          fields[i] + "')");
      }
    }
    rows.push_back(row);
  }
  if (!header)
  {
    error = csv + ": empty file, expected the header '" + headerText + "'";
    return false;
  }
  return true;
}
}

bool ReadProbes(const std::string& csv, std::vector<Probe>& probes, std::string& error)
{
  probes.clear();
  static const char* const names[6] = { "x", "y", "z", "nx", "ny", "nz" };
  std::vector<CsvRow> rows;
  if (!ReadSixColumns(csv, names, "probe", rows, error))
  {
    return false;
  }
  for (const CsvRow& row : rows)
  {
    Probe probe;
    probe.Position = Vec3(row.Values[0], row.Values[1], row.Values[2]);
    const Vec3 normal(row.Values[3], row.Values[4], row.Values[5]);
    const double length = glm::length(normal);
    // length is finite (each component is), but may underflow to 0 or overflow.
    if (!(length > 0.0) || !std::isfinite(length))
    {
      error = csv + ":" + std::to_string(row.Line) +
        ": the normal (nx, ny, nz) has zero or unrepresentable length: '" + row.Text + "'";
      probes.clear();
      return false;
    }
    probe.Normal = normal / length;
    probes.push_back(probe);
  }
  return true;
}

bool ReadProbeValues(const std::string& csv, const std::vector<Probe>& probes,
  std::vector<RGB>& values, std::string& error)
{
  values.clear();
  static const char* const names[6] = { "x", "y", "z", "E_r", "E_g", "E_b" };
  std::vector<CsvRow> rows;
  // A probe output with a sky has the daylight factor too, a computed
  // reference its standard errors (WriteProbeValues).
  if (!ReadSixColumns(csv, names, "reference", rows, error, "DF|SE"))
  {
    return false;
  }
  if (rows.size() != probes.size())
  {
    error = csv + ": " + std::to_string(rows.size()) + " reference values for " +
      std::to_string(probes.size()) + " probes";
    return false;
  }
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    const Vec3 at(rows[i].Values[0], rows[i].Values[1], rows[i].Values[2]);
    const Vec3& p = probes[i].Position;
    if (glm::length(at - p) > 1e-9 * (1.0 + glm::length(p)))
    {
      error = csv + ":" + std::to_string(rows[i].Line) +
        ": the position does not match probe " + std::to_string(i + 1) + ": '" + rows[i].Text + "'";
      values.clear();
      return false;
    }
    values.emplace_back(rows[i].Values[3], rows[i].Values[4], rows[i].Values[5]);
  }
  return true;
}

double DaylightFactor(const RGB& irradiance, const RGB& unobstructed)
{
  // Luminance (Types.h): 0.2126 R + 0.7152 G + 0.0722 B.
  const double sky = Luminance(unobstructed);
  return sky > 0.0 ? Luminance(irradiance) / sky : 0.0;
}

bool WriteProbeValues(const std::string& csv, const std::vector<Probe>& probes,
  const std::vector<RGB>& values, std::string& error, const RGB* skyUnobstructed,
  const std::vector<double>* standardErrors)
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
  bool ok = std::fputs(skyUnobstructed ? "x,y,z,E_r,E_g,E_b,DF\n"
                        : standardErrors ? "x,y,z,E_r,E_g,E_b,SE\n"
                                         : "x,y,z,E_r,E_g,E_b\n",
              out) >= 0;
  for (std::size_t i = 0; ok && i < probes.size(); ++i)
  {
    const Vec3& p = probes[i].Position;
    const RGB& e = values[i];
    ok = std::fprintf(out, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", p.x, p.y, p.z, e.r, e.g, e.b) > 0;
    if (ok && skyUnobstructed)
    {
      ok = std::fprintf(out, ",%.17g", DaylightFactor(e, *skyUnobstructed)) > 0;
    }
    else if (ok && standardErrors)
    {
      ok = std::fprintf(out, ",%.17g", i < standardErrors->size() ? (*standardErrors)[i] : 0.0) > 0;
    }
    ok = ok && std::fputs("\n", out) >= 0;
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
