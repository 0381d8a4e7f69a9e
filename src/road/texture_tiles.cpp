#include "road/texture_tiles.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <new>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>

#include <fftw3.h>

#include "core/csv.hpp"
#include "core/error.hpp"
#include "core/fftw_plan.hpp"
#include "road/portable_normal.hpp"
#include "road/spectral_synthesis.hpp"

namespace rollnoise {
namespace {

struct FftwFree {
  void operator()(void* p) const noexcept { fftw_free(p); }
};

// Tile k's own seed: SplitMix64 (Steele, Lea & Flood 2014) of the road's seed and k, so that
// neighbouring tiles and neighbouring seeds give unrelated engines.
std::uint64_t tile_seed(std::uint64_t seed, std::size_t index) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (static_cast<std::uint64_t>(index) + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// The blend weight of the new tile at s in [0, 1] of the overlap: sin(theta), theta rising from 0
// to pi/2 with zero slope at both ends.
double blend_angle(double s) { return 0.5 * std::numbers::pi * (s - std::sin(2.0 * std::numbers::pi * s) / (2.0 * std::numbers::pi)); }

}  // namespace

TextureTileLayout texture_tile_layout(double spacing, double longest_wavelength, double width) {
  if (!(spacing > 0.0) || !(longest_wavelength > 0.0) || !(width > 0.0)) {
    throw std::invalid_argument("texture_tile_layout: spacing, wavelength and width must be > 0");
  }
  TextureTileLayout l;
  l.spacing = spacing;
  const double overlap = std::ceil(2.0 * longest_wavelength / spacing);
  const double core = std::max(std::ceil(16.0 * longest_wavelength / spacing), std::ceil(0.5 / spacing));
  const double across = std::ceil((width + 2.0 * longest_wavelength) / spacing);
  // One tile's grid (lateral period x tile length) is what a tile costs, whatever the road's length.
  synthesis_grid_size(across, across * (core + overlap));
  l.n_y = fft_friendly_size(static_cast<std::size_t>(across));
  l.n_x = fft_friendly_size(static_cast<std::size_t>(core + overlap));
  l.overlap = static_cast<std::size_t>(overlap);
  l.core = l.n_x - l.overlap;
  return l;
}

std::vector<double> synthesise_texture_tile(const TextureBandPsd& psd, const TextureTileLayout& layout,
                                            std::uint64_t seed, std::size_t index, std::size_t half_lines) {
  const std::size_t n0 = layout.n_x;
  const std::size_t n1 = layout.n_y;
  const std::size_t lines = 2 * half_lines + 1;
  if (lines > n1) throw std::invalid_argument("synthesise_texture_tile: more lines than the lateral period");
  const std::size_t half0 = n0 / 2 + 1;
  const double dnx = 1.0 / (layout.spacing * static_cast<double>(n0));
  const double dny = 1.0 / (layout.spacing * static_cast<double>(n1));
  const double n_max = psd.highest_wavenumber();

  // The nx columns' lateral transforms, kept at the strip's lines: line-major, so that each line's
  // transform along x reads contiguous memory.
  std::unique_ptr<fftw_complex[], FftwFree> kept(fftw_alloc_complex(lines * half0));
  std::unique_ptr<fftw_complex[], FftwFree> column(fftw_alloc_complex(n1));
  std::unique_ptr<fftw_complex[], FftwFree> line_in(fftw_alloc_complex(half0));
  std::unique_ptr<double[], FftwFree> line_out(fftw_alloc_real(n0));
  if (!kept || !column || !line_in || !line_out) throw std::bad_alloc();
  std::fill(&kept[0][0], &kept[0][0] + 2 * lines * half0, 0.0);
  const FftwPlan across([&] {
    return fftw_plan_dft_1d(static_cast<int>(n1), column.get(), column.get(), FFTW_BACKWARD, FFTW_ESTIMATE);
  });
  const FftwPlan along([&] {
    return fftw_plan_dft_c2r_1d(static_cast<int>(n0), line_in.get(), line_out.get(), FFTW_ESTIMATE);
  });

  std::mt19937_64 engine(tile_seed(seed, index));
  // Lateral wavenumbers |ky| <= ky_last: below the lateral Nyquist wavenumber.
  const std::size_t ky_last = (n1 - 1) / 2;
  std::vector<double> cumulative;  // at the cell edges (ky + 1/2)·dny, ky = 0 .. ky_last
  for (std::size_t kx = 0; kx < half0; ++kx) {
    const double nx = static_cast<double>(kx) * dnx;
    if (nx >= n_max || 2 * kx == n0) continue;  // no texture here, or the Nyquist column
    // Cell ky spans [(ky - 1/2) dny, (ky + 1/2) dny]: its integral of S at this nx, and its
    // amplitude |C|^2 = dnx · integral (two-sided density, both signs of (nx, ny) counted).
    const double b_max = std::sqrt((n_max - nx) * (n_max + nx));
    const std::size_t ky_end = std::min(ky_last, static_cast<std::size_t>(std::ceil(b_max / dny + 0.5)));
    cumulative.assign(ky_end + 1, 0.0);
    for (std::size_t ky = 0; ky <= ky_end; ++ky)
      cumulative[ky] = psd.isotropic_line_cumulative(nx, (static_cast<double>(ky) + 0.5) * dny);
    const auto amplitude = [&](std::size_t ky) {
      const double cell = ky == 0 ? 2.0 * cumulative[0] : cumulative[ky] - cumulative[ky - 1];
      return std::sqrt(dnx * std::max(0.0, cell));
    };
    for (std::size_t k = 0; k < n1; ++k) column[k][0] = column[k][1] = 0.0;
    if (kx == 0) {
      // The mean is 0; (0, ky) and (0, -ky) are one conjugate pair, so the line is real.
      for (std::size_t ky = 1; ky <= ky_end; ++ky) {
        const auto [c, s] = portable::random_phasor(engine);
        const double a = amplitude(ky);
        column[ky][0] = a * c;
        column[ky][1] = a * s;
        column[n1 - ky][0] = a * c;
        column[n1 - ky][1] = -a * s;
      }
    } else {
      for (std::size_t ky = 0; ky <= ky_end; ++ky) {
        const double a = amplitude(ky);
        for (int sign = ky == 0 ? 1 : -1; sign <= 1; sign += 2) {
          const auto [c, s] = portable::random_phasor(engine);
          const std::size_t slot = sign > 0 ? ky : n1 - ky;
          column[slot][0] = a * c;
          column[slot][1] = a * s;
        }
      }
    }
    across.execute();
    for (std::size_t line = 0; line < lines; ++line) {
      const std::size_t j = (line + n1 - half_lines) % n1;  // y = (line - half_lines)·spacing
      kept[line * half0 + kx][0] = column[j][0];
      kept[line * half0 + kx][1] = column[j][1];
    }
  }
  std::vector<double> out(n0 * lines);
  for (std::size_t line = 0; line < lines; ++line) {
    std::copy(&kept[line * half0][0], &kept[line * half0][0] + 2 * half0, &line_in[0][0]);
    along.execute();
    for (std::size_t i = 0; i < n0; ++i) out[i * lines + line] = line_out[i];
  }
  return out;
}

TiledTextureSurface::TiledTextureSurface(TextureBandPsd psd, TextureTileLayout layout, std::uint64_t seed,
                                         std::size_t half_lines, double lead_in)
    : psd_(std::move(psd)), layout_(layout), seed_(seed), half_lines_(half_lines), lead_in_(lead_in) {
  if (2 * half_lines_ + 1 > layout_.n_y) throw std::invalid_argument("TiledTextureSurface: strip wider than the period");
}

const std::vector<double>& TiledTextureSurface::field(std::size_t index) const {
  // Tiles of even and odd index take their own slot, so a tile and the one before it (which the
  // overlap blends) are held together.
  Tile& slot = fields_[index % 2];
  if (slot.index != index) {
    slot.index = static_cast<std::size_t>(-1);
    slot.values = synthesise_texture_tile(psd_, layout_, seed_, index, half_lines_);
    slot.index = index;
  }
  return slot.values;
}

const std::vector<double>& TiledTextureSurface::road(std::size_t index) const {
  Tile& slot = roads_[index % 2];  // as field(): a point between two tiles reads both
  if (slot.index == index) return slot.values;
  const std::size_t lines = 2 * half_lines_ + 1;
  std::vector<double> values(layout_.core * lines);
  {
    const std::vector<double>& own = field(index);
    std::copy(own.begin(), own.begin() + static_cast<std::ptrdiff_t>(values.size()), values.begin());
  }
  if (index > 0) {
    // Both raw tiles are held at once (two slots): index - 1 is made now if it was not.
    const std::vector<double>& before = field(index - 1);
    const std::vector<double>& own = field(index);
    for (std::size_t i = 0; i < layout_.overlap; ++i) {
      const double theta = blend_angle(static_cast<double>(i) / static_cast<double>(layout_.overlap));
      const double w_own = std::sin(theta);
      const double w_before = std::cos(theta);
      for (std::size_t l = 0; l < lines; ++l) {
        values[i * lines + l] = w_own * own[i * lines + l] + w_before * before[(i + layout_.core) * lines + l];
      }
    }
  }
  const std::size_t first = index * layout_.core;
  for (std::size_t i = 0; i < layout_.core; ++i) {
    const double w = lead_in_window(layout_.spacing * static_cast<double>(first + i), lead_in_);
    if (w == 1.0) break;
    for (std::size_t l = 0; l < lines; ++l) values[i * lines + l] *= w;
  }
  slot.values = std::move(values);
  slot.index = index;
  return slot.values;
}

double TiledTextureSurface::sample(std::size_t i, long j) const {
  if (j < -static_cast<long>(half_lines_) || j > static_cast<long>(half_lines_)) {
    throw std::logic_error("TiledTextureSurface: line " + std::to_string(j) + " is outside the strip");
  }
  const std::lock_guard lock(mutex_);
  const std::vector<double>& tile = road(i / layout_.core);
  return tile[(i % layout_.core) * (2 * half_lines_ + 1) + static_cast<std::size_t>(j + static_cast<long>(half_lines_))];
}

double TiledTextureSurface::height(double x, double y) const {
  if (x < 0.0) return 0.0;  // the flat lead-in (road_profile.hpp)
  const double h = layout_.spacing;
  const double u = x / h;
  const double v = y / h;
  const double reach = static_cast<double>(half_lines_);
  if (!std::isfinite(u) || !(std::abs(v) <= reach + 1e-9)) {
    throw std::logic_error("TiledTextureSurface: (" + format_number(x) + ", " + format_number(y) +
                           ") m is outside the strip |y| <= " + format_number(reach * h) + " m");
  }
  const auto i = static_cast<std::size_t>(std::floor(u));
  const double fx = u - static_cast<double>(i);
  if (half_lines_ == 0) return (1.0 - fx) * sample(i, 0) + fx * sample(i + 1, 0);  // one line, y = 0
  const long last = static_cast<long>(half_lines_) - 1;
  const long j = std::clamp(static_cast<long>(std::floor(v)), -static_cast<long>(half_lines_), last);
  const double fy = std::clamp(v - static_cast<double>(j), 0.0, 1.0);
  const double z00 = sample(i, j), z10 = sample(i + 1, j);
  const double z01 = sample(i, j + 1), z11 = sample(i + 1, j + 1);
  return (1.0 - fx) * ((1.0 - fy) * z00 + fy * z01) + fx * ((1.0 - fy) * z10 + fy * z11);
}

}  // namespace rollnoise
