// Reproducible random numbers for the statistical defects: the same --seed gives the same
// file on every platform and standard library. std::mt19937_64's output sequence is fixed by
// the C++ standard, but std::normal_distribution and std::uniform_real_distribution are not,
// so the conversions to uniform and normal variates are written out here.
#pragma once
#include <cstdint>
#include <random>

namespace latmpm {

class RandomStream {
 public:
  // `stream` separates independent uses of one seed (one per defect step), so adding a step
  // does not change the numbers another step draws.
  RandomStream(uint64_t seed, uint64_t stream);

  double uniform();   // in [0, 1), 53 random bits
  double normal();    // standard normal (Box–Muller: a fixed number of draws per variate)
  // Uniform integer in [0, n) without modulo bias.
  uint64_t below(uint64_t n);

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0;
};

}  // namespace latmpm
