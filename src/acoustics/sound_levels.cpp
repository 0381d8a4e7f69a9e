#include "acoustics/sound_levels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "acoustics/welch_psd.hpp"
#include "core/csv.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

void require_sample_rate(double sample_rate) {
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate)) {
    throw InputError("", "sample_rate", "must be a finite number > 0 (got " + format_number(sample_rate) + ")");
  }
}

std::vector<double> weighted(std::span<const double> pressure, double sample_rate, FrequencyWeighting weighting) {
  if (weighting == FrequencyWeighting::Z) {
    require_sample_rate(sample_rate);
    return {pressure.begin(), pressure.end()};
  }
  return WeightingFilter(weighting, sample_rate).apply(pressure);
}

}  // namespace

double mean_square(std::span<const double> pressure) {
  if (pressure.empty()) throw std::invalid_argument("mean_square: empty signal");
  double sum = 0.0;
  for (double p : pressure) sum += p * p;
  return sum / static_cast<double>(pressure.size());
}

double sound_pressure_level_db(double mean_square_pa2) {
  if (!(mean_square_pa2 >= 0.0)) {
    throw std::invalid_argument("sound_pressure_level_db: mean square must be >= 0 (got " +
                                format_number(mean_square_pa2) + ")");
  }
  if (mean_square_pa2 == 0.0) return -std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(mean_square_pa2 / (reference_sound_pressure * reference_sound_pressure));
}

double leq_db(std::span<const double> pressure) { return sound_pressure_level_db(mean_square(pressure)); }

double weighted_leq_db(std::span<const double> pressure, double sample_rate, FrequencyWeighting weighting) {
  return leq_db(weighted(pressure, sample_rate, weighting));
}

double laeq_db(std::span<const double> pressure, double sample_rate) {
  return weighted_leq_db(pressure, sample_rate, FrequencyWeighting::A);
}

std::vector<double> time_weighted_levels_db(std::span<const double> pressure, double sample_rate,
                                            FrequencyWeighting weighting, double time_constant) {
  if (!(time_constant > 0.0) || !std::isfinite(time_constant)) {
    throw InputError("", "time_constant", "must be a finite number > 0 s (got " + format_number(time_constant) + ")");
  }
  std::vector<double> levels = weighted(pressure, sample_rate, weighting);
  // The exponential integrator over one sample interval: decay a, and the weight (1 − a) of the
  // interval's own p² (the exact integral of e^{−s/τ}/τ over the interval). expm1 keeps 1 − a
  // accurate for fs τ >> 1.
  const double one_minus_a = -std::expm1(-1.0 / (sample_rate * time_constant));
  const double a = 1.0 - one_minus_a;
  double y = 0.0;
  const CancellationToken cancel;
  constexpr std::size_t block = std::size_t{1} << 16;  // a Ctrl-C poll per block (a logarithm a sample)
  for (std::size_t start = 0; start < levels.size(); start += block) {
    cancel.throw_if_cancelled();
    const std::size_t end = std::min(levels.size(), start + block);
    for (std::size_t n = start; n < end; ++n) {
      y = a * y + one_minus_a * levels[n] * levels[n];
      levels[n] = sound_pressure_level_db(y);
    }
  }
  return levels;
}

double max_time_weighted_level_db(std::span<const double> pressure, double sample_rate, FrequencyWeighting weighting,
                                  double time_constant) {
  if (pressure.empty()) throw std::invalid_argument("max_time_weighted_level_db: empty signal");
  const std::vector<double> levels = time_weighted_levels_db(pressure, sample_rate, weighting, time_constant);
  return *std::max_element(levels.begin(), levels.end());
}

double lafmax_db(std::span<const double> pressure, double sample_rate) {
  return max_time_weighted_level_db(pressure, sample_rate, FrequencyWeighting::A, fast_time_constant);
}

BandSpectrum band_spectrum(std::span<const double> pressure, double sample_rate, const BandSpectrumOptions& options) {
  require_sample_rate(sample_rate);
  if (pressure.empty()) throw InputError("", "signal", "is empty");
  const std::vector<FractionalOctaveBand> bands =
      fractional_octave_bands(options.bands_per_octave, options.f_low, options.f_high);

  std::vector<double> mean_squares;
  if (options.method == BandSpectrumOptions::Method::filter_bank) {
    if (!(options.settle_time >= 0.0) || !std::isfinite(options.settle_time)) {
      throw InputError("", "settle_time", "must be a finite number >= 0 s (got " + format_number(options.settle_time) + ")");
    }
    const double skip_samples = std::round(options.settle_time * sample_rate);
    if (!(skip_samples < static_cast<double>(pressure.size()))) {
      throw InputError("", "settle_time", "of " + format_number(options.settle_time) +
                                              " s leaves no samples of the " + format_number(static_cast<double>(pressure.size()) / sample_rate) +
                                              " s record to average");
    }
    const FractionalOctaveFilterBank bank(bands, sample_rate, options.filter_order);
    mean_squares = bank.band_mean_squares(pressure, static_cast<std::size_t>(skip_samples), options.cancel);
  } else {
    std::size_t n = options.welch_segment_length;
    if (n == 0) {
      // The lowest band's width over 10, as resolution.
      const double wanted = (bands.front().upper - bands.front().lower) / 10.0;
      n = 8;
      while (sample_rate / static_cast<double>(n) > wanted) n *= 2;
      if (n > pressure.size()) {
        throw InputError("", "welch_segment_length",
                         "the " + bands.front().label + " Hz band needs segments of " + std::to_string(n) +
                             " samples (resolution a tenth of its width) but the signal has " +
                             std::to_string(pressure.size()) + "; raise f_low or use the filter bank");
      }
    }
    mean_squares = band_mean_squares_from_psd(welch_psd(pressure, sample_rate, n), bands);
  }

  BandSpectrum spectrum;
  spectrum.bands_per_octave = options.bands_per_octave;
  for (std::size_t i = 0; i < bands.size(); ++i) {
    const FractionalOctaveBand& band = bands[i];
    spectrum.nominal_hz.push_back(band.nominal);
    spectrum.labels.push_back(band.label);
    spectrum.exact_hz.push_back(band.exact);
    const double lp = sound_pressure_level_db(mean_squares[i]);
    spectrum.lp_db.push_back(lp);
    spectrum.lpa_db.push_back(lp + weighting_db(FrequencyWeighting::A, band.exact));
  }
  return spectrum;
}

}  // namespace rollnoise
