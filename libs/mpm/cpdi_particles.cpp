#include "mpm/cpdi_particles.hpp"

#include "core/errors.hpp"
#include "mpm/cpdi.hpp"
#include "points/point_set.hpp"

namespace latmpm::mpm {

void set_cpdi_domains(Particles& ps, const PointSet& points, const std::vector<BodySettings>& bodies,
                      Real cell_size, const std::string& where) {
  for (const BodySettings& b : bodies)
    if (b.role != BodyRole::deformable || !b.hold_tag.empty())
      throw InputError(where, "bodies." + b.name,
                       "shape function cpdi1 takes deformable bodies without held points (their domains are "
                       "convected with F); use rigid bodies for platens and supports");
  const size_t n = points.size();
  if (points.domain_vertices.size() != n)
    throw InputError(where, "points",
                     "shape function cpdi1 needs every point's hexahedral domain (/points/domain_vertices, "
                     "written by latmpm-hexmesh); this point set has none");
  ps.cpdi_domain.resize(n);
  for (size_t p = 0; p < n; ++p) {
    const std::string field = "points[" + std::to_string(p) + "].domain_vertices";
    CpdiDomain d;
    try {
      d = make_cpdi_domain(points.domain_vertices[p]);
    } catch (const NumericalError&) {
      throw InputError(where, field, "the hexahedron is inverted (det J <= 0 inside it)");
    }
    const Vec3 centroid = points.domain_vertices[p][0] - d.offsets[0];
    if ((centroid - points.position[p]).norm() > 1e-6 * cell_size)
      throw InputError(where, field, "the point does not sit at its domain's centroid");
    for (int a = 0; a < 8; ++a) {
      ps.cpdi_domain[p].col(a).head<3>() = d.offsets[a];
      ps.cpdi_domain[p](3, a) = d.weight_fraction[a];
      ps.cpdi_domain[p].col(a).tail<3>() = d.gradient_per_volume[a];
    }
  }
}

}  // namespace latmpm::mpm
