#include "core/machine.hpp"

#include <sched.h>

#include <fstream>
#include <sstream>

namespace latmpm {
namespace {

// The value of the first "KEY : value" line of /proc/cpuinfo whose key is exactly KEY, with
// runs of blanks made one; "" where there is none.
std::string cpuinfo_value(const std::string& wanted) {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::istringstream key_words(line.substr(0, colon)), value_words(line.substr(colon + 1));
    std::string word, key, value;
    while (key_words >> word) key += (key.empty() ? "" : " ") + word;
    if (key != wanted) continue;
    while (value_words >> word) value += (value.empty() ? "" : " ") + word;
    return value;
  }
  return "";
}

}  // namespace

std::string cpu_model() {
  std::string name = cpuinfo_value("model name");
  if (name.empty()) name = "unknown";
  // A virtual machine may name every generation alike ("AMD EPYC"); the family and model
  // numbers tell a Zen 3 (25 1) from a Zen 4 (25 17). No comma: runs.csv is comma-separated.
  const std::string family = cpuinfo_value("cpu family"), model = cpuinfo_value("model");
  if (!family.empty() && !model.empty()) name += " (family " + family + " model " + model + ")";
  return name;
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
