#include "Radiosity/Common/WorkShare.h"

#include "Radiosity/Common/Scene.h"
#include "Radiosity/Common/Stopwatch.h"

namespace radiosity
{
void ThrowShortShare(std::size_t available, std::size_t wanted)
{
  throw SceneError("the ranks' shares do not match: " + std::to_string(available) +
    " bytes left for an item of " + std::to_string(wanted));
}

WorkShare::WorkShare(std::shared_ptr<RankExchange> exchange)
  : Exchange(std::move(exchange))
{
}

std::pair<std::size_t, std::size_t> WorkShare::RangeOf(std::size_t n, int rank) const
{
  const std::size_t ranks = static_cast<std::size_t>(this->Ranks());
  const std::size_t r = (static_cast<std::size_t>(rank) + this->Combines) % ranks;
  return { n / ranks * r + std::min(r, n % ranks), n / ranks * (r + 1) + std::min(r + 1, n % ranks) };
}

void WorkShare::CombineBytes(char* values, std::size_t n, std::size_t size)
{
  // Items of one size: each a run of `size` bytes in place.
  this->CombineItems(
    n,
    [values, size](std::size_t i, std::vector<char>& bytes) {
      bytes.insert(bytes.end(), values + i * size, values + (i + 1) * size);
    },
    [values, size](std::size_t i, const char* data, std::size_t available) {
      if (available < size)
      {
        ThrowShortShare(available, size);
      }
      std::memcpy(values + i * size, data, size);
      return size;
    });
}

void WorkShare::CombineItems(std::size_t n,
  const std::function<void(std::size_t, std::vector<char>&)>& pack,
  const std::function<std::size_t(std::size_t, const char*, std::size_t)>& unpack)
{
  const auto mine = this->Range(n);
  this->Stats.Items += mine.second - mine.first;
  this->Stats.TotalItems += n;
  if (!this->Distributed())
  {
    return;
  }
  struct NextRotation // after the ranges below are read, also when unpack throws
  {
    std::size_t& Combines;
    ~NextRotation() { ++this->Combines; }
  } rotate{ this->Combines };
  const Stopwatch clock;
  std::vector<char> bytes;
  for (std::size_t i = mine.first; i < mine.second; ++i)
  {
    pack(i, bytes);
  }
  const std::vector<std::vector<char>> all = this->Exchange->AllGather(bytes);
  ++this->Stats.Exchanges;
  this->Stats.BytesSent += bytes.size();
  for (int r = 0; r < this->Ranks(); ++r)
  {
    if (r == this->Rank())
    {
      continue;
    }
    const std::vector<char>& theirs = all[static_cast<std::size_t>(r)];
    const auto range = this->RangeOf(n, r);
    std::size_t at = 0;
    for (std::size_t i = range.first; i < range.second; ++i)
    {
      at += unpack(i, theirs.data() + at, theirs.size() - at);
    }
    if (at != theirs.size())
    {
      throw SceneError("the ranks' shares do not match: rank " + std::to_string(r) + " sent " +
        std::to_string(theirs.size()) + " bytes, its items " + std::to_string(at));
    }
    this->Stats.BytesReceived += theirs.size();
  }
  this->Stats.ExchangeSeconds += clock.Seconds();
}

bool WorkShare::AnyRank(bool value)
{
  if (!this->Distributed())
  {
    return value;
  }
  ++this->Stats.Exchanges;
  return this->Exchange->AnyRank(value);
}
} // namespace radiosity
