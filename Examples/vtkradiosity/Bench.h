// `vtkradiosity bench`: every available method on the standard scenes at a
// sweep of accuracy settings; per scene a CSV, an error-against-run-time plot
// (log-log) and a markdown table, for the error harness.
#ifndef vtkradiosity_Bench_h
#define vtkradiosity_Bench_h

#include <string>

namespace radiosity
{
namespace cli
{
/// Returns the exit status; `quick` runs two settings per scene (for CI).
int RunBench(const std::string& outputDir, bool quick);
}
}

#endif
