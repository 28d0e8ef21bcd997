#include "post/run_directory.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "core/errors.hpp"

namespace latmpm::post {

namespace fs = std::filesystem;

const char* to_string(RunStatus status) {
  switch (status) {
    case RunStatus::finished: return "finished";
    case RunStatus::max_steps: return "stopped at max_steps";
    case RunStatus::failed: return "failed";
    case RunStatus::unfinished: return "unfinished";
  }
  return "?";
}

RunStatus parse_run_status(const std::string& log_text, std::string* status_line, std::string* stop_reason) {
  RunStatus status = RunStatus::unfinished;
  std::string found = "no status line in log.txt (still running, or killed)";
  std::stringstream ss(log_text);
  std::string line;
  while (std::getline(ss, line)) {
    // Log lines are "[  12.3s] text".
    const size_t close = line.find("] ");
    const std::string text = line.rfind('[', 0) == 0 && close != std::string::npos ? line.substr(close + 2) : line;
    if (text.rfind("stopped:", 0) == 0 && stop_reason) *stop_reason = text;
    if (text.rfind("status:", 0) != 0) continue;
    found = text;
    std::stringstream words(text.substr(7));
    std::string word;
    words >> word;
    status = word == "finished"    ? RunStatus::finished
             : word == "max_steps" ? RunStatus::max_steps
             : word == "failed"    ? RunStatus::failed
                                   : RunStatus::unfinished;
  }
  if (status_line) *status_line = found;
  return status;
}

RunStatus read_run_status_file(const std::string& path, std::string* status_line, std::string* stop_reason) {
  toml::table status;
  try {
    status = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(path, "", std::string("not a status file: ") + std::string(e.description()));
  }
  const std::string word = status["status"].value_or(std::string());
  if (word.empty()) throw InputError(path, "status", "missing");
  const int64_t steps = status["steps"].value_or(int64_t(0));
  const int64_t exit_status = status["exit"].value_or(int64_t(-1));
  const std::string reason = status["reason"].value_or(std::string());
  if (status_line)
    *status_line = "status.toml: " + word + ", " + std::to_string(steps) + " steps, exit " + std::to_string(exit_status);
  if (stop_reason) *stop_reason = reason.empty() ? "" : "stopped: " + reason;
  return word == "finished"                      ? RunStatus::finished
         : word == "max_steps"                   ? RunStatus::max_steps
         : word == "failed" || word == "error"   ? RunStatus::failed
                                                 : RunStatus::unfinished;  // running, interrupted, bad_input
}

RunDirectory read_run_directory(const std::string& path) {
  if (!fs::is_directory(path)) throw InputError(path, "", "not a run directory (no such directory)");
  for (const char* file : {"series.csv", "scene.toml", "log.txt"})
    if (!fs::is_regular_file(fs::path(path) / file))
      throw InputError(path, "", std::string("not a run directory: no ") + file + " (expected a latmpm-solve -o RUN_DIR)");

  RunDirectory run;
  run.path = path;
  const fs::path status_file = fs::path(path) / "status.toml";
  if (fs::is_regular_file(status_file)) {
    run.status = read_run_status_file(status_file.string(), &run.status_line, &run.stop_reason);
  } else {  // a run directory of a solver from before status.toml
    std::ifstream log(fs::path(path) / "log.txt");
    std::stringstream text;
    text << log.rdbuf();
    run.status = parse_run_status(text.str(), &run.status_line, &run.stop_reason);
  }
  run.series = read_series_csv((fs::path(path) / "series.csv").string());
  for (const char* needed : {"time"})
    if (!run.series.has(needed))
      throw InputError((fs::path(path) / "series.csv").string(), needed, "column missing");
  run.specimen = read_specimen_facts((fs::path(path) / "scene.toml").string());
  return run;
}

std::string file_stem(const std::string& label) {
  std::string stem;
  for (char c : label) stem += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_') ? c : '_';
  if (stem.empty() || stem == "." || stem == "..") stem = "run";
  // A file name has at most 255 bytes, and ".load_displacement.csv" follows: a long label keeps
  // its first 80 characters and a hash of the whole, so that distinct labels stay distinct.
  if (stem.size() > 100) {
    char hash[20];
    std::snprintf(hash, sizeof hash, "_%016zx", std::hash<std::string>{}(label));
    stem = stem.substr(0, 80) + hash;
  }
  return stem;
}

std::vector<std::string> default_labels(const std::vector<std::string>& paths,
                                        const std::vector<std::string>& explicit_labels) {
  // Absolute, normalised, without a trailing separator: "runs/a/" -> "/cwd/runs/a".
  auto directory = [](const std::string& p) {
    fs::path q = fs::absolute(fs::path(p)).lexically_normal();
    if (q.filename().empty()) q = q.parent_path();
    return q;
  };
  auto base = [&](const std::string& p) {
    const std::string name = directory(p).filename().string();
    return name.empty() ? std::string("run") : name;
  };
  std::vector<std::string> labels(paths.size());
  for (size_t i = 0; i < paths.size(); ++i)
    labels[i] = i < explicit_labels.size() && !explicit_labels[i].empty() ? explicit_labels[i] : base(paths[i]);
  // Duplicates: prefix the parent directory's name, then number what still collides.
  std::map<std::string, int> count;
  for (const auto& l : labels) ++count[l];
  for (size_t i = 0; i < paths.size(); ++i) {
    const bool given = i < explicit_labels.size() && !explicit_labels[i].empty();
    if (count[labels[i]] > 1 && !given) {
      labels[i] = directory(paths[i]).parent_path().filename().string() + "/" + labels[i];
    }
  }
  std::set<std::string> seen;
  for (auto& l : labels) {
    std::string candidate = l;
    for (int n = 2; seen.count(file_stem(candidate)); ++n) candidate = l + " (" + std::to_string(n) + ")";
    l = candidate;
    seen.insert(file_stem(l));
  }
  return labels;
}

}  // namespace latmpm::post
