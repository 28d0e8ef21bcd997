// A fresh scratch directory for one test: a new directory under the temp directory
// ($TMPDIR, else /tmp) with a unique name (mkdtemp), removed when the test ends. Tests run in
// parallel (ctest -j) never share a path, and a test never finds an earlier run's files.
//   test::ScratchDir scratch("voxelize");
//   write_stl(mesh, scratch / "a.stl", ...);
// LATMPM_KEEP_SCRATCH=1 keeps the directories, to look at a failed test's files.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace latmpm::test {

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& label = "test") {
    std::string pattern = (std::filesystem::temp_directory_path() / ("latmpm-" + label + "-XXXXXX")).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (!::mkdtemp(name.data())) throw std::runtime_error("cannot create a scratch directory from " + pattern);
    path_ = name.data();
  }
  ~ScratchDir() {
    const char* keep = std::getenv("LATMPM_KEEP_SCRATCH");
    std::error_code ignored;
    if (!(keep && *keep == '1')) std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string string() const { return path_.string(); }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// One scratch directory for the whole test process (a test file's shared inputs), removed at
// exit.
inline const ScratchDir& process_scratch(const std::string& label) {
  static const ScratchDir dir(label);
  return dir;
}

}  // namespace latmpm::test
