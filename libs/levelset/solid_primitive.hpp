// Signed distance (negative inside) to the pieces of a strut-graph solid: capsule (round
// ends), capped cylinder (flat ends), axis-aligned box. Exact Euclidean distances, so each
// is 1-Lipschitz, which the rasteriser uses to skip whole blocks of voxels.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace latmpm {

struct SolidPrimitive {
  enum class Kind { capsule, cylinder, box } kind;
  Eigen::Vector3d a, b;  // capsule/cylinder: axis ends; box: min and max corners
  double radius = 0;     // capsule/cylinder

  double distance(const Eigen::Vector3d& p) const {
    switch (kind) {
      case Kind::capsule: {
        const Eigen::Vector3d ab = b - a;
        const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        return (p - a - t * ab).norm() - radius;
      }
      case Kind::cylinder: {
        // Distance to a finite cylinder: radial and axial excess combined as for a box in
        // (radial, axial) coordinates.
        const Eigen::Vector3d ab = b - a;
        const double length = ab.norm();
        const Eigen::Vector3d axis = ab / length;
        const double along = (p - a).dot(axis);
        const double radial = (p - a - along * axis).norm() - radius;
        const double axial = std::abs(along - 0.5 * length) - 0.5 * length;
        const double outside = std::hypot(std::max(radial, 0.0), std::max(axial, 0.0));
        return outside + std::min(std::max(radial, axial), 0.0);
      }
      case Kind::box: {
        const Eigen::Vector3d q = (p - 0.5 * (a + b)).cwiseAbs() - 0.5 * (b - a);
        return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
      }
    }
    return 0;
  }
  // Axis-aligned bounds of the solid.
  Eigen::Vector3d lower() const {
    return kind == Kind::box ? a : Eigen::Vector3d(a.cwiseMin(b).array() - radius);
  }
  Eigen::Vector3d upper() const {
    return kind == Kind::box ? b : Eigen::Vector3d(a.cwiseMax(b).array() + radius);
  }
};

}  // namespace latmpm
