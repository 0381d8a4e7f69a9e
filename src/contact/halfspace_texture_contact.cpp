#include "contact/halfspace_texture_contact.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <mutex>
#include <new>
#include <stdexcept>

#include <fftw3.h>

#include "core/fftw_plan.hpp"
#include "greens/tread_compliance.hpp"

namespace rollnoise {
namespace {

struct FftwFree {
  void operator()(void* p) const noexcept { fftw_free(p); }
};

}  // namespace

// The zero-padded grid (2nx × 2ny), the influence kernel's transform, and the work arrays:
// one solve at a time per object (the mutex).
struct HalfspaceTextureContact::Fft {
  std::size_t mx, my;  // padded sizes
  std::unique_ptr<double[], FftwFree> real;
  std::unique_ptr<fftw_complex[], FftwFree> spectrum;
  std::vector<std::complex<double>> kernel;  // transform of the influence coefficients, scaled by 1/(mx·my)
  std::unique_ptr<FftwPlan> forward, inverse;
  std::mutex mutex;
};

HalfspaceTextureContact::HalfspaceTextureContact(std::size_t nx, std::size_t ny, double dx, double dy,
                                                 double youngs_modulus, double poisson_ratio)
    : nx_(nx), ny_(ny), dx_(dx), dy_(dy), fft_(std::make_unique<Fft>()) {
  if (nx < 1 || ny < 1 || !(dx > 0.0) || !(dy > 0.0))
    throw std::invalid_argument("HalfspaceTextureContact: a grid of at least one cell of positive size");
  Fft& f = *fft_;
  f.mx = 2 * nx;
  f.my = 2 * ny;
  const std::size_t half = f.my / 2 + 1;
  f.real.reset(fftw_alloc_real(f.mx * f.my));
  f.spectrum.reset(fftw_alloc_complex(f.mx * half));
  if (!f.real || !f.spectrum) throw std::bad_alloc();
  const int mx = static_cast<int>(f.mx), my = static_cast<int>(f.my);
  f.forward = std::make_unique<FftwPlan>([&] { return fftw_plan_dft_r2c_2d(mx, my, f.real.get(), f.spectrum.get(), FFTW_ESTIMATE); });
  f.inverse = std::make_unique<FftwPlan>([&] { return fftw_plan_dft_c2r_2d(mx, my, f.spectrum.get(), f.real.get(), FFTW_ESTIMATE); });
  // The kernel on the padded grid: offset (di, dj) at index (di mod mx, dj mod my); the offsets
  // of nx (and ny), which no pair of cells has, are 0.
  for (std::size_t a = 0; a < f.mx; ++a) {
    for (std::size_t b = 0; b < f.my; ++b) {
      const long di = a < nx ? static_cast<long>(a) : static_cast<long>(a) - static_cast<long>(f.mx);
      const long dj = b < ny ? static_cast<long>(b) : static_cast<long>(b) - static_cast<long>(f.my);
      const bool exists = a != nx && b != ny;
      f.real[a * f.my + b] = exists ? love_rectangle_displacement(static_cast<double>(di) * dx, static_cast<double>(dj) * dy,
                                                                  0.5 * dx, 0.5 * dy, youngs_modulus, poisson_ratio)
                                    : 0.0;
    }
  }
  f.forward->execute();
  const double scale = 1.0 / static_cast<double>(f.mx * f.my);
  f.kernel.resize(f.mx * half);
  for (std::size_t k = 0; k < f.kernel.size(); ++k) f.kernel[k] = {f.spectrum[k][0] * scale, f.spectrum[k][1] * scale};
}

HalfspaceTextureContact::~HalfspaceTextureContact() = default;

void HalfspaceTextureContact::displacement(std::span<const double> pressure, std::span<double> out) const {
  if (pressure.size() != nx_ * ny_ || out.size() != nx_ * ny_)
    throw std::invalid_argument("HalfspaceTextureContact::displacement: one value per grid cell");
  Fft& f = *fft_;
  const std::lock_guard lock(f.mutex);
  std::fill(f.real.get(), f.real.get() + f.mx * f.my, 0.0);
  for (std::size_t i = 0; i < nx_; ++i)
    for (std::size_t j = 0; j < ny_; ++j) f.real[i * f.my + j] = pressure[i * ny_ + j];
  f.forward->execute();
  for (std::size_t k = 0; k < f.kernel.size(); ++k) {
    const std::complex<double> z = std::complex<double>(f.spectrum[k][0], f.spectrum[k][1]) * f.kernel[k];
    f.spectrum[k][0] = z.real();
    f.spectrum[k][1] = z.imag();
  }
  f.inverse->execute();
  for (std::size_t i = 0; i < nx_; ++i)
    for (std::size_t j = 0; j < ny_; ++j) out[i * ny_ + j] = f.real[i * f.my + j];
}

HalfspaceContactResult HalfspaceTextureContact::solve(std::span<const double> heights, double approach, double tolerance,
                                                      int max_iterations) const {
  const std::size_t n = nx_ * ny_;
  if (heights.size() != n) throw std::invalid_argument("HalfspaceTextureContact::solve: one height per grid cell");
  if (!(approach >= 0.0) || !std::isfinite(approach)) throw std::invalid_argument("HalfspaceTextureContact::solve: approach >= 0");
  const double top = *std::max_element(heights.begin(), heights.end());
  std::vector<double> overlap(n);
  for (std::size_t i = 0; i < n; ++i) overlap[i] = heights[i] - (top - approach);
  HalfspaceContactResult r;
  r.pressure.assign(n, 0.0);
  if (approach == 0.0) {
    r.converged = true;
    return r;
  }
  // Start: the pressure of each overlapping cell alone, o_i / K_ii (an upper estimate).
  std::vector<double> u(n), gradient(n), direction(n, 0.0), product(n);
  std::vector<double> one(n, 0.0);
  one[0] = 1.0;
  displacement(one, u);
  const double self = u[0];  // K_ii, the same for every cell
  std::vector<double>& p = r.pressure;
  for (std::size_t i = 0; i < n; ++i) p[i] = overlap[i] > 0.0 ? overlap[i] / self : 0.0;
  double previous_norm = 1.0;
  bool restart = true;
  for (r.iterations = 1; r.iterations <= max_iterations; ++r.iterations) {
    displacement(p, u);
    double norm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      gradient[i] = u[i] - overlap[i];
      if (p[i] > 0.0) norm += gradient[i] * gradient[i];
    }
    const double beta = restart ? 0.0 : norm / previous_norm;
    for (std::size_t i = 0; i < n; ++i) direction[i] = p[i] > 0.0 ? gradient[i] + beta * direction[i] : 0.0;
    previous_norm = norm;
    displacement(direction, product);
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0.0) {
        num += gradient[i] * direction[i];
        den += product[i] * direction[i];
      }
    }
    const double step = den > 0.0 ? num / den : 0.0;
    double change = 0.0, total = 0.0;
    restart = false;
    for (std::size_t i = 0; i < n; ++i) {
      const double before = p[i];
      if (p[i] > 0.0) {
        p[i] = std::max(0.0, p[i] - step * direction[i]);
      } else if (gradient[i] < 0.0) {
        // A cell out of contact that the surfaces overlap at: it enters (Polonsky & Keer's step).
        p[i] = -step * gradient[i];
        if (p[i] > 0.0) restart = true;
      }
      change += std::abs(p[i] - before);
      total += p[i];
    }
    if (total > 0.0 && change <= tolerance * total) {
      r.converged = true;
      break;
    }
  }
  const double cell = dx_ * dy_;
  for (std::size_t i = 0; i < n; ++i) {
    r.force += p[i] * cell;
    if (p[i] > 0.0) r.contact_area += cell;
  }
  return r;
}

}  // namespace rollnoise
