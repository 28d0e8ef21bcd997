// Wall and CPU seconds spent in one phase of a static solve (set-up, assembly, analysis,
// factorisation, solve, stability check, output), summed over its calls: the run log prints
// them so that a slow solve says where its seconds go (docs/statics.md, "Where the seconds
// go"). CPU is the process's (std::clock: all threads, user and system), so on a loaded
// machine it is the steadier figure and wall − CPU is the time spent waiting for a core.
#pragma once
#include <chrono>
#include <ctime>
#include <string>

#include "core/number_text.hpp"

namespace latmpm::statics {

struct PhaseTime {
  double wall = 0;  // s
  double cpu = 0;   // s, all threads of the process
  int calls = 0;
  PhaseTime& operator+=(const PhaseTime& o) {
    wall += o.wall, cpu += o.cpu, calls += o.calls;
    return *this;
  }
};

// Adds the time from its construction to its destruction to `into`.
class PhaseTimer {
 public:
  explicit PhaseTimer(PhaseTime& into) : into_(into) {}
  ~PhaseTimer() {
    into_.wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count();
    into_.cpu += double(std::clock() - cpu_) / CLOCKS_PER_SEC;
    ++into_.calls;
  }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  PhaseTime& into_;
  std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
  std::clock_t cpu_ = std::clock();
};

// "name 12.3/20.1 s (2×)": wall/CPU seconds and the number of calls where more than one.
inline std::string describe(const std::string& name, const PhaseTime& t) {
  return name + " " + format_number("%.1f", t.wall) + "/" + format_number("%.1f", t.cpu) + " s" +
         (t.calls > 1 ? " (" + std::to_string(t.calls) + "×)" : "");
}

}  // namespace latmpm::statics
