// Set-up checks of GIMP particle domains (shape_gimp.hpp) that the shape functions alone
// cannot make.
#pragma once
#include <string>
#include <vector>

#include "mpm/body.hpp"
#include "mpm/particles.hpp"

namespace latmpm::mpm {

// cpGIMP under USL with a deformable point whose domain is wider than a cell (a half-size
// above h/2 along some axis, as hexahedral-mesh points have, latmpm-hexmesh): throws
// InputError (where, "grid.shape", naming the point). Measured on paper B's B2 cylinder on
// a 0.4 mm grid (half-sizes up to 1.04 h): the run stops at step 3 to 6 with a NaN at a rim
// point, at any step size, with or without loading contact; with MUSL the same run closes its
// energy balance to 0.14 %; B3 (up to 0.71 h) fails at cfl 0.3 (docs/paper-b.md).
// The cause is not found; the voxelizer's points (half-size h/(2 ppc)) are not affected.
void refuse_wide_cpgimp_domains(const Particles& ps, const std::vector<BodySettings>& bodies, Real cell_size,
                                const std::string& where);

}  // namespace latmpm::mpm
