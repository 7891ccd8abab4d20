#include "vtkRadiosityConvergenceChart.h"
#include "vtkRadiosityWindowPNG.h"

#include "vtkAxis.h"
#include "vtkChartLegend.h"
#include "vtkChartXY.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPen.h"
#include "vtkPlot.h"
#include "vtkPlotPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkTextProperty.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkRadiosityConvergenceChart);

struct vtkRadiosityConvergenceChart::Internals
{
  struct Series
  {
    vtkSmartPointer<vtkTable> Table;
    std::string Label;
  };
  std::vector<Series> Inputs;
  std::vector<std::pair<std::string, std::string>> Columns; // name, legend label
  vtkSmartPointer<vtkContextView> View;
  vtkSmartPointer<vtkChartXY> Chart;
  int NumberOfLines = 0;
};

namespace
{
// Colour per column (Okabe-Ito, readable by colour-blind readers), dash
// pattern per series, so that "which quantity" and "which run" stay apart.
const unsigned char Palette[][3] = { { 0, 114, 178 }, { 213, 94, 0 }, { 0, 158, 115 },
  { 204, 121, 167 }, { 230, 159, 0 }, { 86, 180, 233 }, { 0, 0, 0 } };
const int PaletteSize = static_cast<int>(sizeof(Palette) / sizeof(Palette[0]));
const int PenStyles[] = { vtkPen::SOLID_LINE, vtkPen::DASH_LINE, vtkPen::DOT_LINE,
  vtkPen::DASH_DOT_LINE, vtkPen::DASH_DOT_DOT_LINE };
const int PenStylesSize = static_cast<int>(sizeof(PenStyles) / sizeof(PenStyles[0]));
const int Markers[] = { vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
  vtkPlotPoints::CROSS };
const int MarkersSize = static_cast<int>(sizeof(Markers) / sizeof(Markers[0]));
}

//------------------------------------------------------------------------------
vtkRadiosityConvergenceChart::vtkRadiosityConvergenceChart()
  : Internal(new Internals)
{
  this->SetTimeColumn("time_s");
  this->SetTitle("Convergence");
  this->AddColumn("unshot_power_W", "unshot power (W)");
  this->AddColumn("energy_balance", "abs(energy balance)");
  this->AddColumn("rms_error", "RMS error");
  this->AddColumn("max_rel_error", "max relative error");

  this->Internal->View = vtkSmartPointer<vtkContextView>::New();
  this->Internal->View->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  this->Internal->View->GetRenderWindow()->SetOffScreenRendering(1);
  this->Internal->View->GetRenderWindow()->SetMultiSamples(0);
  this->Internal->Chart = vtkSmartPointer<vtkChartXY>::New();
  this->Internal->View->GetScene()->AddItem(this->Internal->Chart);
  vtkChartXY* chart = this->Internal->Chart;
  chart->SetShowLegend(true);
  // Outside the plot area: decaying curves fill every corner of it.
  chart->GetLegend()->SetInline(false);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::CENTER);
  chart->GetTitleProperties()->SetFontSize(16);
  chart->GetTitleProperties()->BoldOn();
  chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("run time (s)");
  chart->GetAxis(vtkAxis::LEFT)->SetTitle("value (log scale)");
}

//------------------------------------------------------------------------------
vtkRadiosityConvergenceChart::~vtkRadiosityConvergenceChart()
{
  this->SetTimeColumn(nullptr);
  this->SetTitle(nullptr);
}

//------------------------------------------------------------------------------
void vtkRadiosityConvergenceChart::SetInputData(vtkTable* history)
{
  this->Internal->Inputs.clear();
  if (history)
  {
    this->Internal->Inputs.push_back({ history, std::string() });
  }
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRadiosityConvergenceChart::AddInputData(vtkTable* history, const char* label)
{
  if (!history)
  {
    vtkErrorMacro("AddInputData: null table.");
    return;
  }
  this->Internal->Inputs.push_back({ history, label ? label : "" });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRadiosityConvergenceChart::RemoveAllInputs()
{
  this->Internal->Inputs.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkRadiosityConvergenceChart::GetNumberOfInputs() const
{
  return static_cast<int>(this->Internal->Inputs.size());
}

//------------------------------------------------------------------------------
void vtkRadiosityConvergenceChart::AddColumn(const char* name, const char* label)
{
  if (!name || !*name)
  {
    vtkErrorMacro("AddColumn: empty column name.");
    return;
  }
  this->Internal->Columns.emplace_back(name, label && *label ? label : name);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkRadiosityConvergenceChart::RemoveAllColumns()
{
  this->Internal->Columns.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkRadiosityConvergenceChart::GetNumberOfColumns() const
{
  return static_cast<int>(this->Internal->Columns.size());
}

//------------------------------------------------------------------------------
int vtkRadiosityConvergenceChart::BuildPlots()
{
  vtkChartXY* chart = this->Internal->Chart;
  chart->ClearPlots();
  chart->SetTitle(this->Title ? this->Title : "");
  chart->GetAxis(vtkAxis::LEFT)->SetLogScale(true);
  chart->GetAxis(vtkAxis::BOTTOM)->SetLogScale(this->LogTime);
  const char* timeName = this->TimeColumn ? this->TimeColumn : "";

  int lines = 0;
  for (size_t s = 0; s < this->Internal->Inputs.size(); ++s)
  {
    const Internals::Series& series = this->Internal->Inputs[s];
    vtkDataArray* time = vtkDataArray::SafeDownCast(series.Table->GetColumnByName(timeName));
    if (!time)
    {
      vtkErrorMacro("Input " << s << (series.Label.empty() ? "" : " (" + series.Label + ")")
                             << " has no numeric column '" << timeName << "'.");
      return -1;
    }
    for (size_t c = 0; c < this->Internal->Columns.size(); ++c)
    {
      const auto& column = this->Internal->Columns[c];
      vtkDataArray* values =
        vtkDataArray::SafeDownCast(series.Table->GetColumnByName(column.first.c_str()));
      if (!values)
      {
        continue; // an optional column: histories may omit the error columns
      }
      // Log axes need positive values: plot |v| (the energy balance has a
      // sign) and drop NaN (no reference known), infinities and zeros.
      vtkNew<vtkDoubleArray> x;
      x->SetName(timeName);
      vtkNew<vtkDoubleArray> y;
      std::string label = column.second;
      if (!series.Label.empty())
      {
        label += ", " + series.Label;
      }
      y->SetName(label.c_str());
      const vtkIdType n = std::min(time->GetNumberOfTuples(), values->GetNumberOfTuples());
      // Values below 1e-12 of the column's largest are rounding noise (an
      // energy balance of 1e-16 at the first iteration): they would only
      // stretch the log axis.
      double largest = 0.0;
      for (vtkIdType i = 0; i < n; ++i)
      {
        const double v = std::abs(values->GetComponent(i, 0));
        largest = std::isfinite(v) ? std::max(largest, v) : largest;
      }
      for (vtkIdType i = 0; i < n; ++i)
      {
        const double t = time->GetComponent(i, 0);
        const double v = std::abs(values->GetComponent(i, 0));
        if (std::isfinite(t) && std::isfinite(v) && v > 1e-12 * largest &&
          (!this->LogTime || t > 0.0))
        {
          x->InsertNextValue(t);
          y->InsertNextValue(v);
        }
      }
      if (y->GetNumberOfTuples() == 0)
      {
        continue;
      }
      vtkNew<vtkTable> table;
      table->AddColumn(x);
      table->AddColumn(y);
      vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
      plot->SetInputData(table, 0, 1);
      plot->SetLabel(label);
      const unsigned char* rgb = Palette[c % PaletteSize];
      plot->SetColor(rgb[0], rgb[1], rgb[2], 255);
      plot->SetWidth(2.0f);
      plot->GetPen()->SetLineType(PenStyles[s % PenStylesSize]);
      // Past the five line styles the series repeat one: markers tell them apart.
      if (s >= static_cast<size_t>(PenStylesSize))
      {
        if (auto* points = vtkPlotPoints::SafeDownCast(plot))
        {
          points->SetMarkerStyle(Markers[(s / PenStylesSize - 1) % MarkersSize]);
          points->SetMarkerSize(6.0f);
        }
      }
      ++lines;
    }
  }
  return lines;
}

//------------------------------------------------------------------------------
bool vtkRadiosityConvergenceChart::Render(int width, int height)
{
  this->Internal->NumberOfLines = 0;
  if (this->Internal->Inputs.empty())
  {
    vtkErrorMacro("No convergence history: call SetInputData first.");
    return false;
  }
  const int lines = this->BuildPlots();
  if (lines < 0)
  {
    return false;
  }
  if (lines == 0)
  {
    vtkErrorMacro("Nothing to plot: no chosen column has a finite non-zero value.");
    return false;
  }
  this->Internal->NumberOfLines = lines;
  vtkRenderWindow* window = this->Internal->View->GetRenderWindow();
  std::string why;
  if (!vtkRadiosityCanOpenWindow(window, why))
  {
    vtkErrorMacro(<< why);
    return false;
  }
  window->SetSize(std::min(std::max(width, 16), 16384), std::min(std::max(height, 16), 16384));
  this->Internal->Chart->RecalculateBounds();
  this->Internal->View->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkRadiosityConvergenceChart::WritePNG(const char* fileName, int width, int height)
{
  if (!fileName || !*fileName)
  {
    vtkErrorMacro("No file name given for the PNG image.");
    return false;
  }
  if (!this->Render(width, height))
  {
    return false;
  }
  std::string error;
  if (!vtkRadiosityWriteWindowPNG(this->GetRenderWindow(), fileName, error))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkRadiosityConvergenceChart::GetNumberOfLines() const
{
  return this->Internal->NumberOfLines;
}

//------------------------------------------------------------------------------
vtkChartXY* vtkRadiosityConvergenceChart::GetChart()
{
  return this->Internal->Chart;
}

//------------------------------------------------------------------------------
vtkContextView* vtkRadiosityConvergenceChart::GetContextView()
{
  return this->Internal->View;
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkRadiosityConvergenceChart::GetRenderWindow()
{
  return this->Internal->View->GetRenderWindow();
}

//------------------------------------------------------------------------------
void vtkRadiosityConvergenceChart::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TimeColumn: " << (this->TimeColumn ? this->TimeColumn : "(none)") << "\n";
  os << indent << "Title: " << (this->Title ? this->Title : "(none)") << "\n";
  os << indent << "LogTime: " << (this->LogTime ? "On" : "Off") << "\n";
  os << indent << "Inputs: " << this->Internal->Inputs.size() << "\n";
  for (const auto& series : this->Internal->Inputs)
  {
    os << indent.GetNextIndent() << "'" << series.Label << "': " << series.Table.GetPointer()
       << "\n";
  }
  os << indent << "Columns:\n";
  for (const auto& column : this->Internal->Columns)
  {
    os << indent.GetNextIndent() << column.first << " (" << column.second << ")\n";
  }
  os << indent << "NumberOfLines: " << this->Internal->NumberOfLines << "\n";
  os << indent << "Chart: " << this->Internal->Chart.GetPointer() << "\n";
}
