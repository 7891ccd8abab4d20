// Checks a solved .vtp for the corpus test (Testing/Corpus/run_corpus.py):
// its Irradiance arrays (points and cells) must exist, be finite and
// non-negative. Prints "zero" (all values 0) or "non-zero", the range and the
// counts; exit status 1 with the reason otherwise.
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: CorpusOutputCheck SOLVED.vtp\n";
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
  return 0;
}
