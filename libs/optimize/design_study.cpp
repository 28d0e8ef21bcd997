#include "optimize/design_study.hpp"

#include <cmath>
#include <memory>

#include "optimize/connectivity.hpp"

namespace latmpm::optimize {

Real evaluate_binary_design(const DesignGrid& grid, const std::vector<Real>& binary, const LoadCase& load_case,
                            const SimpMaterial& material, int refine) {
  const DesignGrid fine = grid.refined(refine);
  const Real s = grid.spacing();
  const Index3 n = grid.lattice();
  std::vector<Real> rho(fine.point_count());
  for (size_t q = 0; q < rho.size(); ++q) {
    // The design point whose lattice box holds the refined point.
    const Vec3 x = fine.position(q);
    Index3 l;
    for (int a = 0; a < 3; ++a) l[a] = std::min(n[a] - 1, int(std::floor(x[a] / s)));
    if (grid.planar) l[2] = 0;
    rho[q] = binary[grid.index(l)];
  }
  SimpMaterial weak = material;
  weak.weak_ratio = 1e-9;
  if (material.model == mpm::MaterialKind::linear_elastic)
    return evaluate_compliance(fine, rho, std::vector<char>(rho.size(), 1), load_case, weak).compliance;
  // Neo-Hookean: void of 1e-9 E would invert under the solid's large strains (paper C
  // Sec. 5), so only the solid points are simulated (the narrow band of the 0/1 design).
  std::vector<char> solid(rho.size());
  for (size_t q = 0; q < rho.size(); ++q) solid[q] = rho[q] > 0.5;
  return evaluate_compliance(fine, rho, solid, load_case, material).compliance;
}

MethodOutcome run_method(const OptimizeScene& scene, const std::string& method,
                         const std::function<void(const IterationRecord&)>& on_iteration) {
  MethodOutcome out;
  out.method = method;
  OptimisationSettings settings = scene.settings;
  settings.material = scene.material;
  std::unique_ptr<Parameterisation> design;
  Real binarise = 0;
  if (method == "leto") {
    if (scene.leto_volume_fraction > 0) settings.volume_fraction = scene.leto_volume_fraction;
    design = std::make_unique<LetoDesign>(scene.grid, scene.leto, settings.volume_fraction);
    binarise = scene.leto_binarise;
  } else {
    design = std::make_unique<SimpDesign>(scene.grid, scene.simp, settings.volume_fraction);
    settings.band.enabled = false;  // SIMP: weak material everywhere
    if (scene.simp_max_iterations > 0) settings.max_iterations = scene.simp_max_iterations;
    binarise = scene.simp_binarise;
  }
  out.result = optimise(scene.grid, scene.load_case, *design, settings, on_iteration);
  const auto& h = out.result.history;
  out.compliance_last = h.empty() ? 0 : h.back().compliance;
  Real seconds = 0;
  for (const auto& r : h) seconds += r.seconds;
  out.seconds_per_iteration = h.empty() ? 0 : seconds / Real(h.size());

  std::vector<Real> rho = out.result.density;
  if (method == "leto" && scene.correction_slack >= 0)
    out.corrections = correct_connectivity(scene.grid, rho, binarise, scene.correction_slack);
  out.binary.resize(rho.size());
  for (size_t q = 0; q < rho.size(); ++q) out.binary[q] = rho[q] > binarise ? 1 : 0;
  out.volume_fraction = volume_fraction(scene.grid, out.binary);
  out.components = component_count(scene.grid, out.binary, 0.5);
  out.compliance_binary = evaluate_binary_design(scene.grid, out.binary, scene.load_case, scene.material, 1);
  if (scene.evaluate_refined)
    out.compliance_refined = evaluate_binary_design(scene.grid, out.binary, scene.load_case, scene.material, scene.refine);
  if (scene.evaluate_other_model) {
    SimpMaterial other = scene.material;
    other.model = other.model == mpm::MaterialKind::linear_elastic ? mpm::MaterialKind::neo_hookean
                                                                   : mpm::MaterialKind::linear_elastic;
    out.compliance_other_model = evaluate_binary_design(scene.grid, out.binary, scene.load_case, other, 1);
  }
  return out;
}

}  // namespace latmpm::optimize
