// Progress of long work on stderr: percent done, rate, and an estimate of the time left.
// Prints at most once per `interval_s`; quiet when `enabled` is false (--quiet).
#pragma once
#include <chrono>
#include <string>

namespace latmpm {

// Seconds left of work at `done` of `total`, `elapsed` seconds after it stood at
// `done_at_start` (a resumed run starts part-way): the rate of this part, extrapolated. NaN
// until this part has made progress.
double estimate_time_left(double elapsed, double done_at_start, double done, double total);

class Progress {
 public:
  // `done_at_start`: how much of `total` was done before (a resumed run), in the same units.
  Progress(std::string label, double total, bool enabled = true, double interval_s = 2.0, double done_at_start = 0);
  // `done` in the same units as total; `detail` is appended (e.g. "step 120, 3.1e6 upd/s").
  void update(double done, const std::string& detail = "");
  void finish(const std::string& detail = "");
  double elapsed_seconds() const;

 private:
  std::string label_;
  double total_;
  double done_at_start_;
  bool enabled_;
  double interval_;
  std::chrono::steady_clock::time_point start_, last_;
};

// "1h02m", "3m05s", "12.3s"
std::string format_duration(double seconds);

}  // namespace latmpm
