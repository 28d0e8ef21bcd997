// Per-particle history of a material model, declared once by the model: J2 plasticity's
// plastic strain and hardening variable, a damage variable. A model with history lists its
// variables in a static member
//   static constexpr std::array<HistoryVariable, K> history = {{{"name", initial}, ...}};
// and takes them in its updates as one T per variable:
//   update_stress(const Deformation<T>&, Stress<T>&, T* history) const
//   strain_energy_density(const Deformation<T>&, const Stress<T>&, const T* history) const
// Models without history keep the two-argument forms. The solver stores each variable as a
// particle column (Particles::history, structure of arrays) that the field registry
// (particle_fields.hpp) sorts, checkpoints and restores with the other fields.
#pragma once
#include <array>
#include <type_traits>
#include <vector>

#include "core/errors.hpp"
#include "mpm/deformation.hpp"
#include "mpm/particles.hpp"

namespace latmpm::mpm {

struct HistoryVariable {
  const char* name;  // unique across the models of a run; a particle column's name
  Real initial;      // value at the start of a run
  // The model derives it from a point's deformation and stress (history_from_state, below)
  // at the start of a run, and where a checkpoint lacks the column (written before the
  // variable existed); otherwise such a checkpoint is refused.
  bool derived = false;
};

template <class Model, class = void>
struct material_history {
  static constexpr std::array<HistoryVariable, 0> variables{};
};
template <class Model>
struct material_history<Model, std::void_t<decltype(Model::history)>> {
  static constexpr auto variables = Model::history;
};
template <class Model>
inline constexpr size_t history_size = material_history<Model>::variables.size();

// The model's stress update with its history (one T per variable) when it has one.
template <class Model, class T>
inline void update_material_stress(const Model& model, const Deformation<T>& d, Stress<T>& s, T* history) {
  if constexpr (history_size<Model> > 0)
    model.update_stress(d, s, history);
  else
    model.update_stress(d, s);
}

template <class Model, class T>
inline T material_energy_density(const Model& model, const Deformation<T>& d, const Stress<T>& s, const T* history) {
  if constexpr (history_size<Model> > 0)
    return model.strain_energy_density(d, s, history);
  else
    return model.strain_energy_density(d, s);
}

// Energy the model has dissipated per reference volume, J/m³: the history variable a
// dissipative model names with `static constexpr size_t dissipation_history = k;` (J2's
// accumulated plastic work), zero for the others. The energy balance counts V0 times it.
template <class Model, class = void>
struct has_dissipation_history : std::false_type {};
template <class Model>
struct has_dissipation_history<Model, std::void_t<decltype(Model::dissipation_history)>> : std::true_type {};

template <class Model, class T>
inline T material_dissipation_density(const Model&, const T* history) {
  if constexpr (has_dissipation_history<Model>::value)
    return history[Model::dissipation_history];
  else
    return T{};
}

// A model whose `derived` variables follow from a point's state provides
//   void history_from_state(const Deformation<Real>&, const Stress<Real>&, Real* history) const
// which sets those (linear elastic's stress work from the complementary energy).
template <class Model, class = void>
struct derives_history : std::false_type {};
template <class Model>
struct derives_history<Model, std::void_t<decltype(&Model::history_from_state)>> : std::true_type {};

// Adds a column for each of the model's history variables to ps (one column per name:
// two bodies of one model share them) and returns their indices in Particles::history, in
// the model's order. Call before Particles::resize; the columns are sized with the others.
template <class Model>
std::vector<uint32_t> declare_history(Particles& ps) {
  std::vector<uint32_t> columns;
  for (const HistoryVariable& v : material_history<Model>::variables) {
    uint32_t k = 0;
    while (k < ps.history.size() && ps.history[k].name != v.name) ++k;
    if (k == ps.history.size()) ps.history.push_back({v.name, v.initial, std::vector<Real>(ps.size(), v.initial), v.derived});
    columns.push_back(k);
  }
  return columns;
}

}  // namespace latmpm::mpm
