// Statistical printing defects of the struts themselves, on a strut graph (before
// voxelizing). Each is seeded (RandomStream) and acts on members (strut_members.hpp), so a
// strut made wavy stays one strut for the defects that follow. Definitions, typical
// magnitudes from the additive-manufacturing literature and sources: docs/imperfections.md.
#pragma once
#include <string>
#include <vector>

#include "imperfect/random_stream.hpp"
#include "imperfect/strut_members.hpp"

namespace latmpm {

// Each member's diameter is multiplied by a random factor X with E[X] = 1 + bias and
// sd(X) / E[X] = cov: lognormal (always positive), or normal redrawn until positive.
struct DiameterScatter {
  double cov = 0;   // coefficient of variation, 0.05 = 5 %
  double bias = 0;  // mean relative change, +0.03 = printed 3 % thicker than designed
  bool normal = false;
};

// Smooth random lateral deflection of each member from the straight line between its ends:
// δ(s) = Σ_{k=1..modes} (α_k n1 + β_k n2) sin(k π s), s ∈ [0, 1] along the member,
// α_k, β_k ~ N(0, (amplitude · ℓ / k²)²), ℓ the member's end-to-end length, n1, n2 normal to it.
// Straight members are first split into `segments` capsules so the union follows the curve.
struct Waviness {
  double amplitude = 0;  // relative to the member length
  int modes = 3;
  int segments = 8;
};

// Each junction node (a member end) moves by a Gaussian vector, sd `sigma` per axis; a node
// on a plate keeps its component normal to the plate face (it stays on the plate). Interior
// nodes of a wavy member move with the linear interpolation of its two ends.
struct NodeJitter {
  double sigma = 0;  // m
};

enum class OnDisconnected { refuse, drop, keep };

// round(fraction · members) members, chosen uniformly at random, are removed; nodes left
// without struts are removed. If the rest is not one connected body (struts and plates):
// refuse (InputError), drop the loose pieces (keeping the piece that holds the plates, or
// the largest if there are none; refused if the plates end up in different pieces), or keep
// it and say so.
struct MissingStruts {
  double fraction = 0;
  OnDisconnected on_disconnected = OnDisconnected::refuse;
};

struct DefectResult {
  std::string record;              // one line for /imperfections
  std::vector<std::string> notes;  // warnings for the user
};

// Each throws InputError naming `option` for parameters out of range; waviness and jitter
// throw when they make two members touch that did not (struts would cross), before changing
// anything.
DefectResult scatter_strut_diameters(MemberGraph& g, const DiameterScatter& d, RandomStream& random,
                                     const std::string& option, const std::string& where);
DefectResult add_waviness(MemberGraph& g, const Waviness& w, RandomStream& random, const std::string& option,
                          const std::string& where);
DefectResult jitter_nodes(MemberGraph& g, const NodeJitter& j, RandomStream& random, const std::string& option,
                          const std::string& where);
DefectResult remove_struts(MemberGraph& g, const MissingStruts& m, RandomStream& random, const std::string& option,
                           const std::string& where);

// Mean and coefficient of variation of the member diameters (each member counted once).
std::pair<double, double> member_diameter_statistics(const MemberGraph& g, const std::string& where);

}  // namespace latmpm
