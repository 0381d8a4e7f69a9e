#include "audio/resampler.hpp"

#include <samplerate.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace rollnoise {
namespace {

struct SrcDeleter {
  void operator()(SRC_STATE* state) const noexcept { src_delete(state); }
};

constexpr double max_stage_ratio = 256.0;  // libsamplerate's limit (SRC_MAX_RATIO)

// Output frames per call of the converter: a Ctrl-C poll between calls. The sinc converter
// keeps its position as the fraction of an input sample between its outputs, so output made in
// pieces is the output made at once, sample for sample (ResamplerTest checks this).
constexpr long frames_per_call = 1L << 16;

// One libsamplerate pass; returns round(n · ratio) samples.
std::vector<float> convert(const std::vector<float>& input, double ratio, const CancellationToken& cancel) {
  const auto n_out =
      static_cast<std::size_t>(std::llround(static_cast<double>(input.size()) * ratio));
  int error = 0;
  std::unique_ptr<SRC_STATE, SrcDeleter> state(src_new(SRC_SINC_BEST_QUALITY, 1, &error));
  if (!state) throw std::runtime_error(std::string("libsamplerate: ") + src_strerror(error));

  // Room for the whole output plus what the converter may add at the end.
  std::vector<float> output(n_out + 64 + static_cast<std::size_t>(std::ceil(ratio)) * 8);
  SRC_DATA data{};
  data.data_in = input.data();
  data.input_frames = static_cast<long>(input.size());
  data.data_out = output.data();
  data.src_ratio = ratio;
  data.end_of_input = 1;
  long room = static_cast<long>(output.size());
  std::size_t produced = 0;
  for (;;) {
    cancel.throw_if_cancelled();
    data.output_frames = std::min(room, frames_per_call);
    error = src_process(state.get(), &data);
    if (error != 0) throw std::runtime_error(std::string("libsamplerate: ") + src_strerror(error));
    produced += static_cast<std::size_t>(data.output_frames_gen);
    data.data_in += data.input_frames_used;
    data.input_frames -= data.input_frames_used;
    data.data_out += data.output_frames_gen;
    room -= data.output_frames_gen;
    if (data.output_frames_gen == 0 || room == 0 || produced >= n_out) break;
  }
  output.resize(n_out, 0.0F);  // pads with zeros in the (theoretical) case of a short output
  return output;
}

}  // namespace

Eigen::VectorXd resample(const Eigen::VectorXd& signal, double fs_in, double fs_out, const CancellationToken& cancel) {
  if (!(fs_in > 0.0) || !(fs_out > 0.0) || !std::isfinite(fs_in) || !std::isfinite(fs_out))
    throw std::invalid_argument("resample: sample rates must be positive and finite");
  if (fs_in == fs_out || signal.size() == 0) return signal;
  const double ratio = fs_out / fs_in;
  const auto n_out =
      static_cast<std::size_t>(std::llround(static_cast<double>(signal.size()) * ratio));
  if (n_out > (std::size_t{1} << 34U))
    throw std::invalid_argument("resample: output of " + std::to_string(n_out) +
                                " samples is too long");

  // Equal stages, each within libsamplerate's ratio range.
  const double log_ratio = std::abs(std::log(ratio));
  const int stages =
      std::max(1, static_cast<int>(std::ceil(log_ratio / std::log(max_stage_ratio) - 1e-12)));
  const double stage_ratio = std::pow(ratio, 1.0 / stages);

  std::vector<float> data(static_cast<std::size_t>(signal.size()));
  for (Eigen::Index i = 0; i < signal.size(); ++i)
    data[static_cast<std::size_t>(i)] = static_cast<float>(signal[i]);
  // Every stage at the exact ratio (sample k of a stage is at time k / its rate); the length
  // is set once at the end.
  for (int s = 0; s < stages; ++s) data = convert(data, stage_ratio, cancel);
  data.resize(n_out, 0.0F);

  Eigen::VectorXd out(static_cast<Eigen::Index>(n_out));
  for (std::size_t i = 0; i < n_out; ++i) out[static_cast<Eigen::Index>(i)] = data[i];
  return out;
}

}  // namespace rollnoise
