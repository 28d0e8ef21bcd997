// Files between tools: outputs appear whole or not at all, and "-" means a pipe.
//   OutputFile out(path_or_dash, "-o");  write to out.temp_path(); out.commit();
// Until commit() the data lives under a temporary name beside the target (rename is atomic),
// or in $TMPDIR for stdout; if anything throws first, the destructor removes it, so a failed
// run never leaves a half-written file. HDF5 needs a seekable file, so stdin/stdout are
// staged through a temporary file. Temporary files are registered with the signal handler
// (core/interruption.hpp): SIGINT/SIGTERM remove them too.
#pragma once
#include <string>
#include <utility>
#include <vector>

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
  // Writes `text` as the whole temporary file; OutputError on a full disk.
  void write_text(const std::string& text) const;
  // Renames the temporary file to the target, or copies it to stdout. Throws OutputError
  // (removing the temporary file) when that fails: a closed pipe, a full disk.
  void commit();

 private:
  std::string target_, option_, temp_;
  int slot_ = -1;  // signal-handler registration of temp_
  bool committed_ = false;
};

// The name to show for `path` in a message: the target of the OutputFile staging it there
// ("-" for stdout), else `path` itself.
std::string shown_path(const std::string& path);

// Writes `text` to `target` through an OutputFile (whole or not at all); OutputError on a
// full disk.
void write_file_atomically(const std::string& target, const std::string& text, const std::string& option);

// Refuses two outputs naming one file (also through ./, .. or symbolic links, or hard links
// to an existing file): the second would silently replace the first. Each entry is
// {option, path}; "-" (stdout) is left to the caller.
void refuse_aliased_outputs(const std::vector<std::pair<std::string, std::string>>& outputs);

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
  int slot_ = -1;
  bool temporary_ = false;
};

}  // namespace latmpm
