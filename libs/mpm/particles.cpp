#include "mpm/particles.hpp"

namespace latmpm::mpm {

namespace {
template <class T>
void apply(std::vector<T>& v, const std::vector<uint32_t>& order) {
  std::vector<T> out(v.size());
  for (size_t i = 0; i < order.size(); ++i) out[i] = v[order[i]];
  v.swap(out);
}

template <class T>
size_t bytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}
}  // namespace

void Particles::permute(const std::vector<uint32_t>& order) {
  apply(position, order);
  apply(velocity, order);
  apply(mass, order);
  apply(volume0, order);
  for (auto& component : deformation_component) apply(component, order);
  for (auto& component : stress_component) apply(component, order);
  apply(half_size0, order);
  apply(body, order);
  apply(id, order);
  apply(flags, order);
}

void Particles::resize(size_t n) {
  position.resize(n, Vec3::Zero());
  velocity.resize(n, Vec3::Zero());
  mass.resize(n, 0);
  volume0.resize(n, 0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) deformation_component[size_t(3 * r + c)].resize(n, r == c ? Real(1) : Real(0));
  for (auto& component : stress_component) component.resize(n, 0);
  half_size0.resize(n, Vec3::Zero());
  body.resize(n, 0);
  id.resize(n, 0);
  flags.resize(n, 0);
}

size_t Particles::memory_bytes() const {
  size_t total = bytes(position) + bytes(velocity) + bytes(mass) + bytes(volume0) + bytes(half_size0) +
                 bytes(body) + bytes(id) + bytes(flags);
  for (const auto& component : deformation_component) total += bytes(component);
  for (const auto& component : stress_component) total += bytes(component);
  return total;
}

}  // namespace latmpm::mpm
