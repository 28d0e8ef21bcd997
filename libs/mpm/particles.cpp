#include "mpm/particles.hpp"

#include "mpm/particle_fields.hpp"

namespace latmpm::mpm {

void Particles::permute(const std::vector<uint32_t>& order) {
  for_each_particle_field(*this, [&](const ParticleField& field, auto& v, const auto&) {
    if (field.optional && v.empty()) return;
    std::remove_reference_t<decltype(v)> out(v.size());
    for (size_t i = 0; i < order.size(); ++i) out[i] = v[order[i]];
    v.swap(out);
  });
}

void Particles::resize(size_t n) {
  for_each_particle_field(*this, [&](const ParticleField& field, auto& v, const auto& fill) {
    if (!(field.optional && v.empty())) v.resize(n, fill);
  });
}

const HistoryColumn* Particles::history_column(const std::string& name) const {
  for (const auto& c : history)
    if (c.name == name) return &c;
  return nullptr;
}

size_t particle_memory_bytes(const Particles& ps) {
  size_t bytes = 0;
  for_each_particle_field(ps, [&](const ParticleField&, const auto& v, const auto&) {
    bytes += v.capacity() * sizeof(v[0]);
  });
  return bytes;
}

}  // namespace latmpm::mpm
