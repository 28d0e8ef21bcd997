// Struts as printed members. Waviness replaces one strut by a chain of short capsules
// (segments) so that their union follows a curved axis; later defects must still treat the
// chain as one strut: one diameter, one removal, jitter at its ends only. `member` maps each
// strut (segment) of a StrutGraph to the member it belongs to.
//
// On disk: the optional dataset /geometry/strut_member (int32, M) beside the strut graph
// (docs/formats.md). Without it every strut is its own member.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/strut_graph.hpp"

namespace latmpm {

class Hdf5File;

// A strut graph together with the member of each strut (same length as graph.struts).
struct MemberGraph {
  StrutGraph graph;
  std::vector<int32_t> member;
};

struct MemberChain {
  std::vector<int32_t> nodes;   // from one end to the other (k + 1 nodes)
  std::vector<int32_t> struts;  // the k segments in chain order
};

// Every strut its own member.
std::vector<int32_t> one_member_per_strut(const StrutGraph& graph);

// The chains, indexed by member id after renumbering ids to 0..K-1 in order of first
// appearance (done in place on `member`). Throws InputError naming `where` if a member's
// segments do not form one open chain.
std::vector<MemberChain> member_chains(const StrutGraph& graph, std::vector<int32_t>& member,
                                       const std::string& where);

std::vector<int32_t> read_strut_members(const Hdf5File& file, const StrutGraph& graph);
// Writes /geometry/strut_member only when some member has more than one segment.
void write_strut_members(Hdf5File& file, const std::vector<int32_t>& member);

}  // namespace latmpm
