#include "acoustics/band_power.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/error.hpp"

namespace rollnoise {

std::size_t welch_segment_for(std::size_t samples, std::size_t max_segment) {
  if (samples < 8) throw InputError("", "samples", "a record of " + std::to_string(samples) + " samples is shorter than 8");
  std::size_t n = 8;
  while (2 * n <= samples && 2 * n <= std::max<std::size_t>(max_segment, 8)) n *= 2;
  return n;
}

std::vector<double> fluctuation_band_mean_squares(std::span<const double> signal, double sample_rate,
                                                  const std::vector<FractionalOctaveBand>& bands,
                                                  std::size_t segment_length) {
  const double mean =
      signal.empty() ? 0.0 : std::accumulate(signal.begin(), signal.end(), 0.0) / static_cast<double>(signal.size());
  std::vector<double> fluctuation(signal.begin(), signal.end());
  for (double& x : fluctuation) x -= mean;
  return band_mean_squares_from_psd(welch_psd(fluctuation, sample_rate, segment_length), bands);
}

std::vector<double> band_sums(std::span<const double> frequency, std::span<const double> value,
                              const std::vector<FractionalOctaveBand>& bands) {
  if (frequency.size() != value.size()) throw std::invalid_argument("band_sums: frequency and value differ in length");
  std::vector<double> sums(bands.size(), 0.0);
  for (std::size_t b = 0; b < bands.size(); ++b)
    for (std::size_t k = 0; k < frequency.size(); ++k)
      if (frequency[k] >= bands[b].lower && frequency[k] < bands[b].upper) sums[b] += value[k];
  return sums;
}

std::vector<double> band_means_of(const std::vector<FractionalOctaveBand>& bands,
                                  const std::function<double(double)>& of_frequency, int points) {
  if (points < 1) throw std::invalid_argument("band_means_of: points must be >= 1");
  std::vector<double> means;
  means.reserve(bands.size());
  for (const FractionalOctaveBand& band : bands) {
    double sum = 0.0;
    for (int i = 0; i < points; ++i) sum += of_frequency(band.lower + (i + 0.5) * (band.upper - band.lower) / points);
    means.push_back(sum / points);
  }
  return means;
}

double level_db(double mean_square, double reference) {
  if (!(mean_square > 0.0)) return -std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(mean_square / (reference * reference));
}

PointAveragedPsd::PointAveragedPsd(std::size_t points, double sample_rate, std::size_t segment_length,
                                   std::vector<std::vector<double>> weights)
    : points_(points),
      sample_rate_(sample_rate),
      length_(segment_length),
      weights_(std::move(weights)),
      segment_((length_ < 8 || length_ % 2 != 0)
                   ? throw std::invalid_argument("PointAveragedPsd: segment length must be even and >= 8")
                   : length_),
      power_(length_ / 2 + 1) {
  if (points_ == 0) throw std::invalid_argument("PointAveragedPsd: no points");
  for (std::vector<double>& w : weights_) {
    if (w.size() != points_) throw std::invalid_argument("PointAveragedPsd: one weight per point");
    const double total = std::accumulate(w.begin(), w.end(), 0.0);
    if (!(total > 0.0) || std::any_of(w.begin(), w.end(), [](double x) { return !(x >= 0.0); }))
      throw std::invalid_argument("PointAveragedPsd: weights must be >= 0 with a positive sum");
    for (double& x : w) x /= total;
  }
  used_.assign(points_, 0);
  for (std::size_t p = 0; p < points_; ++p)
    for (const std::vector<double>& w : weights_) used_[p] = used_[p] || w[p] > 0.0;
  buffer_.assign(points_ * length_, 0.0f);
  gathered_.assign(kBlock * length_, 0.0f);
  sums_.assign(weights_.size(), std::vector<double>(length_ / 2 + 1, 0.0));
}

void PointAveragedPsd::push(std::span<const double> sample) {
  if (sample.size() != points_) throw std::invalid_argument("PointAveragedPsd: one value per point");
  // Sample t goes to row t mod N: a step's write is one contiguous row (a field of 20 000 belt
  // cells written with a stride of N floats missed the cache at every value).
  float* row = buffer_.data() + ((pushed_ % length_) * points_);
  for (std::size_t p = 0; p < points_; ++p) row[p] = static_cast<float>(sample[p]);
  ++pushed_;
  if (pushed_ < length_ || (pushed_ - length_) % (length_ / 2) != 0) return;
  // A full segment, samples [pushed − N, pushed): rows from (pushed − N) mod N on, wrapping.
  // Each point's periodogram (welch_psd of exactly one segment: the same operations in the same
  // order), weighted. Points are gathered kBlock at a time into contiguous segments.
  const std::size_t first_row = (pushed_ - length_) % length_;
  const std::size_t bins = power_.size();
  for (std::size_t p0 = 0; p0 < points_; p0 += kBlock) {
    const std::size_t block = std::min(kBlock, points_ - p0);
    // The block's part of each row, in time order (rows first_row … N − 1, then 0 …), copied
    // whole: a tile of N rows × block points that each point's transform reads down a column.
    const float* source = buffer_.data() + first_row * points_ + p0;
    for (std::size_t i = 0; i < length_; ++i, source += points_) {
      if (i == length_ - first_row) source = buffer_.data() + p0;
      std::copy_n(source, block, gathered_.data() + i * kBlock);
    }
    for (std::size_t b = 0; b < block; ++b) {
      const std::size_t p = p0 + b;
      if (!used_[p]) continue;
      std::fill(power_.begin(), power_.end(), 0.0);
      segment_.add_power(gathered_.data() + b, kBlock, power_);
      segment_.to_one_sided_density(power_, sample_rate_, 1);
      for (std::size_t a = 0; a < weights_.size(); ++a) {
        const double w = weights_[a][p];
        if (w == 0.0) continue;
        for (std::size_t k = 0; k < bins; ++k) sums_[a][k] += w * power_[k];
      }
    }
  }
  ++segments_;
}

PowerSpectralDensity PointAveragedPsd::average(std::size_t a) const {
  if (segments_ == 0) throw InputError("", "samples", "fewer samples than one Welch segment of " + std::to_string(length_));
  PowerSpectralDensity psd;
  psd.sample_rate = sample_rate_;
  psd.segment_length = length_;
  psd.segments = segments_;
  psd.density = sums_.at(a);
  for (double& d : psd.density) d /= static_cast<double>(segments_);
  return psd;
}

}  // namespace rollnoise
