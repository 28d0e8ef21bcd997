#include "post/curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace latmpm::post {

double trapezoid(const Curve& c) {
  double sum = 0;
  for (size_t i = 1; i < c.size(); ++i) sum += 0.5 * (c.y[i] + c.y[i - 1]) * (c.x[i] - c.x[i - 1]);
  return sum;
}

std::vector<double> cumulative_trapezoid(const Curve& c) {
  std::vector<double> out(c.size(), 0.0);
  for (size_t i = 1; i < c.size(); ++i)
    out[i] = out[i - 1] + 0.5 * (c.y[i] + c.y[i - 1]) * (c.x[i] - c.x[i - 1]);
  return out;
}

double interpolate(const Curve& c, double x) {
  if (c.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (x <= c.x.front()) return c.y.front();
  if (x >= c.x.back()) return c.y.back();
  const size_t hi = size_t(std::upper_bound(c.x.begin(), c.x.end(), x) - c.x.begin());
  const size_t lo = hi - 1;
  const double span = c.x[hi] - c.x[lo];
  if (span <= 0) return c.y[hi];
  const double w = (x - c.x[lo]) / span;
  return (1 - w) * c.y[lo] + w * c.y[hi];
}

size_t argmax(const std::vector<double>& y) {
  return size_t(std::max_element(y.begin(), y.end()) - y.begin());
}

double fitted_slope(const Curve& c, double x0, double x1) {
  double n = 0, sx = 0, sy = 0;
  for (size_t i = 0; i < c.size(); ++i)
    if (c.x[i] >= x0 && c.x[i] <= x1) n += 1, sx += c.x[i], sy += c.y[i];
  if (n < 2) return std::numeric_limits<double>::quiet_NaN();
  const double mx = sx / n, my = sy / n;
  double sxx = 0, sxy = 0;
  for (size_t i = 0; i < c.size(); ++i)
    if (c.x[i] >= x0 && c.x[i] <= x1) {
      sxx += (c.x[i] - mx) * (c.x[i] - mx);
      sxy += (c.x[i] - mx) * (c.y[i] - my);
    }
  if (sxx <= 0) return std::numeric_limits<double>::quiet_NaN();
  return sxy / sxx;
}

double interval_mean(const Curve& c, double x0, double x1) {
  if (c.empty() || !(x1 > x0)) return std::numeric_limits<double>::quiet_NaN();
  // The interpolated curve restricted to [x0, x1], integrated exactly (piecewise linear).
  Curve part;
  part.x.push_back(x0), part.y.push_back(interpolate(c, x0));
  for (size_t i = 0; i < c.size(); ++i)
    if (c.x[i] > x0 && c.x[i] < x1) part.x.push_back(c.x[i]), part.y.push_back(c.y[i]);
  part.x.push_back(x1), part.y.push_back(interpolate(c, x1));
  return trapezoid(part) / (x1 - x0);
}

Curve bin_average(const Curve& c, double x0, double x1, double step) {
  Curve out;
  if (c.empty() || !(step > 0) || !(x1 > x0)) return out;
  const size_t bins = size_t(std::ceil((x1 - x0) / step - 1e-9));
  std::vector<double> sum(bins, 0.0);
  std::vector<int> count(bins, 0);
  for (size_t i = 0; i < c.size(); ++i) {
    if (c.x[i] < x0 || c.x[i] > x1) continue;
    const size_t k = std::min(bins - 1, size_t((c.x[i] - x0) / step));
    sum[k] += c.y[i], count[k] += 1;
  }
  for (size_t k = 0; k < bins; ++k) {
    const double centre = x0 + (double(k) + 0.5) * step;
    out.x.push_back(centre);
    out.y.push_back(count[k] > 0 ? sum[k] / count[k] : interpolate(c, centre));
  }
  return out;
}

Curve monotone_prefix(const Curve& c, double tolerance) {
  Curve out;
  double top = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < c.size(); ++i) {
    if (c.x[i] < top - tolerance) break;
    if (c.x[i] >= top) {
      out.x.push_back(c.x[i]), out.y.push_back(c.y[i]);
      top = c.x[i];
    }
  }
  return out;
}

}  // namespace latmpm::post
