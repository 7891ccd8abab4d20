#include "Report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace radiosity
{
namespace cli
{
bool WriteThroughTemporary(const std::string& file, const std::string& extension,
  const std::function<bool(const std::string& temporary)>& write, std::string& error)
{
  const std::string temporary = file + ".partial" + extension;
  if (!write(temporary) || std::rename(temporary.c_str(), file.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    error = "cannot write " + file;
    return false;
  }
  return true;
}

bool MakeDirectories(const std::string& directory, std::string& error)
{
  std::error_code code;
  std::filesystem::create_directories(directory, code);
  if (code || !std::filesystem::is_directory(directory))
  {
    error = "cannot create the directory " + directory + ": " +
      (code ? code.message() : std::string("a file of that name is in the way"));
    return false;
  }
  return true;
}

bool WriteFileAtomically(const std::string& file, const std::string& text, std::string& error)
{
  return WriteThroughTemporary(file, "",
    [&text](const std::string& temporary) {
      std::ofstream out(temporary, std::ios::binary);
      out << text;
      out.close();
      return static_cast<bool>(out);
    },
    error);
}

std::string HistoryCsv(const ConvergenceHistory& history)
{
  std::ostringstream s;
  s.precision(10);
  const auto names = ConvergenceHistory::ColumnNames();
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    s << (i ? "," : "") << names[i];
  }
  s << "\n";
  for (const ConvergenceRow& r : history.Rows)
  {
    s << r.Iteration << "," << r.TimeSeconds << "," << r.UnshotPowerW << "," << r.EnergyBalance
      << "," << r.RmsError << "," << r.MaxRelError << "," << r.OvershootPowerW << "\n";
  }
  return s.str();
}

nlohmann::json HistoryJson(const ConvergenceHistory& history)
{
  // JSON has no NaN: unknown error figures are null.
  const auto value = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json columns;
  for (const auto& name : ConvergenceHistory::ColumnNames())
  {
    columns[name] = nlohmann::json::array();
  }
  for (const ConvergenceRow& r : history.Rows)
  {
    columns["iteration"].push_back(r.Iteration);
    columns["time_s"].push_back(r.TimeSeconds);
    columns["unshot_power_W"].push_back(value(r.UnshotPowerW));
    columns["energy_balance"].push_back(value(r.EnergyBalance));
    columns["rms_error"].push_back(value(r.RmsError));
    columns["max_rel_error"].push_back(value(r.MaxRelError));
    columns["overshoot_power_W"].push_back(value(r.OvershootPowerW));
  }
  return columns;
}

}
}
