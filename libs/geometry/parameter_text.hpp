// Values for StrutGraph::parameters: SI numbers with their unit, precise enough to be read
// back by parse_quantity ("0.00933333333 m", "0.523598776 rad").
#pragma once
#include <cstdio>
#include <string>

namespace latmpm {

inline std::string quantity_text(double si_value, const char* unit) {
  char text[64];
  std::snprintf(text, sizeof text, "%.12g %s", si_value, unit);
  return text;
}

}  // namespace latmpm
