#include "core/progress.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace latmpm {

double estimate_time_left(double elapsed, double done_at_start, double done, double total) {
  const double progress = done - done_at_start;
  return progress > 0 ? elapsed * (total - done) / progress : NAN;
}

Progress::Progress(std::string label, double total, bool enabled, double interval_s, double done_at_start)
    : label_(std::move(label)), total_(total), done_at_start_(done_at_start), enabled_(enabled),
      interval_(interval_s), start_(std::chrono::steady_clock::now()), last_(start_) {}

double Progress::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string format_duration(double s) {
  char buf[32];
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 60) {
    std::snprintf(buf, sizeof buf, "%.1fs", s);
  } else if (s < 3600) {
    std::snprintf(buf, sizeof buf, "%dm%02ds", int(s / 60), int(s) % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%dh%02dm", int(s / 3600), (int(s) % 3600) / 60);
  }
  return buf;
}

void Progress::update(double done, const std::string& detail) {
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_) return;
  last_ = now;
  double elapsed = elapsed_seconds();
  double fraction = total_ > 0 ? done / total_ : 0;
  double left = estimate_time_left(elapsed, done_at_start_, done, total_);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%5.1f%%", 100 * fraction);
  std::cerr << label_ << ": " << buf << ", elapsed " << format_duration(elapsed) << ", left ~"
            << format_duration(left) << (detail.empty() ? "" : ", " + detail) << "\n";
}

void Progress::finish(const std::string& detail) {
  if (!enabled_) return;
  std::cerr << label_ << ": done in " << format_duration(elapsed_seconds())
            << (detail.empty() ? "" : ", " + detail) << "\n";
}

}  // namespace latmpm
