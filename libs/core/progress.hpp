// Progress of long work on stderr: percent done, rate, and an estimate of the time left.
// Prints at most once per `interval_s`; quiet when `enabled` is false (--quiet).
#pragma once
#include <chrono>
#include <string>

namespace latmpm {

class Progress {
 public:
  Progress(std::string label, double total, bool enabled = true, double interval_s = 2.0);
  // `done` in the same units as total; `detail` is appended (e.g. "step 120, 3.1e6 upd/s").
  void update(double done, const std::string& detail = "");
  void finish(const std::string& detail = "");
  double elapsed_seconds() const;

 private:
  std::string label_;
  double total_;
  bool enabled_;
  double interval_;
  std::chrono::steady_clock::time_point start_, last_;
};

// "1h02m", "3m05s", "12.3s"
std::string format_duration(double seconds);

}  // namespace latmpm
