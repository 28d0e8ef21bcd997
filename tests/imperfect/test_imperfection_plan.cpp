#include <catch2/catch.hpp>

#include <initializer_list>

#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "imperfect/imperfection_plan.hpp"
#include "synthetic_inputs.hpp"

using namespace latmpm;
using Kind = ImperfectionStep::Kind;

namespace {

ImperfectionPlan plan_of(std::initializer_list<const char*> args) {
  CommandLine cl("latmpm-imperfect", "test");
  cl.positional("input", "input");
  cl.option("output", "PATH", "output");
  cl.alias('o', "output");
  declare_imperfection_options(cl);
  cl.flag("quiet", "quiet");
  std::vector<const char*> argv{"latmpm-imperfect"};
  argv.insert(argv.end(), args.begin(), args.end());
  cl.parse(static_cast<int>(argv.size()), argv.data());
  return plan_from_command_line(cl);
}

}  // namespace

TEST_CASE("Steps come in the order their options were given, each --type with its own parameters", "[imperfect][plan]") {
  const auto plan = plan_of({"in.h5", "-o", "out.h5", "--type", "A", "--amount", "1mm", "--quiet", "--type", "bowed-lattice",
                             "--direction=y", "--amount", "0.5mm", "--bodies", "lattice,top_plate"});
  REQUIRE(plan.steps.size() == 2);
  CHECK(plan.steps[0].shape.type == ShapeType::slant_top_layer);
  CHECK(plan.steps[0].shape.amount == Approx(1e-3));
  CHECK(plan.steps[0].shape.direction == Eigen::Vector3d(1, 0, 0));
  CHECK(plan.steps[1].shape.type == ShapeType::bowed_lattice);
  CHECK(plan.steps[1].shape.amount == Approx(0.5e-3));
  CHECK(plan.steps[1].shape.direction == Eigen::Vector3d(0, 1, 0));
  CHECK(plan.steps[1].shape.bodies == std::vector<std::string>{"lattice", "top_plate"});

  const auto defects = plan_of({"in.h5", "-o", "-", "--waviness", "1%", "--seed", "9", "--strut-diameter-bias", "3%",
                                "--node-jitter", "0.05mm", "--strut-diameter-cov", "5%", "--missing-struts", "1%"});
  REQUIRE(defects.steps.size() == 4);
  CHECK(defects.seed == 9);
  CHECK(defects.steps[0].kind == Kind::waviness);
  CHECK(defects.steps[0].waviness.amplitude == Approx(0.01));
  CHECK(defects.steps[1].kind == Kind::diameter);  // placed by its first option, the bias
  CHECK(defects.steps[1].diameter.cov == Approx(0.05));
  CHECK(defects.steps[1].diameter.bias == Approx(0.03));
  CHECK(defects.steps[2].kind == Kind::jitter);
  CHECK(defects.steps[2].jitter.sigma == Approx(0.05e-3));
  CHECK(defects.steps[3].kind == Kind::missing);
}

TEST_CASE("Parameters before the first --type belong to it; the paper's amount is the default", "[imperfect][plan]") {
  const auto plan = plan_of({"in.h5", "-o", "x.h5", "--amount", "2mm", "--type", "B", "--type", "C"});
  REQUIRE(plan.steps.size() == 2);
  CHECK(plan.steps[0].shape.amount == Approx(2e-3));
  CHECK(plan.steps[1].shape.amount == Approx(1.28e-3));
}

TEST_CASE("Malformed plans are refused with the option named", "[imperfect][plan]") {
  CHECK_THROWS_AS(plan_of({"in.h5", "-o", "x.h5", "--amount", "1mm"}), UsageError);
  CHECK_THROWS_WITH(plan_of({"in.h5", "-o", "x.h5", "--type", "C", "--amount", "1.28"}), Catch::StartsWith("--amount"));
  CHECK_THROWS_WITH(plan_of({"in.h5", "-o", "x.h5", "--type", "E"}), Catch::StartsWith("--type"));
  CHECK_THROWS_WITH(plan_of({"in.h5", "-o", "x.h5", "--type", "sine"}), Catch::StartsWith("--amount"));
  CHECK_THROWS_AS(plan_of({"in.h5", "-o", "x.h5", "--type", "A", "--amount", "1mm", "--amount", "2mm"}), UsageError);
  CHECK_THROWS_AS(plan_of({"in.h5", "-o", "x.h5", "--type", "A", "--mode", "2"}), UsageError);
  CHECK_THROWS_WITH(plan_of({"in.h5", "-o", "x.h5", "--node-jitter", "0.1"}), Catch::StartsWith("--node-jitter"));
  CHECK_THROWS_WITH(plan_of({"in.h5", "-o", "x.h5", "--missing-struts", "1%", "--disconnected", "ignore"}),
                    Catch::StartsWith("--disconnected"));
}

TEST_CASE("Composition follows the order given: C then A differs from A then C", "[imperfect][plan]") {
  // C moves points vertically and A's shear depends on height, so the two do not commute.
  const PointSet start = test::printed_block();
  auto run = [&](std::initializer_list<const char*> args) {
    PointSet p = start;
    const auto r = apply_plan(p, plan_of(args), "block");
    return std::make_pair(p, r.records);
  };
  const auto [ca, ca_records] = run({"in.h5", "-o", "x.h5", "--type", "C", "--type", "A"});
  const auto [ac, ac_records] = run({"in.h5", "-o", "x.h5", "--type", "A", "--type", "C"});
  // The same result as applying the two by hand in that order.
  PointSet by_hand = start;
  ShapePerturbation c;
  c.type = ShapeType::curved_top_base;
  ShapePerturbation a;
  a.type = ShapeType::slant_top_layer;
  apply_shape_perturbation(by_hand, c, "block");
  apply_shape_perturbation(by_hand, a, "block");
  CHECK(ca.position == by_hand.position);
  CHECK(ac.position != by_hand.position);
  REQUIRE(ca_records.size() == 2);
  CHECK_THAT(ca_records[0], Catch::StartsWith("C curved-top-base"));
  CHECK_THAT(ac_records[0], Catch::StartsWith("A slant-top-layer"));
}

TEST_CASE("A step that needs the other kind of input is refused", "[imperfect][plan]") {
  PointSet p = test::printed_block();
  CHECK_THROWS_WITH(apply_plan(p, plan_of({"in.h5", "-o", "x.h5", "--waviness", "1%"}), "block.h5"),
                    Catch::StartsWith("--waviness") && Catch::Contains("strut graph"));
  MemberGraph g;
  CHECK_THROWS_WITH(apply_plan(g, plan_of({"in.h5", "-o", "x.h5", "--type", "D"}), "lattice.h5"),
                    Catch::StartsWith("--type") && Catch::Contains("point set"));
}
