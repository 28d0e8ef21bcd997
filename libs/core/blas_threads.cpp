#include "core/blas_threads.hpp"

#include <dlfcn.h>

namespace latmpm {

BlasThreadLimit::BlasThreadLimit(int threads) {
  using Get = int (*)();
  auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  set_ = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!get || !set_ || threads <= 0) return;
  const int current = get();
  if (current > threads) {
    saved_ = current;
    set_(threads);
  }
}

BlasThreadLimit::~BlasThreadLimit() {
  if (saved_ > 0) set_(saved_);
}

}  // namespace latmpm
