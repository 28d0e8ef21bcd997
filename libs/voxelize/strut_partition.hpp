// A lattice's points partitioned into strut groups for multi-field grid contact
// (mpm/field_contact.hpp, docs/contact.md "Strut groups of a lattice"): every strut gets a
// colour, every point of the strut body the colour of its nearest strut, except the points
// of a joint zone around each graph node, which stay untagged (the body's rest field,
// bonded to every group). Struts meeting at a node are then glued through the joint and
// slide on each other away from it; same-coloured struts are one field and stick where
// they touch, so the colouring keeps them as far apart as the number of colours allows.
#pragma once
#include <string>
#include <vector>

#include "geometry/strut_graph.hpp"
#include "points/point_set.hpp"

namespace latmpm {

// Point tags of the groups: "strut_c0", "strut_c1", ... (a scene names them all with
// [contact] groups = "strut_c*").
inline constexpr const char* strut_group_tag_prefix = "strut_c";
std::string strut_group_tag(int colour);

struct StrutPartition {
  std::vector<int> colour;           // per strut, 0 … colours − 1
  std::vector<double> joint_radius;  // per node, m: points nearer than this to the node are the joint
  int colours = 0;
  // Smallest surface gap between two struts of one colour, m (axis-to-axis distance minus
  // both radii; +inf when no two share a colour): closer than this, struts of one colour
  // touch and stick.
  double same_colour_gap = 0;
};

// Joint zone of node n: R_n = max over the struts a, b at n of r_a and of (r_a + r_b) /
// (2 sin(θ_ab / 2)) — where the capsules of two struts at angle θ_ab stop overlapping, so
// no point beyond R_n lies in two struts — capped at 0.45 of the shortest strut at n (each
// strut keeps a tagged middle); a node with one strut is a joint (R_n = r) only on a
// plate (within r of its box), a free end none (R_n = 0). Colours: the struts' conflict graph joins two struts whose
// surface gap is below D (struts sharing a node always: their gap is negative), coloured
// greedily (DSatur); D is the largest gap for which that takes at most `max_colours`.
// Throws InputError if max_colours < 1 or the struts at one node need more colours.
StrutPartition partition_struts(const StrutGraph& graph, int max_colours);

// Tags the graph's strut-body points: tag strut_group_tag(c) on a point whose nearest strut
// (least capsule distance |x − axis| − r, the arg-min of the level-set union) has colour c,
// unless the point lies within the joint radius of a node. Records the partition in the
// point set's parameters ("strut_groups", "strut_group_gap").
void tag_strut_groups(PointSet& points, const StrutGraph& graph, const StrutPartition& partition);

}  // namespace latmpm
