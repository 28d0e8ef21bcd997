// Metrics of an impact run with a free rigid flyer (paper A Sec. 6: a 10 kg flyer at 2 m/s),
// read from the series columns flyer_velocity, flyer_kinetic_energy and flyer_potential_energy
// (docs/post.md says what happens when they are absent):
//   peak load        largest load of the series and its time
//   reversal time    first time the flyer's velocity along its initial direction of motion
//                    falls to zero (linear interpolation between rows)
//   rebound speed    largest speed against the initial direction after the reversal
//   energy absorbed  E(0) − E(end), E = kinetic + potential energy of the flyer; also
//                    E(0) − E(t_reversal), the most the specimen took
// The initial direction of motion is the sign of the first non-zero velocity, so the metrics
// hold whichever sign convention the series uses.
#pragma once
#include <limits>
#include <string>
#include <vector>

namespace latmpm::post {

struct ImpactHistory {
  std::vector<double> time, load;                        // s, N
  std::vector<double> velocity;                          // m/s, flyer, along the loading axis
  std::vector<double> kinetic_energy, potential_energy;  // J; either may be empty (absent)
};

struct ImpactMetrics {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double peak_load = none, peak_time = none;
  double impact_speed = none;   // |v| at the first row
  double reversal_time = none;  // s
  double rebound_speed = none;  // m/s
  double energy_absorbed = none, energy_absorbed_at_reversal = none;  // J
  double final_time = none;
  std::vector<std::string> notes;
};

ImpactMetrics impact_metrics(const ImpactHistory& history);

}  // namespace latmpm::post
