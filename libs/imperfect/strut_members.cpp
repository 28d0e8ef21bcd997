#include "imperfect/strut_members.hpp"

#include <algorithm>
#include <map>
#include <numeric>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"

namespace latmpm {

std::vector<int32_t> one_member_per_strut(const StrutGraph& graph) {
  std::vector<int32_t> member(graph.struts.size());
  std::iota(member.begin(), member.end(), 0);
  return member;
}

std::vector<MemberChain> member_chains(const StrutGraph& graph, std::vector<int32_t>& member,
                                       const std::string& where) {
  if (member.size() != graph.struts.size())
    throw InputError(where, "/geometry/strut_member", "length differs from /geometry/struts");
  std::map<int32_t, int32_t> renumber;
  for (auto& m : member) {
    auto it = renumber.emplace(m, static_cast<int32_t>(renumber.size())).first;
    m = it->second;
  }
  std::vector<std::vector<int32_t>> segments(renumber.size());
  for (size_t s = 0; s < member.size(); ++s) segments[member[s]].push_back(static_cast<int32_t>(s));

  std::vector<MemberChain> chains(segments.size());
  for (size_t m = 0; m < segments.size(); ++m) {
    const auto& segs = segments[m];
    MemberChain& chain = chains[m];
    if (segs.size() == 1) {
      chain.nodes = {graph.struts[segs[0]].a, graph.struts[segs[0]].b};
      chain.struts = segs;
      continue;
    }
    // Walk the path from an end (a node used by one segment of the member).
    std::map<int32_t, std::vector<int32_t>> at_node;
    for (int32_t s : segs) {
      at_node[graph.struts[s].a].push_back(s);
      at_node[graph.struts[s].b].push_back(s);
    }
    int32_t start = -1;
    for (const auto& [node, list] : at_node) {
      if (list.size() > 2) start = -2;
      if (list.size() == 1 && start == -1) start = node;
    }
    auto not_a_chain = [&] {
      return InputError(where, "/geometry/strut_member", "member " + std::to_string(m) + " is not one open chain of struts");
    };
    if (start < 0) throw not_a_chain();
    chain.nodes.push_back(start);
    int32_t previous = -1, node = start;
    while (chain.struts.size() < segs.size()) {
      int32_t next_strut = -1;
      for (int32_t s : at_node[node])
        if (s != previous) next_strut = s;
      if (next_strut < 0) throw not_a_chain();
      const Strut& st = graph.struts[next_strut];
      node = st.a == node ? st.b : st.a;
      chain.struts.push_back(next_strut);
      chain.nodes.push_back(node);
      previous = next_strut;
    }
    if (at_node[node].size() != 1) throw not_a_chain();
  }
  return chains;
}

std::vector<int32_t> read_strut_members(const Hdf5File& file, const StrutGraph& graph) {
  if (!file.exists("/geometry/strut_member")) return one_member_per_strut(graph);
  auto member = file.read_int32("/geometry/strut_member");
  if (member.size() != graph.struts.size())
    throw InputError(file.path(), "/geometry/strut_member", "length differs from /geometry/struts");
  return member;
}

void write_strut_members(Hdf5File& file, const std::vector<int32_t>& member) {
  std::vector<int32_t> sorted = member;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) return;  // all single
  file.write("/geometry/strut_member", member, {member.size()});
}

}  // namespace latmpm
