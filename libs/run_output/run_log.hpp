// RUN_DIR/log.txt: what was run (command line, version, settings), progress lines as the
// run goes and how it ended. Every line is flushed, so the log says why a run stopped even
// when the process dies next.
#pragma once
#include <fstream>
#include <string>

namespace latmpm {

class RunLog {
 public:
  // Creates (truncates) the file, or appends; an empty path writes nothing (the MPI
  // processes other than rank 0).
  explicit RunLog(const std::string& path, bool append = false);
  // "[  12.3s] text": seconds since the log was opened.
  void line(const std::string& text);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream out_;
  double start_;
};

}  // namespace latmpm
