// The JSON report and the convergence CSV of a solve (SPEC: --report).
#ifndef vtkradiosity_Report_h
#define vtkradiosity_Report_h

#include "Radiosity/Common/ConvergenceHistory.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace radiosity
{
namespace cli
{
/// Runs `write` on a temporary path beside `file` (`file` + ".partial" +
/// `extension`, for writers that choose the format by the name), then
/// renames it to `file`; the temporary is removed whatever failed, so that no
/// half-written output is ever left. False with `error` on failure.
bool WriteThroughTemporary(const std::string& file, const std::string& extension,
  const std::function<bool(const std::string& temporary)>& write, std::string& error);

/// Writes `text` to `file` through a temporary file and a rename, so that no
/// half-written output is ever left; false with `error` on failure.
bool WriteFileAtomically(const std::string& file, const std::string& text, std::string& error);

/// Creates `directory` and its missing parents; false with `error` (naming
/// the directory and the reason) when it cannot.
bool MakeDirectories(const std::string& directory, std::string& error);

/// The history as CSV with the SPEC columns (NaN written as "nan").
std::string HistoryCsv(const ConvergenceHistory& history);

/// The history as JSON columns.
nlohmann::json HistoryJson(const ConvergenceHistory& history);
}
}

#endif
