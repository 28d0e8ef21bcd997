// The input of latmpm-optimize: a TOML scene (docs/paper-c.md lists every key) with the
// design domain, material, supports, loads, the optimiser and its two methods (LETO and
// the SIMP baseline), read the way libs/scene reads simulation scenes: every dimensional
// value with its unit, unknown keys refused, every error one line naming file:line and key
// (InputError, exit status 2), defaults written back into the resolved document.
#pragma once
#include <string>
#include <vector>

#include "optimize/compliance.hpp"
#include "optimize/leto_design.hpp"
#include "optimize/load_case.hpp"
#include "optimize/optimisation.hpp"
#include "optimize/simp_design.hpp"

namespace latmpm::optimize {

struct OptimizeScene {
  std::string source;          // the scene file
  std::string resolved_toml;   // with defaults and --set overrides applied
  DesignGrid grid;
  SimpMaterial material;
  LoadCase load_case;
  OptimisationSettings settings;  // band: LETO's narrow band schedule
  std::vector<std::string> methods;  // "leto", "simp", in the order given
  LetoSettings leto;
  int correction_slack = 4;    // lattice steps (connectivity correction), < 0: off
  Real leto_binarise = 0.9;    // paper C Sec. 4.2
  // LETO's own volume bound (paper C Sec. 4.2: set below the volume of SIMP's binary design,
  // since LETO's binary volume can end above its bound); 0: optimize.volume_fraction.
  Real leto_volume_fraction = 0;
  SimpSettings simp;
  Real simp_binarise = 0.5;
  int simp_max_iterations = 0;  // 0: optimize.max_iterations
  int refine = 2;              // evaluation grid: cell / refine (paper C: 2)
  bool evaluate_refined = true;
  // Also the binary design's compliance under the other material model (linear elastic <->
  // neo-Hookean) at the optimisation resolution: how a design made for one model fares
  // under the other (paper C Sec. 4.3).
  bool evaluate_other_model = false;
};

OptimizeScene read_optimize_scene(const std::string& path, const std::vector<std::string>& overrides = {});
OptimizeScene parse_optimize_scene(const std::string& text, const std::string& name,
                                   const std::vector<std::string>& overrides = {});

}  // namespace latmpm::optimize
