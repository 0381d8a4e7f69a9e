#include "acoustics/frequency_weighting.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

using Poles = WeightingPoles;

// The un-normalised closed forms of Annex E, as amplitude ratios (before the normalisation
// constant is subtracted).
double c_ratio(double f) {
  const double f2 = f * f;
  return (Poles::f4 * Poles::f4 * f2) / ((f2 + Poles::f1 * Poles::f1) * (f2 + Poles::f4 * Poles::f4));
}

double a_ratio(double f) {
  const double f2 = f * f;
  return (Poles::f4 * Poles::f4 * f2 * f2) /
         ((f2 + Poles::f1 * Poles::f1) * std::sqrt(f2 + Poles::f2 * Poles::f2) *
          std::sqrt(f2 + Poles::f3 * Poles::f3) * (f2 + Poles::f4 * Poles::f4));
}

// The reference frequency of the weightings' normalisation (IEC 61672-1:2013: 1 kHz).
constexpr double reference_frequency = 1000.0;

double omega(double f) { return 2.0 * std::numbers::pi * f; }

}  // namespace

std::string to_string(FrequencyWeighting weighting) {
  switch (weighting) {
    case FrequencyWeighting::A: return "A";
    case FrequencyWeighting::C: return "C";
    case FrequencyWeighting::Z: return "Z";
  }
  throw std::logic_error("to_string: unknown FrequencyWeighting");
}

FrequencyWeighting parse_frequency_weighting(const std::string& text, const std::string& key) {
  if (text == "A" || text == "a") return FrequencyWeighting::A;
  if (text == "C" || text == "c") return FrequencyWeighting::C;
  if (text == "Z" || text == "z") return FrequencyWeighting::Z;
  throw InputError("", key, "must be \"A\", \"C\" or \"Z\" (got \"" + text + "\")");
}

double weighting_normalisation_db(FrequencyWeighting weighting) {
  // Computed once: the value the formulas take at 1 kHz.
  static const double a1000 = 20.0 * std::log10(a_ratio(reference_frequency));
  static const double c1000 = 20.0 * std::log10(c_ratio(reference_frequency));
  switch (weighting) {
    case FrequencyWeighting::A: return a1000;
    case FrequencyWeighting::C: return c1000;
    case FrequencyWeighting::Z: return 0.0;
  }
  throw std::logic_error("weighting_normalisation_db: unknown FrequencyWeighting");
}

double weighting_db(FrequencyWeighting weighting, double frequency) {
  if (!(frequency >= 0.0) || !std::isfinite(frequency)) {
    throw std::invalid_argument("weighting_db: frequency must be finite and >= 0 (got " + format_number(frequency) + ")");
  }
  if (weighting == FrequencyWeighting::Z) return 0.0;
  if (frequency == 0.0) return -std::numeric_limits<double>::infinity();
  const double ratio = weighting == FrequencyWeighting::A ? a_ratio(frequency) : c_ratio(frequency);
  return 20.0 * std::log10(ratio) - weighting_normalisation_db(weighting);
}

WeightingFilter::WeightingFilter(FrequencyWeighting weighting, double sample_rate)
    : weighting_(weighting), sample_rate_(sample_rate) {
  if (!(sample_rate > 2.0 * reference_frequency) || !std::isfinite(sample_rate)) {
    throw InputError("", "sample_rate",
                     "must be a finite number > 2000 Hz so that the 1 kHz reference of the weighting lies below "
                     "the Nyquist frequency (got " + format_number(sample_rate) + ")");
  }
  if (weighting == FrequencyWeighting::Z) return;  // no sections, gain 1

  const double fs = sample_rate;
  const double k = 2.0 * fs;  // bilinear transform s = k (1 − z⁻¹)/(1 + z⁻¹)
  // A pole prewarped to its own frequency: the bilinear transform maps the digital frequency f
  // to the analogue one k·tan(π f/fs); prewarping puts the digital pole's corner at f exactly.
  const auto prewarp = [&](double f) { return k * std::tan(std::numbers::pi * f / fs); };

  // s²/((s + wa)(s + wb)), bilinear: numerator k²(1 − z⁻¹)², denominator
  // ((k + wa) + (wa − k) z⁻¹)((k + wb) + (wb − k) z⁻¹).
  const auto high_pass_pair = [&](double fa, double fb) {
    const double wa = prewarp(fa);
    const double wb = prewarp(fb);
    const double d0 = (k + wa) * (k + wb);
    const double g = k * k / d0;
    return Section{g, -2.0 * g, g, (2.0 * wa * wb - 2.0 * k * k) / d0, (k - wa) * (k - wb) / d0};
  };

  // ω4²/(s + ω4)², matched (see the header): poles e^{−ω4/fs}; numerator b(z) of degree 2 whose
  // squared magnitude, written as c0 + c1 x + c2 x² in x = cos ω, equals the prototype's
  // |H|²·|a(e^{jω})|² at ω = 0, 0.6π and 0.8π (0, 0.3 fs and 0.4 fs).
  const auto matched_low_pass_pair = [&](double f) {
    const double w = omega(f);
    const double p = std::exp(-w / fs);
    const double a1 = -2.0 * p;
    const double a2 = p * p;
    const auto target = [&](double digital) {  // |H(jΩ)|² |a(e^{jω})|², Ω = ω fs (no warping)
      const double big_omega = digital * fs;
      const double h = w * w / (w * w + big_omega * big_omega);
      const std::complex<double> z1 = std::polar(1.0, -digital);
      return h * h * std::norm(1.0 + a1 * z1 + a2 * z1 * z1);
    };
    // The quadratic through (x_i, y_i), by Lagrange: Σ y_i (x − x_j)(x − x_k)/d_i.
    const std::array<double, 3> match = {0.0, 0.6 * std::numbers::pi, 0.8 * std::numbers::pi};
    double c0 = 0.0;
    double c1 = 0.0;
    double c2 = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
      const double xi = std::cos(match[i]);
      const double xj = std::cos(match[(i + 1) % 3]);
      const double xk = std::cos(match[(i + 2) % 3]);
      const double weight = target(match[i]) / ((xi - xj) * (xi - xk));
      c2 += weight;
      c1 -= weight * (xj + xk);
      c0 += weight * xj * xk;
    }
    // |b|² must stay positive over the whole axis −1 <= x <= 1 (ends and vertex), or the fit is
    // no magnitude response; it is, for every fs > 2 kHz (checked from 2 kHz to 768 kHz).
    const auto q = [&](double x) { return c0 + c1 * x + c2 * x * x; };
    double least = std::min(q(-1.0), q(1.0));
    if (c2 != 0.0 && std::abs(c1 / (2.0 * c2)) < 1.0) least = std::min(least, q(-c1 / (2.0 * c2)));
    if (!(least > 0.0)) throw std::logic_error("WeightingFilter: the matched f4 section has no valid numerator");
    const double y0 = q(1.0);

    // Spectral factorisation. b(z) = g (1 − r1 z⁻¹)(1 − r2 z⁻¹) has
    // |b|² = g² Π (1 + ri² − 2 ri x) = g² Π (−2 ri)(x − xi), xi = (1 + ri²)/(2 ri):
    // each root xi of c0 + c1 x + c2 x² gives the zero ri = 1/(xi ± √(xi² − 1)), the sign
    // chosen so that |ri| <= 1 (minimum phase). Roots by the cancellation-free quadratic formula;
    // a vanishing c2 is a numerator of degree 1 (one root at infinity, r = 0).
    using C = std::complex<double>;
    const auto zero_of = [](C x) {
      const C s = std::sqrt(x * x - 1.0);
      const C big = std::abs(x + s) >= std::abs(x - s) ? x + s : x - s;
      return 1.0 / big;
    };
    // Roots of c2 x² + c1 x + c0: t/c2 and c0/t, t = −(c1 + sign(c1)√(c1² − 4 c2 c0))/2.
    // t = 0 only for c1 = c2 = 0, a constant |b|²: no zeros at all.
    const C disc = std::sqrt(C(c1 * c1 - 4.0 * c2 * c0));
    const C t = -0.5 * (c1 + (c1 >= 0.0 ? disc : -disc));
    C r1 = 0.0;
    C r2 = 0.0;
    if (std::abs(t) > 0.0) {
      r2 = zero_of(c0 / t);
      if (std::abs(c2) > 1e-15 * (std::abs(c0) + std::abs(c1))) r1 = zero_of(t / c2);
    }
    // Real coefficients: the zeros are real or a conjugate pair.
    const double m1 = -(r1 + r2).real();
    const double m2 = (r1 * r2).real();
    // Gain from the DC value: |b(1)|² = y0.
    const double g = std::sqrt(y0) / std::abs(1.0 + m1 + m2);
    return Section{g, g * m1, g * m2, a1, a2};
  };

  sections_.push_back(high_pass_pair(Poles::f1, Poles::f1));
  if (weighting == FrequencyWeighting::A) sections_.push_back(high_pass_pair(Poles::f2, Poles::f3));
  sections_.push_back(matched_low_pass_pair(Poles::f4));

  // Exactly the formula's value (0 dB) at the 1 kHz reference.
  gain_ = 1.0;
  gain_ = std::pow(10.0, weighting_db(weighting, reference_frequency) / 20.0) / std::abs(response(reference_frequency));
}

std::complex<double> WeightingFilter::response(double frequency) const {
  if (!(frequency >= 0.0 && frequency <= 0.5 * sample_rate_)) {
    throw std::invalid_argument("WeightingFilter::response: frequency " + format_number(frequency) +
                                " Hz is outside [0, fs/2]");
  }
  const std::complex<double> z1 = std::polar(1.0, -2.0 * std::numbers::pi * frequency / sample_rate_);
  const std::complex<double> z2 = z1 * z1;
  std::complex<double> h = gain_;
  for (const Section& s : sections_) h *= (s.b0 + s.b1 * z1 + s.b2 * z2) / (1.0 + s.a1 * z1 + s.a2 * z2);
  return h;
}

double WeightingFilter::response_db(double frequency) const { return 20.0 * std::log10(std::abs(response(frequency))); }

std::vector<double> WeightingFilter::apply(std::span<const double> signal, const CancellationToken& cancel) const {
  std::vector<double> out(signal.begin(), signal.end());
  // Transposed direct form II per section, section after section over the whole signal (double
  // precision: the 20.6 Hz poles sit 2.7e-3 inside the unit circle at 48 kHz, far from where
  // rounding in this form matters). In blocks, polling Ctrl-C between them (an hour at 48 kHz
  // is 1.7e8 samples).
  constexpr std::size_t block = std::size_t{1} << 16;
  for (const Section& s : sections_) {
    double w1 = 0.0;
    double w2 = 0.0;
    for (std::size_t start = 0; start < out.size(); start += block) {
      cancel.throw_if_cancelled();
      const std::size_t end = std::min(out.size(), start + block);
      for (std::size_t n = start; n < end; ++n) {
        const double x = out[n];
        const double y = s.b0 * x + w1;
        w1 = s.b1 * x - s.a1 * y + w2;
        w2 = s.b2 * x - s.a2 * y;
        out[n] = y;
      }
    }
  }
  for (double& v : out) v *= gain_;
  return out;
}

}  // namespace rollnoise
