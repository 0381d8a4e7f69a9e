#include "contact/tread_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace rollnoise {
namespace {

// s taken into [0, L).
double wrap(double s, double length) {
  const double r = std::fmod(s, length);
  return r < 0.0 ? r + length : (r >= length ? 0.0 : r);
}

}  // namespace

TreadPattern::TreadPattern(TreadPatternGeometry geometry, double circumference)
    : geometry_(std::move(geometry)), circumference_(circumference) {
  if (!(circumference_ > 0.0 && std::isfinite(circumference_)))
    throw std::invalid_argument("tread pattern: the circumference must be > 0");
  const TreadPatternGeometry& g = geometry_;
  if (!g.pitch_lengths.empty()) {
    if (!(std::abs(g.groove_angle) < 0.5 * std::numbers::pi))
      throw std::invalid_argument("tread pattern: the groove angle must lie within ±90° of the lateral");
    if (!(g.groove_width > 0.0) || !(g.groove_depth >= 0.0))
      throw std::invalid_argument("tread pattern: lateral grooves need a width > 0 and a depth >= 0");
    double total = 0.0;
    for (double l : g.pitch_lengths) {
      if (!(l > 0.0 && std::isfinite(l))) throw std::invalid_argument("tread pattern: pitch lengths must be > 0");
      total += l;
    }
    starts_.reserve(g.pitch_lengths.size());
    double sum = 0.0;
    for (double l : g.pitch_lengths) {
      starts_.push_back(circumference_ * sum / total);
      sum += l;
    }
    groove_slope_ = std::tan(g.groove_angle);
    groove_half_length_ = 0.5 * g.groove_width / std::cos(g.groove_angle);
    const double shortest = circumference_ * *std::min_element(g.pitch_lengths.begin(), g.pitch_lengths.end()) / total;
    if (!(2.0 * groove_half_length_ < shortest))
      throw std::invalid_argument("tread pattern: a lateral groove must be shorter along the circumference than the "
                                  "shortest pitch");
  }
  for (const TreadRib& rib : g.ribs)
    if (!(rib.width > 0.0) || !(rib.depth >= 0.0) || !std::isfinite(rib.position))
      throw std::invalid_argument("tread pattern: a circumferential groove needs a width > 0 and a depth >= 0");
  if (g.map) {
    const TreadHeightMap& m = *g.map;
    if (m.lines_around < 2 || m.y.size() < 2 || m.z.size() != m.lines_around * m.y.size())
      throw std::invalid_argument("tread pattern: a map needs at least 2 x 2 values, nx·ny of them");
  }
}

double TreadPattern::lateral_groove(double s, double y) const {
  // Along the groove's own line the start s_k moves by y·tan α.
  const double t = wrap(s - y * groove_slope_, circumference_);
  const auto next = std::upper_bound(starts_.begin(), starts_.end(), t);
  const double after = next == starts_.end() ? circumference_ : *next;  // s_N = L ≡ s_0
  const double before = *(next - 1);  // starts_[0] = 0 ≤ t
  const double distance = std::min(t - before, after - t);
  return distance < groove_half_length_ ? -geometry_.groove_depth : 0.0;
}

double TreadPattern::map_height(double s, double y) const {
  const TreadHeightMap& m = *geometry_.map;
  const std::size_t nx = m.lines_around, ny = m.y.size();
  const double spacing = circumference_ / static_cast<double>(nx);
  const double u = wrap(s, circumference_) / spacing;
  const auto i0 = std::min(static_cast<std::size_t>(u), nx - 1);
  const std::size_t i1 = (i0 + 1) % nx;  // periodic around
  const double fx = u - static_cast<double>(i0);
  const double yc = std::clamp(y, m.y.front(), m.y.back());
  const auto upper = std::upper_bound(m.y.begin(), m.y.end(), yc);
  const auto j0 = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(upper - m.y.begin() - 1, 0, static_cast<std::ptrdiff_t>(ny) - 2));
  const double fy = (yc - m.y[j0]) / (m.y[j0 + 1] - m.y[j0]);
  const auto z = [&](std::size_t i, std::size_t j) { return m.z[i * ny + j]; };
  return (1.0 - fx) * ((1.0 - fy) * z(i0, j0) + fy * z(i0, j0 + 1)) + fx * ((1.0 - fy) * z(i1, j0) + fy * z(i1, j0 + 1));
}

double TreadPattern::height(double s, double y) const {
  double h = 0.0;
  if (!starts_.empty()) h = std::min(h, lateral_groove(s, y));
  for (const TreadRib& rib : geometry_.ribs)
    if (std::abs(y - rib.position) < 0.5 * rib.width) h = std::min(h, -rib.depth);
  if (geometry_.map) h = std::min(h, map_height(s, y));
  return h;
}

double TreadPattern::lateral_mean(double s, double y, double dy) const {
  constexpr int samples = 16;
  double sum = 0.0;
  for (int k = 0; k < samples; ++k) sum += height(s, y + ((k + 0.5) / samples - 0.5) * dy);
  return sum / samples;
}

int TreadPattern::tone_order() const {
  if (!starts_.empty()) return static_cast<int>(starts_.size());
  if (!geometry_.map) return 0;
  const TreadHeightMap& m = *geometry_.map;
  const std::size_t nx = m.lines_around, ny = m.y.size();
  std::vector<double> mean(nx, 0.0);
  for (std::size_t i = 0; i < nx; ++i)
    for (std::size_t j = 0; j < ny; ++j) mean[i] += m.z[i * ny + j] / static_cast<double>(ny);
  int best = 0;
  double largest = 0.0;
  for (std::size_t order = 1; order <= nx / 2; ++order) {
    std::complex<double> sum = 0.0;
    for (std::size_t i = 0; i < nx; ++i)
      sum += mean[i] * std::polar(1.0, -2.0 * std::numbers::pi * static_cast<double>(order * i % nx) / static_cast<double>(nx));
    if (std::abs(sum) > largest * (1.0 + 1e-12)) {
      largest = std::abs(sum);
      best = static_cast<int>(order);
    }
  }
  return best;
}

}  // namespace rollnoise
