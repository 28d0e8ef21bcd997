#include "run_output/run_log.hpp"

#include <chrono>
#include <cstdio>

#include "core/errors.hpp"

namespace latmpm {
namespace {
double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

RunLog::RunLog(const std::string& path, bool append)
    : path_(path), start_(now_seconds()) {
  if (path.empty()) return;  // no file: the lines go nowhere
  out_.open(path, append ? std::ios::app : std::ios::trunc);
  if (!out_) throw InputError(path, "", "cannot write the log file");
}

void RunLog::line(const std::string& text) {
  if (path_.empty()) return;
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "[%8.1fs] ", now_seconds() - start_);
  out_ << stamp << text << std::endl;
}

}  // namespace latmpm
