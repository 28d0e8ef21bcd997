// Memory bandwidth of this machine, the ceiling a memory-bound particle pass can reach
// (docs/benchmarks.md, "What bounds the rate"): the four STREAM kernels (McCalpin) on
// three arrays of 2^24 doubles (128 MiB each, far beyond the caches), split over T threads,
// best of 10 repetitions. Bytes counted as STREAM does (reads + writes, no write-allocate).
//   bench_stream [THREADS]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

namespace {
// Runs body(begin, end) on `threads` contiguous slices of [0, n) and returns the wall seconds.
template <class Body>
double timed_parallel(size_t n, int threads, Body body) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(body, n * t / threads, n * (t + 1) / threads);
  for (auto& th : pool) th.join();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

int main(int argc, char** argv) {
  const int threads = argc > 1 ? std::max(1, std::atoi(argv[1])) : 1;
  const size_t n = size_t(1) << 24;
  std::vector<double> a(n), b(n), c(n);
  // First touch by the threads that use each slice.
  timed_parallel(n, threads, [&](size_t i0, size_t i1) {
    for (size_t i = i0; i < i1; ++i) a[i] = 1, b[i] = 2, c[i] = 0;
  });
  const char* names[4] = {"copy", "scale", "add", "triad"};
  const double bytes[4] = {16.0 * n, 16.0 * n, 24.0 * n, 24.0 * n};
  double best[4] = {1e30, 1e30, 1e30, 1e30};
  for (int r = 0; r < 10; ++r) {
    best[0] = std::min(best[0], timed_parallel(n, threads, [&](size_t i0, size_t i1) {
                         for (size_t i = i0; i < i1; ++i) c[i] = a[i];
                       }));
    best[1] = std::min(best[1], timed_parallel(n, threads, [&](size_t i0, size_t i1) {
                         for (size_t i = i0; i < i1; ++i) b[i] = 3 * c[i];
                       }));
    best[2] = std::min(best[2], timed_parallel(n, threads, [&](size_t i0, size_t i1) {
                         for (size_t i = i0; i < i1; ++i) c[i] = a[i] + b[i];
                       }));
    best[3] = std::min(best[3], timed_parallel(n, threads, [&](size_t i0, size_t i1) {
                         for (size_t i = i0; i < i1; ++i) a[i] = b[i] + 3 * c[i];
                       }));
  }
  std::printf("threads %d:", threads);
  for (int k = 0; k < 4; ++k) std::printf("  %s %.1f GB/s", names[k], bytes[k] / best[k] / 1e9);
  std::printf("  (check %g)\n", a[n / 2]);
  return 0;
}
