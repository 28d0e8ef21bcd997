// Files between tools: outputs appear whole or not at all, and "-" means a pipe.
//   OutputFile out(path_or_dash, "-o");  write to out.temp_path(); out.commit();
// Until commit() the data lives under a temporary name beside the target (rename is atomic),
// or in $TMPDIR for stdout; if anything throws first, the destructor removes it, so a failed
// run never leaves a half-written file. HDF5 needs a seekable file, so stdin/stdout are
// staged through a temporary file.
#pragma once
#include <string>

namespace latmpm {

class OutputFile {
 public:
  // Checks at once that the target can be written (throws InputError naming `option`).
  OutputFile(const std::string& target, const std::string& option);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  const std::string& temp_path() const { return temp_; }
  const std::string& target() const { return target_; }
  bool to_stdout() const { return target_ == "-"; }
  // Renames the temporary file to the target, or copies it to stdout.
  void commit();

 private:
  std::string target_, option_, temp_;
  bool committed_ = false;
};

class InputFile {
 public:
  // "-" copies standard input to a temporary file; otherwise checks the file is readable.
  InputFile(const std::string& source, const std::string& option);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& path() const { return path_; }      // what to open
  const std::string& source() const { return source_; }  // what the user named
  std::string display_name() const { return source_ == "-" ? "<stdin>" : source_; }

 private:
  std::string source_, path_;
  bool temporary_ = false;
};

}  // namespace latmpm
