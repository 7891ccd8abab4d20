// The ranks' split of a solve's work (MPI ranks, issue 19). Every rank holds
// the whole scene (ScenePieces.h) and runs the same solver on it; the loops
// that cost (the meshless gathers, the progressive shots' receivers, the
// hierarchical links' form factors and blockers) compute only this rank's
// share of their items, and the shares are exchanged, so that every rank
// goes on with every value. A value does not depend on the rank that
// computed it, so 1, 2 or 4 ranks give the same answer bit for bit.
//
// The exchange itself is the caller's (the filters implement RankExchange
// over vtkMultiProcessController): the core knows no MPI.
#ifndef Radiosity_WorkShare_h
#define Radiosity_WorkShare_h

#include "Radiosity/Common/SolverTypes.h"

#include <cstddef>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace radiosity
{
/// What the ranks exchange. Every call is a collective: every rank makes the
/// same calls in the same order.
class RankExchange
{
public:
  virtual ~RankExchange() = default;
  virtual int Rank() const = 0;
  virtual int Ranks() const = 0;
  /// Every rank's bytes, in rank order.
  virtual std::vector<std::vector<char>> AllGather(const std::vector<char>& mine) = 0;
  /// True on every rank when `value` is true on any.
  virtual bool AnyRank(bool value) = 0;
};

/// What this rank did of the shared loops, for the report.
struct WorkShareStatistics
{
  std::size_t Items = 0;      ///< items this rank computed
  std::size_t TotalItems = 0; ///< items of the shared loops, all ranks together
  std::size_t Exchanges = 0;  ///< collectives
  std::size_t BytesSent = 0;
  std::size_t BytesReceived = 0;
  double ExchangeSeconds = 0.0; ///< waiting in the exchanges (the imbalance included)
};

[[noreturn]] void ThrowShortShare(std::size_t available, std::size_t wanted);

class WorkShare
{
public:
  /// One rank: every loop whole here, no exchange.
  WorkShare() = default;
  explicit WorkShare(std::shared_ptr<RankExchange> exchange);

  bool Distributed() const { return this->Exchange && this->Exchange->Ranks() > 1; }
  int Rank() const { return this->Exchange ? this->Exchange->Rank() : 0; }
  int Ranks() const { return this->Exchange ? this->Exchange->Ranks() : 1; }

  /// This rank's items [first, second) of the next Combine's loop over `n`:
  /// contiguous, sizes differing by one at most. The ranks that take the
  /// larger shares rotate from one Combine to the next, so that many small
  /// loops (the face cluster refinement's rounds) do not always load the
  /// same ranks.
  std::pair<std::size_t, std::size_t> Range(std::size_t n) const { return RangeOf(n, this->Rank()); }
  std::pair<std::size_t, std::size_t> RangeOf(std::size_t n, int rank) const;

  /**
   * values[0, n): on entry this rank's Range(n) is filled, on return every
   * item is, the other ranks' from their shares. T is copied as bytes.
   */
  template <typename T>
  void Combine(T* values, std::size_t n)
  {
    static_assert(std::is_trivially_copyable<T>::value, "Combine copies values as bytes");
    this->CombineBytes(reinterpret_cast<char*>(values), n, sizeof(T));
  }

  /**
   * Items of variable size: `pack(i, bytes)` appends item i of this rank's
   * share to `bytes`, `unpack(i, data, size)` reads item i of another
   * rank's share back and returns the bytes it read.
   */
  void CombineItems(std::size_t n, const std::function<void(std::size_t, std::vector<char>&)>& pack,
    const std::function<std::size_t(std::size_t, const char*, std::size_t)>& unpack);

  /// True on every rank when `value` is true on any (a rank's abort or time
  /// limit stops every rank at the same point); `value` on one rank.
  bool AnyRank(bool value);

  const WorkShareStatistics& Statistics() const { return this->Stats; }

private:
  void CombineBytes(char* values, std::size_t n, std::size_t size);
  std::shared_ptr<RankExchange> Exchange;
  WorkShareStatistics Stats;
  std::size_t Combines = 0; ///< CombineItems calls so far: the shares' rotation
};

/// Appends the first `size` bytes of `value` (trivially copyable) to `bytes`.
template <typename T>
void PutBytes(std::vector<char>& bytes, const T& value, std::size_t size = sizeof(T))
{
  static_assert(std::is_trivially_copyable<T>::value, "copied as bytes");
  const char* begin = reinterpret_cast<const char*>(&value);
  bytes.insert(bytes.end(), begin, begin + size);
}

/// Reads `size` bytes of `data` (of which `available` are left) into the
/// start of `value`; returns `size`. Throws SceneError when fewer are left.
template <typename T>
std::size_t GetBytes(const char* data, std::size_t available, T& value, std::size_t size = sizeof(T))
{
  static_assert(std::is_trivially_copyable<T>::value, "copied as bytes");
  if (available < size)
  {
    ThrowShortShare(available, size);
  }
  std::memcpy(reinterpret_cast<char*>(&value), data, size);
  return size;
}

/// The iteration and time limits (ReachedLimit) agreed over the ranks: a
/// rank's clock stops every rank at the same iteration.
inline bool ReachedLimitOnAnyRank(WorkShare& share, long long iteration, long long maxIterations,
  double elapsed, double maxSeconds, StopReason& stop)
{
  const bool here = ReachedLimit(iteration, maxIterations, elapsed, maxSeconds, stop);
  if (share.AnyRank(here))
  {
    if (!here)
    {
      stop = StopReason::TimeLimit;
    }
    return true;
  }
  return false;
}

/// The solver's share: `share` when set, else one rank's (no exchange).
inline WorkShare& ShareOrAlone(const std::shared_ptr<WorkShare>& share)
{
  static thread_local WorkShare alone;
  return share ? *share : alone;
}
} // namespace radiosity

#endif
