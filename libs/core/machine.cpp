#include "core/machine.hpp"

#include <sched.h>

#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>

#include "core/text.hpp"

namespace latmpm {
namespace {

// The words of `text` with one blank between them ("model name\t: AMD  EPYC" has runs).
std::string words_of(const std::string& text) {
  std::istringstream in(text);
  return joined(std::vector<std::string>(std::istream_iterator<std::string>(in), {}), " ");
}

// The first "KEY : value" line of /proc/cpuinfo for each key (the first processor's), in one
// read; empty where the file is missing.
std::map<std::string, std::string> cpuinfo() {
  std::map<std::string, std::string> values;
  std::ifstream file("/proc/cpuinfo");
  for (std::string line; std::getline(file, line);) {
    const auto colon = line.find(':');
    if (colon != std::string::npos) values.emplace(words_of(line.substr(0, colon)), words_of(line.substr(colon + 1)));
  }
  return values;
}

}  // namespace

std::string cpu_model() {
  // The machine does not change while a process runs: /proc/cpuinfo is read once.
  static const std::string model = [] {
    const auto info = cpuinfo();
    auto value = [&](const char* key) {
      const auto it = info.find(key);
      return it == info.end() ? std::string() : it->second;
    };
    std::string name = value("model name");
    if (name.empty()) name = "unknown";
    // A virtual machine may name every generation alike ("AMD EPYC"); the family and model
    // numbers tell a Zen 3 (25 1) from a Zen 4 (25 17). No comma: runs.csv is comma-separated.
    const std::string family = value("cpu family"), number = value("model");
    if (!family.empty() && !number.empty()) name += " (family " + family + " model " + number + ")";
    return name;
  }();
  return model;
}

const char* vector_instruction_set() {
#if defined(__AVX512F__)
  return "avx512";
#elif defined(__AVX2__)
  return "avx2";
#elif defined(__AVX__)
  return "avx";
#elif defined(__SSE2__)
  return "sse2";
#else
  return "none";
#endif
}

int usable_cpus() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  const int n = CPU_COUNT(&set);
  return n > 0 ? n : 1;
}

}  // namespace latmpm
