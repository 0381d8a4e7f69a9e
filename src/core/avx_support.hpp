#pragma once
// Whether the hand-vectorised AVX paths (contact/window_convolution.cpp, contact/pmatrix_lcp.cpp)
// are built for this processor family and supported by the processor running the program. Each
// path gives the same bits as its plain loop; this only chooses between them at run time.
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define ROLLNOISE_AVX_PATHS 1
#endif

namespace rollnoise {

// `wanted` and, where the AVX paths are built, the processor has AVX.
inline bool avx_available(bool wanted) noexcept {
#if defined(ROLLNOISE_AVX_PATHS)
  return wanted && __builtin_cpu_supports("avx");
#else
  (void)wanted;  // no AVX path on this processor family
  return false;
#endif
}

}  // namespace rollnoise
