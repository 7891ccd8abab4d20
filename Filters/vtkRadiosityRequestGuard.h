// The boundary of every algorithm of this module: no exception leaves a
// RequestData (in ParaView one would end the session). The core reports bad
// input as radiosity::SceneError (and a solve over its memory budget as its
// subclass MemoryBudgetExceeded); Embree, CGAL and the standard library throw
// their own. Each is reported through the algorithm's Fail (vtkErrorMacro and
// its LastError), the output is emptied, and the request fails with 0, as
// VTK's convention for a failed request is.
#ifndef vtkRadiosityRequestGuard_h
#define vtkRadiosityRequestGuard_h

#include "vtkDataObject.h"

#include "Radiosity/Common/Scene.h"

#include <exception>
#include <new>
#include <string>

/**
 * Runs `body` (returning 1 on success, or the 0 of a Fail it called) and
 * turns an exception into `fail(message)`: "bad input: ..." for a
 * SceneError, "out of memory: ..." for std::bad_alloc, "internal error: ..."
 * otherwise. `fail` returns 0. On failure `output` (when given) is emptied.
 */
template <typename Body, typename Fail>
int vtkRadiosityGuardedRequest(vtkDataObject* output, const Body& body, const Fail& fail)
{
  int status = 0;
  try
  {
    status = body();
  }
  catch (const radiosity::SceneError& e)
  {
    status = fail(std::string("bad input: ") + e.what());
  }
  catch (const std::bad_alloc&)
  {
    status = fail("out of memory: the solve could not allocate what it needed; coarsen the settings "
                  "or lower MaxMemory so that the estimate refuses it before it starts");
  }
  catch (const std::exception& e)
  {
    status = fail(std::string("internal error: ") + e.what());
  }
  catch (...)
  {
    status = fail("internal error: an unknown exception");
  }
  if (!status && output)
  {
    output->Initialize();
  }
  return status ? 1 : 0;
}

#endif
