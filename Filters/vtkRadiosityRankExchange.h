// The collectives of a distributed solve (vtkRadiosityFilter under a
// vtkMultiProcessController of several processes): every rank calls each
// function at the same point of its request, whether it holds a piece of
// the scene or none. What the exchanged pieces mean is the core's
// (Radiosity/Common/ScenePieces.h); this is only the transport.
#ifndef vtkRadiosityRankExchange_h
#define vtkRadiosityRankExchange_h

#include "RadiosityFiltersModule.h" // for export macro
#include "vtkType.h"

#include <memory>
#include <string>
#include <vector>

class vtkMultiProcessController;
namespace radiosity
{
class WorkShare;
}

namespace vtkRadiosityRankExchange
{
/**
 * Collective. "" when `localError` is "" on every rank; otherwise, on every
 * rank alike, the message of the lowest rank that failed, with
 * " (rank r of n)" appended: a request fails on all ranks or on none, and
 * no rank waits in a later collective for one that gave up.
 */
RADIOSITYFILTERS_EXPORT std::string AgreeOnError(
  vtkMultiProcessController* controller, const std::string& localError);

/// Collective: whether `flag` is true on some rank.
RADIOSITYFILTERS_EXPORT bool AnyRank(vtkMultiProcessController* controller, bool flag);

/**
 * Collective. Every rank's bytes, in rank order (an all-gather of lengths,
 * then of the bytes). `received` (per rank, in rank order): how many bytes
 * each rank received from the others.
 */
RADIOSITYFILTERS_EXPORT std::vector<std::vector<char>> AllGatherBytes(vtkMultiProcessController* controller,
  const std::vector<char>& mine, std::vector<vtkIdType>& received);

/// The ranks' split of a solve's loops (radiosity::WorkShare) over
/// `controller` (not owned: it must outlive the share).
RADIOSITYFILTERS_EXPORT std::shared_ptr<radiosity::WorkShare> MakeWorkShare(
  vtkMultiProcessController* controller);
}

#endif
