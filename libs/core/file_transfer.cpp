#include "core/file_transfer.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <vector>

#include "core/errors.hpp"

namespace fs = std::filesystem;

namespace latmpm {
namespace {

std::string make_temp_in(const std::string& dir, const std::string& stem) {
  std::string pattern = (dir.empty() ? "." : dir) + "/." + stem + ".tmp.XXXXXX";
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

std::string temp_dir() {
  const char* t = std::getenv("TMPDIR");
  return (t && *t) ? t : "/tmp";
}

}  // namespace

OutputFile::OutputFile(const std::string& target, const std::string& option)
    : target_(target), option_(option) {
  if (target.empty()) throw InputError(option, "", "empty output path");
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
}

OutputFile::~OutputFile() {
  if (!committed_ && !temp_.empty()) std::remove(temp_.c_str());
}

void OutputFile::commit() {
  if (committed_) return;
  if (to_stdout()) {
    std::ifstream in(temp_, std::ios::binary);
    std::cout.flush();
    std::cout << in.rdbuf();
    std::cout.flush();
    std::remove(temp_.c_str());
    if (!std::cout) throw InputError(option_, "", "cannot write to standard output");
  } else {
    apply_umask_permissions(temp_);
    if (std::rename(temp_.c_str(), target_.c_str()) != 0)
      throw InputError(option_, "", "cannot rename the finished file to '" + target_ + "'");
  }
  committed_ = true;
}

InputFile::InputFile(const std::string& source, const std::string& option) : source_(source) {
  if (source.empty()) throw InputError(option, "", "empty input path");
  if (source == "-") {
    path_ = make_temp_in(temp_dir(), "latmpm-stdin");
    if (path_.empty()) throw InputError(option, "", "cannot stage standard input in " + temp_dir());
    temporary_ = true;
    std::ofstream out(path_, std::ios::binary);
    out << std::cin.rdbuf();
    out.close();
    if (fs::file_size(path_) == 0) {
      std::remove(path_.c_str());
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
}

}  // namespace latmpm
