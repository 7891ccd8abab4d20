#include "ProgressBar.h"

#include <cmath>

#include <unistd.h>

namespace radiosity
{
namespace cli
{
namespace
{
constexpr int BarWidth = 20;
// Fast enough to look alive, slow enough not to cost the solver anything.
constexpr auto TerminalInterval = std::chrono::milliseconds(100);
// A log gets one line a second at most.
constexpr auto PlainInterval = std::chrono::seconds(1);
} // namespace

ProgressBar::ProgressBar(std::FILE* out)
  : ProgressBar(out, out != nullptr && ::isatty(::fileno(out)) == 1)
{
}

ProgressBar::ProgressBar(std::FILE* out, bool terminal)
  : Out(out)
  , Terminal(terminal)
{
}

std::string ProgressBar::Format(const ProgressStatus& status) const
{
  double fraction = status.Fraction;
  if (!(fraction >= 0.0))
  {
    fraction = 0.0; // NaN or negative: an estimate that is not there yet
  }
  fraction = fraction > 1.0 ? 1.0 : fraction;
  // The epsilon keeps 0.43 from showing as 42% (0.43 * 100 < 43 in binary).
  const int percent = static_cast<int>(std::floor(100.0 * fraction + 1e-9));
  char numbers[256];
  std::snprintf(numbers, sizeof(numbers), "%3d%% %s  it %lld  residual %.1e", percent,
    status.Phase.c_str(), status.Iteration, status.Residual);
  if (!this->Terminal)
  {
    return numbers;
  }
  const int filled = static_cast<int>(std::floor(BarWidth * fraction));
  std::string line = "[";
  line.append(static_cast<std::size_t>(filled), '#');
  line.append(static_cast<std::size_t>(BarWidth - filled), '.');
  line += "] ";
  return line + numbers;
}

void ProgressBar::Draw(const ProgressStatus& status)
{
  const std::string line = this->Format(status);
  if (this->Terminal)
  {
    // Spaces over what a longer previous line left behind.
    const std::size_t pad = this->LastWidth > line.size() ? this->LastWidth - line.size() : 0;
    std::fprintf(this->Out, "\r%s%*s", line.c_str(), static_cast<int>(pad), "");
    this->LastWidth = line.size();
  }
  else
  {
    std::fprintf(this->Out, "%s\n", line.c_str());
  }
  std::fflush(this->Out);
  this->LastDraw = Clock::now();
  this->Pending = false;
}

bool ProgressBar::Update(const ProgressStatus& status)
{
  if (this->Out == nullptr)
  {
    return true;
  }
  std::lock_guard<std::mutex> lock(this->Mutex);
  const auto now = Clock::now();
  const bool phaseChanged = !this->Started || status.Phase != this->LastPhase;
  const auto interval = this->Terminal ? Clock::duration(TerminalInterval)
                                       : Clock::duration(PlainInterval);
  this->Last = status;
  this->LastPhase = status.Phase;
  if (phaseChanged || now - this->LastDraw >= interval)
  {
    this->Started = true;
    this->Draw(status);
  }
  else
  {
    this->Pending = true;
  }
  return true;
}

void ProgressBar::Finish(const std::string& message)
{
  if (this->Out == nullptr)
  {
    return;
  }
  std::lock_guard<std::mutex> lock(this->Mutex);
  if (this->Pending)
  {
    this->Draw(this->Last); // the last state is always shown
  }
  if (this->Terminal && this->Started)
  {
    std::fputc('\n', this->Out);
  }
  if (!message.empty())
  {
    std::fprintf(this->Out, "%s\n", message.c_str());
  }
  std::fflush(this->Out);
  this->Started = false;
  this->LastWidth = 0;
}
} // namespace cli
} // namespace radiosity
