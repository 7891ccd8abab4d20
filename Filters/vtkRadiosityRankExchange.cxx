#include "vtkRadiosityRankExchange.h"

#include "Radiosity/Common/WorkShare.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <limits>
#include <numeric>
#include <stdexcept>

namespace vtkRadiosityRankExchange
{
std::string AgreeOnError(vtkMultiProcessController* controller, const std::string& localError)
{
  const int ranks = controller->GetNumberOfProcesses();
  const int failed = localError.empty() ? 0 : 1;
  std::vector<int> all(static_cast<std::size_t>(ranks), 0);
  controller->AllGather(&failed, all.data(), 1);
  int root = 0;
  while (root < ranks && !all[static_cast<std::size_t>(root)])
  {
    ++root;
  }
  if (root == ranks)
  {
    return std::string();
  }
  vtkIdType length = static_cast<vtkIdType>(localError.size());
  controller->Broadcast(&length, 1, root);
  std::string message(static_cast<std::size_t>(length), ' ');
  if (controller->GetLocalProcessId() == root)
  {
    message = localError;
  }
  if (length > 0)
  {
    controller->Broadcast(&message[0], length, root);
  }
  return message + " (rank " + std::to_string(root) + " of " + std::to_string(ranks) + ")";
}

bool AnyRank(vtkMultiProcessController* controller, bool flag)
{
  const int mine = flag ? 1 : 0;
  int any = 0;
  controller->AllReduce(&mine, &any, 1, vtkCommunicator::MAX_OP);
  return any != 0;
}

std::vector<std::vector<char>> AllGatherBytes(vtkMultiProcessController* controller,
  const std::vector<char>& mine, std::vector<vtkIdType>& received)
{
  const int ranks = controller->GetNumberOfProcesses();
  const vtkIdType length = static_cast<vtkIdType>(mine.size());
  std::vector<vtkIdType> lengths(static_cast<std::size_t>(ranks), 0);
  controller->AllGather(&length, lengths.data(), 1);
  std::vector<vtkIdType> offsets(static_cast<std::size_t>(ranks), 0);
  vtkIdType total = 0;
  for (int r = 0; r < ranks; ++r)
  {
    offsets[static_cast<std::size_t>(r)] = total;
    total += lengths[static_cast<std::size_t>(r)];
  }
  // MPI counts are ints: a scene of more than 2 GB in all is refused
  // (every rank alike: the lengths are the same everywhere).
  if (total > static_cast<vtkIdType>(std::numeric_limits<int>::max()))
  {
    throw std::length_error("the gathered scene is " + std::to_string(total) +
      " bytes, more than one MPI all-gather carries (2^31 - 1)");
  }
  std::vector<char> all(static_cast<std::size_t>(total) + 1);
  controller->AllGatherV(mine.empty() ? all.data() : mine.data(), all.data(), length,
    lengths.data(), offsets.data());
  std::vector<std::vector<char>> pieces(static_cast<std::size_t>(ranks));
  received.assign(static_cast<std::size_t>(ranks), 0);
  for (int r = 0; r < ranks; ++r)
  {
    const auto at = all.begin() + offsets[static_cast<std::size_t>(r)];
    pieces[static_cast<std::size_t>(r)].assign(at, at + lengths[static_cast<std::size_t>(r)]);
    received[static_cast<std::size_t>(r)] = total - lengths[static_cast<std::size_t>(r)];
  }
  return pieces;
}

namespace
{
class ControllerExchange : public radiosity::RankExchange
{
public:
  explicit ControllerExchange(vtkMultiProcessController* controller)
    : Controller(controller)
  {
  }
  int Rank() const override { return this->Controller->GetLocalProcessId(); }
  int Ranks() const override { return this->Controller->GetNumberOfProcesses(); }
  std::vector<std::vector<char>> AllGather(const std::vector<char>& mine) override
  {
    std::vector<vtkIdType> received;
    return AllGatherBytes(this->Controller, mine, received);
  }
  bool AnyRank(bool value) override { return vtkRadiosityRankExchange::AnyRank(this->Controller, value); }

private:
  vtkMultiProcessController* Controller;
};
}

std::shared_ptr<radiosity::WorkShare> MakeWorkShare(vtkMultiProcessController* controller)
{
  return std::make_shared<radiosity::WorkShare>(std::make_shared<ControllerExchange>(controller));
}
}
