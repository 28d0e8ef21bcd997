// The one file that talks to gmsh.
#include "cad/step_export.hpp"

#include <gmsh.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <set>
#include <utility>

#include "core/errors.hpp"
#include "core/interruption.hpp"

namespace latmpm {
namespace {

// OpenCASCADE's STEP writer prints transfer statistics on stdout, which may carry the
// strut-graph file (-o -): silence fd 1 while gmsh works.
struct SilencedStdout {
  int saved = -1;
  SilencedStdout() {
    std::fflush(stdout);
    std::cout.flush();
    saved = ::dup(1);
    const int null = ::open("/dev/null", O_WRONLY);
    if (saved >= 0 && null >= 0) ::dup2(null, 1);
    if (null >= 0) ::close(null);
  }
  ~SilencedStdout() {
    std::fflush(stdout);
    if (saved >= 0) {
      ::dup2(saved, 1);
      ::close(saved);
    }
  }
};

// gmsh is a global singleton: initialise for one export, always finalise.
struct GmshSession {
  SilencedStdout silence;
  GmshSession() {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("Geometry.OCCParallel", 1);  // threaded booleans
    gmsh::model::add("latmpm");
  }
  ~GmshSession() { gmsh::finalize(); }
};

}  // namespace

StepReport write_step(const StrutGraph& graph, const std::string& path, bool verbose) {
  const auto start = std::chrono::steady_clock::now();
  constexpr double mm = 1e3;  // STEP written in millimetres, OpenCASCADE's default unit
  StepReport report;
  try {
    GmshSession session;
    gmsh::vectorpair solids;
    for (const Plate& p : graph.plates) {
      const Eigen::Vector3d size = p.max - p.min;
      solids.emplace_back(3, gmsh::model::occ::addBox(mm * p.min.x(), mm * p.min.y(), mm * p.min.z(),
                                                      mm * size.x(), mm * size.y(), mm * size.z()));
    }
    std::set<std::pair<int32_t, double>> spheres;  // round ends: one sphere per node and radius
    for (const Strut& s : graph.struts) {
      const Eigen::Vector3d a = mm * graph.nodes[s.a], axis = mm * (graph.nodes[s.b] - graph.nodes[s.a]);
      solids.emplace_back(3, gmsh::model::occ::addCylinder(a.x(), a.y(), a.z(), axis.x(), axis.y(),
                                                           axis.z(), mm * s.radius));
      if (graph.strut_ends == StrutEnds::round) spheres.insert({{s.a, s.radius}, {s.b, s.radius}});
    }
    for (const auto& [node, radius] : spheres) {
      const Eigen::Vector3d c = mm * graph.nodes[node];
      solids.emplace_back(3, gmsh::model::occ::addSphere(c.x(), c.y(), c.z(), mm * radius));
    }
    report.solids = solids.size();
    if (solids.size() > 1) {
      if (verbose)
        std::cerr << "  STEP: fusing " << solids.size() << " solids with OpenCASCADE (minutes for large lattices)\n";
      gmsh::vectorpair fused;
      std::vector<gmsh::vectorpair> map;
      gmsh::model::occ::fuse({solids.front()}, gmsh::vectorpair(solids.begin() + 1, solids.end()), fused, map);
    }
    gmsh::model::occ::synchronize();
    // gmsh chooses the format by extension: write "<path>.step", then move it into place.
    const TemporaryPath step_file(path + ".step");
    const std::string& step_path = step_file.path();
    gmsh::write(step_path);
    if (std::rename(step_path.c_str(), path.c_str()) != 0) {
      std::remove(step_path.c_str());
      throw InputError(path, "", "cannot move the STEP file into place");
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path, "STEP", std::string("gmsh/OpenCASCADE failed: ") + e.what());
  } catch (...) {
    throw InputError(path, "STEP", "gmsh/OpenCASCADE failed");
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

StepContents read_step_contents(const std::string& path) {
  StepContents contents;
  try {
    GmshSession session;
    gmsh::vectorpair shapes;
    gmsh::model::occ::importShapes(path, shapes, true, "step");
    for (const auto& [dim, tag] : shapes) {
      if (dim != 3) continue;
      double mass = 0;
      gmsh::model::occ::getMass(dim, tag, mass);
      contents.volume += mass * 1e-9;  // mm³ → m³
      ++contents.solids;
    }
  } catch (const std::exception& e) {
    throw InputError(path, "STEP", std::string("gmsh/OpenCASCADE cannot read it: ") + e.what());
  } catch (...) {
    throw InputError(path, "STEP", "gmsh/OpenCASCADE cannot read it");
  }
  return contents;
}

}  // namespace latmpm
