// Closed-form form factors used as exact references (tests, and the analytic
// references of the error harness). Formulas from Howell's catalogue of
// radiation configuration factors (C-11, C-14, B-13).
#ifndef Radiosity_ClosedFormFactors_h
#define Radiosity_ClosedFormFactors_h

namespace radiosity
{
namespace closedform
{
/// Area-to-area: directly opposed parallel rectangles a x b at distance c (Howell C-11).
double ParallelRectangles(double a, double b, double c);

/// Area-to-area: rectangles with a common edge of length l, at 90 degrees,
/// widths w (emitter) and h (receiver): from the w x l rectangle to the h x l one (Howell C-14).
double PerpendicularRectangles(double l, double w, double h);

/// Differential element to a coaxial parallel disc of radius r at distance h (Howell B-13).
double PointToCoaxialDisc(double r, double h);

/// Differential element to a parallel rectangle a x b with one corner above the
/// element, at distance c (Howell B-3).
double PointToParallelRectangleCorner(double a, double b, double c);
} // namespace closedform
} // namespace radiosity

#endif
