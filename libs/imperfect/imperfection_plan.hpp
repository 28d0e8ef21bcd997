// What one latmpm-imperfect run does: an ordered list of perturbations, read from the
// command line in the order the options were given (issue 4: "applied in the order given").
//   --type T [--amount --direction --bodies --length --mode --column-bottom --layer-height]
//       one shape perturbation per --type (repeatable); its parameters follow it
//   --strut-diameter-cov / --strut-diameter-bias / --diameter-distribution   one step
//   --waviness [--waviness-modes --waviness-segments]                         one step
//   --node-jitter                                                             one step
//   --missing-struts [--disconnected]                                         one step
// A step's place in the order is where its first option appears.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "imperfect/shape_perturbation.hpp"
#include "imperfect/strut_defects.hpp"

namespace latmpm {

class CommandLine;
class Hdf5File;

struct ImperfectionStep {
  enum class Kind { shape, diameter, waviness, jitter, missing } kind = Kind::shape;
  ShapePerturbation shape;
  DiameterScatter diameter;
  Waviness waviness;
  NodeJitter jitter;
  MissingStruts missing;
  std::string option;  // the option that starts the step ("--type", "--waviness"...), for messages
};

struct ImperfectionPlan {
  std::vector<ImperfectionStep> steps;
  uint64_t seed = 1;
};

// Declares every option of the plan (and --seed) on the tool's command line.
void declare_imperfection_options(CommandLine& cl);
// Reads the steps in order. Throws UsageError for a parameter without its step (e.g.
// --amount without --type) and InputError for malformed values.
ImperfectionPlan plan_from_command_line(const CommandLine& cl);

struct ImperfectionRun {
  std::vector<std::string> records;  // one line per step, for /imperfections and the history
  std::vector<std::string> notes;    // things the user should know (fallbacks, warnings)
};

// Apply the steps in order. Statistical steps need a strut graph, shape steps a point set:
// the other kind is refused (InputError naming the option and `where`, the input file).
ImperfectionRun apply_plan(PointSet& points, const ImperfectionPlan& plan, const std::string& where);
ImperfectionRun apply_plan(MemberGraph& graph, const ImperfectionPlan& plan, const std::string& where);

}  // namespace latmpm
