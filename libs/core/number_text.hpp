// A number as text with a printf format ("%.3g"): for log lines and summaries, where a
// stream's state would leak between fields. One value per call; the result is at most 63
// characters (longer output is cut).
#pragma once
#include <cstdio>
#include <string>

namespace latmpm {

inline std::string format_number(const char* fmt, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, value);
  return buf;
}

}  // namespace latmpm
