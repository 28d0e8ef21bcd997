#include "imperfect/imperfection_plan.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "imperfect/direction.hpp"

namespace latmpm {
namespace {

const std::set<std::string> shape_parameters = {"amount", "direction", "bodies", "length", "mode", "column-bottom", "layer-height"};
// Statistical step of each option, by the option that names the step.
const std::map<std::string, std::string> statistical_step_of = {
    {"strut-diameter-cov", "strut-diameter-cov"}, {"strut-diameter-bias", "strut-diameter-cov"},
    {"diameter-distribution", "strut-diameter-cov"}, {"waviness", "waviness"}, {"waviness-modes", "waviness"},
    {"waviness-segments", "waviness"}, {"node-jitter", "node-jitter"}, {"missing-struts", "missing-struts"},
    {"disconnected", "missing-struts"}};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= text.size()) {
    size_t comma = text.find(',', start);
    if (comma == std::string::npos) comma = text.size();
    if (comma > start) out.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return out;
}

long whole_number(const std::string& text, const std::string& option) {
  char* end = nullptr;
  long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0') throw InputError(option, "", "'" + text + "' is not a whole number");
  return v;
}

// Options that take no value: latmpm-imperfect's flags (CommandLine::flag).
const std::set<std::string> flags_without_value = {"quiet", "help", "version"};

// Options in the order given: (name, value) pairs, from argv as the parser accepted it
// (CommandLine keeps values, not their order across options).
std::vector<std::pair<std::string, std::string>> options_in_order(const CommandLine& cl) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto& argv = cl.argv();
  for (size_t i = 1; i < argv.size(); ++i) {
    const std::string& arg = argv[i];
    if (arg == "--") break;
    if (arg == "-o") {
      ++i;
      continue;
    }
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) continue;
    std::string name = arg.substr(2), value;
    if (auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    } else if (!flags_without_value.count(name) && i + 1 < argv.size()) {
      value = argv[++i];
    }
    out.emplace_back(name, value);
  }
  return out;
}

ShapePerturbation read_shape(const std::map<std::string, std::string>& given, const std::string& type_text) {
  ShapePerturbation p;
  p.type = parse_shape_type(type_text, "--type");
  auto has = [&](const char* k) { return given.count(k) > 0; };
  if (has("amount")) {
    p.amount = parse_quantity(given.at("amount"), dimension::length, "--amount");
  } else if (p.type == ShapeType::sine) {
    throw InputError("--amount", "", "--type sine needs an amplitude (paper A uses a = 0.02 L, e.g. 0.32mm for L = 16mm)");
  }
  if (has("direction")) p.direction = parse_horizontal_direction(given.at("direction"), "--direction");
  if (has("bodies")) {
    p.bodies = split_list(given.at("bodies"));
    if (p.bodies.empty()) throw InputError("--bodies", "", "names no body");
  }
  if (has("layer-height")) {
    p.layer_height = parse_quantity(given.at("layer-height"), dimension::length, "--layer-height");
    if (!(p.layer_height > 0)) throw InputError("--layer-height", "", "must be positive");
  }
  const bool sine = p.type == ShapeType::sine;
  for (const char* k : {"length", "mode", "column-bottom"})
    if (has(k) && !sine) throw UsageError(std::string("--") + k + " belongs to --type sine, not --type " + type_text);
  if (has("length")) {
    p.length = parse_quantity(given.at("length"), dimension::length, "--length");
    if (!(p.length > 0)) throw InputError("--length", "", "must be positive");
  }
  if (has("mode")) {
    p.mode = static_cast<int>(whole_number(given.at("mode"), "--mode"));
    if (p.mode < 1) throw InputError("--mode", "", "must be 1 or more");
  }
  if (has("column-bottom")) p.column_bottom = parse_quantity(given.at("column-bottom"), dimension::length, "--column-bottom");
  return p;
}

double fraction(const CommandLine& cl, const std::string& name) {
  return parse_quantity(cl.text(name), dimension::none, "--" + name);
}

}  // namespace

void declare_imperfection_options(CommandLine& cl) {
  cl.repeated_option("type", "T", "shape perturbation of a point set: A|slant-top-layer, B|slant-lattice, "
                                  "C|curved-top-base, D|bowed-lattice, sine; repeat for several, in order");
  cl.repeated_option("amount", "LEN", "largest displacement of any point, for the --type before it [A-D: 1.28mm; sine: required]");
  cl.repeated_option("direction", "DIR", "horizontal direction: x, y, -x, -y or an angle from +x towards +y (30deg) [x]; "
                                         "C: the direction across which the top base curves");
  cl.repeated_option("bodies", "NAMES", "comma-separated bodies to move [A, C: lattice,top_plate; B: all; D: lattice; "
                                        "sine: bodies not named *plate]");
  cl.repeated_option("layer-height", "LEN", "A, C: height of the top cell layer [from the file's parameters]");
  cl.repeated_option("length", "LEN", "sine: column length L [height of the moved bodies]");
  cl.repeated_option("mode", "N", "sine: number of half waves over L [1]");
  cl.repeated_option("column-bottom", "Z", "sine: height z0 where the sine starts [bottom of the moved bodies]");
  cl.option("strut-diameter-cov", "PCT", "strut graph: scatter of strut diameters, coefficient of variation (typical 3-10%)");
  cl.option("strut-diameter-bias", "PCT", "strut graph: mean change of strut diameters, e.g. 5% thicker than designed");
  cl.option("diameter-distribution", "D", "lognormal, or normal (redrawn until positive) [lognormal]");
  cl.option("waviness", "PCT", "strut graph: random smooth lateral deflection, sd of the first mode / strut length (typical 0.5-3%)");
  cl.option("waviness-modes", "N", "sine modes in the deflection, mode k with sd amplitude/k^2 [3]");
  cl.option("waviness-segments", "N", "capsules a straight strut is split into to follow its curve [8]");
  cl.option("node-jitter", "LEN", "strut graph: Gaussian displacement of strut junctions, sd per axis (typical 0.02-0.1mm)");
  cl.option("missing-struts", "PCT", "strut graph: fraction of struts removed at random (typical 0-2%)");
  cl.option("disconnected", "WHAT", "when removal splits the body: refuse, drop (the loose pieces) or keep [refuse]");
  cl.option("seed", "N", "seed of the statistical defects: the same seed gives the same file", "1");
}

ImperfectionPlan plan_from_command_line(const CommandLine& cl) {
  ImperfectionPlan plan;
  const long seed = cl.integer("seed");
  if (seed < 0) throw InputError("--seed", "", "must be zero or positive");
  plan.seed = static_cast<uint64_t>(seed);

  // 1. Group the options into steps, in order.
  struct Pending {
    std::string starter;                       // "type" or a statistical step's main option
    std::string type_text;
    std::map<std::string, std::string> given;  // shape parameters
  };
  std::vector<Pending> pending;
  std::vector<std::pair<std::string, std::string>> orphans;  // shape parameters before any --type
  std::set<std::string> statistical_seen;
  bool any_type = false;
  for (const auto& [name, value] : options_in_order(cl)) {
    if (name == "type") {
      pending.push_back({"type", value, {}});
      if (!any_type)  // parameters given before the first --type belong to it
        for (const auto& [k, v] : orphans) pending.back().given[k] = v;
      any_type = true;
    } else if (shape_parameters.count(name)) {
      auto last = std::find_if(pending.rbegin(), pending.rend(), [](const Pending& p) { return p.starter == "type"; });
      if (last == pending.rend()) {
        orphans.emplace_back(name, value);
        continue;
      }
      if (last->given.count(name))
        throw UsageError("--" + name + " given twice for one --type " + last->type_text + " (each --type takes its own)");
      last->given[name] = value;
    } else if (auto it = statistical_step_of.find(name); it != statistical_step_of.end()) {
      if (statistical_seen.insert(it->second).second) pending.push_back({it->second, "", {}});
    }
  }
  if (!orphans.empty() && !any_type) throw UsageError("--" + orphans.front().first + " needs a --type to apply to");

  // 2. Read each step's values.
  for (const Pending& p : pending) {
    ImperfectionStep step;
    step.option = "--" + p.starter;
    if (p.starter == "type") {
      step.kind = ImperfectionStep::Kind::shape;
      step.shape = read_shape(p.given, p.type_text);
    } else if (p.starter == "strut-diameter-cov") {
      step.kind = ImperfectionStep::Kind::diameter;
      if (cl.given("strut-diameter-cov")) step.diameter.cov = fraction(cl, "strut-diameter-cov");
      else step.option = "--strut-diameter-bias";
      if (cl.given("strut-diameter-bias")) step.diameter.bias = fraction(cl, "strut-diameter-bias");
      const std::string distribution = cl.given("diameter-distribution") ? cl.text("diameter-distribution") : "lognormal";
      if (distribution != "lognormal" && distribution != "normal")
        throw InputError("--diameter-distribution", "", "'" + distribution + "' is not lognormal or normal");
      step.diameter.normal = distribution == "normal";
      if (!cl.given("strut-diameter-cov") && !cl.given("strut-diameter-bias"))
        throw UsageError("--diameter-distribution needs --strut-diameter-cov or --strut-diameter-bias");
    } else if (p.starter == "waviness") {
      step.kind = ImperfectionStep::Kind::waviness;
      if (!cl.given("waviness")) throw UsageError("--waviness-modes and --waviness-segments need --waviness");
      step.waviness.amplitude = fraction(cl, "waviness");
      if (cl.given("waviness-modes")) step.waviness.modes = static_cast<int>(cl.integer("waviness-modes"));
      if (cl.given("waviness-segments")) step.waviness.segments = static_cast<int>(cl.integer("waviness-segments"));
    } else if (p.starter == "node-jitter") {
      step.kind = ImperfectionStep::Kind::jitter;
      step.jitter.sigma = cl.quantity("node-jitter", dimension::length);
    } else if (p.starter == "missing-struts") {
      step.kind = ImperfectionStep::Kind::missing;
      if (!cl.given("missing-struts")) throw UsageError("--disconnected needs --missing-struts");
      step.missing.fraction = fraction(cl, "missing-struts");
      const std::string what = cl.given("disconnected") ? cl.text("disconnected") : "refuse";
      if (what == "refuse") step.missing.on_disconnected = OnDisconnected::refuse;
      else if (what == "drop") step.missing.on_disconnected = OnDisconnected::drop;
      else if (what == "keep") step.missing.on_disconnected = OnDisconnected::keep;
      else throw InputError("--disconnected", "", "'" + what + "' is not refuse, drop or keep");
    }
    plan.steps.push_back(step);
  }
  return plan;
}

ImperfectionRun apply_plan(PointSet& points, const ImperfectionPlan& plan, const std::string& where) {
  ImperfectionRun run;
  for (const auto& step : plan.steps) {
    if (step.kind != ImperfectionStep::Kind::shape)
      throw InputError(step.option, "", "acts on strut graphs (before voxelizing), but " + where + " holds a point set");
    ShapeResult r = apply_shape_perturbation(points, step.shape, where);
    run.records.push_back(r.record);
    for (auto& n : r.notes) run.notes.push_back(shape_label(step.shape.type) + ": " + n);
  }
  return run;
}

ImperfectionRun apply_plan(MemberGraph& graph, const ImperfectionPlan& plan, const std::string& where) {
  ImperfectionRun run;
  for (size_t i = 0; i < plan.steps.size(); ++i) {
    const auto& step = plan.steps[i];
    // One random stream per step, so a step's draws depend on the seed and its place only.
    RandomStream random(plan.seed, 1 + i);
    DefectResult r;
    switch (step.kind) {
      case ImperfectionStep::Kind::shape:
        throw InputError("--type", "", shape_label(step.shape.type) + " acts on point sets (voxelize first), but " + where +
                                           " holds a strut graph");
      case ImperfectionStep::Kind::diameter: r = scatter_strut_diameters(graph, step.diameter, random, step.option, where); break;
      case ImperfectionStep::Kind::waviness: r = add_waviness(graph, step.waviness, random, step.option, where); break;
      case ImperfectionStep::Kind::jitter: r = jitter_nodes(graph, step.jitter, random, step.option, where); break;
      case ImperfectionStep::Kind::missing: r = remove_struts(graph, step.missing, random, step.option, where); break;
    }
    run.records.push_back(r.record + " (seed " + std::to_string(plan.seed) + ", step " + std::to_string(i + 1) + ")");
    run.notes.insert(run.notes.end(), r.notes.begin(), r.notes.end());
  }
  return run;
}

}  // namespace latmpm
