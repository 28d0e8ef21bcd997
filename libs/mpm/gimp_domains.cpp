#include "mpm/gimp_domains.hpp"

#include <sstream>

#include "core/errors.hpp"

namespace latmpm::mpm {

void refuse_wide_cpgimp_domains(const Particles& ps, const std::vector<BodySettings>& bodies, Real h,
                                const std::string& where) {
  for (size_t p = 0; p < ps.size(); ++p) {
    if (bodies[size_t(ps.body[p])].role != BodyRole::deformable) continue;
    const Real half = ps.half_size0[p].maxCoeff();
    if (half <= Real(0.5) * h * (1 + 1e-12)) continue;
    std::ostringstream msg;
    msg << "cpgimp with scheme usl: point " << ps.id[p] << " of body '" << bodies[size_t(ps.body[p])].name
        << "' has a domain half-size of " << half << " m, more than half a cell (" << 0.5 * h
        << " m); such domains diverge under USL (measured, docs/paper-b.md): use scheme = \"musl\", "
           "shape = \"cpdi1\" or \"ugimp\", or a finer grid";
    throw InputError(where, "grid.shape", msg.str());
  }
}

}  // namespace latmpm::mpm
