#include "core/units.hpp"
#include "imperfect/shape_perturbation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "core/errors.hpp"
#include "core/text.hpp"
#include "imperfect/direction.hpp"
#include "imperfect/lattice_frame.hpp"

namespace latmpm {
namespace {

std::string mm(double metres) { return format_millimetres(metres, 6); }

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The shape f of a field, its gradient, and the axis e of the displacement.
struct Field {
  std::function<double(const Eigen::Vector3d&)> value;
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> gradient;
  Eigen::Vector3d axis;
  std::string formula;  // for the record
};

// Linear ramp from 0 at z = lo to 1 at z = lo + height, constant outside.
double ramp(double z, double lo, double height) { return std::clamp((z - lo) / height, 0.0, 1.0); }
double ramp_slope(double z, double lo, double height) {
  return (z > lo && z < lo + height) ? 1.0 / height : 0.0;
}

std::vector<std::string> default_bodies(ShapeType type, const PointSet& points) {
  switch (type) {
    case ShapeType::slant_top_layer:
    case ShapeType::curved_top_base: return {"lattice", "top_plate"};
    case ShapeType::slant_lattice: return points.body_names;
    case ShapeType::bowed_lattice: return {"lattice"};
    case ShapeType::sine: {
      std::vector<std::string> out;
      for (const auto& name : points.body_names)
        if (!ends_with(name, "plate")) out.push_back(name);
      return out;
    }
  }
  return {};
}

// Indices of the bodies to move: those named (each must exist), or the present defaults.
std::vector<int> resolve_bodies(const PointSet& points, const ShapePerturbation& p, const std::string& where) {
  std::vector<int> out;
  if (!p.bodies.empty()) {
    for (const auto& name : p.bodies) {
      int index = points.body_index(name);
      if (index < 0)
        throw InputError("--bodies", "", "no body '" + name + "' in " + where + " (its bodies: " + joined(points.body_names, ",") + ")");
      if (std::find(out.begin(), out.end(), index) == out.end()) out.push_back(index);
    }
    return out;
  }
  const auto defaults = default_bodies(p.type, points);
  for (const auto& name : defaults)
    if (int index = points.body_index(name); index >= 0) out.push_back(index);
  if (out.empty())
    throw InputError(where, "/points/body_names", "has none of the bodies " + shape_label(p.type) + " moves by default (" +
                     joined(defaults, ",") + "); name them with --bodies");
  return out;
}

double top_layer_height(const LatticeFrame& frame, const std::string& where, ShapeType type) {
  if (frame.layer_height > 0) return frame.layer_height;
  throw InputError(where, "/points/parameters/layer_height",
                   "absent (and no cells or layers parameter): " + shape_label(type) +
                       " needs the top cell layer; give --layer-height");
}

Field make_field(const PointSet& points, const ShapePerturbation& p, const std::vector<int>& bodies,
                 const std::string& where, std::vector<std::string>& notes) {
  const Eigen::Vector3d ez(0, 0, 1);
  const Extent moved = body_extent(points, bodies);
  auto frame_notes = [&](const LatticeFrame& f) { notes.insert(notes.end(), f.notes.begin(), f.notes.end()); };
  switch (p.type) {
    case ShapeType::slant_top_layer: {
      LatticeFrame frame = find_lattice_frame(points, where, p.layer_height);
      frame_notes(frame);
      const double h = top_layer_height(frame, where, p.type), za = frame.lattice_zmax - h;
      return {[=](const Eigen::Vector3d& x) { return ramp(x.z(), za, h); },
              [=](const Eigen::Vector3d& x) -> Eigen::Vector3d { return ramp_slope(x.z(), za, h) * ez; },
              p.direction,
              "f = clamp((z - " + mm(za) + ") / " + mm(h) + ", 0, 1)"};
    }
    case ShapeType::slant_lattice: {
      const double lo = moved.min.z(), height = moved.max.z() - moved.min.z();
      return {[=](const Eigen::Vector3d& x) { return (x.z() - lo) / height; },
              [=](const Eigen::Vector3d&) -> Eigen::Vector3d { return ez / height; },
              p.direction,
              "f = (z - " + mm(lo) + ") / " + mm(height)};
    }
    case ShapeType::curved_top_base: {
      LatticeFrame frame = find_lattice_frame(points, where, p.layer_height);
      frame_notes(frame);
      const double h = top_layer_height(frame, where, p.type), za = frame.lattice_zmax - h;
      // Across-width of the top base along the direction (of all moved points if the top
      // base is not moved), from the particle domains so the edges are the material's edges.
      const int top = points.body_index("top_plate");
      const bool plate_moved = top >= 0 && std::find(bodies.begin(), bodies.end(), top) != bodies.end();
      const std::vector<int> across_bodies = plate_moved ? std::vector<int>{top} : bodies;
      const Eigen::Vector3d e = p.direction;
      double lo = 1e300, hi = -1e300;
      std::vector<bool> wanted(points.body_names.size(), false);
      for (int b : across_bodies) wanted[b] = true;
      for (size_t i = 0; i < points.size(); ++i) {
        if (!wanted[points.body[i]]) continue;
        const double s = e.dot(points.position[i]);
        const double reach = std::abs(e.x()) * points.half_size[i].x() + std::abs(e.y()) * points.half_size[i].y();
        lo = std::min(lo, s - reach);
        hi = std::max(hi, s + reach);
      }
      const double centre = 0.5 * (lo + hi), half_width = 0.5 * (hi - lo);
      auto across = [=](const Eigen::Vector3d& x) { return (e.dot(x) - centre) / half_width; };
      // The crest: the point of the top base nearest the centre line stays in place (there
      // may be none exactly on it), so a flat plate resting on the crest has the full amount
      // of gap at the edges.
      double crest2 = 1;
      for (size_t i = 0; i < points.size(); ++i)
        if (wanted[points.body[i]]) crest2 = std::min(crest2, std::pow(across(points.position[i]), 2));
      if (crest2 >= 1) throw InputError(where, "/points/position", "the top base has no width along the direction");
      auto curve = [=](double xi) { return std::clamp((xi * xi - crest2) / (1 - crest2), 0.0, 1.0); };
      auto curve_slope = [=](double xi) {
        const double c = (xi * xi - crest2) / (1 - crest2);
        return (c > 0 && c < 1) ? 2 * xi / ((1 - crest2) * half_width) : 0.0;
      };
      std::ostringstream formula;
      formula.precision(6);
      formula << "f = -clamp((xi^2 - " << crest2 << ") / (1 - " << crest2 << "), 0, 1) * clamp((z - " << mm(za)
              << ") / " << mm(h) << ", 0, 1), xi = (x.e - " << mm(centre) << ") / " << mm(half_width);
      return {[=](const Eigen::Vector3d& x) { return -curve(across(x)) * ramp(x.z(), za, h); },
              [=](const Eigen::Vector3d& x) -> Eigen::Vector3d {
                const double xi = across(x);
                return -(curve_slope(xi) * ramp(x.z(), za, h) * e + curve(xi) * ramp_slope(x.z(), za, h) * ez);
              },
              ez, formula.str()};
    }
    case ShapeType::bowed_lattice: {
      LatticeFrame frame = find_lattice_frame(points, where);
      frame_notes(frame);
      const double z0 = frame.lattice_zmin, span = frame.lattice_zmax - frame.lattice_zmin;
      auto inside = [=](double z) { return z > z0 && z < z0 + span; };
      return {[=](const Eigen::Vector3d& x) { return inside(x.z()) ? std::sin(M_PI * (x.z() - z0) / span) : 0.0; },
              [=](const Eigen::Vector3d& x) -> Eigen::Vector3d {
                return inside(x.z()) ? Eigen::Vector3d(M_PI / span * std::cos(M_PI * (x.z() - z0) / span) * ez)
                                     : Eigen::Vector3d::Zero();
              },
              p.direction,
              "f = sin(pi (z - " + mm(z0) + ") / " + mm(span) + ") between the bases"};
    }
    case ShapeType::sine: {
      const double z0 = p.column_bottom ? *p.column_bottom : moved.min.z();
      const double length = p.length > 0 ? p.length : moved.max.z() - z0;
      if (!(length > 0)) throw InputError("--length", "", "the column length must be positive (got " + mm(length) + ")");
      if (p.mode < 1) throw InputError("--mode", "", "the mode number must be 1 or more (got " + std::to_string(p.mode) + ")");
      const double k = p.mode * M_PI / length;
      auto inside = [=](double z) { return z > z0 && z < z0 + length; };
      return {[=](const Eigen::Vector3d& x) { return inside(x.z()) ? std::sin(k * (x.z() - z0)) : 0.0; },
              [=](const Eigen::Vector3d& x) -> Eigen::Vector3d {
                return inside(x.z()) ? Eigen::Vector3d(k * std::cos(k * (x.z() - z0)) * ez) : Eigen::Vector3d::Zero();
              },
              p.direction,
              "f = sin(" + std::to_string(p.mode) + " pi (z - " + mm(z0) + ") / " + mm(length) + ") on the column"};
    }
  }
  throw std::logic_error("unknown shape type");
}

}  // namespace

ShapeType parse_shape_type(const std::string& text, const std::string& where) {
  if (text == "A" || text == "slant-top-layer") return ShapeType::slant_top_layer;
  if (text == "B" || text == "slant-lattice") return ShapeType::slant_lattice;
  if (text == "C" || text == "curved-top-base") return ShapeType::curved_top_base;
  if (text == "D" || text == "bowed-lattice") return ShapeType::bowed_lattice;
  if (text == "sine") return ShapeType::sine;
  throw InputError(where, "", "unknown type '" + text +
                                  "' (A slant-top-layer, B slant-lattice, C curved-top-base, D bowed-lattice, sine)");
}

std::string shape_label(ShapeType type) {
  switch (type) {
    case ShapeType::slant_top_layer: return "A slant-top-layer";
    case ShapeType::slant_lattice: return "B slant-lattice";
    case ShapeType::curved_top_base: return "C curved-top-base";
    case ShapeType::bowed_lattice: return "D bowed-lattice";
    case ShapeType::sine: return "sine";
  }
  return "?";
}

std::vector<Eigen::Vector3d> shape_displacements(const PointSet& points, const ShapePerturbation& p,
                                                 const std::string& where, ShapeResult* result) {
  if (!std::isfinite(p.amount)) throw InputError("--amount", "", "must be finite");
  ShapeResult local;
  ShapeResult& r = result ? *result : local;
  r = ShapeResult{};
  const std::vector<int> bodies = resolve_bodies(points, p, where);
  const Field field = make_field(points, p, bodies, where, r.notes);

  std::vector<bool> moved(points.body_names.size(), false);
  for (int b : bodies) moved[b] = true;
  double largest_shape = 0, largest_slope = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!moved[points.body[i]]) continue;
    ++r.moved_points;
    largest_shape = std::max(largest_shape, std::abs(field.value(points.position[i])));
    largest_slope = std::max(largest_slope, field.gradient(points.position[i]).norm());
  }
  std::vector<std::string> names;
  for (int b : bodies) names.push_back(points.body_names[b]);
  if (!(largest_shape > 0))
    throw InputError(where, "/points/position", shape_label(p.type) + " moves no point of bodies " + joined(names, ",") +
                                                   " (they lie where the field is zero)");
  r.scale = 1.0 / largest_shape;
  // |∇u| = |a| s |∇f| because u = a s f e is f's gradient times a unit vector.
  r.largest_gradient = std::abs(p.amount) * r.scale * largest_slope;
  if (r.largest_gradient >= 1.0) {
    std::ostringstream os;
    os << mm(std::abs(p.amount)) << " is too large for " << shape_label(p.type) << ": the displacement gradient reaches "
       << r.largest_gradient << " (>= 1), so the perturbed geometry could fold and struts cross; the limit here is "
       << mm(1.0 / (r.scale * largest_slope));
    throw InputError("--amount", "", os.str());
  }

  std::vector<Eigen::Vector3d> u(points.size(), Eigen::Vector3d::Zero());
  const double factor = p.amount * r.scale;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!moved[points.body[i]]) continue;
    u[i] = factor * field.value(points.position[i]) * field.axis;
    r.largest_displacement = std::max(r.largest_displacement, u[i].norm());
  }

  std::ostringstream os;
  os.precision(8);
  os << shape_label(p.type) << ": amount " << mm(p.amount) << " along "
     << (p.type == ShapeType::curved_top_base ? "z, curved across " : "") << describe_direction(p.direction)
     << ", bodies " << joined(names, ",") << "; u = amount * s * f, " << field.formula << ", s = " << r.scale
     << "; max |grad u| = " << r.largest_gradient << "; " << r.moved_points << " points moved";
  r.record = os.str();
  return u;
}

ShapeResult apply_shape_perturbation(PointSet& points, const ShapePerturbation& p, const std::string& where) {
  ShapeResult r;
  const auto u = shape_displacements(points, p, where, &r);
  for (size_t i = 0; i < points.size(); ++i) {
    if (u[i] == Eigen::Vector3d::Zero()) continue;
    points.position[i] += u[i];
    if (!points.domain_vertices.empty())  // a CPDI1 domain moves with its point
      for (auto& v : points.domain_vertices[i]) v += u[i];
  }
  return r;
}

}  // namespace latmpm
