// Setting up CPDI1 particles (shape_cpdi.hpp): each point's reference hexahedron (the point
// set's /points/domain_vertices, which latmpm-hexmesh writes) becomes the particle's
// CpdiParticleDomain. Paper B Sec. 2.2: one material point per element of a hexahedral mesh.
#pragma once
#include <string>
#include <vector>

#include "mpm/body.hpp"
#include "mpm/particles.hpp"

namespace latmpm {
struct PointSet;
}

namespace latmpm::mpm {

// Fills ps.cpdi_domain from points.domain_vertices (ps in the point set's order). Throws
// InputError (where, field, problem) when the point set has no domains, a domain is inverted,
// a point does not sit at its domain's centroid, or a body is not a plain deformable one
// (rigid point bodies and held points carry no domain to convect; use rigid bodies).
void set_cpdi_domains(Particles& ps, const PointSet& points, const std::vector<BodySettings>& bodies,
                      Real cell_size, const std::string& where);

}  // namespace latmpm::mpm
