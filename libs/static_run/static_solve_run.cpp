#include "static_run/static_solve_run.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/interruption.hpp"
#include "core/number_text.hpp"
#include "core/tool_main.hpp"
#include "run_output/run_log.hpp"
#include "run_output/run_status.hpp"
#include "run_output/series_writer.hpp"
#include "run_output/snapshot_writer.hpp"
#include "scene/scene_points.hpp"
#include "static_run/static_scene_problem.hpp"
#include "statics/elastic_energy.hpp"
#include "statics/phase_time.hpp"

namespace latmpm {

namespace {

const std::vector<SeriesColumn> static_columns = {
    {"step", "1", "converged load increments"},
    {"time", "s", "pseudo-time: platen travel / driven speed (no dynamics: a static solve)"},
    {"displacement", "m", "driven body's travel along the loading axis"},
    {"load_driven", "N", "reaction on the driven body along the loading axis, compression positive"},
    {"load_fixed", "N", "reaction on the supports against the loading axis, compression positive"},
    {"strain_energy", "J", "sum V0 psi over deformable points"},
    {"newton_iterations", "1", "projected Newton steps of the increment"},
    {"linear_iterations", "1", "linear solver iterations of the increment, abandoned attempts included (1 per direct solve, CG iterations of Krylov steps)"},
    {"residual", "1", "relative residual force at convergence"},
    {"min_jacobian", "1", "smallest det F over the points"},
    {"stable", "1", "1: the true tangent is positive definite (0: the static path ends here)"},
};

// The points at displacement u: material points at X + u(X) with σ and J; supports at
// rest, the platen moved by travel·direction.
ParticleSnapshot static_snapshot(const PointSet& points, const Scene& scene, const StaticSceneProblem& sp,
                                 const statics::Vector& u, double travel, long step, double time) {
  ParticleSnapshot s;
  s.resize(points.size());
  s.step = step;
  s.time = time;
  for (const auto& b : scene.bodies) s.body_names.push_back(b.name);
  for (size_t p = 0; p < points.size(); ++p) {
    Eigen::Vector3d x = points.position[p];
    if (scene.bodies[size_t(points.body[p])].role == BodyRole::driven) x += travel * sp.loading.direction;
    for (int a = 0; a < 3; ++a) s.position[3 * p + a] = x[a];
    s.jacobian[p] = 1;
    s.body[p] = points.body[p];
  }
  const statics::StaticProblem& problem = *sp.problem;
  const statics::NarrowBand& band = problem.band();
  for (size_t q = 0; q < sp.material_points.size(); ++q) {
    const size_t p = sp.material_points[q];
    Eigen::Vector3d x = points.position[p];
    for (uint32_t e = band.point_offset[q]; e < band.point_offset[q + 1]; ++e)
      x += band.entry_weight[e] * u.segment<3>(Eigen::Index(3 * band.entry_node[e]));
    for (int a = 0; a < 3; ++a) s.position[3 * p + a] = x[a];
    const statics::Mat3 F = problem.deformation_gradient(q, u);
    const statics::Mat3 sigma = statics::cauchy_stress(F, problem.first_piola(q, F));
    const float t6[6] = {float(sigma(0, 0)), float(sigma(0, 1)), float(sigma(0, 2)),
                         float(sigma(1, 1)), float(sigma(1, 2)), float(sigma(2, 2))};
    for (int c = 0; c < 6; ++c) s.stress[6 * p + c] = t6[c];
    s.von_mises[p] = float(mpm::von_mises(mpm::to_voigt(sigma)));
    s.jacobian[p] = float(F.determinant());
  }
  return s;
}

// Where the seconds went, wall/CPU (docs/statics.md, "Where the seconds go"). The check's
// assembly and factorisation are also in those columns; "forces, energy, line search" is
// the rest of the path.
void log_phase_times(RunLog& log, const statics::PhaseTime& set_up, const statics::PhaseTime& assembly,
                     const statics::SolverTimes& solver, const statics::PhaseTime& check,
                     const statics::PhaseTime& output, const statics::PhaseTime& path) {
  statics::PhaseTime rest = path;
  for (const statics::PhaseTime* t : {&assembly, &solver.analyse, &solver.factorise, &solver.solve, &solver.krylov, &output})
    rest.wall -= t->wall, rest.cpu -= t->cpu;
  rest.calls = 1;
  log.line("time (wall/CPU): " + statics::describe("set-up (points, band, pattern)", set_up) + ", " +
           statics::describe("assembly", assembly) + ", " + statics::describe("analysis", solver.analyse) + ", " +
           statics::describe("factorisation", solver.factorise) + ", " + statics::describe("solve", solver.solve) +
           ", " + statics::describe("Krylov (CG on the last factor)", solver.krylov) + ", " + statics::describe("forces, energy, line search", rest) + ", " + statics::describe("output", output) +
           "; of these the stability check " + statics::describe("", check).substr(1));
}
}  // namespace

StaticSolveSummary run_static_scene(const Scene& scene, Provenance provenance, const std::string& run_dir,
                                    bool progress) {
  const auto start = std::chrono::steady_clock::now();
  statics::PhaseTime set_up, output, path_time;
  std::optional<statics::PhaseTimer> set_up_timer(set_up);
  PointSet points = load_scene_points(scene, &provenance);
  StaticSceneProblem sp = make_static_problem(scene, points);
  set_up_timer.reset();
  statics::StaticProblem& problem = *sp.problem;
  const statics::LinearSolverKind solver_kind = scene.solver.statics.linear_solver;
  statics::NewtonOptions newton;
  newton.tolerance = scene.solver.statics.tolerance;
  newton.krylov_iterations = scene.solver.statics.krylov_iterations;
  newton.max_iterations = scene.solver.statics.newton_iterations;
  newton.stall_window = scene.solver.statics.stall_window;
  newton.stop_requested = [] { return interruption_signal() != 0; };

  std::filesystem::create_directories(run_dir);
  // From the first file written: a first signal stops the path between Newton steps (or before
  // its first), so the run directory always ends with its status.toml.
  InterruptionDeferral deferral;
  {
    OutputFile out(run_dir + "/scene.toml", run_dir + "/scene.toml");
    std::ofstream file(out.temp_path(), std::ios::trunc);
    file << "# Resolved scene written by " << provenance.tool << " " << provenance.version << "\n# "
         << provenance.command_line << "\n" << scene.resolved_toml;
    if (!file.flush()) throw InputError(run_dir + "/scene.toml", "", "cannot write (disk full?)");
    file.close();
    out.commit();
  }
  RunLog log(run_dir + "/log.txt");
  log.line(provenance.tool + " " + provenance.version);
  log.line("command: " + provenance.command_line);
  log.line("scene: " + scene.source + " (resolved copy: scene.toml)");
  log.line("static solve (paper C Sec. 3.3): projected Newton on the narrow band, linear solver " +
           statics::to_string(scene.solver.statics.linear_solver) + ", tolerance " +
           format_number("%g", scene.solver.statics.tolerance) + ", affine stabilisation β " +
           format_number("%g", scene.solver.statics.stabilisation));
  log.line("points: " + std::to_string(problem.point_count()) + " material, band nodes " +
           std::to_string(problem.band().node_count()) + " (" + std::to_string(problem.dof_count()) +
           " unknowns), support nodes " + std::to_string(sp.loading.support_nodes.size()) + ", platen nodes " +
           std::to_string(sp.loading.platen_nodes.size()) + ", shape " + to_string(scene.settings.shape_function) + ", cell " +
           format_number("%g", scene.settings.cell_size) + " m");
  log.line("loading: travel " + format_number("%g", sp.loading.travel) + " m in " + std::to_string(sp.loading.increments) +
           " increments" +
           (sp.contact_gap > 0 ? ", from contact (the rigid platen first closed a gap of " +
                                     format_number("%g", sp.contact_gap) + " m)"
                               : ""));

  double speed = 0;  // of the one driven body (checked by make_static_problem)
  for (const auto& b : scene.bodies)
    if (b.role == BodyRole::driven) speed = b.velocity.norm();
  for (const auto& r : scene.rigid_bodies)
    if (r.motion == mpm::RigidMotion::driven) speed = r.velocity.norm();
  SeriesWriter series(run_dir + "/series.csv", run_dir + "/series.h5", static_columns, provenance);
  SnapshotWriter snapshots(run_dir, provenance);
  statics::Vector zero = statics::Vector::Zero(Eigen::Index(problem.dof_count()));
  snapshots.write(static_snapshot(points, scene, sp, zero, 0, 0, 0));
  series.append({0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1});

  long step = 0;
  auto observe = [&](const statics::PathPoint& pt, const statics::Vector& u) {
    statics::PhaseTimer timer(output);
    ++step;
    series.append({double(step), pt.travel / speed, pt.travel, pt.load, pt.support_load, pt.energy,
                   double(pt.newton_iterations), double(pt.linear_iterations), pt.residual, pt.min_jacobian,
                   pt.stable ? 1.0 : 0.0});
    snapshots.write(static_snapshot(points, scene, sp, u, pt.travel, step, pt.travel / speed));
    const std::string line = "increment " + std::to_string(step) + ": travel " + format_number("%.6g", pt.travel) +
                             " m, load " + format_number("%.6g", pt.load) + " N, Newton " +
                             std::to_string(pt.newton_iterations) + (pt.predicted ? " from the predictor" : "") + " (" +
                             std::to_string(pt.true_tangent_steps) + " true tangent, " + std::to_string(pt.krylov_steps) +
                             " Krylov), linear " +
                             std::to_string(pt.linear_iterations) + " (last residual " +
                             format_number("%.1e", pt.linear_residual) + "), residual " + format_number("%.2e", pt.residual) +
                             ", min J " + format_number("%.4f", pt.min_jacobian) + (pt.stable ? "" : ", UNSTABLE");
    log.line(line);
    if (progress) std::cerr << "latmpm-solve: " << line << "\n";
  };
  // Iterative solves (CG, AMG) to 1e-4 of the Newton tolerance: at 1e-2 of it a linear
  // problem took two Newton steps instead of one (QUICK T2P30, docs/statics.md).
  statics::SparseSolver solver(solver_kind, 1e-4 * scene.solver.statics.tolerance);
  std::vector<statics::Vec3> node_positions(problem.band().node_count());  // the AMG's rigid-body modes
  for (size_t n = 0; n < node_positions.size(); ++n) node_positions[n] = problem.band().node_position(n);
  solver.set_node_positions(std::move(node_positions));
  // Every Newton step in the log: a paper-size increment that does not converge is tens of
  // minutes of steps (docs/statics.md), which the increment lines alone leave silent.
  newton.on_step = [&](const statics::NewtonStep& s) {
    log.line("  increment " + std::to_string(step + 1) + ", Newton step " + std::to_string(s.iteration) +
             ": residual " + format_number("%.2e", s.residual_before) + ", " +
             (s.true_tangent ? "true tangent" : "projected") + ", " +
             (s.krylov                ? "Krylov (" + std::to_string(s.linear_iterations) + " CG)"
              : solver.is_direct()   ? std::string("factorised")
                                     : std::to_string(s.linear_iterations) + " iterations") +
             ", step " + format_number("%.3g", s.alpha));
  };
  newton.on_failure = [&](const std::string& why) {
    log.line("  increment " + std::to_string(step + 1) + ": Newton failed: " + why);
  };
  std::optional<statics::PhaseTimer> path_timer(path_time);
  const statics::PathReport path = statics::load_by_platen(problem, sp.loading, solver, newton, observe);
  path_timer.reset();
  log.line("linear solver: " + solver.describe());
  if (sp.loading.check_stability || path.cut_backs > 0)
    log.line("stability checks answered by Newton's last factorisation: " + std::to_string(path.checks_from_newton) +
             "; increments cut back after a Newton failure: " + std::to_string(path.cut_backs));
  log_phase_times(log, set_up, problem.assembly_time(), solver.times(), path.stability_check, output, path_time);
  series.save();

  StaticSolveSummary s;
  s.increments = int(step);
  s.points = problem.point_count();
  s.unknowns = problem.dof_count();
  s.travel = path.last_stable_travel;
  // A non-positive-definite tangent and a load maximum are both ends of a stable path (the
  // run's answer); only a Newton failure is a failed run.
  const bool instability = path.end_reason == "tangent not positive definite" || path.end_reason == "load maximum";
  s.status = !path.ended ? "finished" : path.stopped ? "interrupted" : instability ? "unstable" : "not converged";
  if (path.stopped) {
    s.signal = interruption_signal();
    log.line(std::string("stopped by ") + signal_name(s.signal) + " after " + std::to_string(step) +
             " increments (last converged travel " + format_number("%.6g", path.last_stable_travel) +
             " m, load " + format_number("%.6g", path.last_stable_load) +
             " N): the series and snapshots hold them; a static solve has no checkpoint");
  } else if (path.ended) {
    s.end_travel = path.end_travel;
    s.end_load = path.end_load;
    log.line("the static path ends (" + path.end_reason + ") at travel " + format_number("%.6g", path.end_travel) +
             " m, load " + format_number("%.6g", path.end_load) + " N (last stable: " +
             format_number("%.6g", path.last_stable_travel) + " m, " + format_number("%.6g", path.last_stable_load) + " N)");
  }
  s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The run's status as every latmpm-solve run names it (status.toml, the log's last line).
  const std::string run_status = s.status == "not converged" ? "failed" : path.stopped ? "interrupted" : "finished";
  RunOutcome outcome;  // RUN_DIR/status.toml, as every latmpm-solve run writes it
  outcome.status = run_status;
  outcome.exit_status = path.stopped ? exit_signal_base + s.signal : 0;
  // Where the path ends, for pipelines reading status.toml (pipelines/lattice-stiffness/table.sh).
  outcome.reason = path.stopped ? std::string("stopped by ") + signal_name(s.signal)
                   : path.ended ? "the static path ends (" + path.end_reason + ") at travel " +
                                    format_number("%.6g", path.end_travel) + " m, load " +
                                    format_number("%.6g", path.end_load) + " N"
                              : "";
  outcome.steps = s.increments;
  outcome.simulated_time = s.travel / speed;
  outcome.points = points.size();
  outcome.wall_seconds = process_wall_seconds();
  outcome.cpu_seconds = process_cpu_seconds();
  outcome.stepping_wall_seconds = s.wall_seconds;
  outcome.peak_memory_mb = process_peak_memory_mb();
  write_run_status(run_dir, outcome, provenance);
  // latmpm-post reads "status:" (finished / failed) and "stopped:" (why) lines.
  if (path.ended && !path.stopped)
    log.line("stopped: the static path ends (" + path.end_reason + ") at travel " + format_number("%.6g", path.end_travel) + " m");
  log.line("status: " + run_status + " (static " + s.status +
           "), " + std::to_string(s.increments) + " increments, wall " + format_number("%.2f", s.wall_seconds) + " s");
  return s;
}

}  // namespace latmpm
