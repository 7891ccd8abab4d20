#include "Radiosity/Common/ClosedFormFactors.h"
#include "Radiosity/Common/Types.h" // radiosity::Pi

#include <cmath>

namespace radiosity
{
namespace closedform
{
double ParallelRectangles(double a, double b, double c)
{
  const double X = a / c;
  const double Y = b / c;
  const double X2 = X * X;
  const double Y2 = Y * Y;
  const double s1 = std::log(std::sqrt((1 + X2) * (1 + Y2) / (1 + X2 + Y2)));
  const double s2 = X * std::sqrt(1 + Y2) * std::atan(X / std::sqrt(1 + Y2));
  const double s3 = Y * std::sqrt(1 + X2) * std::atan(Y / std::sqrt(1 + X2));
  const double s4 = -X * std::atan(X) - Y * std::atan(Y);
  return 2.0 / (Pi * X * Y) * (s1 + s2 + s3 + s4);
}

double PerpendicularRectangles(double l, double w, double h)
{
  const double H = h / l;
  const double W = w / l;
  const double H2 = H * H;
  const double W2 = W * W;
  const double R = std::sqrt(H2 + W2);
  const double t1 = W * std::atan(1 / W) + H * std::atan(1 / H) - R * std::atan(1 / R);
  const double a = (1 + W2) * (1 + H2) / (1 + W2 + H2);
  const double b = W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2));
  const double c = H2 * (1 + H2 + W2) / ((1 + H2) * (H2 + W2));
  const double t2 = 0.25 * std::log(a * std::pow(b, W2) * std::pow(c, H2));
  return (t1 + t2) / (Pi * W);
}

double PointToCoaxialDisc(double r, double h)
{
  return r * r / (r * r + h * h);
}

double PointToParallelRectangleCorner(double a, double b, double c)
{
  const double A = a / c;
  const double B = b / c;
  const double sa = std::sqrt(1 + A * A);
  const double sb = std::sqrt(1 + B * B);
  return 1.0 / (2 * Pi) * (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb));
}
} // namespace closedform
} // namespace radiosity
