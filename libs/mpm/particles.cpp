#include "mpm/particles.hpp"

namespace latmpm::mpm {

namespace {
template <class T>
void apply(std::vector<T>& v, const std::vector<uint32_t>& order) {
  std::vector<T> out(v.size());
  for (size_t i = 0; i < order.size(); ++i) out[i] = v[order[i]];
  v.swap(out);
}
}  // namespace

void Particles::permute(const std::vector<uint32_t>& order) {
  apply(position, order);
  apply(velocity, order);
  apply(mass, order);
  apply(volume0, order);
  apply(deformation, order);
  apply(stress, order);
  apply(half_size0, order);
  apply(body, order);
  apply(id, order);
  apply(flags, order);
  if (!contact_body.empty()) apply(contact_body, order), apply(contact_anchor, order);
}

void Particles::resize(size_t n) {
  position.resize(n, Vec3::Zero());
  velocity.resize(n, Vec3::Zero());
  mass.resize(n, 0);
  volume0.resize(n, 0);
  deformation.resize(n, Mat3::Identity());
  stress.resize(n, SymTensor::Zero());
  half_size0.resize(n, Vec3::Zero());
  body.resize(n, 0);
  id.resize(n, 0);
  flags.resize(n, 0);
  if (!contact_body.empty()) contact_body.resize(n, -1), contact_anchor.resize(n, Vec3::Zero());
}

}  // namespace latmpm::mpm
