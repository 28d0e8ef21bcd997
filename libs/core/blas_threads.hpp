// How many threads the BLAS under a sparse factorisation (CHOLMOD's supernodal Cholesky) may
// use, for the length of a scope. OpenBLAS's threads wait for work by spinning on
// sched_yield: on small factorisations (< 1e10 flops, e.g. every test problem, the QUICK
// lattices, the explicit solver's null-space filter) that costs more system time than the
// threads save (test_statics on the shared 2-core machine: 23 s system CPU with 2 BLAS
// threads, 2 s with 1). Larger factorisations keep the BLAS's own number, whatever thread
// count the run was given (OPENBLAS_NUM_THREADS sets it). Looked up at run time, so that any
// BLAS works (only OpenBLAS has the call; others are left as they are).
#pragma once

namespace latmpm {

class BlasThreadLimit {
 public:
  // At most `threads` BLAS threads in this scope (≤ 0: the BLAS's own number).
  explicit BlasThreadLimit(int threads);
  // One thread for a factorisation of fewer than 1e10 flops, the BLAS's own number above.
  static BlasThreadLimit for_flops(double flops) { return BlasThreadLimit(flops < 1e10 ? 1 : 0); }
  ~BlasThreadLimit();
  BlasThreadLimit(const BlasThreadLimit&) = delete;
  BlasThreadLimit& operator=(const BlasThreadLimit&) = delete;

 private:
  using Set = void (*)(int);
  Set set_ = nullptr;
  int saved_ = 0;
};

}  // namespace latmpm
