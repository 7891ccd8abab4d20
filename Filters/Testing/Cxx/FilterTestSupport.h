// Helpers of the filters' tests.
#ifndef FilterTestSupport_h
#define FilterTestSupport_h

#include <iostream>
#include <string>

namespace FilterTestSupport
{
// `ok`, reporting `what` on stderr when it is false: a test runs every
// check and fails at the end if any failed.
inline bool Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
  }
  return ok;
}
}

#endif
