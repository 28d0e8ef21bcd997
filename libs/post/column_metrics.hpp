// Buckling of a column against Euler's load (paper A Sec. 4, REFERENCE.md):
//   P_E = π² E I / (K L)²,  I = π t⁴ / 64  (solid circular section of diameter t)
// K is the effective-length factor of the end conditions: 0.5 clamped–clamped, 0.7
// clamped–pinned, 1 pinned–pinned, 2 clamped–free. The column scenes (fixed base plate,
// driven top plate, both holding every grid node the column's ends touch) are clamped–clamped.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "post/compression_metrics.hpp"

namespace latmpm::post {

inline constexpr double clamped_clamped_k = 0.5;

// N; E in Pa, diameter and length in m.
double euler_load(double youngs_modulus, double diameter, double length, double k);

struct ColumnMetrics {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double euler_load = none, k = none;
  double peak_load = none, peak_ratio = none;  // peak / P_E
  // Mean load over the last quarter of the travel (after buckling), and its ratio to P_E
  // (computed here only: the column pipeline's summary reads it from metrics.csv).
  double post_buckling_load = none, post_buckling_ratio = none;
  std::vector<std::string> notes;
};

// `diameter` and `length` of the column (m), E (Pa); NaN ones give a note and no ratios.
ColumnMetrics column_metrics(const LoadHistory& history, double youngs_modulus, double diameter,
                             double length, double k = clamped_clamped_k);

}  // namespace latmpm::post
