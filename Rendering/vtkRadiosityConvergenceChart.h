/**
 * @class   vtkRadiosityConvergenceChart
 * @brief   Plots convergence histories: error and unshot power against run time.
 *
 * Input: one or more tables with the columns of SPEC.md's ConvergenceHistory
 * (`iteration, time_s, unshot_power_W, energy_balance, rms_error,
 * max_rel_error`; extra columns are ignored unless chosen with AddColumn).
 * Each table is a series (for instance "with acceleration" and "without"):
 * each chosen column of each series is one line, its colour given by the
 * column and its dash pattern by the series.
 *
 * The x axis is the run time in seconds (log scale when LogTime is on), the y
 * axis is a log scale, so the absolute value of each entry is plotted (the
 * energy balance has a sign) and points that are NaN, infinite or zero are
 * dropped. A column with no point left (for instance the error columns, all
 * NaN when no reference is known) draws no line and no legend entry.
 *
 * Drawn offscreen by VTK's charts (vtkContextView + vtkChartXY).
 */

#ifndef vtkRadiosityConvergenceChart_h
#define vtkRadiosityConvergenceChart_h

#include "RadiosityRenderingModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For the internals

class vtkChartXY;
class vtkContextView;
class vtkRenderWindow;
class vtkTable;

class RADIOSITYRENDERING_EXPORT vtkRadiosityConvergenceChart : public vtkObject
{
public:
  static vtkRadiosityConvergenceChart* New();
  vtkTypeMacro(vtkRadiosityConvergenceChart, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * SetInputData replaces all series by one unlabelled series;
   * AddInputData appends a series whose label is added to its legend entries.
   */
  void SetInputData(vtkTable* history);
  void AddInputData(vtkTable* history, const char* label);
  void RemoveAllInputs();
  int GetNumberOfInputs() const;
  ///@}

  ///@{
  /**
   * The columns plotted, with their legend labels. By default unshot_power_W,
   * energy_balance, rms_error and max_rel_error.
   */
  void AddColumn(const char* name, const char* label);
  void RemoveAllColumns();
  int GetNumberOfColumns() const;
  ///@}

  ///@{
  /**
   * Name of the x column (default "time_s").
   */
  vtkSetStringMacro(TimeColumn);
  vtkGetStringMacro(TimeColumn);
  ///@}

  ///@{
  /**
   * Chart title (default "Convergence").
   */
  vtkSetStringMacro(Title);
  vtkGetStringMacro(Title);
  ///@}

  ///@{
  /**
   * Whether the time axis is a log scale too (default off); non-positive
   * times are then dropped.
   */
  vtkSetMacro(LogTime, bool);
  vtkGetMacro(LogTime, bool);
  vtkBooleanMacro(LogTime, bool);
  ///@}

  /**
   * Builds the chart and renders it at width x height pixels (each clamped to
   * [16, 16384]). Returns false with an error when an input lacks the time
   * column or when no line is left to draw.
   */
  bool Render(int width, int height);

  /**
   * Render, then write the image as PNG. False with an error on failure.
   */
  bool WritePNG(const char* fileName, int width, int height);

  /**
   * Number of lines drawn by the last Render.
   */
  int GetNumberOfLines() const;

  ///@{
  /**
   * The chart, its view and window (for styling and image regression tests).
   */
  vtkChartXY* GetChart();
  vtkContextView* GetContextView();
  vtkRenderWindow* GetRenderWindow();
  ///@}

protected:
  vtkRadiosityConvergenceChart();
  ~vtkRadiosityConvergenceChart() override;

  /// Rebuilds the plots from the inputs; returns the number of lines.
  int BuildPlots();

  char* TimeColumn = nullptr;
  char* Title = nullptr;
  bool LogTime = false;

private:
  vtkRadiosityConvergenceChart(const vtkRadiosityConvergenceChart&) = delete;
  void operator=(const vtkRadiosityConvergenceChart&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
