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
    : path_(path), out_(path, append ? std::ios::app : std::ios::trunc), start_(now_seconds()) {
  if (!out_) throw InputError(path, "", "cannot write the log file");
}

void RunLog::line(const std::string& text) {
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "[%8.1fs] ", now_seconds() - start_);
  out_ << stamp << text << std::endl;
}

}  // namespace latmpm
