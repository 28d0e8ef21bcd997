#include "core/provenance.hpp"

#include <ctime>

#include "core/hdf5_file.hpp"
#include "core/text.hpp"

namespace latmpm {

std::string quoted_command_line(int argc, const char* const* argv) {
  std::string out;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    bool plain = !a.empty() && a.find_first_not_of(
                                   "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                   "0123456789-_./=:,+%^@") == std::string::npos;
    if (!out.empty()) out += ' ';
    if (plain) {
      out += a;
    } else {
      out += '\'';
      for (char c : a) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
      out += '\'';
    }
  }
  return out;
}

Provenance Provenance::for_run(const std::string& tool, int argc, const char* const* argv) {
  Provenance p;
  p.tool = tool;
  p.version = version_string();
  p.command_line = quoted_command_line(argc, argv);
  std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  p.created_utc = buf;
  return p;
}

std::string Provenance::summary_line() const {
  const std::string inputs_text = joined(inputs);
  return created_utc + " " + tool + " " + version + ": " + command_line +
         (inputs_text.empty() ? "" : " (inputs: " + inputs_text + ")");
}

void Provenance::inherit_from(const Hdf5File& input) {
  Provenance earlier = read_provenance(input);
  for (const auto& line : earlier.history) history.push_back(line);
  if (!earlier.tool.empty()) history.push_back(earlier.summary_line());
}

void write_provenance(Hdf5File& file, const Provenance& p) {
  file.set_attribute("/", "tool", p.tool);
  file.set_attribute("/", "version", p.version);
  file.set_attribute("/", "command_line", p.command_line);
  file.set_attribute("/", "created_utc", p.created_utc);
  file.set_attribute("/", "units", "SI: m, kg, s, Pa, N, J; angles in rad");
  file.write_strings("/provenance/inputs", p.inputs);
  file.write_strings("/provenance/history", p.history);
}

Provenance read_provenance(const Hdf5File& file) {
  Provenance p;
  if (!file.has_attribute("/", "tool")) return p;
  p.tool = file.string_attribute("/", "tool");
  p.version = file.string_attribute("/", "version");
  p.command_line = file.string_attribute("/", "command_line");
  p.created_utc = file.string_attribute("/", "created_utc");
  if (file.exists("/provenance/inputs")) p.inputs = file.read_strings("/provenance/inputs");
  if (file.exists("/provenance/history")) p.history = file.read_strings("/provenance/history");
  return p;
}

}  // namespace latmpm
