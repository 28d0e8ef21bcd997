// What latmpm-optimize writes per method into the output directory (docs/paper-c.md):
//   <method>-history.csv   iteration, compliance (J), volume fraction, band threshold,
//                          seconds, active points, unknowns
//   <method>-design.csv    per quadrature point: x, y, z (mm), density, binary
//   <method>-design.gp     gnuplot script drawing the binary design into <method>-design.png
// and summary.toml over all methods (with each exported part's volume and stiffness, so that
// pipelines copy them instead of computing). Every file opens with provenance comment lines.
#pragma once
#include <string>
#include <vector>

#include "optimize/design_export.hpp"
#include "optimize/design_study.hpp"

namespace latmpm::optimize {

void write_method_files(const std::string& directory, const OptimizeScene& scene, const MethodOutcome& outcome,
                        const std::vector<std::string>& provenance_lines);

// `exports[i]` is the part exported from `outcomes[i]`.
void write_summary(const std::string& directory, const OptimizeScene& scene, const std::vector<MethodOutcome>& outcomes,
                   const std::vector<ExportReport>& exports, const std::vector<std::string>& provenance_lines);

}  // namespace latmpm::optimize
