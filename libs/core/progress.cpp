#include "core/progress.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

namespace latmpm {

Progress::Progress(std::string label, double total, bool enabled, double interval_s)
    : label_(std::move(label)), total_(total), enabled_(enabled), interval_(interval_s),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

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
  double left = fraction > 0 ? elapsed * (1 - fraction) / fraction : NAN;
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
