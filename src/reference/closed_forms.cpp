#include "reference/closed_forms.hpp"

#include <cmath>

namespace physics::reference {

double bounce_apex(double h, double e, int n) { return h * std::pow(e, 2 * n); }

double bounce_impact_time(double h, double g, double e, int n) {
  const double t0 = std::sqrt(2.0 * h / g);
  double t = t0, flight = 2.0 * t0;
  for (int k = 1; k <= n; ++k) {
    flight *= e;
    t += flight;
  }
  return t;
}

double bounce_rest_time(double h, double g, double e) {
  return std::sqrt(2.0 * h / g) * (1.0 + e) / (1.0 - e);
}

std::pair<double, double> two_body(double m1, double v1, double m2, double v2, double e) {
  const double p = m1 * v1 + m2 * v2, m = m1 + m2;
  return {(p + m2 * e * (v2 - v1)) / m, (p + m1 * e * (v1 - v2)) / m};
}

std::vector<double> cradle(int n, double v) {
  std::vector<double> out(static_cast<std::size_t>(n), 0.0);
  if (n > 0) out.back() = v;
  return out;
}

}  // namespace physics::reference
