// The solvers' `Threads` option: 0 leaves TBB's default (every core), N > 0
// runs the solve in a task arena of N threads. The limit is scoped to that
// solve: a tbb::global_control would cap every TBB user of the process while
// the solve runs (in ParaView: the rest of the session, another filter).
#ifndef Radiosity_ThreadLimit_h
#define Radiosity_ThreadLimit_h

#include <tbb/task_arena.h>

#include <utility>

namespace radiosity
{
/// `body()` with at most `threads` TBB threads (0: TBB's default); its
/// result, or its exception, is returned as from a direct call.
template <typename Body>
auto RunWithThreads(int threads, Body&& body) -> decltype(body())
{
  if (threads <= 0)
  {
    return body();
  }
  tbb::task_arena arena(threads);
  return arena.execute(std::forward<Body>(body));
}
} // namespace radiosity

#endif
