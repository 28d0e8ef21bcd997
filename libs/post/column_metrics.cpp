#include "post/column_metrics.hpp"

#include <cmath>

#include "post/curve.hpp"

namespace latmpm::post {

double euler_load(double youngs_modulus, double diameter, double length, double k) {
  const double pi = M_PI;
  const double second_moment = pi * std::pow(diameter, 4) / 64;
  return pi * pi * youngs_modulus * second_moment / ((k * length) * (k * length));
}

ColumnMetrics column_metrics(const LoadHistory& h, double youngs_modulus, double diameter, double length,
                             double k) {
  ColumnMetrics m;
  m.k = k;
  const Curve curve = monotone_prefix(Curve{h.displacement, h.load});
  if (curve.size() >= 2 && curve.x.back() > curve.x.front()) {
    m.peak_load = curve.y[argmax(curve.y)];
    m.post_buckling_load = interval_mean(curve, curve.x.front() + 0.75 * (curve.x.back() - curve.x.front()), curve.x.back());
  } else {
    m.notes.push_back("column: fewer than two rows of increasing travel");
  }
  if (!(std::isfinite(youngs_modulus) && std::isfinite(diameter) && std::isfinite(length))) {
    m.notes.push_back("Euler load: E, strut_diameter or strut_length unknown");
    return m;
  }
  m.euler_load = euler_load(youngs_modulus, diameter, length, k);
  m.peak_ratio = m.peak_load / m.euler_load;
  m.post_buckling_ratio = m.post_buckling_load / m.euler_load;
  return m;
}

}  // namespace latmpm::post
