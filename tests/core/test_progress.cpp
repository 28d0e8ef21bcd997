#include <catch2/catch.hpp>

#include <cmath>

#include "core/progress.hpp"

using namespace latmpm;

TEST_CASE("The time left extrapolates the rate of the current part of the work", "[core][progress]") {
  // A fresh run: 25 % in 10 s leaves 30 s at the same rate.
  CHECK(estimate_time_left(10, 0, 25, 100) == Approx(30));
  // A run resumed at 50 %: 10 s for the next 10 % leaves 40 s, not the 10 s that 60 % done
  // in 10 s would suggest.
  CHECK(estimate_time_left(10, 50, 60, 100) == Approx(40));
  // Units of the work do not matter (simulated time here), only its fractions.
  CHECK(estimate_time_left(10, 0.0125, 0.015, 0.025) == Approx(40));
  // Finished: nothing left. No progress in this part yet: unknown, shown as "?".
  CHECK(estimate_time_left(10, 0, 100, 100) == 0);
  CHECK(std::isnan(estimate_time_left(10, 50, 50, 100)));
  CHECK(format_duration(estimate_time_left(10, 50, 50, 100)) == "?");
}

TEST_CASE("Durations read as seconds, minutes or hours", "[core][progress]") {
  CHECK(format_duration(12.34) == "12.3s");
  CHECK(format_duration(185) == "3m05s");
  CHECK(format_duration(3720) == "1h02m");
}
