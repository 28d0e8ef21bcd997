#include "solve_tool.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "scratch_dir.hpp"
#include "tiny_column.hpp"

namespace fs = std::filesystem;

namespace latmpm::test {

const char* const tiny_scene = R"([run]
end = { plate_displacement = "0.2mm" }
[grid]
cell = "1mm"
shape = "ugimp"
[time]
cfl = 0.3
mass_scaling = 6
[[points]]
file = "column.h5"
[bodies.column]
role = "deformable"
material = { E = "10MPa", nu = 0.4, density = "1050kg/m^3" }
[bodies.bottom_plate]
role = "fixed"
[bodies.top_plate]
role = "driven"
velocity = ["0mm/s", "0mm/s", "-100mm/s"]
[output]
series_every = 25
snapshot_every = 100
)";

fs::path scratch() {
  static const fs::path dir = [] {
    const fs::path d = process_scratch("solve-tool").path();
    write_points(tiny_column({}), (d / "column.h5").string());
    return d;
  }();
  return dir;
}

std::string write_scene(const std::string& name, const std::string& text) {
  const fs::path path = scratch() / name;
  std::ofstream(path) << text;
  return path.string();
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

ToolRun run_solve(const std::string& args) {
  const fs::path out = scratch() / "stdout.txt", err = scratch() / "stderr.txt";
  const std::string cmd = std::string(LATMPM_BIN_DIR) + "/latmpm-solve " + args + " >" + out.string() +
                          " 2>" + err.string();
  const int raw = std::system(cmd.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(err), read_text(out)};
}

}  // namespace latmpm::test
