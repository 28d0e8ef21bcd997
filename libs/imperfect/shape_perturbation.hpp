// The shape perturbations of a printed lattice (paper A Sec. 5.3, Fig. 9) and the column
// imperfection u0(z) = a sin(π z / L) (paper A Sec. 4), applied to a point set.
//
// Each type is a displacement field u(x) = a · s · f(x) · e: a shape f, an axis e (a horizontal
// direction, or z for C) and the amount a. The scale s makes the largest displacement of any
// moved point exactly |a| (the definition of "amount"): s = 1 / max_p |f(x_p)|, which
// is 1 for A; for the others s − 1 is of order (point spacing / span), because points sit
// up to half a spacing inside the material's extent and off the crest. The exact fields are
// in docs/imperfections.md:
//   A slant-top-layer  f = clamp((z − z_a) / h, 0, 1), z_a = lattice top − h   (lattice, top_plate)
//   B slant-lattice    f = (z − z_lo) / (z_hi − z_lo), over the moved bodies    (every body)
//   C curved-top-base  f = −c(ξ) · clamp((z − z_a) / h, 0, 1), axis z, c = clamp((ξ² − ξc²) / (1 − ξc²), 0, 1)
//                      ξ = 2 (x − centre)·e / W across the top base, ξc that of its point nearest the centre
//                                                                            (lattice, top_plate)
//   D bowed-lattice    f = sin(π (z − z0) / (z1 − z0)) between the bases, 0 outside  (lattice)
//   sine               f = sin(n π (z − z0) / L) on [z0, z0 + L], 0 outside  (bodies not "*plate")
// Only points of the moved bodies change; volumes, half sizes, bodies and tags never do.
// Refused (InputError): a body not in the file, a field that moves no point, and an amount
// whose displacement gradient reaches |∇u| ≥ 1 at a moved point — beyond that the map
// x → x + u(x) may fold and struts could cross (below it the map is a contraction
// perturbation of the identity and therefore one-to-one).
#pragma once
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "points/point_set.hpp"

namespace latmpm {

enum class ShapeType { slant_top_layer, slant_lattice, curved_top_base, bowed_lattice, sine };

// "A".."D" or "sine", or the long names; anything else throws InputError naming `where`.
ShapeType parse_shape_type(const std::string& text, const std::string& where);
std::string shape_label(ShapeType type);  // "A slant-top-layer", "sine"

struct ShapePerturbation {
  ShapeType type = ShapeType::slant_top_layer;
  double amount = 1.28e-3;                     // m, largest displacement; negative reverses it
  Eigen::Vector3d direction{1, 0, 0};          // horizontal unit vector (A, B, D, sine; C: across)
  std::vector<std::string> bodies;             // bodies to move; empty = the type's default
  double layer_height = 0;                     // m, A and C: replaces the file's value when > 0
  // sine only:
  double length = 0;                           // m, L; 0 = height of the moved bodies
  int mode = 1;                                // n, half waves over L
  std::optional<double> column_bottom;         // m, z0; default the bottom of the moved bodies
};

struct ShapeResult {
  std::string record;            // one line describing what was done (for /imperfections)
  std::vector<std::string> notes;  // parameters the file lacked and what was used instead
  size_t moved_points = 0;
  double largest_displacement = 0;  // m, = |amount| unless the amount is 0
  double largest_gradient = 0;      // max |∇u| over the moved points (< 1)
  double scale = 1;                 // s above
};

// The displacement of every point (zero for points of bodies not moved), with the checks
// above. `where` names the input file in messages.
std::vector<Eigen::Vector3d> shape_displacements(const PointSet& points, const ShapePerturbation& p,
                                                 const std::string& where, ShapeResult* result = nullptr);

// Moves the points by shape_displacements(). Untouched points keep their exact coordinates.
ShapeResult apply_shape_perturbation(PointSet& points, const ShapePerturbation& p, const std::string& where);

}  // namespace latmpm
