// The JSON report and the convergence CSV of a solve (SPEC: --report).
#ifndef vtkradiosity_Report_h
#define vtkradiosity_Report_h

#include "Radiosity/ConvergenceHistory.h"

#include <nlohmann/json.hpp>

#include <string>

namespace radiosity
{
namespace cli
{
/// Writes `text` to `file` through a temporary file and a rename, so that no
/// half-written output is ever left; false with `error` on failure.
bool WriteFileAtomically(const std::string& file, const std::string& text, std::string& error);

/// The history as CSV with the SPEC columns (NaN written as "nan").
std::string HistoryCsv(const ConvergenceHistory& history);

/// The history as JSON columns.
nlohmann::json HistoryJson(const ConvergenceHistory& history);
}
}

#endif
