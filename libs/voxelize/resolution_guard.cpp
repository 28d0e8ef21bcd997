#include "voxelize/resolution_guard.hpp"

#include <cstdio>

namespace latmpm {

StrutResolution strut_resolution(const StrutGraph& graph, double cell_size, int ppc) {
  StrutResolution r;
  for (size_t s = 0; s < graph.struts.size(); ++s) {
    const double d = 2.0 * graph.struts[s].radius;
    if (!r.has_struts || d < r.diameter) {
      r.has_struts = true;
      r.strut = s;
      r.diameter = d;
    }
  }
  if (!r.has_struts) return r;
  r.cells_across = r.diameter / cell_size;
  r.points_across = r.cells_across * ppc;
  r.verdict = r.points_across < 1   ? StrutResolution::Verdict::too_coarse
              : r.points_across < 3 ? StrutResolution::Verdict::coarse
                                    : StrutResolution::Verdict::fine;
  return r;
}

std::string describe(const StrutResolution& r) {
  if (!r.has_struts) return "no struts";
  char text[160];
  std::snprintf(text, sizeof text, "thinnest strut (#%zu) %.4g mm: %.3g points, %.3g cells across",
                r.strut, r.diameter * 1e3, r.points_across, r.cells_across);
  return text;
}

}  // namespace latmpm
