// Which struts touch? Two members (see strut_members.hpp) touch when some segment capsule of
// one overlaps some segment capsule of the other: the distance between their axes is less
// than the sum of their radii. Members that share a node always touch there and are left
// out. The criterion for "a defect makes struts cross" (docs/imperfections.md): a pair that
// did not touch before the defect touches after it.
#pragma once
#include <Eigen/Core>
#include <map>
#include <utility>
#include <vector>

#include "imperfect/strut_members.hpp"

namespace latmpm {

// Touching pairs (i < j, member ids) with a point between the two axes where they are closest.
std::map<std::pair<int, int>, Eigen::Vector3d> touching_members(const StrutGraph& graph,
                                                                const std::vector<MemberChain>& chains);

// Shortest distance between the segments [p0, p1] and [q0, q1]; `midpoint` receives the
// middle of the closest pair of points. (Ericson, Real-Time Collision Detection, Sec. 5.1.9.)
double segment_distance(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& q0,
                        const Eigen::Vector3d& q1, Eigen::Vector3d* midpoint = nullptr);

}  // namespace latmpm
