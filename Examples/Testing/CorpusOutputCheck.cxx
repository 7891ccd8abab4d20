// Checks a solved .vtp for the corpus test (Testing/Corpus/run_corpus.py):
// its Irradiance arrays (points and cells) must exist, be finite and
// non-negative. Prints "zero" (all values 0) or "non-zero", the range and the
// counts, then a line "bounds: xmin xmax ymin ymax zmin zmax" (the corpus
// test places its light from it); exit status 1 with the reason otherwise.
// With --nonzero (the solve under the corpus test's light) a zero peak
// irradiance fails too.
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  const bool nonzero = argc == 3 && std::string(argv[2]) == "--nonzero";
  if (argc != 2 && !nonzero)
  {
    std::cerr << "usage: CorpusOutputCheck SOLVED.vtp [--nonzero]\n";
    return 2;
  }
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(argv[1]);
  reader->Update();
  vtkPolyData* out = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || !out || out->GetNumberOfCells() == 0)
  {
    std::cout << "cannot read " << argv[1] << " or it has no cells\n";
    return 1;
  }
  double lo = INFINITY, hi = -INFINITY;
  for (vtkFieldData* data : { static_cast<vtkFieldData*>(out->GetPointData()),
         static_cast<vtkFieldData*>(out->GetCellData()) })
  {
    vtkDataArray* a = data->GetArray("Irradiance");
    const char* where = data == out->GetPointData() ? "point" : "cell";
    if (!a || a->GetNumberOfComponents() != 3)
    {
      std::cout << "no 3-component " << where << " array Irradiance\n";
      return 1;
    }
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double v = a->GetComponent(i, c);
        if (!std::isfinite(v) || v < 0)
        {
          std::cout << where << " Irradiance " << i << " component " << c << " is " << v << "\n";
          return 1;
        }
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
  }
  std::cout << (hi == 0 ? "zero" : "non-zero") << " irradiance in [" << lo << ", " << hi << "] on "
            << out->GetNumberOfCells() << " cells\n";
  double b[6];
  out->GetBounds(b);
  std::cout.precision(17);
  std::cout << "bounds: " << b[0] << " " << b[1] << " " << b[2] << " " << b[3] << " " << b[4] << " "
            << b[5] << "\n";
  if (nonzero && hi == 0)
  {
    std::cout << "zero peak irradiance under a light\n";
    return 1;
  }
  return 0;
}
