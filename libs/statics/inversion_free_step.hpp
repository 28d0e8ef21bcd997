// The inversion-free step bound of paper C Sec. 3.3 (after Smith & Schaefer 2015): along a
// search direction the deformation gradient of point p is F_p + α D_p, and
//   det(F + α D) = det F + α tr(adj(F) D) + α² tr(F adj(D)) + α³ det D
// is a cubic in α. The largest feasible step is the smallest positive root over all points
// of det(F + α D) = ε det F (paper C Eq. 35), with ε > 0 keeping a margin from det = 0
// against round-off. The line search then starts from min(1, that root).
#pragma once
#include <vector>

#include "statics/elastic_energy.hpp"

namespace latmpm::statics {

// Smallest α > 0 with det(F + α D) = margin · det F, or +∞ when there is none (det F > 0).
Real inversion_free_step(const Mat3& F, const Mat3& D, Real margin);

// The same over all points (D_p = F_p(u + d) − F_p(u)).
Real inversion_free_step(const std::vector<Mat3>& F, const std::vector<Mat3>& D, Real margin);

}  // namespace latmpm::statics
