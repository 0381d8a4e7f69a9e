#include "contact/cell_contact_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace rollnoise {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

}  // namespace

CellContactLaws::CellContactLaws(std::size_t cells, double force_cap, double minimum_compliance)
    : cap_(force_cap),
      minimum_compliance_(minimum_compliance),
      top_(cells, 0.0),
      approach_(cells * levels, 0.0f),
      slope_(cells * (levels + 1), 0.0f),
      energy_(cells * levels, 0.0) {
  if (!(force_cap > 0.0) || !std::isfinite(force_cap))
    throw std::invalid_argument("CellContactLaws: the force cap must be finite and > 0");
  if (!(minimum_compliance > 0.0) || !std::isfinite(minimum_compliance))
    throw std::invalid_argument("CellContactLaws: the minimum compliance must be finite and > 0");
  forces_.resize(levels);
  for (int k = 0; k < levels; ++k) forces_[static_cast<std::size_t>(k)] = force_cap * std::pow(10.0, (k - levels + 1) / 4.0);
  // A valid law until set: the minimum compliance alone.
  const std::vector<double> linear(levels, 0.0);
  for (std::size_t c = 0; c < cells; ++c) set(c, 0.0, linear);
}

void CellContactLaws::set(std::size_t cell, double top, std::span<const double> approaches) {
  if (cell >= cells() || approaches.size() != static_cast<std::size_t>(levels))
    throw std::invalid_argument("CellContactLaws::set: cell out of range or not one approach per level");
  if (!std::isfinite(top)) throw std::invalid_argument("CellContactLaws::set: the first-touch height is not finite");
  top_[cell] = top;
  double previous_delta = 0.0, previous_force = 0.0;
  float previous_stored = 0.0f;
  for (int k = 0; k < levels; ++k) {
    const double f = forces_[static_cast<std::size_t>(k)];
    const double given = approaches[static_cast<std::size_t>(k)];
    if (!(given >= 0.0) || !std::isfinite(given))
      throw std::invalid_argument("CellContactLaws::set: an approach is negative or not finite");
    const double delta = std::max(given, previous_delta + minimum_compliance_ * (f - previous_force));
    float stored = static_cast<float>(delta);
    if (!(stored > previous_stored)) stored = std::nextafter(previous_stored, std::numeric_limits<float>::infinity());
    approach_[cell * levels + static_cast<std::size_t>(k)] = stored;
    // The floor from the stored value, so that setting a cell from its stored approaches (the
    // cache) gives the same floats.
    previous_delta = static_cast<double>(stored);
    previous_force = f;
    previous_stored = stored;
  }
  for (int i = 0; i <= levels; ++i)
    slope_[cell * (levels + 1) + static_cast<std::size_t>(i)] = static_cast<float>(monotone_slope(cell, i));
  // ∫ of each cubic Hermite segment: h·[(f0 + f1)/2 + h·(m0 − m1)/12].
  double energy = 0.0;
  for (int i = 0; i < levels; ++i) {
    const double h = node_delta(cell, i + 1) - node_delta(cell, i);
    energy += h * (0.5 * (node_force(i) + node_force(i + 1)) + h * (node_slope(cell, i) - node_slope(cell, i + 1)) / 12.0);
    energy_[cell * levels + static_cast<std::size_t>(i)] = energy;
  }
}

Eigen::VectorXd CellContactLaws::tops() const {
  return Eigen::Map<const Eigen::VectorXd>(top_.data(), static_cast<Eigen::Index>(top_.size()));
}

Eigen::MatrixXd CellContactLaws::approach_table() const {
  // approach_ is cell-major: a row-major cells × levels array.
  using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  return Eigen::Map<const RowMajor>(approach_.data(), static_cast<Eigen::Index>(cells()), levels).cast<double>();
}

double CellContactLaws::monotone_slope(std::size_t cell, int i) const noexcept {
  const auto secant = [&](int s) {
    return (node_force(s + 1) - node_force(s)) / (node_delta(cell, s + 1) - node_delta(cell, s));
  };
  if (i == 0) return secant(0);
  if (i == levels) return secant(levels - 1);
  // Fritsch–Carlson (Brodlie's weights): a weighted harmonic mean of the neighbouring secants,
  // which keeps the cubic monotone on every segment.
  const double h0 = node_delta(cell, i) - node_delta(cell, i - 1), h1 = node_delta(cell, i + 1) - node_delta(cell, i);
  const double w1 = 2.0 * h1 + h0, w2 = h1 + 2.0 * h0;
  return (w1 + w2) / (w1 / secant(i - 1) + w2 / secant(i));
}

int CellContactLaws::segment_of(std::size_t cell, double delta, int* hint) const noexcept {
  // The last node at or below δ (levels: beyond the last node); the hint's segment first.
  if (hint && *hint >= 0 && *hint <= levels && node_delta(cell, *hint) <= delta &&
      (*hint == levels || delta < node_delta(cell, *hint + 1)))
    return *hint;
  int lo = 0, hi = levels + 1;  // node lo ≤ δ < node hi (hi = levels + 1: none above)
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (node_delta(cell, mid) <= delta) lo = mid;
    else hi = mid;
  }
  if (hint) *hint = lo;
  return lo;
}

void CellContactLaws::force(std::size_t cell, double delta, double& force, double& slope, int* hint) const {
  if (delta == 0.0) {  // most points of a step's window, out of contact: the cubic at t = 0 of segment 0
    force = 0.0;
    slope = node_slope(cell, 0);
    return;
  }
  force_on_segment(cell, segment_of(cell, delta, hint), delta, force, slope);
}

void CellContactLaws::force_on_segment(std::size_t cell, int i, double delta, double& force,
                                       double& slope) const noexcept {
  const double d0 = node_delta(cell, i), f0 = node_force(i);
  if (i == levels) {
    slope = node_slope(cell, levels);
    force = f0 + slope * (delta - d0);
    return;
  }
  const double h = node_delta(cell, i + 1) - d0, f1 = node_force(i + 1);
  const double m0 = node_slope(cell, i), m1 = node_slope(cell, i + 1);
  const double t = (delta - d0) / h, t2 = t * t, t3 = t2 * t;
  force = (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * h * m0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * h * m1;
  slope = ((6 * t2 - 6 * t) * f0 + (-6 * t2 + 6 * t) * f1) / h + (3 * t2 - 4 * t + 1) * m0 + (3 * t2 - 2 * t) * m1;
}

double CellContactLaws::solve_on_segment(std::size_t cell, int i, double w, double c, double target,
                                         double guess) const {
  // The segment's cubic in t = (δ − d0)/h, fixed once: Newton in t, safeguarded by the bracket.
  const double d0 = node_delta(cell, i), h = node_delta(cell, i + 1) - d0;
  const double f0 = node_force(i), f1 = node_force(i + 1);
  const double hm0 = h * node_slope(cell, i), hm1 = h * node_slope(cell, i + 1);
  // Start at the guess when it lies on the segment (a contact step's Newton predicts δ to second
  // order: one or two steps remain), else where the chord between the segment's ends meets the
  // target (g is increasing and nearly linear on a segment): Newton then takes two or three.
  const double g0 = w * d0 + c * f0 - target, g1 = w * (d0 + h) + c * f1 - target;
  double lo = 0.0, hi = 1.0, t = g1 > g0 ? std::clamp(-g0 / (g1 - g0), 0.0, 1.0) : 0.5;
  if (const double from_guess = (guess - d0) / h; from_guess > 0.0 && from_guess < 1.0) t = from_guess;
  // δ = d0 + h·t is known to its round-off, eps·δ: in t, eps·(d0 + h)/h, which is far above eps
  // on a short segment far from the origin (stopping at eps in t would bisect to the end).
  const double resolution = 4.0 * kEps * (d0 + h) / h;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double t2 = t * t, t3 = t2 * t;
    const double f = (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * hm0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * hm1;
    const double df = (6 * t2 - 6 * t) * (f0 - f1) + (3 * t2 - 4 * t + 1) * hm0 + (3 * t2 - 2 * t) * hm1;  // dF/dt
    const double g = w * (d0 + h * t) + c * f - target;
    // g is known to the round-off of its terms: closer is noise (with c·F ≫ δ far above eps·δ).
    if (std::abs(g) <= 4.0 * kEps * (w * (d0 + h * t) + c * std::abs(f) + std::abs(target))) return d0 + h * t;
    if (g > 0.0) hi = t;
    else lo = t;
    const double derivative = w * h + c * df;
    double next = derivative > 0.0 ? t - g / derivative : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - t) <= resolution || hi - lo <= resolution) return d0 + h * next;
    t = next;
  }
  return d0 + h * t;
}

double CellContactLaws::approach_at(std::size_t cell, double f) const {
  if (!(f > 0.0)) return 0.0;
  const auto above = std::upper_bound(forces_.begin(), forces_.end(), f);
  const int i = static_cast<int>(above - forces_.begin());  // node i has F ≤ f < node i + 1's
  if (i == levels) return node_delta(cell, levels) + (f - node_force(levels)) / node_slope(cell, levels);
  return solve_on_segment(cell, i, 0.0, 1.0, f);
}

int CellContactLaws::compression_segment(std::size_t cell, double y, double c, int* hint) const noexcept {
  // The node i with δ_i + c·F_i ≤ y < the next one's (increasing in i); the hint's first.
  const auto below = [&](int i) { return node_delta(cell, i) + c * node_force(i) <= y; };
  if (hint && *hint >= 0 && *hint <= levels && below(*hint) && (*hint == levels || !below(*hint + 1))) return *hint;
  int lo = 0, hi = levels + 1;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (below(mid)) lo = mid;
    else hi = mid;
  }
  if (hint) *hint = lo;
  return lo;
}

double CellContactLaws::compression_of(std::size_t cell, double y, double c, int* hint, double guess) const {
  double force = 0.0, slope = 0.0;
  return compression_of(cell, y, c, hint, guess, force, slope);
}

double CellContactLaws::compression_of(std::size_t cell, double y, double c, int* hint, double guess, double& force,
                                       double& slope) const {
  const int i = y > 0.0 ? compression_segment(cell, y, c, hint) : 0;
  double delta = 0.0;
  if (!(y > 0.0)) {
    delta = 0.0;
  } else if (i == levels) {
    const double d = node_delta(cell, levels), s = node_slope(cell, levels);
    delta = d + (y - d - c * node_force(levels)) / (1.0 + c * s);
  } else {
    delta = solve_on_segment(cell, i, 1.0, c, y, guess);
  }
  // δ may land a round-off outside segment i: F there is the segment's cubic continued, which
  // differs from the neighbour's by far less than the solve's own tolerance.
  force_on_segment(cell, i, delta, force, slope);
  return delta;
}

double CellContactLaws::stored_energy(std::size_t cell, double delta, int* hint) const {
  // The nodes' energies, then the part of the segment: ∫₀^t of the cubic Hermite basis,
  // h·[f0(t − t³ + t⁴/2) + h·m0(t²/2 − 2t³/3 + t⁴/4) + f1(t³ − t⁴/2) + h·m1(t⁴/4 − t³/3)].
  const int i = segment_of(cell, delta, hint);
  const double d0 = node_delta(cell, i);
  if (i == levels) {
    const double d = delta - d0;
    return node_energy(cell, levels) + d * (node_force(levels) + 0.5 * node_slope(cell, levels) * d);
  }
  const double h = node_delta(cell, i + 1) - d0;
  const double t = (delta - d0) / h, t2 = t * t, t3 = t2 * t, t4 = t3 * t;
  return node_energy(cell, i) +
         h * (node_force(i) * (t - t3 + 0.5 * t4) + h * node_slope(cell, i) * (0.5 * t2 - 2.0 * t3 / 3.0 + 0.25 * t4) +
              node_force(i + 1) * (t3 - 0.5 * t4) + h * node_slope(cell, i + 1) * (0.25 * t4 - t3 / 3.0));
}

CellLawSprings::CellLawSprings(std::shared_ptr<const CellContactLaws> laws, Eigen::Index points)
    : laws_(std::move(laws)), cell_(static_cast<std::size_t>(points), 0), hint_(static_cast<std::size_t>(points), 0) {
  if (!laws_ || laws_->cells() == 0) throw std::invalid_argument("CellLawSprings: no laws");
}

void CellLawSprings::evaluate(Eigen::Index p, double delta, double& force, double& slope) const {
  laws_->force(cell_[static_cast<std::size_t>(p)], std::abs(delta), force, slope, &hint_[static_cast<std::size_t>(p)]);
  force = std::copysign(force, delta);
}

double CellLawSprings::compression_of(Eigen::Index p, double y, double c, double guess) const {
  // y = δ + c·F(δ) increases with δ, so its segments are δ's: one hint serves both.
  return std::copysign(laws_->compression_of(cell_[static_cast<std::size_t>(p)], std::abs(y), c,
                                             &hint_[static_cast<std::size_t>(p)], std::abs(guess)),
                       y);
}

void CellLawSprings::compress(Eigen::Index p, double y, double c, double guess, double& delta, double& force,
                              double& slope) const {
  const double magnitude = laws_->compression_of(cell_[static_cast<std::size_t>(p)], std::abs(y), c,
                                                 &hint_[static_cast<std::size_t>(p)], std::abs(guess), force, slope);
  delta = std::copysign(magnitude, y);
  force = std::copysign(force, delta);
}

double CellLawSprings::compression_at(Eigen::Index p, double force) const {
  return laws_->approach_at(cell_[static_cast<std::size_t>(p)], force);
}

double CellLawSprings::stored_energy(Eigen::Index p, double delta) const {
  return laws_->stored_energy(cell_[static_cast<std::size_t>(p)], std::abs(delta), &hint_[static_cast<std::size_t>(p)]);
}

}  // namespace rollnoise
