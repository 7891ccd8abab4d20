// Compares a PNG the command line wrote with its baseline through VTK's own
// regression comparison (vtkTesting, as vtkRegressionTestImage does for the
// C++ tests): CliImageCompare CANDIDATE.png BASELINE.png TEMP_DIR [THRESHOLD].
// Exit 0 when they match (VTK's default threshold 0.05 unless given); 1
// otherwise, with the difference image in TEMP_DIR. A missing baseline fails
// and leaves the candidate there to be looked at and committed.
#include "vtkNew.h"
#include "vtkTesting.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 4)
  {
    std::cerr << "usage: CliImageCompare CANDIDATE.png BASELINE.png TEMP_DIR [THRESHOLD]\n";
    return 2;
  }
  vtkNew<vtkTesting> testing;
  testing->AddArgument("-V");
  testing->AddArgument(argv[2]);
  testing->AddArgument("-T");
  testing->AddArgument(argv[3]);
  const double threshold = argc > 4 ? std::atof(argv[4]) : 0.05;
  const int result = testing->RegressionTest(argv[1], threshold, std::cout);
  return result == vtkTesting::PASSED ? 0 : 1;
}
