// Which machine a run's cost was measured on. The same run costs 3.5× more CPU on one CPU of
// this project's machine kind than on another (docs/benchmarks.md, "Eight-lane splats on
// AVX2"), so a cost figure without its CPU cannot be compared with another. status.toml and
// the solver's log carry these (docs/scene.md, "The run directory").
#pragma once
#include <string>

namespace latmpm {

// The processor's name as the kernel reports it ("model name" of /proc/cpuinfo, runs of
// blanks made one; "unknown" where missing), then its family and model numbers where the
// kernel gives them: "AMD EPYC (family 25 model 1)".
std::string cpu_model();
// The widest vector instruction set this build's code was compiled for: "avx512", "avx2",
// "avx", "sse2" or "none" (the build follows the building machine, -march=native).
const char* vector_instruction_set();
// Processors this process may run on (sched_getaffinity; at least 1).
int usable_cpus();

}  // namespace latmpm
