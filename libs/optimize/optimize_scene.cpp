#include "optimize/optimize_scene.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "scene/toml_table_reader.hpp"

namespace latmpm::optimize {
namespace {

using scene_toml::Origins;
using scene_toml::TableReader;

Box read_box(TableReader& t) {
  Box b{t.vector("min", dimension::length), t.vector("max", dimension::length)};
  if ((b.hi.array() < b.lo.array()).any()) t.fail("max", "must not be below min in any component");
  return b;
}

void read_domain(TableReader t, OptimizeScene& s) {
  DesignGrid& g = s.grid;
  g.cell_size = t.quantity("cell", dimension::length);
  if (!(g.cell_size > 0)) t.fail("cell", "must be positive");
  const Vec3 size = t.vector("size", dimension::length);
  g.planar = t.boolean("planar", false);
  g.per_cell = int(t.integer("points_per_cell", 2));
  if (g.per_cell < 1 || g.per_cell > 4) t.fail("points_per_cell", "must be 1 to 4");
  for (int a = 0; a < 3; ++a) {
    if (!(size[a] > 0)) t.fail("size", "the design domain is empty: every component must be positive");
    if (a == 2 && g.planar) continue;
    const Real cells = size[a] / g.cell_size;
    if (std::abs(cells - std::round(cells)) > 1e-6 * cells)
      t.fail("size", "component " + std::to_string(a) + " is not a whole number of cells");
    g.cells[a] = int(std::round(cells));
  }
  if (g.planar) {
    g.cells[2] = 1;
    g.thickness = size[2];
  }
  t.finish();
}

void read_material(TableReader t, OptimizeScene& s) {
  const std::string model = t.text("model", "linear_elastic");
  if (model == "linear_elastic") s.material.model = mpm::MaterialKind::linear_elastic;
  else if (model == "neo_hookean") s.material.model = mpm::MaterialKind::neo_hookean;
  else t.fail("model", "expected linear_elastic or neo_hookean, got '" + model + "'");
  s.material.young_modulus = t.quantity("E", dimension::pressure);
  if (!(s.material.young_modulus > 0)) t.fail("E", "must be positive");
  s.material.poisson_ratio = t.number("nu");
  if (!(s.material.poisson_ratio > -1 && s.material.poisson_ratio < 0.5)) t.fail("nu", "must lie in (-1, 0.5)");
  s.material.penalty = t.number("penalty", 3);
  if (!(s.material.penalty >= 1)) t.fail("penalty", "must be at least 1");
  t.finish();
}

void read_supports_and_loads(TableReader& root, OptimizeScene& s) {
  TableReader supports = root.table("supports");
  for (const std::string& name : supports.keys()) {
    TableReader t = supports.table(name);
    Support sup;
    sup.name = name;
    sup.box = read_box(t);
    const std::string held = t.text("held", "xyz");
    if (held.empty() || held.find_first_not_of("xyz") != std::string::npos) t.fail("held", "expected some of x, y, z (e.g. \"xyz\")");
    for (int a = 0; a < 3; ++a) sup.held[size_t(a)] = held.find(char('x' + a)) != std::string::npos;
    // At least one grid node of the domain inside the box.
    const Real h = s.grid.cell_size;
    bool any = false;
    for (int k = 0; k <= s.grid.cells[2] && !any; ++k)
      for (int j = 0; j <= s.grid.cells[1] && !any; ++j)
        for (int i = 0; i <= s.grid.cells[0] && !any; ++i) any = sup.box.contains(h * Vec3(i, j, k));
    if (!any) t.fail("min", "the support holds no grid node of the design domain");
    t.finish();
    s.load_case.supports.push_back(sup);
  }
  if (s.load_case.supports.empty()) root.fail("supports", "the scene holds nothing ([supports.<name>] tables)");
  supports.finish();

  TableReader loads = root.table("loads");
  for (const std::string& name : loads.keys()) {
    TableReader t = loads.table(name);
    Load l;
    l.name = name;
    l.box = read_box(t);
    l.force = t.vector("force", dimension::force);
    if (!(l.force.norm() > 0)) t.fail("force", "must not be zero");
    t.finish();
    s.load_case.loads.push_back(l);
  }
  if (s.load_case.loads.empty()) root.fail("loads", "the scene loads nothing ([loads.<name>] tables)");
  const auto points = loaded_points(s.grid, s.load_case);
  for (size_t l = 0; l < points.size(); ++l)
    if (points[l].empty()) {
      TableReader t = loads.table(s.load_case.loads[l].name);
      t.fail("min", "the load acts on no material: no design point lies inside its box");
    }
  loads.finish();
}

void read_optimizer(TableReader t, OptimizeScene& s) {
  OptimisationSettings& o = s.settings;
  o.volume_fraction = t.number("volume_fraction");
  if (!(o.volume_fraction > 0 && o.volume_fraction < 1)) t.fail("volume_fraction", "must lie in (0, 1)");
  o.max_iterations = int(t.integer("max_iterations", 250));
  if (o.max_iterations < 1) t.fail("max_iterations", "must be at least 1");
  o.tolerance = t.number("tolerance", 1e-3);
  if (!(o.tolerance > 0)) t.fail("tolerance", "must be positive");
  const std::string methods = t.choice("methods", {"leto", "simp", "both"}, "both");
  if (methods == "both") s.methods = {"leto", "simp"};
  else s.methods = {methods};
  t.finish();
}

void read_leto(TableReader t, OptimizeScene& s) {
  LetoSettings& l = s.leto;
  l.kernel_radius_cells = t.number("kernel_radius", 1.5);
  if (!(l.kernel_radius_cells > 0)) t.fail("kernel_radius", "must be positive (cells)");
  l.clamp_knee = t.number("clamp_knee", 0.9);
  if (!(l.clamp_knee > 0 && l.clamp_knee < 1)) t.fail("clamp_knee", "must lie in (0, 1)");
  l.density_move = t.number("density_move", 0.5);
  l.position_move_cells = t.number("position_move", 0.5);
  l.carrier_density_max = t.number("carrier_density_max", 2);
  if (!(l.carrier_density_max > 0)) t.fail("carrier_density_max", "must be positive");
  if (!(l.density_move > 0) || !(l.position_move_cells >= 0)) t.fail("density_move", "moves must be positive");
  NarrowBandSchedule& b = s.settings.band;
  b.enabled = t.boolean("narrow_band", true);
  b.start = t.number("band_start", 0.01);
  b.end = t.number("band_end", 0.9);
  if (!(b.start >= 0 && b.start <= b.end && b.end < 1)) t.fail("band_end", "need 0 ≤ band_start ≤ band_end < 1");
  b.ramp_iterations = int(t.integer("band_ramp", 90));
  l.sharpen_end = t.number("sharpen", 0);
  if (!(l.sharpen_end == 0 || l.sharpen_end > 1.01)) t.fail("sharpen", "must be 0 (off) or the final β of Eq. 38, above 1.01");
  l.sharpen_ramp = int(t.integer("sharpen_ramp", b.ramp_iterations));
  if (l.sharpen_ramp < 1) t.fail("sharpen_ramp", "must be at least 1 (iterations)");
  s.correction_slack = int(t.integer("correction_slack", 2 * s.grid.per_cell));
  s.leto_binarise = t.number("binarise", 0.9);
  s.leto_volume_fraction = t.number("volume_fraction", 0);
  if (!(s.leto_volume_fraction == 0 || (s.leto_volume_fraction > 0 && s.leto_volume_fraction < 1)))
    t.fail("volume_fraction", "must lie in (0, 1), or 0 for optimize.volume_fraction");
  t.finish();
}

void read_simp(TableReader t, OptimizeScene& s) {
  SimpSettings& p = s.simp;
  p.filter_radius_cells = t.number("filter_radius", 1.5);
  if (!(p.filter_radius_cells >= 1)) t.fail("filter_radius", "must be at least 1 (cells)");
  p.beta_max = t.number("beta_max", 16);
  p.beta_every = int(t.integer("beta_every", 25));
  p.move = t.number("move", 0.2);
  s.simp_binarise = t.number("binarise", 0.5);
  s.simp_max_iterations = int(t.integer("max_iterations", 0));
  t.finish();
}

void read_evaluation(TableReader t, OptimizeScene& s) {
  s.evaluate_refined = t.boolean("refined", true);
  s.refine = int(t.integer("refine", s.grid.per_cell));
  s.evaluate_other_model = t.boolean("other_model", false);
  if (s.refine < 1) t.fail("refine", "must be at least 1");
  t.finish();
}

}  // namespace

OptimizeScene parse_optimize_scene(const std::string& text, const std::string& name,
                                   const std::vector<std::string>& overrides) {
  toml::table document;
  try {
    document = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    throw InputError(name + ":" + std::to_string(e.source().begin.line), "", "not valid TOML: " + std::string(e.description()));
  }
  Origins origins(name);
  for (const auto& o : overrides) scene_toml::apply_override(document, o, origins);
  OptimizeScene s;
  s.source = name;
  TableReader root(document, "", origins);
  read_domain(root.table("domain"), s);
  read_material(root.table("material"), s);
  read_supports_and_loads(root, s);
  read_optimizer(root.table("optimize"), s);
  read_leto(root.table_or_empty("leto"), s);
  read_simp(root.table_or_empty("simp"), s);
  read_evaluation(root.table_or_empty("evaluation"), s);
  root.finish();
  std::ostringstream os;
  os << toml::toml_formatter(document, toml::toml_formatter::default_flags | toml::format_flags::relaxed_float_precision) << "\n";
  s.resolved_toml = os.str();
  return s;
}

OptimizeScene read_optimize_scene(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot read the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_optimize_scene(text.str(), path, overrides);
}

}  // namespace latmpm::optimize
