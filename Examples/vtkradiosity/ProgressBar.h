// Progress display of the command-line program (SPEC: a bar with phase,
// iteration and residual on a terminal; plain lines otherwise, so that logs
// and CI output stay readable).
#ifndef vtkradiosity_ProgressBar_h
#define vtkradiosity_ProgressBar_h

#include "Radiosity/Common/SolverTypes.h"

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace radiosity
{
namespace cli
{
class ProgressBar
{
public:
  /// Terminal mode when `out` is a terminal (isatty).
  explicit ProgressBar(std::FILE* out = stderr);
  /// Explicit mode, for tests and for callers that know better.
  ProgressBar(std::FILE* out, bool terminal);

  /**
   * Terminal: one line redrawn in place with '\r',
   * `[########............]  43% shooting  it 1234  residual 2.3e-03`,
   * at most 10 redraws a second (and at once when the phase changes).
   * Otherwise: a plain line at most once a second, plus the first one and one
   * per phase change. Always returns true: the bar never aborts a solve, so it
   * can serve directly as a radiosity::ProgressCallback.
   */
  bool Update(const ProgressStatus& status);

  /// Shows the last status if it was not shown yet, ends the bar's line and
  /// prints `message` (if not empty) on its own line.
  void Finish(const std::string& message);

  /// Adapter: `radiosity::ProgressCallback cb = std::ref(bar);`
  bool operator()(const ProgressStatus& status) { return this->Update(status); }

private:
  using Clock = std::chrono::steady_clock;
  std::string Format(const ProgressStatus& status) const;
  void Draw(const ProgressStatus& status);

  std::FILE* Out;
  bool Terminal;
  std::mutex Mutex; // the solver may report from a worker thread
  bool Started = false;
  bool Pending = false; // a status arrived that is not shown yet
  Clock::time_point LastDraw;
  ProgressStatus Last;
  std::string LastPhase;
  std::size_t LastWidth = 0; // characters of the current terminal line
};
} // namespace cli
} // namespace radiosity

#endif
