#include "run_output/solve_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"
#include "core/interruption.hpp"
#include "core/machine.hpp"
#include "core/progress.hpp"
#include "core/tool_main.hpp"
#include "core/number_text.hpp"
#include "core/text.hpp"
#include "mpm/checkpoint_io.hpp"
#include "mpm/simulation.hpp"
#include "points/point_set.hpp"
#include "run_output/run_log.hpp"
#include "run_output/run_status.hpp"
#include "run_output/scene_simulation.hpp"
#include "run_output/snapshot_writer.hpp"
#include "run_output/solver_series.hpp"
#include "scene/driven_body_reach.hpp"
#include "scene/scene_points.hpp"

namespace fs = std::filesystem;

namespace latmpm {
namespace {


double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// How the processes shared the run (docs/cluster.md): particles per process now, and the
// halo and migration bytes a process sent per step (mean over the processes). Collective.
std::string domain_summary(const mpm::Simulation& sim, int64_t first_step) {
  const auto& domain = sim.domain();
  const double local = double(sim.particles().size()), steps = double(std::max<int64_t>(sim.step_count() - first_step, 1));
  const double fewest = domain.reduce_min(local), most = domain.reduce_max(local);
  const auto traffic = domain.traffic();
  const double processes = domain.process_count();
  const double halo = domain.reduce_sum(double(traffic.halo_bytes)) / processes / steps;
  const double nodes = domain.reduce_sum(double(traffic.halo_nodes)) / processes / steps;
  const double migration = domain.reduce_sum(double(traffic.migration_bytes)) / processes / steps;
  return "processes: " + format_number("%.0f", fewest) + " to " + format_number("%.0f", most) +
         " particles each; per process and step " + format_number("%.4g", nodes) + " halo nodes sent, " +
         format_number("%.4g", halo) + " halo bytes, " + format_number("%.4g", migration) + " migration bytes";
}

}  // namespace

SolveRun::SolveRun(Scene scene, Provenance provenance, const SolveOptions& options)
    : scene_(std::move(scene)), provenance_(std::move(provenance)), options_(options) {
  PointSet points = load_scene_points(scene_, &provenance_);
  if (std::abs(points.cell_size - scene_.settings.cell_size) > 1e-9 * scene_.settings.cell_size) {
    std::ostringstream note;
    note << "note: the points were made for a " << points.cell_size * 1e3 << " mm cell, the grid has "
         << scene_.settings.cell_size * 1e3 << " mm";
    points_summary_ += note.str() + "\n";
  }
  for (const std::string& warning : driven_body_warnings(scene_, points)) points_summary_ += warning + "\n";
  std::vector<size_t> count(points.body_names.size(), 0);
  for (int32_t b : points.body) ++count[b];
  for (size_t b = 0; b < count.size(); ++b)
    points_summary_ += "body " + points.body_names[b] + " (" + to_string(scene_.bodies[b].role) +
                       "): " + std::to_string(count[b]) + " points\n";
  if (!scene_.quasi_static_note.empty()) points_summary_ += scene_.quasi_static_note + "\n";
  for (const BodySpec& b : scene_.omitted_bodies)
    points_summary_ += "body " + b.name + " (omitted): its points are not simulated\n";
  simulation_ = std::make_unique<mpm::Simulation>(points, solver_bodies(scene_),
                                                  solver_settings(scene_, options_.threads), scene_.where);
  specimen_area_ = mpm::AverageStressForce::initial_cross_section(*simulation_, loading_axis(scene_));
  for (const auto& r : solver_rigid_bodies(scene_)) {
    simulation_->add_rigid_body(r);
    points_summary_ += "rigid body " + r.name + " (" + mpm::to_string(r.motion) + " " + mpm::to_string(r.shape) +
                       (r.motion == mpm::RigidMotion::free ? ", " + format_number("%g", r.mass) + " kg" : std::string()) +
                       ", velocity " + format_number("%g", r.velocity.x()) + " " + format_number("%g", r.velocity.y()) + " " +
                       format_number("%g", r.velocity.z()) + " m/s)\n";
  }
}

SolveRun::~SolveRun() = default;

bool SolveRun::writes_output() const { return simulation_->domain().rank() == 0; }

SolveSummary SolveRun::run(const std::string& run_dir) {
  const InterruptionDeferral stop_between_steps;  // a signal stops the run after its step, saved
  mpm::Simulation& sim = *simulation_;
  // On several MPI processes (docs/cluster.md) every process steps and takes part in the
  // outputs' sums and gathers; rank 0 alone writes the run directory.
  const bool writer = writes_output();
  const bool several = sim.domain().process_count() > 1;
  std::error_code ec;
  if (writer) {
    fs::create_directories(run_dir, ec);
    if (ec || !fs::is_directory(run_dir))
      throw InputError(run_dir, "", "cannot create the run directory" + (ec ? ": " + ec.message() : ""));
    // Staging files of a run killed outright (SIGKILL) while it saved.
    for (const std::string& dir : {run_dir, run_dir + "/snapshots"}) remove_stale_temporaries(dir);
  }

  // 1. What is run: the resolved scene and the head of the log. A resumed run first takes
  //    the state of its checkpoint.
  const std::string checkpoint_path = run_dir + "/checkpoint.h5";
  std::vector<XdmfFrame> kept_frames;
  double wall_before = 0;
  RunOutcome before;  // the earlier parts of a resumed run: their wall and CPU time
  if (options_.resume) {
    if (!fs::is_regular_file(checkpoint_path))
      throw InputError(checkpoint_path, "", "no checkpoint to resume from (the run wrote none)");
    Hdf5File file(checkpoint_path, Hdf5File::Mode::read);
    sim.load_state(file, "/state");  // checks the state as it reads it
    // The outputs: the snapshots written so far, checked as they are read.
    const mpm::CheckpointReader output = mpm::CheckpointReader(file, "/state").group("/output");
    const ValueRange non_negative{0, std::numeric_limits<double>::max()};
    const auto names = output.strings("frame_files");
    const auto times = output.rows<double>("frame_times", names.size(), non_negative);
    const auto steps = output.rows<int64_t>("frame_steps", names.size(), {0, double(sim.step_count())});
    const double all_points = sim.domain().reduce_sum(double(sim.particles().size()));  // each process holds its share
    const auto points = output.rows<int64_t>("frame_points", names.size(), {0, all_points});
    // The frames' extra scalars are the run's material history columns, the same in every
    // frame: those its checkpoint holds (a column it lacks, derived on loading, was not in
    // the earlier run's snapshots either: Simulation::load_state).
    std::vector<std::string> history;
    for (const auto& column : sim.particles().history)
      if (file.exists("/state/particles/" + column.name)) history.push_back(column.name);
    for (size_t i = 0; i < names.size(); ++i)
      kept_frames.push_back({names[i], times[i], steps[i], size_t(points[i]), history});
    wall_before = output.attribute("wall_seconds", non_negative);
    before.stepping_wall_seconds = wall_before;
    if (output.has_attribute("cpu_seconds")) {  // checkpoints written since status.toml
      before.cpu_seconds = output.attribute("cpu_seconds", non_negative);
      before.wall_seconds = output.attribute("process_wall_seconds", non_negative);
    }
  } else if (writer) {
    // A checkpoint left by an earlier run in this directory is not this run's state: resuming
    // from it after this run is stopped would splice two runs together.
    fs::remove(checkpoint_path, ec);
    if (ec) throw InputError(checkpoint_path, "", "cannot remove the earlier run's checkpoint: " + ec.message());
  }
  if (writer)
    write_file_atomically(run_dir + "/scene.toml",
                        "# Resolved scene written by " + provenance_.tool + " " + provenance_.version +
                            "\n# " + provenance_.command_line + "\n" + scene_.resolved_toml,
                        run_dir + "/scene.toml");
  RunLog log(writer ? run_dir + "/log.txt" : "", options_.resume);
  if (several)
    log.line("processes: " + std::to_string(sim.domain().process_count()) +
             " (MPI); rank 0 writes the run directory, every process its rows of each snapshot and "
             "checkpoint (parallel HDF5; docs/cluster.md)");
  if (options_.resume)
    log.line("resumed from checkpoint.h5 at step " + std::to_string(sim.step_count()) + ", t = " +
             format_number("%.9g", sim.time()) + " s (" + format_number("%.1f", wall_before) + " s of wall time before)");
  const double end = end_time(scene_);
  const Eigen::Vector3d axis = loading_axis(scene_);
  // Every process's (a resumed run on several processes holds its share already).
  const size_t particles = size_t(sim.domain().reduce_sum(double(sim.particles().size())));
  log.line(provenance_.tool + " " + provenance_.version);
  log.line("machine: " + cpu_model() + ", " + std::to_string(usable_cpus()) + " CPUs usable, built for " +
           vector_instruction_set() + ", " + mpm::precision_name + " precision");
  log.line("command: " + provenance_.command_line);
  log.line("scene: " + scene_.source + " (resolved copy: scene.toml)");
  for (const auto& f : scene_.point_files) log.line("points: " + f.path);
  std::istringstream summary(points_summary_);
  for (std::string l; std::getline(summary, l);) log.line(l);
  log.line("grid: cell " + format_number("%g", scene_.settings.cell_size) + " m, shape " + to_string(scene_.settings.shape_function) +
           ", scheme " + to_string(scene_.settings.scheme) + ", flip " + format_number("%g", scene_.settings.flip_blend) +
           (scene_.settings.null_space_filter == mpm::NullSpaceFilter::none
                ? std::string()
                : ", null-space filter " + to_string(scene_.settings.null_space_filter) + " every " +
                      std::to_string(scene_.settings.null_space_filter_every) + " steps") +
           (scene_.settings.shape_function == mpm::ShapeFunctionKind::ddmp
                ? ", DDMP null-space stabilization " + format_number("%g", scene_.settings.ddmp_stabilization) +
                      (scene_.settings.ddmp_stabilization > 0 ? " of the elastic moduli" : " (Paper A as printed)")
                : std::string()));
  if (const auto& contact = scene_.settings.field_contact; contact.enabled) {
    log.line("contact: a velocity field per body and per point group (" + listed_or_none(contact.groups) +
             "), friction " + format_number("%g", contact.friction) + ", fill " + format_number("%g", contact.fill) +
             ", bonded bodies " + listed_or_none(contact.bonded_bodies));
  }
  // The stable step, not next_time_step(): that one throws for a fixed step above the limit,
  // which the stepping loop below reports with everything saved.
  const double stable = sim.stable_time_step();
  const double dt0 = scene_.settings.fixed_time_step > 0 ? scene_.settings.fixed_time_step : stable;
  log.line("time: " + (scene_.settings.fixed_time_step > 0 ? "fixed dt " + format_number("%g", scene_.settings.fixed_time_step) + " s"
                                     : "cfl " + format_number("%g", scene_.settings.cfl)) +
           ", stable dt " + format_number("%.4g", stable) + " s at the start, mass scaling " +
           format_number("%g", scene_.settings.mass_scaling));
  log.line("end: t = " + format_number("%g", end) + " s, about " + format_number("%.0f", std::ceil(end / dt0)) +
           " steps" + (scene_.max_steps ? ", at most " + std::to_string(scene_.max_steps) : ""));
  log.line("loading axis: (" + format_number("%g", axis.x()) + ", " + format_number("%g", axis.y()) + ", " +
           format_number("%g", axis.z()) + "), record area " + format_number("%g", sim.record_area()) + " m^2");

  // 2. The outputs, observing every step.
  const SolverSeries series_row(sim, axis, specimen_area_);
  const auto columns = series_row.columns();
  std::vector<std::vector<double>> earlier_rows;
  if (options_.resume) {
    // The rows up to the checkpoint that the regular schedule wrote (not a final row of a
    // run stopped by max_steps): exactly the rows an uninterrupted run has there.
    std::vector<std::string> header;
    for (auto& row : read_series_csv(run_dir + "/series.csv", &header)) {
      const auto step = int64_t(row.at(0));
      if (step <= sim.step_count() && step % scene_.series_every == 0) earlier_rows.push_back(row);
    }
    for (size_t c = 0; c < columns.size(); ++c)
      if (c >= header.size() || header[c] != columns[c].header())
        throw InputError(run_dir + "/series.csv", columns[c].header(), "the series does not match the scene's columns");
  }
  sim.domain().barrier();  // every process has read the run directory before rank 0 rewrites it
  std::unique_ptr<SeriesWriter> series_writer;
  std::unique_ptr<SnapshotWriter> snapshot_writer;
  if (writer) {
    series_writer = std::make_unique<SeriesWriter>(run_dir + "/series.csv", run_dir + "/series.h5", columns, provenance_,
                                                   earlier_rows);
    snapshot_writer = options_.resume ? std::make_unique<SnapshotWriter>(run_dir, provenance_, kept_frames)
                                      : std::make_unique<SnapshotWriter>(run_dir, provenance_);
  }
  // A row and a snapshot are taken on every process (their sums and the gather of the
  // particles are collective) and written by the writer.
  auto append_row = [&](const mpm::Simulation& s, const mpm::StepDiagnostics& d) {
    const auto row = series_row.row(s, d);
    if (series_writer) series_writer->append(row);
  };
  auto save_series = [&] {
    if (series_writer) series_writer->save();
  };
  auto write_snapshot = [&](const mpm::Simulation& s) {
    if (!several) {
      snapshot_writer->write(solver_snapshot(s));
      return;
    }
    // One file, every process writing its block of the points (in id order) into it at once.
    size_t first = 0;
    const mpm::Particles mine = s.domain().particles_in_id_block(s.particles(), particles, first);
    const ParticleSnapshot block = solver_snapshot(s, mine, first);
    auto fill_rows = [&](const std::string& path) {
      s.domain().write_shared_rows(path, [&](Hdf5File& file) { write_snapshot_rows(file, block, first); });
    };
    if (snapshot_writer)
      snapshot_writer->write_shared(block, particles, fill_rows);
    else
      fill_rows("");
  };
  if (!options_.resume) {
    append_row(sim, sim.last_diagnostics());
    write_snapshot(sim);
  }
  save_series();

  // Checkpoints: the solver state and what the outputs need to continue.
  double last_checkpoint = 0;
  auto save_checkpoint = [&](double wall) {
    if (!writer) {  // another process: its rows of the state, into rank 0's file (collective)
      sim.save_state(nullptr, "/state");
      sim.save_state_rows("", "/state");
      last_checkpoint = wall;
      return;
    }
    SnapshotWriter& snapshots = *snapshot_writer;
    OutputFile out(checkpoint_path, checkpoint_path);
    {
      Hdf5File file(out.temp_path(), Hdf5File::Mode::create);
      write_provenance(file, provenance_);
      sim.save_state(file, "/state");
      // Snapshots the regular schedule wrote up to here (a resumed run keeps these).
      std::vector<std::string> names;
      std::vector<double> times;
      std::vector<int64_t> steps, points;
      for (const auto& f : snapshots.frames())
        if (f.step == 0 || (scene_.snapshot_every > 0 && f.step % scene_.snapshot_every == 0))
          names.push_back(f.hdf5_file), times.push_back(f.time), steps.push_back(f.step),
              points.push_back(int64_t(f.points));
      file.write_strings("/output/frame_files", names);
      file.write("/output/frame_times", times, {times.size()});
      file.write("/output/frame_steps", steps, {steps.size()});
      file.write("/output/frame_points", points, {points.size()});
      file.set_attribute("/output", "wall_seconds", wall_before + wall);
      file.set_attribute("/output", "cpu_seconds", before.cpu_seconds + process_cpu_seconds());
      file.set_attribute("/output", "process_wall_seconds", before.wall_seconds + process_wall_seconds());
      file.set_attribute("/output", "step", int64_t(sim.step_count()));
      file.set_attribute("/output", "time", sim.time());
      file.close();
    }
    sim.save_state_rows(out.temp_path(), "/state");  // several processes: each its particles' rows
    out.commit();
    last_checkpoint = wall;
  };

  const double time_at_start = sim.time();  // a resumed run starts part-way: its rate is this part's
  Progress progress(provenance_.tool, end, options_.progress && writer, 2.0, time_at_start);
  const auto start = std::chrono::steady_clock::now();
  double last_log = 0;
  int64_t last_row_step = earlier_rows.empty() ? 0 : int64_t(earlier_rows.back()[0]);
  int64_t last_snapshot_step = kept_frames.empty() ? 0 : kept_frames.back().step;
  const int64_t first_step = sim.step_count();  // a resumed run starts later
  // Particle-updates per second of this part's stepping over `wall` seconds of it.
  auto rate_over = [&](double wall) {
    return wall > 0 ? double(particles) * double(sim.step_count() - first_step) / wall : 0.0;
  };
  auto rate = [&] { return rate_over(seconds_since(start)); };
  // status.toml: "running" now, how the run ended at the end (run_status.hpp).
  auto outcome = [&](const std::string& status, int exit_status, const std::string& reason) {
    RunOutcome o = outcome_without_run(status, exit_status, reason);
    o.steps = sim.step_count();
    o.simulated_time = sim.time();
    o.points = particles;
    o.wall_seconds += before.wall_seconds;
    o.cpu_seconds += before.cpu_seconds;
    // One clock reading for both, so that status.toml's rate is exactly its steps over its time.
    const double wall = seconds_since(start);
    o.stepping_wall_seconds = wall_before + wall;
    o.updates_per_second = rate_over(wall);
    o.precision = mpm::precision_name;
    return o;
  };
  if (writer) write_run_status(run_dir, outcome("running", -1, ""), provenance_);
  auto status_text = [&] {
    return "step " + std::to_string(sim.step_count()) + ", t = " + format_number("%.4g", sim.time()) + " s, " +
           format_number("%.3g", rate()) + " particle-updates/s";
  };
  // The outputs as observers, in this order after every step: series row, snapshot, then
  // progress, checkpoint and log.
  sim.add_observer([&](const mpm::Simulation& s, const mpm::StepDiagnostics& d) {
    if (d.step % scene_.series_every != 0) return;
    append_row(s, d);
    last_row_step = d.step;
  });
  sim.add_observer([&](const mpm::Simulation& s, const mpm::StepDiagnostics& d) {
    if (!(scene_.snapshot_every > 0 && d.step % scene_.snapshot_every == 0)) return;
    write_snapshot(s);
    save_series();
    last_snapshot_step = d.step;
  });
  sim.add_observer([&](const mpm::Simulation&, const mpm::StepDiagnostics& d) {
    progress.update(d.time, status_text());
    const double wall = seconds_since(start);
    // Every process decides alike: the checkpoint is collective, the clocks are not.
    if ((scene_.checkpoint.every_steps > 0 && d.step % scene_.checkpoint.every_steps == 0) ||
        (scene_.checkpoint.every_minutes > 0 &&
         sim.domain().reduce_max(wall - last_checkpoint >= 60 * scene_.checkpoint.every_minutes ? 1 : 0) > 0))
      save_checkpoint(wall);
    if (wall - last_log >= options_.log_interval_s) {
      last_log = wall;
      const double done = d.time / end;
      log.line("progress: " + format_number("%.1f", 100 * done) + "%, " + status_text() + ", left ~" +
               format_duration(estimate_time_left(wall, time_at_start, d.time, end)));
    }
  });

  // 3. Step to the end.
  SolveSummary result;
  result.status = "finished";
  result.particles = particles;
  try {
    while (sim.time() < end * (1 - 1e-12)) {
      // A signal reaches the processes at different times: all stop after the same step.
      const int signal = int(sim.domain().reduce_max(interruption_signal()));
      if (signal) {
        result.status = "interrupted";
        result.signal = signal;
        log.line(std::string("stopped by ") + signal_name(result.signal) + " after step " +
                 std::to_string(sim.step_count()) + ": checkpoint saved, --resume continues");
        save_checkpoint(seconds_since(start));
        break;
      }
      if (scene_.max_steps > 0 && sim.step_count() >= scene_.max_steps) {
        result.status = "max_steps";
        save_checkpoint(seconds_since(start));  // so that --resume can continue it
        break;
      }
      if (sim.time() + sim.next_time_step() >= end)
        sim.run_until(end);  // the last step is shortened to land on the end time
      else
        sim.step();
    }
  } catch (const std::exception& e) {
    // Keep everything readable: the series as far as it got, the state at the failure.
    const bool numerical = dynamic_cast<const NumericalError*>(&e) != nullptr;
    const std::string reason = std::string(numerical ? "numerical failure: " : "error: ") + e.what();
    log.line("stopped: " + reason);
    try {
      save_series();
      // Apart from the time series: the failure may have struck mid-step, so this state
      // need not be the whole state of any step. (With several processes the others may
      // not be in step with this one: no gather, no failure state yet.)
      if (snapshot_writer && !several)
        log.line("state when the failure was detected (" + std::to_string(sim.step_count()) +
                 " steps completed): " + snapshot_writer->write_separate(solver_snapshot(sim), "failure") +
                 ", failure.xmf");
    } catch (const std::exception& save_error) {
      log.line(std::string("could not save the state: ") + save_error.what());
    }
    log.line("status: failed steps=" + std::to_string(sim.step_count()) + " time=" +
             format_number("%.9g", sim.time()) + " wall_s=" + format_number("%.3f", seconds_since(start)));
    if (writer)
      write_run_status(run_dir, outcome(numerical ? "failed" : "error", numerical ? exit_numerical : exit_internal, reason),
                       provenance_);
    // A stop every process raised together: the others wait until rank 0 has written the
    // record above, so that the MPI_Abort that ends the job cannot cut it short.
    if (several && dynamic_cast<const CollectiveNumericalError*>(&e) != nullptr) sim.domain().barrier();
    throw;
  }

  // 4. The final state, then the summary.
  if (several) log.line(domain_summary(sim, first_step));
  if (last_row_step != sim.step_count()) append_row(sim, sim.last_diagnostics());
  if (last_snapshot_step != sim.step_count()) write_snapshot(sim);
  save_series();
  result.steps = sim.step_count();
  result.simulated_time = sim.time();
  result.wall_seconds = seconds_since(start);
  result.updates_per_second = rate();
  progress.finish(status_text());
  log.line("status: " + result.status + " steps=" + std::to_string(result.steps) + " time=" +
           format_number("%.9g", result.simulated_time) + " wall_s=" + format_number("%.3f", result.wall_seconds) +
           " updates_per_s=" + format_number("%.4g", result.updates_per_second));
  const std::string reason = result.status == "max_steps" ? "run.max_steps reached"
                             : result.signal           ? std::string("stopped by ") + signal_name(result.signal)
                                                       : "";
  if (writer)
    write_run_status(run_dir, outcome(result.status, result.signal ? exit_signal_base + result.signal : exit_ok, reason),
                     provenance_);
  return result;
}

}  // namespace latmpm
