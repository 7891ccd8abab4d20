// The solvers' `Threads` option: 0 leaves TBB's default (every core),
// N > 0 caps the parallelism of every TBB loop while the returned object lives.
#ifndef Radiosity_ThreadLimit_h
#define Radiosity_ThreadLimit_h

#include <tbb/global_control.h>

#include <memory>

namespace radiosity
{
inline std::unique_ptr<tbb::global_control> LimitThreads(int threads)
{
  if (threads <= 0)
  {
    return nullptr;
  }
  return std::make_unique<tbb::global_control>(
    tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
}
} // namespace radiosity

#endif
