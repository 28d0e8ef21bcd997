#include "core/file_transfer.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <vector>

#include "core/errors.hpp"
#include "core/interruption.hpp"

namespace fs = std::filesystem;

namespace latmpm {
namespace {

std::string make_temp_in(const std::string& dir, const std::string& stem) {
  // A file name may have 255 bytes: a long target's staging name keeps the first 200 of them.
  std::string pattern = (dir.empty() ? "." : dir) + "/." + stem.substr(0, 200) + ".tmp.XXXXXX";
  std::vector<char> buf(pattern.begin(), pattern.end());
  buf.push_back('\0');
  int fd = mkstemp(buf.data());
  if (fd < 0) return "";
  ::close(fd);
  return std::string(buf.data());
}

// mkstemp creates files with mode 0600; a finished output gets the usual 0666 & ~umask.
void apply_umask_permissions(const std::string& path) {
  mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(path.c_str(), 0666 & ~mask);
}

// Standard input into `path`: the number of bytes, -1 when a write or the close failed.
long copy_stdin_to(const std::string& path) {
  FILE* out = std::fopen(path.c_str(), "wb");
  if (!out) return -1;
  std::vector<char> buffer(1 << 16);
  long total = 0;
  bool ok = true;
  for (size_t n; ok && (n = std::fread(buffer.data(), 1, buffer.size(), stdin)) > 0; total += long(n))
    ok = std::fwrite(buffer.data(), 1, n, out) == n;
  ok = (std::fclose(out) == 0) && ok;
  return ok ? total : -1;
}

std::string temp_dir() {
  const char* t = std::getenv("TMPDIR");
  return (t && *t) ? t : "/tmp";
}

std::mutex staging_mutex;
std::map<std::string, std::string> staged_targets;  // temporary path -> target

}  // namespace

std::string shown_path(const std::string& path) {
  const std::lock_guard<std::mutex> lock(staging_mutex);
  const auto found = staged_targets.find(path);
  return found == staged_targets.end() ? path : found->second;
}

OutputFile::OutputFile(const std::string& target, const std::string& option)
    : target_(target), option_(option) {
  if (target.empty()) throw InputError(option, "", "empty output path");
  const SignalsHeld created_and_registered_together;
  if (to_stdout()) {
    temp_ = make_temp_in(temp_dir(), "latmpm-stdout");
  } else {
    fs::path p(target);
    if (fs::is_directory(p)) throw InputError(option, "", "'" + target + "' is a directory");
    std::string dir = p.parent_path().string();
    if (!dir.empty() && !fs::is_directory(dir))
      throw InputError(option, "", "cannot write '" + target + "': directory '" + dir + "' does not exist");
    temp_ = make_temp_in(dir, p.filename().string());
  }
  if (temp_.empty())
    throw InputError(option, "", "cannot write '" + target + "': directory not writable");
  slot_ = register_temporary(temp_);
  const std::lock_guard<std::mutex> lock(staging_mutex);
  staged_targets[temp_] = target_;
}

OutputFile::~OutputFile() {
  if (!committed_ && !temp_.empty()) std::remove(temp_.c_str());
  unregister_temporary(slot_);
  const std::lock_guard<std::mutex> lock(staging_mutex);
  staged_targets.erase(temp_);
}

void OutputFile::write_text(const std::string& text) const {
  std::ofstream stream(temp_, std::ios::binary | std::ios::trunc);
  stream << text;
  stream.close();
  if (!stream) throw OutputError(target_, "write failed (disk full?)");
}

void OutputFile::commit() {
  if (committed_) return;
  if (to_stdout()) {
    std::ifstream in(temp_, std::ios::binary);
    std::cout.flush();
    std::cout << in.rdbuf();
    std::cout.flush();
    std::remove(temp_.c_str());
    committed_ = true;
    if (!std::cout) throw OutputError(option_ + " -", "standard output: write failed (closed pipe or disk full?)");
  } else {
    apply_umask_permissions(temp_);
    if (std::rename(temp_.c_str(), target_.c_str()) != 0)
      throw OutputError(option_ + " " + target_, "cannot rename the finished file into place");
    committed_ = true;
  }
}

InputFile::InputFile(const std::string& source, const std::string& option) : source_(source) {
  if (source.empty()) throw InputError(option, "", "empty input path");
  if (source == "-") {
    {
      const SignalsHeld created_and_registered_together;
      path_ = make_temp_in(temp_dir(), "latmpm-stdin");
      if (path_.empty()) throw InputError(option, "", "cannot stage standard input in " + temp_dir());
      temporary_ = true;
      slot_ = register_temporary(path_);
    }
    const long bytes = copy_stdin_to(path_);
    if (bytes <= 0) {
      std::remove(path_.c_str());
      unregister_temporary(slot_);
      if (bytes < 0) throw OutputError(temp_dir(), "cannot stage standard input (disk full?)");
      throw InputError("<stdin>", "", "empty input (did the previous tool fail?)");
    }
    return;
  }
  path_ = source;
  if (!fs::exists(path_)) throw InputError(source, "", "no such file");
  if (fs::is_directory(path_)) throw InputError(source, "", "is a directory, expected a file");
  std::ifstream probe(path_, std::ios::binary);
  if (!probe) throw InputError(source, "", "cannot be read");
}

InputFile::~InputFile() {
  if (temporary_) std::remove(path_.c_str());
  unregister_temporary(slot_);
}

void write_file_atomically(const std::string& target, const std::string& text, const std::string& option) {
  OutputFile out(target, option);
  out.write_text(text);
  out.commit();
}

void refuse_aliased_outputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
  // The file a path would write: absolute, normalised, symbolic links followed, also a link
  // to a file that does not exist yet (weakly_canonical stops there).
  auto resolved = [](const std::string& path) {
    std::error_code ec;
    fs::path p = fs::absolute(path, ec).lexically_normal();
    for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++hops) {
      const fs::path link = fs::read_symlink(p, ec);
      if (ec) break;
      p = (link.is_absolute() ? link : p.parent_path() / link).lexically_normal();
    }
    const fs::path canonical = fs::weakly_canonical(p, ec);
    return ec ? p : canonical;
  };
  auto same_file = [&](const std::string& a, const std::string& b) {
    std::error_code ec;
    if (resolved(a) == resolved(b)) return true;
    return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
  };
  for (size_t i = 0; i < outputs.size(); ++i)
    for (size_t j = i + 1; j < outputs.size(); ++j) {
      const auto& [option_a, a] = outputs[i];
      const auto& [option_b, b] = outputs[j];
      if (a.empty() || b.empty() || a == "-" || b == "-") continue;
      if (same_file(a, b))
        throw InputError(option_b + " " + b, "", "names the same file as " + option_a + " " + a +
                                                     " (one output would replace the other)");
    }
}

}  // namespace latmpm
