#include "acoustics/fractional_octave_bands.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

void require_bands_per_octave(int b) {
  if (b < 1) throw std::invalid_argument("bands per octave must be >= 1 (got " + std::to_string(b) + ")");
}

// The R10 preferred numbers ×100 (IEC 61260-1:2014 Annex E; ISO 3): integers, so that the
// nominal values are the decimal numbers exactly as far as a double can hold them.
constexpr std::array<int, 10> r10_times_100 = {100, 125, 160, 200, 250, 315, 400, 500, 630, 800};

// value × 10^exponent with the power of ten exact (an integer, or divided by one).
double scale_by_power_of_ten(double value, int exponent) {
  double p = 1.0;
  for (int i = 0; i < std::abs(exponent); ++i) p *= 10.0;
  return exponent >= 0 ? value * p : value / p;
}

// Floor division for negative numerators too.
int floor_div(int a, int b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0); }

}  // namespace

double exact_mid_band_frequency(int index, int bands_per_octave) {
  require_bands_per_octave(bands_per_octave);
  const double b = bands_per_octave;
  const double exponent = bands_per_octave % 2 == 1 ? index / b : (2.0 * index + 1.0) / (2.0 * b);
  // G^e = 10^(0.3 e): one pow, no accumulated products.
  return band_reference_frequency * std::pow(10.0, 0.3 * exponent);
}

double lower_band_edge(double mid_band, int bands_per_octave) {
  require_bands_per_octave(bands_per_octave);
  return mid_band * std::pow(10.0, -0.3 / (2.0 * bands_per_octave));
}

double upper_band_edge(double mid_band, int bands_per_octave) {
  require_bands_per_octave(bands_per_octave);
  return mid_band * std::pow(10.0, 0.3 / (2.0 * bands_per_octave));
}

int nearest_band_index(double frequency, int bands_per_octave) {
  require_bands_per_octave(bands_per_octave);
  if (!(frequency > 0.0) || !std::isfinite(frequency)) {
    throw std::invalid_argument("nearest_band_index: frequency must be finite and > 0 (got " +
                                format_number(frequency) + ")");
  }
  // Octaves above f_r, in units of G.
  const double octaves = std::log10(frequency / band_reference_frequency) / 0.3;
  const double b = bands_per_octave;
  if (bands_per_octave % 2 == 1) return static_cast<int>(std::lround(b * octaves));
  return static_cast<int>(std::lround((2.0 * b * octaves - 1.0) / 2.0));
}

double nominal_mid_band_frequency(int index, int bands_per_octave) {
  require_bands_per_octave(bands_per_octave);
  // Octave and third-octave bands: R10 numbers, the band of x being the R10 step 10x/b from 1 kHz
  // (f_m = 1000·10^(3x/(10b)); third octaves: one step per band, octaves: three).
  if (bands_per_octave == 1 || bands_per_octave == 3) {
    const int step = bands_per_octave == 1 ? 3 * index : index;  // R10 steps above 1000 Hz
    const int decade = floor_div(step, 10);
    const int position = step - 10 * decade;
    // 1000 Hz = 100 (the R10 entry ×100) × 10^1; the decade adds its power.
    return scale_by_power_of_ten(r10_times_100[static_cast<std::size_t>(position)], decade + 1);
  }
  // Other bandwidths: the exact frequency to 3 significant figures if its leading digit is 1-4,
  // to 2 if it is 5-9.
  const double exact = exact_mid_band_frequency(index, bands_per_octave);
  const int magnitude = static_cast<int>(std::floor(std::log10(exact)));  // exact = d.ddd × 10^magnitude
  const double leading = exact / std::pow(10.0, magnitude);
  const int figures = leading < 5.0 ? 3 : 2;
  const int exponent = magnitude - (figures - 1);  // round to a multiple of 10^exponent
  const double units = std::round(scale_by_power_of_ten(exact, -exponent));
  return scale_by_power_of_ten(units, exponent);
}

std::string nominal_label(double nominal) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", nominal);
  return buffer;
}

FractionalOctaveBand fractional_octave_band(int index, int bands_per_octave) {
  FractionalOctaveBand band;
  band.bands_per_octave = bands_per_octave;
  band.index = index;
  band.exact = exact_mid_band_frequency(index, bands_per_octave);
  band.lower = lower_band_edge(band.exact, bands_per_octave);
  band.upper = upper_band_edge(band.exact, bands_per_octave);
  band.nominal = nominal_mid_band_frequency(index, bands_per_octave);
  band.label = nominal_label(band.nominal);
  return band;
}

std::vector<FractionalOctaveBand> fractional_octave_bands(int bands_per_octave, double f_low, double f_high) {
  if (bands_per_octave < 1 || bands_per_octave > 48) {
    throw InputError("", "bands_per_octave", "must be an integer from 1 to 48 (got " + std::to_string(bands_per_octave) + ")");
  }
  if (!(f_low > 0.0) || !std::isfinite(f_low)) {
    throw InputError("", "f_low", "must be a finite number > 0 Hz (got " + format_number(f_low) + ")");
  }
  if (!(f_high >= f_low) || !std::isfinite(f_high)) {
    throw InputError("", "f_high", "must be a finite number >= f_low (got " + format_number(f_high) + ")");
  }
  const int first = nearest_band_index(f_low, bands_per_octave);
  const int last = nearest_band_index(f_high, bands_per_octave);
  std::vector<FractionalOctaveBand> bands;
  for (int x = first; x <= last; ++x) bands.push_back(fractional_octave_band(x, bands_per_octave));
  return bands;
}

FractionalOctaveFilterBank::FractionalOctaveFilterBank(std::vector<FractionalOctaveBand> bands, double sample_rate,
                                                       int order)
    : bands_(std::move(bands)), sample_rate_(sample_rate), order_(order) {
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate)) {
    throw InputError("", "sample_rate", "must be a finite number > 0 (got " + format_number(sample_rate) + ")");
  }
  if (order < 1 || order > 8) {
    throw InputError("", "filter_order", "must be an integer from 1 to 8 (got " + std::to_string(order) + ")");
  }
  if (bands_.empty()) throw InputError("", "bands", "no bands to filter");
  const double nyquist = 0.5 * sample_rate;
  for (const FractionalOctaveBand& band : bands_) {
    if (!(band.lower > 0.0 && band.lower < band.upper)) {
      throw InputError("", "bands", "band " + band.label + " has edges " + format_number(band.lower) + " and " +
                                        format_number(band.upper) + " Hz; need 0 < lower < upper");
    }
    if (!(band.upper < nyquist)) {
      throw InputError("", "f_high", "the " + band.label + " Hz band reaches " + format_number(band.upper) +
                                         " Hz, at or above the Nyquist frequency " + format_number(nyquist) +
                                         " Hz of the sample rate; lower f_high or raise the sample rate");
    }
  }

  // Butterworth prototype poles p_k = exp(iπ(2k + N − 1)/(2N)), k = 1..N (left half plane).
  // Low-pass to band-pass: s = (p B ± √((p B)² − 4 ω0²))/2 with ω0² = ω1 ω2, B = ω2 − ω1 at the
  // prewarped edges ωi = 2 fs tan(π fi/fs); bilinear transform z = (2fs + s)/(2fs − s). Each
  // prototype pole in the upper half plane gives two band-pass poles, each a section with its
  // conjugate; a real prototype pole gives one conjugate pair, one section.
  using C = std::complex<double>;
  const double k = 2.0 * sample_rate;
  const double pi = std::numbers::pi;
  sections_.reserve(bands_.size());
  for (const FractionalOctaveBand& band : bands_) {
    const double w1 = k * std::tan(pi * band.lower / sample_rate);
    const double w2 = k * std::tan(pi * band.upper / sample_rate);
    const double w0 = std::sqrt(w1 * w2);
    const double bw = w2 - w1;
    // The digital frequency where the analogue centre ω0 lands: the passband's gain-1 point.
    const double centre = 2.0 * std::atan(w0 / k);

    std::vector<C> poles;  // s-plane, one of each conjugate pair
    for (int m = 1; m <= order; ++m) {
      const C p = std::polar(1.0, pi * (2.0 * m + order - 1.0) / (2.0 * order));
      if (p.imag() < -1e-12) continue;  // the conjugate's pair is made from the upper one
      const C half = 0.5 * p * bw;
      const C root = std::sqrt(half * half - w0 * w0);
      if (std::abs(p.imag()) <= 1e-12) {
        poles.push_back(half + root);  // a real prototype pole: half ± root are conjugates
      } else {
        poles.push_back(half + root);
        poles.push_back(half - root);
      }
    }

    std::vector<Section> band_sections;
    const C zc = std::polar(1.0, -centre);  // z⁻¹ at the centre
    for (const C& s : poles) {
      const C zp = (k + s) / (k - s);
      Section section{1.0, 0.0, -1.0, -2.0 * zp.real(), std::norm(zp)};
      // Unit gain at the centre for each section, so the product is the prototype's 1 there.
      const C h = (1.0 - zc * zc) / (1.0 + section.a1 * zc + section.a2 * zc * zc);
      const double g = 1.0 / std::abs(h);
      section.b0 = g;
      section.b2 = -g;
      band_sections.push_back(section);
    }
    sections_.push_back(std::move(band_sections));
  }
}

std::complex<double> FractionalOctaveFilterBank::response(std::size_t band, double frequency) const {
  if (band >= sections_.size()) throw std::out_of_range("FractionalOctaveFilterBank::response: no band " + std::to_string(band));
  if (!(frequency >= 0.0 && frequency <= 0.5 * sample_rate_)) {
    throw std::invalid_argument("FractionalOctaveFilterBank::response: frequency " + format_number(frequency) +
                                " Hz is outside [0, fs/2]");
  }
  const std::complex<double> z1 = std::polar(1.0, -2.0 * std::numbers::pi * frequency / sample_rate_);
  const std::complex<double> z2 = z1 * z1;
  std::complex<double> h = 1.0;
  for (const Section& s : sections_[band]) h *= (s.b0 + s.b1 * z1 + s.b2 * z2) / (1.0 + s.a1 * z1 + s.a2 * z2);
  return h;
}

double FractionalOctaveFilterBank::response_db(std::size_t band, double frequency) const {
  return 20.0 * std::log10(std::abs(response(band, frequency)));
}

namespace {

// Runs the sections over the signal sample by sample (transposed direct form II) and hands
// each output sample to `sink`.
template <class Section, class Sink>
void run_sections(const std::vector<Section>& sections, std::span<const double> signal, Sink&& sink,
                  const CancellationToken& cancel) {
  constexpr std::size_t max_sections = 8;
  std::array<double, max_sections> w1{};
  std::array<double, max_sections> w2{};
  const std::size_t count = sections.size();
  // In blocks, polling Ctrl-C between them: an hour of sound at 48 kHz is 1.7e8 samples a band.
  constexpr std::size_t block = std::size_t{1} << 16;
  for (std::size_t start = 0; start < signal.size(); start += block) {
    cancel.throw_if_cancelled();
    const std::size_t end = std::min(signal.size(), start + block);
    for (std::size_t n = start; n < end; ++n) {
      double v = signal[n];
      for (std::size_t j = 0; j < count; ++j) {
        const Section& s = sections[j];
        const double y = s.b0 * v + w1[j];
        w1[j] = s.b1 * v - s.a1 * y + w2[j];
        w2[j] = s.b2 * v - s.a2 * y;
        v = y;
      }
      sink(n, v);
    }
  }
}

}  // namespace

std::vector<double> FractionalOctaveFilterBank::filter(std::size_t band, std::span<const double> signal) const {
  if (band >= sections_.size()) throw std::out_of_range("FractionalOctaveFilterBank::filter: no band " + std::to_string(band));
  std::vector<double> out(signal.size());
  run_sections(sections_[band], signal, [&](std::size_t n, double y) { out[n] = y; }, CancellationToken());
  return out;
}

std::vector<double> FractionalOctaveFilterBank::band_mean_squares(std::span<const double> signal, std::size_t skip,
                                                                  const CancellationToken& cancel) const {
  if (skip >= signal.size()) {
    throw InputError("", "settle_time", "leaves no samples to average (" + std::to_string(skip) + " of " +
                                            std::to_string(signal.size()) + " samples skipped)");
  }
  std::vector<double> result;
  result.reserve(sections_.size());
  const double count = static_cast<double>(signal.size() - skip);
  for (const auto& band_sections : sections_) {
    double sum = 0.0;
    run_sections(
        band_sections, signal,
        [&](std::size_t n, double y) {
          if (n >= skip) sum += y * y;
        },
        cancel);
    result.push_back(sum / count);
  }
  return result;
}

std::vector<double> band_mean_squares_from_psd(const PowerSpectralDensity& psd,
                                               const std::vector<FractionalOctaveBand>& bands) {
  const double nyquist = 0.5 * psd.sample_rate;
  std::vector<double> result;
  result.reserve(bands.size());
  for (const FractionalOctaveBand& band : bands) {
    if (!(band.upper <= nyquist)) {
      throw InputError("", "f_high", "the " + band.label + " Hz band reaches " + format_number(band.upper) +
                                         " Hz, above the Nyquist frequency " + format_number(nyquist) + " Hz");
    }
    result.push_back(integrate_psd(psd, band.lower, band.upper));
  }
  return result;
}

}  // namespace rollnoise
