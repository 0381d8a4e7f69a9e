#pragma once
// A batch of `count` real transforms of length n, each between a real field (n values) and its
// n/2 + 1 complex bins, with FFTW-aligned buffers and plans made once. backward() is
// unnormalised (FFTW's c2r) and overwrites the spectrum.
#include <fftw3.h>

#include <complex>
#include <cstddef>
#include <memory>
#include <new>

#include "core/fftw_plan.hpp"

namespace rollnoise {

class RealFftBatch {
 public:
  RealFftBatch(int length, int count)
      : length_(length),
        count_(count),
        field_(fftw_alloc_real(static_cast<std::size_t>(length) * count)),
        spectrum_(fftw_alloc_complex(static_cast<std::size_t>(bins()) * count)),
        forward_([&] {
          if (!field_ || !spectrum_) throw std::bad_alloc();
          return fftw_plan_many_dft_r2c(1, &length_, count_, field_.get(), nullptr, 1, length_, spectrum_.get(),
                                        nullptr, 1, bins(), FFTW_ESTIMATE);
        }),
        backward_([&] {
          return fftw_plan_many_dft_c2r(1, &length_, count_, spectrum_.get(), nullptr, 1, bins(), field_.get(),
                                        nullptr, 1, length_, FFTW_ESTIMATE | FFTW_DESTROY_INPUT);
        }) {}

  int length() const noexcept { return length_; }
  int bins() const noexcept { return length_ / 2 + 1; }
  double& at(int transform, int index) { return field_.get()[static_cast<std::size_t>(transform) * length_ + index]; }
  std::complex<double>& bin(int transform, int m) {
    return reinterpret_cast<std::complex<double>&>(spectrum_.get()[static_cast<std::size_t>(transform) * bins() + m]);
  }
  double* field() noexcept { return field_.get(); }
  void forward() const { forward_.execute(); }    // field → spectrum
  void backward() const { backward_.execute(); }  // spectrum → field

 private:
  struct FftwFree {
    void operator()(void* p) const noexcept { fftw_free(p); }
  };
  int length_;
  int count_;
  std::unique_ptr<double, FftwFree> field_;
  std::unique_ptr<fftw_complex, FftwFree> spectrum_;
  FftwPlan forward_;
  FftwPlan backward_;
};

}  // namespace rollnoise
