// Draws two synthetic convergence histories (with and without acceleration)
// and compares the chart with the baseline; checks that all-NaN columns are
// skipped and that a table without the time column is refused.

#include "vtkRadiosityConvergenceChart.h"

#include "vtkDoubleArray.h"
#include "vtkFloatingPointExceptions.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <string>

namespace
{
vtkSmartPointer<vtkDoubleArray> Column(vtkTable* table, const char* name)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  table->AddColumn(a);
  return a.GetPointer();
}

// Unshot power decays like exp(-rate t); the energy balance alternates in sign
// (its absolute value is plotted); the errors decay more slowly and have a
// floor. Without a reference the error columns are NaN (SPEC.md).
vtkSmartPointer<vtkTable> MakeHistory(int n, double rate, double dt, bool withErrors)
{
  vtkSmartPointer<vtkTable> t = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkIntArray> iteration;
  iteration->SetName("iteration");
  t->AddColumn(iteration);
  auto time = Column(t, "time_s");
  auto unshot = Column(t, "unshot_power_W");
  auto balance = Column(t, "energy_balance");
  auto rms = Column(t, "rms_error");
  auto maxRel = Column(t, "max_rel_error");
  auto extra = Column(t, "extra");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < n; ++i)
  {
    const double ti = dt * (i + 1);
    iteration->InsertNextValue(i);
    time->InsertNextValue(ti);
    unshot->InsertNextValue(100.0 * std::exp(-rate * ti));
    // The first entry is exactly zero: it must be dropped, not break the log axis.
    balance->InsertNextValue(i == 0 ? 0.0 : ((i % 2) ? 1.0 : -1.0) * 1e-3 * std::exp(-0.5 * rate * ti));
    rms->InsertNextValue(withErrors ? 0.5 * std::exp(-0.7 * rate * ti) + 1e-4 : nan);
    maxRel->InsertNextValue(withErrors ? 2.0 * std::exp(-0.6 * rate * ti) + 5e-4 : nan);
    extra->InsertNextValue(1e9); // not chosen: must not be drawn
  }
  return t;
}
}

int TestRadiosityConvergenceChart(int argc, char* argv[])
{
  vtkFloatingPointExceptions::Disable();

  // Without a reference only unshot power and energy balance can be drawn.
  {
    vtkNew<vtkRadiosityConvergenceChart> chart;
    chart->SetInputData(MakeHistory(20, 1.0, 0.1, false));
    if (!chart->Render(200, 150) || chart->GetNumberOfLines() != 2)
    {
      std::cerr << "Expected 2 lines without errors, got " << chart->GetNumberOfLines() << "\n";
      return EXIT_FAILURE;
    }
  }

  // A table with no time column is refused with an error naming the column.
  {
    vtkNew<vtkRadiosityConvergenceChart> chart;
    vtkNew<vtkTable> bad;
    Column(bad, "unshot_power_W")->InsertNextValue(1.0);
    chart->SetInputData(bad);
    vtkNew<vtkTest::ErrorObserver> observer;
    chart->AddObserver(vtkCommand::ErrorEvent, observer);
    if (chart->Render(200, 150) ||
      observer->GetErrorMessage().find("'time_s'") == std::string::npos)
    {
      std::cerr << "Missing time column not refused: '" << observer->GetErrorMessage() << "'\n";
      return EXIT_FAILURE;
    }
  }

  vtkNew<vtkRadiosityConvergenceChart> chart;
  chart->SetTitle("Convergence: synthetic history");
  chart->AddInputData(MakeHistory(60, 0.8, 0.1, true), "with acceleration");
  chart->AddInputData(MakeHistory(60, 0.35, 0.1, true), "without");
  if (!chart->Render(800, 450))
  {
    return EXIT_FAILURE;
  }
  if (chart->GetNumberOfLines() != 8)
  {
    std::cerr << "Expected 8 lines, got " << chart->GetNumberOfLines() << "\n";
    return EXIT_FAILURE;
  }

  // WritePNG renders the same chart into a file (-T: the test output dir).
  char* tempDir =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  const std::string png = std::string(tempDir) + "/TestRadiosityConvergenceChart-written.png";
  delete[] tempDir;
  if (!chart->WritePNG(png.c_str(), 800, 450))
  {
    std::cerr << "WritePNG failed for " << png << "\n";
    return EXIT_FAILURE;
  }

  const int retVal = vtkRegressionTestImage(chart->GetRenderWindow());
  return !retVal;
}
