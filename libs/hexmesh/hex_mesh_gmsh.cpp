// The one file that talks to gmsh for hexahedral meshes.
#include <gmsh.h>

#include <cmath>
#include <map>
#include <utility>

#include "core/errors.hpp"
#include "hexmesh/hex_mesh.hpp"
#include "points/hexahedron.hpp"

namespace latmpm {
namespace {

constexpr int gmsh_hexahedron_8 = 5;  // gmsh element type of the trilinear hexahedron

// gmsh is a global singleton: one session per mesh, always finalised; quiet on the terminal.
struct GmshMeshSession {
  GmshMeshSession() {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::model::add("latmpm-hexmesh");
  }
  ~GmshMeshSession() { gmsh::finalize(); }
  GmshMeshSession(const GmshMeshSession&) = delete;
  GmshMeshSession& operator=(const GmshMeshSession&) = delete;
};

const char* volume_element_name(int type) {
  switch (type) {
    case 4: return "4-node tetrahedra";
    case 6: return "6-node prisms";
    case 7: return "5-node pyramids";
    case 11: return "10-node tetrahedra";
    case 12: return "27-node hexahedra";
    case 17: return "20-node hexahedra";
    default: return "volume elements other than 8-node hexahedra";
  }
}

// The current gmsh model's 8-node hexahedra, each turned to a positive Jacobian.
HexMesh collect_hexahedra(const std::string& where, double scale) {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 3);
  for (int type : types)
    if (type != gmsh_hexahedron_8)
      throw InputError(where, "elements", std::string("holds ") + volume_element_name(type) +
                                              "; CPDI1 domains must be 8-node hexahedra (recombine the mesh)");
  std::vector<size_t> element_tags, element_nodes;
  gmsh::model::mesh::getElementsByType(gmsh_hexahedron_8, element_tags, element_nodes);
  if (element_tags.empty()) throw InputError(where, "elements", "holds no 8-node hexahedra");
  std::vector<size_t> node_tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(node_tags, coords, parametric, -1, -1, false, false);
  HexMesh mesh;
  std::map<size_t, size_t> index;
  for (size_t i = 0; i < node_tags.size(); ++i) {
    if (index.count(node_tags[i])) continue;
    index[node_tags[i]] = mesh.nodes.size();
    mesh.nodes.push_back(scale * Eigen::Vector3d(coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]));
  }
  mesh.elements.resize(element_tags.size());
  for (size_t e = 0; e < element_tags.size(); ++e) {
    std::array<size_t, 8>& element = mesh.elements[e];
    HexVertices x;
    for (int a = 0; a < 8; ++a) {
      const auto found = index.find(element_nodes[8 * e + size_t(a)]);
      if (found == index.end()) throw InputError(where, "elements", "element " + std::to_string(element_tags[e]) + " names a node that does not exist");
      element[size_t(a)] = found->second;
      x[size_t(a)] = mesh.nodes[found->second];
    }
    // A mirrored vertex order (all Jacobians negative) is the same element: swap the faces.
    if (hex_integrals(x).volume < 0) {
      for (int a = 0; a < 4; ++a) std::swap(element[size_t(a)], element[size_t(a) + 4]), std::swap(x[size_t(a)], x[size_t(a) + 4]);
    }
    if (!(hex_integrals(x).min_jacobian > 0))
      throw InputError(where, "elements", "element " + std::to_string(element_tags[e]) + " is inverted or degenerate (det J <= 0)");
  }
  return mesh;
}

void require_positive(double value, const char* field) {
  if (!(value > 0) || !std::isfinite(value)) throw InputError("hex mesh", field, "must be positive");
}

void mesh_and_collect(HexMesh& out, const std::string& msh_path) {
  // gmsh throws std::string as well as std::exception (e.g. a cylinder of 1e-300 m).
  try {
    gmsh::model::geo::synchronize();
    gmsh::model::mesh::generate(3);
    out = collect_hexahedra("generated mesh", 1);
    if (!msh_path.empty()) gmsh::write(msh_path);  // only a mesh that passed the checks
  } catch (const std::string& e) {
    throw InputError("hex mesh", "", "gmsh cannot mesh the cylinder: " + e);
  }
}

}  // namespace

CylinderMeshSpec paper_b_cylinder(int level, double diameter, double height) {
  if (level < 1 || level > 12) throw InputError("hex mesh", "level", "must be between 1 and 12");
  CylinderMeshSpec s;
  s.diameter = diameter;
  s.height = height;
  s.core_divisions = 2 * level;
  s.ring_divisions = level;
  s.axial_divisions = 4 * level;
  return s;
}

HexMesh cylinder_hex_mesh(const CylinderMeshSpec& spec, const std::string& msh_path) {
  require_positive(spec.diameter, "diameter");
  require_positive(spec.height, "height");
  // gmsh's geometry tolerances are absolute: a cylinder far below a nanometre cannot be built
  // (gmsh throws a std::string for 1e-300 m), nor one beyond a kilometre meshed sensibly.
  for (const auto& [field, value] : {std::pair<const char*, double>{"diameter", spec.diameter}, {"height", spec.height}})
    if (value < 1e-9 || value > 1e3) throw InputError("hex mesh", field, "must lie between 1 nm and 1 km");
  if (spec.core_divisions < 1 || spec.ring_divisions < 1 || spec.axial_divisions < 1)
    throw InputError("hex mesh", "divisions", "must be at least 1");
  if (!(spec.core_fraction > 0.05 && spec.core_fraction < 0.65))
    throw InputError("hex mesh", "core_fraction", "must lie in (0.05, 0.65)");
  GmshMeshSession session;
  namespace geo = gmsh::model::geo;
  const double r = spec.diameter / 2, s = spec.core_fraction * r;
  const int centre = geo::addPoint(0, 0, 0);
  int inner[4], outer[4], side[4], arc[4], radial[4];
  for (int i = 0; i < 4; ++i) {
    const double angle = M_PI / 4 + M_PI / 2 * i;
    inner[i] = geo::addPoint(std::sqrt(2.0) * s * std::cos(angle), std::sqrt(2.0) * s * std::sin(angle), 0);
    outer[i] = geo::addPoint(r * std::cos(angle), r * std::sin(angle), 0);
  }
  for (int i = 0; i < 4; ++i) {
    side[i] = geo::addLine(inner[i], inner[(i + 1) % 4]);
    arc[i] = geo::addCircleArc(outer[i], centre, outer[(i + 1) % 4]);
    radial[i] = geo::addLine(inner[i], outer[i]);
  }
  std::vector<int> surfaces{geo::addPlaneSurface({geo::addCurveLoop({side[0], side[1], side[2], side[3]})})};
  for (int i = 0; i < 4; ++i)
    surfaces.push_back(geo::addPlaneSurface({geo::addCurveLoop({side[i], radial[(i + 1) % 4], -arc[i], -radial[i]})}));
  for (int i = 0; i < 4; ++i) {
    geo::mesh::setTransfiniteCurve(side[i], spec.core_divisions + 1);
    geo::mesh::setTransfiniteCurve(arc[i], spec.core_divisions + 1);
    geo::mesh::setTransfiniteCurve(radial[i], spec.ring_divisions + 1);
  }
  gmsh::vectorpair base, extruded;
  for (int surface : surfaces) {
    geo::mesh::setTransfiniteSurface(surface);
    geo::mesh::setRecombine(2, surface);
    base.emplace_back(2, surface);
  }
  geo::extrude(base, 0, 0, spec.height, extruded, {spec.axial_divisions}, {}, true);
  HexMesh mesh;
  mesh_and_collect(mesh, msh_path);
  return mesh;
}

HexMesh box_hex_mesh(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Vector3i& n,
                     const std::string& msh_path) {
  for (int d = 0; d < 3; ++d) require_positive(hi[d] - lo[d], "box size");
  if ((n.array() < 1).any()) throw InputError("hex mesh", "divisions", "must be at least 1");
  GmshMeshSession session;
  namespace geo = gmsh::model::geo;
  const int p[4] = {geo::addPoint(lo.x(), lo.y(), lo.z()), geo::addPoint(hi.x(), lo.y(), lo.z()),
                    geo::addPoint(hi.x(), hi.y(), lo.z()), geo::addPoint(lo.x(), hi.y(), lo.z())};
  int line[4];
  for (int i = 0; i < 4; ++i) {
    line[i] = geo::addLine(p[i], p[(i + 1) % 4]);
    geo::mesh::setTransfiniteCurve(line[i], (i % 2 == 0 ? n.x() : n.y()) + 1);
  }
  const int surface = geo::addPlaneSurface({geo::addCurveLoop({line[0], line[1], line[2], line[3]})});
  geo::mesh::setTransfiniteSurface(surface);
  geo::mesh::setRecombine(2, surface);
  gmsh::vectorpair extruded;
  geo::extrude({{2, surface}}, 0, 0, hi.z() - lo.z(), extruded, {n.z()}, {}, true);
  HexMesh mesh;
  mesh_and_collect(mesh, msh_path);
  return mesh;
}

HexMesh read_hex_mesh(const std::string& path, double metres_per_unit) {
  require_positive(metres_per_unit, "units");
  GmshMeshSession session;
  // gmsh throws std::string as well as std::exception (a truncated file): either is bad input.
  try {
    gmsh::open(path);
    return collect_hexahedra(path, metres_per_unit);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("gmsh cannot read it: ") + e.what());
  } catch (const std::string& e) {
    throw InputError(path, "", "gmsh cannot read it: " + e);
  } catch (...) {
    throw InputError(path, "", "gmsh cannot read it");
  }
}

double hex_mesh_volume(const HexMesh& mesh) {
  double v = 0;
  for (const auto& element : mesh.elements) {
    HexVertices x;
    for (int a = 0; a < 8; ++a) x[size_t(a)] = mesh.nodes[element[size_t(a)]];
    v += hex_integrals(x).volume;
  }
  return v;
}

}  // namespace latmpm
