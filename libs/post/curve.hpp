// Sampled curves y(x) and the numerical operations the metrics are built from: trapezoid
// integrals, interpolation, least-squares slopes and resampling by bin averages. Plain
// functions over two equally long vectors; nothing here knows about runs or units.
#pragma once
#include <cstddef>
#include <vector>

namespace latmpm::post {

struct Curve {
  std::vector<double> x, y;
  std::size_t size() const { return x.size(); }
  bool empty() const { return x.empty(); }
};

// ∫ y dx by the trapezoid rule over the whole curve (x need not be monotonic: a reversal
// subtracts, as work done while unloading does).
double trapezoid(const Curve& c);
// Running trapezoid integral: result[i] = ∫ from x[0] to x[i].
std::vector<double> cumulative_trapezoid(const Curve& c);

// y at x by linear interpolation; x must be ascending. Outside the range: the end values.
double interpolate(const Curve& c, double x);

// Index of the largest y (the first one if tied); the curve must not be empty.
std::size_t argmax(const std::vector<double>& y);

// Least-squares slope of y over the points with x in [x0, x1] (ordinary linear regression).
// Returns NaN with fewer than two points or no spread in x.
double fitted_slope(const Curve& c, double x0, double x1);

// Mean of y over x in [x0, x1], as ∫ y dx / (x1 − x0) on the interpolated curve (so uneven
// sampling does not bias it). x must be ascending and cover [x0, x1].
double interval_mean(const Curve& c, double x0, double x1);

// The curve on an even grid x = x0 + (k + ½)·step: each new point is the mean of the samples
// whose x falls in its bin [x0 + k·step, x0 + (k+1)·step); empty bins are interpolated.
// Averaging in bins removes the solver's step-to-step oscillation without shifting features
// by more than one bin (ISO 13314 evaluates at fixed strain intervals, e.g. 0.1 %).
Curve bin_average(const Curve& c, double x0, double x1, double step);

// The leading part of a curve on which x never decreases by more than `tolerance` from its
// running maximum; samples that go back are dropped (e.g. a plate that springs back).
Curve monotone_prefix(const Curve& c, double tolerance = 0.0);

}  // namespace latmpm::post
