// The particle state a snapshot shows, independent of the solver's own storage: points in
// their original PointSet order (the solver re-sorts its particles), so point i is the same
// material point in every snapshot and ParaView can follow it.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace latmpm {

struct ParticleSnapshot {
  int64_t step = 0;
  double time = 0;  // s
  std::vector<double> position;   // N×3, m
  std::vector<float> velocity;    // N×3, m/s
  // N×6 Cauchy stress, Pa, in XDMF "Tensor6" order: xx, xy, xz, yy, yz, zz.
  std::vector<float> stress;
  std::vector<float> von_mises;   // N, Pa
  std::vector<float> jacobian;    // N, J = det F
  std::vector<int32_t> body;      // N, index into body_names
  std::vector<std::string> body_names;
  // Further per-point scalars by name (the solver's material history columns), N each.
  struct Scalar {
    std::string name;
    std::vector<float> values;
  };
  std::vector<Scalar> extra_scalars;

  size_t size() const { return body.size(); }
  // Sizes the arrays for n points.
  void resize(size_t n);
};

}  // namespace latmpm
