// Sound output: calibrated WAV files (level kept within 0.01 dB through a write and read),
// resampling (level within 0.05 dB, frequency kept, exact length, no time shift) and seamless
// looping (no jump at the joints, level within 0.1 dB).
#include <gtest/gtest.h>
#include <samplerate.h>
#include <sndfile.h>

#include <atomic>
#include <csignal>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "audio/resampler.hpp"
#include "audio/seamless_loop.hpp"
#include "audio/wav_file.hpp"
#include "core/error.hpp"

namespace rollnoise {
namespace {

namespace fs = std::filesystem;
using std::numbers::pi;

// A fresh directory per test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("rollnoise_audio_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(std::random_device{}()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

Eigen::VectorXd sine(double frequency, double amplitude, double fs, Eigen::Index n,
                     double phase = 0.0) {
  Eigen::VectorXd x(n);
  for (Eigen::Index i = 0; i < n; ++i)
    x[i] = amplitude * std::sin(2.0 * pi * frequency * static_cast<double>(i) / fs + phase);
  return x;
}

double rms(const Eigen::VectorXd& x) {
  return std::sqrt(x.squaredNorm() / static_cast<double>(x.size()));
}
double db(double ratio) { return 20.0 * std::log10(ratio); }

double max_step(const Eigen::VectorXd& x) {
  double step = 0.0;
  for (Eigen::Index i = 1; i < x.size(); ++i) step = std::max(step, std::abs(x[i] - x[i - 1]));
  return step;
}

// Frequency from the rising zero crossings (linear interpolation between samples).
double zero_crossing_frequency(const Eigen::VectorXd& x, double fs) {
  double first = -1.0, last = -1.0;
  int crossings = 0;
  for (Eigen::Index i = 1; i < x.size(); ++i) {
    if (x[i - 1] < 0.0 && x[i] >= 0.0) {
      const double t = static_cast<double>(i - 1) + x[i - 1] / (x[i - 1] - x[i]);
      if (first < 0.0) first = t;
      last = t;
      ++crossings;
    }
  }
  return (crossings - 1) * fs / (last - first);
}

// The frequency of the largest DFT magnitude (Hann window) on a 0.1 Hz grid in [lo, hi].
double dft_peak_frequency(const Eigen::VectorXd& x, double fs, double lo, double hi) {
  const auto n = x.size();
  double best = 0.0, best_f = 0.0;
  for (double f = lo; f <= hi; f += 0.1) {
    std::complex<double> sum = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double w =
          0.5 - 0.5 * std::cos(2.0 * pi * static_cast<double>(i) / static_cast<double>(n));
      sum += w * x[i] * std::polar(1.0, -2.0 * pi * f * static_cast<double>(i) / fs);
    }
    if (std::abs(sum) > best) {
      best = std::abs(sum);
      best_f = f;
    }
  }
  return best_f;
}

// ------------------------------------------------------------------------------------------
// WAV

TEST(Wav, CalibratedSineKeepsItsLevel) {
  TempDir dir;
  const double fs = 48000.0, full_scale = 12.3456789;
  const Eigen::VectorXd p = sine(1000.0, 2.0 * std::sqrt(2.0), fs, 48000);  // 2 Pa rms, 100 dB
  const fs::path file = dir / "cpx_front.wav";
  WavWriteOptions options;
  options.full_scale_pa = full_scale;
  options.title = "cpx_front";
  const WavWriteReport report = write_wav(file, p, fs, options);
  EXPECT_NEAR(report.peak, 2.0 * std::sqrt(2.0) / full_scale, 1e-12);
  EXPECT_EQ(report.samples_over_full_scale, 0U);

  const WavData wav = read_wav(file);
  ASSERT_EQ(wav.channels.size(), 1U);
  ASSERT_EQ(wav.frames(), 48000U);
  EXPECT_EQ(wav.sample_rate, fs);
  EXPECT_EQ(wav.comment, "full scale = 12.3456789 Pa (rollnoise)");
  ASSERT_TRUE(wav.full_scale_pa.has_value());
  EXPECT_EQ(*wav.full_scale_pa, full_scale);  // exactly
  const Eigen::VectorXd back = wav.channels[0] * *wav.full_scale_pa;
  const double level_error_db = db(rms(back) / rms(p));
  std::printf("  WAV round trip: level error %.3g dB, max sample error %.3g Pa\n", level_error_db,
              (back - p).cwiseAbs().maxCoeff());
  EXPECT_LT(std::abs(level_error_db), 0.01);
  EXPECT_LT((back - p).cwiseAbs().maxCoeff(), 1e-6);  // float: 6e-8 of full scale
}

TEST(Wav, MultiChannelRoundTrip) {
  TempDir dir;
  const double fs = 44100.0;
  std::vector<Eigen::VectorXd> channels{sine(100.0, 0.5, fs, 4410), sine(3000.0, 0.1, fs, 4410),
                                        Eigen::VectorXd::Constant(4410, -0.25)};
  WavWriteOptions options;
  options.full_scale_pa = 1.0;
  write_wav(dir / "three.wav", channels, fs, options);
  const WavData wav = read_wav(dir / "three.wav");
  ASSERT_EQ(wav.channels.size(), 3U);
  EXPECT_EQ(wav.sample_rate, fs);
  for (std::size_t c = 0; c < 3; ++c) {
    ASSERT_EQ(wav.channels[c].size(), 4410);
    EXPECT_LT((wav.channels[c] - channels[c]).cwiseAbs().maxCoeff(), 1e-7) << "channel " << c;
    EXPECT_LT(std::abs(db(rms(wav.channels[c]) / rms(channels[c]))), 0.01);
  }
}

TEST(Wav, ClippingIsRefusedOrReported) {
  TempDir dir;
  const Eigen::VectorXd p = sine(1000.0, 3.0, 48000.0, 480);
  WavWriteOptions options;
  options.full_scale_pa = 2.0;
  EXPECT_THROW(write_wav(dir / "clip.wav", p, 48000.0, options), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "clip.wav"));

  options.clipping = WavClipping::report;
  const WavWriteReport report = write_wav(dir / "clip.wav", p, 48000.0, options);
  EXPECT_GT(report.samples_over_full_scale, 100U);
  EXPECT_NEAR(report.peak, 1.5, 1e-3);
  const WavData wav = read_wav(dir / "clip.wav");
  EXPECT_NEAR(wav.channels[0].cwiseAbs().maxCoeff(), 1.5, 1e-3) << "float keeps values over 1";

  options.full_scale_pa = 0.0;
  EXPECT_THROW(write_wav(dir / "bad.wav", p, 48000.0, options), std::runtime_error);
  options.full_scale_pa = 1.0;
  EXPECT_THROW(write_wav(dir / "bad.wav", p, 48000.5, options), std::runtime_error);
  EXPECT_THROW(write_wav(dir / "missing_dir" / "x.wav", p, 48000.0, options), std::runtime_error);
}

TEST(Wav, ReadsIntegerPcmNormalisedAndRejectsNonAudio) {
  TempDir dir;
  // A 16-bit file written by libsndfile itself: integer full scale reads as 1.0.
  SF_INFO info{};
  info.samplerate = 8000;
  info.channels = 2;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  const std::string name = (dir / "pcm16.wav").string();
  SNDFILE* file = sf_open(name.c_str(), SFM_WRITE, &info);
  ASSERT_NE(file, nullptr);
  const short frames[6] = {16384, -32768, 0, 8192, -16384, 32767};
  ASSERT_EQ(sf_writef_short(file, frames, 3), 3);
  sf_close(file);
  const WavData wav = read_wav(name);
  ASSERT_EQ(wav.channels.size(), 2U);
  ASSERT_EQ(wav.frames(), 3U);
  EXPECT_EQ(wav.sample_rate, 8000.0);
  EXPECT_EQ(wav.channels[0][0], 0.5);
  EXPECT_EQ(wav.channels[1][0], -1.0);
  EXPECT_EQ(wav.channels[1][1], 0.25);
  EXPECT_TRUE(wav.comment.empty());
  EXPECT_FALSE(wav.full_scale_pa.has_value());

  std::ofstream(dir / "text.wav") << "this is not a sound file\n";
  EXPECT_THROW(read_wav(dir / "text.wav"), InputError);
  EXPECT_THROW(read_wav(dir / "absent.wav"), InputError);
  try {
    read_wav(dir / "text.wav");
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), (dir / "text.wav").string());
  }
}

TEST(Wav, FullScaleComment) {
  EXPECT_EQ(full_scale_comment(12.3), "full scale = 12.3 Pa (rollnoise)");
  EXPECT_EQ(full_scale_from_comment("full scale = 12.3 Pa (rollnoise)"), 12.3);
  EXPECT_EQ(full_scale_from_comment("calibrated; full scale=2e-3 Pa"), 2e-3);
  EXPECT_FALSE(full_scale_from_comment("full scale = -1 Pa").has_value());
  EXPECT_FALSE(full_scale_from_comment("full scale = 94 dB").has_value());
  EXPECT_FALSE(full_scale_from_comment("").has_value());
  EXPECT_EQ(round_full_scale(3.7), 5.0);
  EXPECT_EQ(round_full_scale(0.85), 1.0);  // 0.85 Pa + 1 dB = 0.95 Pa
  EXPECT_EQ(round_full_scale(0.9), 2.0);   // 0.9 Pa + 1 dB = 1.01 Pa
  EXPECT_EQ(round_full_scale(0.012, 0.0), 0.02);
  EXPECT_EQ(round_full_scale(0.0), 1.0);
}

// ------------------------------------------------------------------------------------------
// Resampling

TEST(Resampler, SineFrom12kTo48kKeepsLevelFrequencyAndTiming) {
  const double f = 1000.0, fs_in = 12000.0, fs_out = 48000.0;
  const Eigen::VectorXd x = sine(f, 1.0, fs_in, 12000, 0.3);
  const Eigen::VectorXd y = resample(x, fs_in, fs_out);
  ASSERT_EQ(y.size(), 48000);
  // Away from the ends (where the signal itself starts and stops), the ideal 48 kHz sine.
  const Eigen::Index edge = 480;  // 10 ms
  const Eigen::VectorXd inner = y.segment(edge, y.size() - 2 * edge);
  const Eigen::VectorXd ideal = sine(f, 1.0, fs_out, 48000, 0.3).segment(edge, y.size() - 2 * edge);
  const double level_db = db(rms(inner) / rms(ideal));
  const double whole_db = db(rms(y) / rms(x));
  const double zc = zero_crossing_frequency(inner, fs_out);
  const double peak = dft_peak_frequency(inner, fs_out, 990.0, 1010.0);
  const double max_error = (inner - ideal).cwiseAbs().maxCoeff();
  std::printf(
      "  12 kHz -> 48 kHz: level %.2e dB (whole signal %.2e dB), zero crossings %.4f Hz, DFT "
      "peak %.1f Hz, max deviation from the ideal sine %.2e\n",
      level_db, whole_db, zc, peak, max_error);
  EXPECT_LT(std::abs(level_db), 0.05);
  EXPECT_LT(std::abs(whole_db), 0.05);
  EXPECT_NEAR(zc, f, 0.01);
  EXPECT_NEAR(peak, f, 0.15);
  EXPECT_LT(max_error, 1e-3) << "time-aligned, no delay";
}

TEST(Resampler, ExactLengthsAndOtherRates) {
  for (const Eigen::Index n :
       {Eigen::Index{1}, Eigen::Index{7}, Eigen::Index{1001}, Eigen::Index{44101}}) {
    const Eigen::VectorXd x = sine(440.0, 0.5, 44100.0, n);
    EXPECT_EQ(resample(x, 44100.0, 48000.0).size(),
              std::llround(static_cast<double>(n) * 48000.0 / 44100.0));
    EXPECT_EQ(resample(x, 44100.0, 12345.0).size(),
              std::llround(static_cast<double>(n) * 12345.0 / 44100.0));
  }
  // 48 kHz -> 44.1 kHz: a 440 Hz tone stays at 440 Hz and its level.
  const Eigen::VectorXd x = sine(440.0, 0.5, 48000.0, 48000);
  const Eigen::VectorXd y = resample(x, 48000.0, 44100.0);
  ASSERT_EQ(y.size(), 44100);
  const Eigen::VectorXd inner = y.segment(441, 44100 - 882);
  EXPECT_NEAR(zero_crossing_frequency(inner, 44100.0), 440.0, 0.01);
  EXPECT_LT(std::abs(db(rms(inner) / (0.5 / std::sqrt(2.0)))), 0.05);
  // Equal rates: a copy.
  EXPECT_EQ(resample(x, 48000.0, 48000.0), x);
  EXPECT_THROW(resample(x, 0.0, 48000.0), std::invalid_argument);
  EXPECT_THROW(resample(x, 48000.0, -1.0), std::invalid_argument);
}

TEST(Resampler, LargeRatiosGoInStages) {
  // 25.6 MHz -> 48 kHz is a ratio of 1/533: two stages.
  const double fs_in = 25.6e6, f = 1000.0;
  const Eigen::VectorXd x = sine(f, 1.0, fs_in, 256000);  // 10 ms
  const Eigen::VectorXd y = resample(x, fs_in, 48000.0);
  ASSERT_EQ(y.size(), 480);
  const Eigen::VectorXd inner = y.segment(96, 288);
  const Eigen::VectorXd ideal = sine(f, 1.0, 48000.0, 480).segment(96, 288);
  const double max_error = (inner - ideal).cwiseAbs().maxCoeff();
  std::printf("  25.6 MHz -> 48 kHz (2 stages): max deviation from the ideal sine %.2e\n",
              max_error);
  EXPECT_LT(max_error, 2e-3);
}

// Resampling polls Ctrl-C between pieces of output; made in pieces, the output is the output of
// libsamplerate's one-call src_simple, bit for bit (a long noise at 12 kHz -> 48 kHz, which
// takes several pieces, and 25.6 MHz -> 48 kHz per stage).
TEST(Resampler, OutputInPiecesIsTheOneCallOutputBitForBit) {
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0F, 1.0F);
  std::vector<float> input(100000);
  for (float& v : input) v = noise(rng);
  Eigen::VectorXd x(static_cast<Eigen::Index>(input.size()));
  for (std::size_t i = 0; i < input.size(); ++i) x[static_cast<Eigen::Index>(i)] = input[i];
  const Eigen::VectorXd y = resample(x, 12000.0, 48000.0);
  ASSERT_EQ(y.size(), 400000);

  std::vector<float> once(static_cast<std::size_t>(y.size()) + 1024);
  SRC_DATA data{};
  data.data_in = input.data();
  data.input_frames = static_cast<long>(input.size());
  data.data_out = once.data();
  data.output_frames = static_cast<long>(once.size());
  data.src_ratio = 4.0;
  ASSERT_EQ(src_simple(&data, SRC_SINC_BEST_QUALITY, 1), 0);
  ASSERT_GE(data.output_frames_gen, y.size());
  Eigen::Index differing = 0;
  for (Eigen::Index i = 0; i < y.size(); ++i) differing += y[i] != static_cast<double>(once[static_cast<std::size_t>(i)]);
  EXPECT_EQ(differing, 0) << "samples that differ from the one-call conversion";
}

// A cancelled token: resample and write_wav throw Interrupted, and write_wav leaves no file.
// (The flag is the test's own, set before the call: no timing involved.)
TEST(Wav, WritingAndResamplingStopWhenCancelled) {
  TempDir dir;
  std::atomic<int> flag{0};
  const CancellationToken token(flag);
  const Eigen::VectorXd x = sine(1000.0, 1.0, 48000.0, 48000 * 3);
  WavWriteOptions options;
  options.full_scale_pa = 2.0;
  options.cancel = token;
  write_wav(dir / "ok.wav", x, 48000.0, options);  // not cancelled: written
  EXPECT_TRUE(fs::is_regular_file(dir / "ok.wav"));
  EXPECT_EQ(resample(x, 48000.0, 44100.0, token).size(), 44100 * 3);

  flag = SIGINT;
  try {
    write_wav(dir / "stopped.wav", x, 48000.0, options);
    ADD_FAILURE() << "write_wav did not poll the token";
  } catch (const Interrupted& stopped) {
    EXPECT_EQ(stopped.exit_status(), 130);
  }
  EXPECT_FALSE(fs::exists(dir / "stopped.wav")) << "a partial WAV file is left";
  EXPECT_THROW(resample(x, 48000.0, 44100.0, token), Interrupted);
}

// ------------------------------------------------------------------------------------------
// Seamless loop

struct LoopFigures {
  double level_db;
  double max_step_ratio;    // largest step of the looped signal / largest step of the original
  double naive_step_ratio;  // the same for plain repetition
};

LoopFigures check_loop(const Eigen::VectorXd& x, double fs, double duration) {
  const Eigen::VectorXd y = loop_to_duration(x, fs, duration);
  const Eigen::Index period = make_loopable(x, fs).size();
  EXPECT_GE(y.size(), static_cast<Eigen::Index>(std::ceil(duration * fs)));
  EXPECT_EQ(y.size() % period, 0) << "whole periods";
  EXPECT_LT(y.size() - period, static_cast<Eigen::Index>(std::ceil(duration * fs)));
  // The file loops too: the step from its end to its start is an ordinary one.
  EXPECT_LE(std::abs(y[0] - y[y.size() - 1]), max_step(x) * (1.0 + 1e-3));
  Eigen::VectorXd naive(y.size());
  for (Eigen::Index i = 0; i < y.size(); ++i) naive[i] = x[i % x.size()];
  return {db(rms(y) / rms(x)), max_step(y) / max_step(x), max_step(naive) / max_step(x)};
}

TEST(SeamlessLoop, NoiseLoopsWithoutClicksAtItsLevel) {
  const double fs = 48000.0;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  // Low-pass noise (two one-pole filters, corner about 40 Hz): its steps are small against its
  // amplitude, so a jump at a joint would stand out.
  Eigen::VectorXd x(62400);  // 1.3 s
  double s1 = 0.0, s2 = 0.0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    s1 = 0.995 * s1 + normal(rng);
    x[i] = s2 = 0.995 * s2 + s1;
  }
  const LoopFigures figures = check_loop(x, fs, 5.0);
  std::printf(
      "  loop of 1.3 s noise to 5 s: level %.1e dB, largest step %.3f of the original's "
      "(plain repetition: %.3f)\n",
      figures.level_db, figures.max_step_ratio, figures.naive_step_ratio);
  EXPECT_GT(figures.naive_step_ratio, 2.0) << "the test signal must have a discontinuity";
  EXPECT_LT(std::abs(figures.level_db), 0.1);
  EXPECT_LE(figures.max_step_ratio, 1.0);
}

TEST(SeamlessLoop, ToneWithFractionalPeriodsLoopsWithoutAJump) {
  const double fs = 48000.0;
  // 997.3 Hz for 0.3717 s: the end does not meet the start; plain repetition jumps.
  const Eigen::VectorXd x = sine(997.3, 1.0, fs, 17842, 0.4);
  const LoopFigures figures = check_loop(x, fs, 5.0);
  std::printf(
      "  loop of a 0.37 s tone to 5 s: level %.1e dB, largest step %.3f of the "
      "original's (plain repetition: %.3f)\n",
      figures.level_db, figures.max_step_ratio, figures.naive_step_ratio);
  EXPECT_GT(figures.naive_step_ratio, 2.0) << "the test signal must have a discontinuity";
  EXPECT_LT(std::abs(figures.level_db), 0.1);
  // Two sines of the same frequency mixed at constant power: the steps stay the sine's own
  // (to the accuracy of the measured correlation).
  EXPECT_LE(figures.max_step_ratio, 1.0 + 1e-3);
}

TEST(SeamlessLoop, ToneAndNoiseMixture) {
  const double fs = 48000.0;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, 0.3);
  Eigen::VectorXd x = sine(523.0, 1.0, fs, 40000, 1.0) + sine(1210.0, 0.5, fs, 40000, 0.2);
  double state = 0.0;
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += (state = 0.995 * state + normal(rng));
  const LoopFigures figures = check_loop(x, fs, 5.0);
  std::printf(
      "  loop of 0.83 s tones + noise to 5 s: level %.1e dB, largest step %.3f "
      "(plain repetition: %.3f)\n",
      figures.level_db, figures.max_step_ratio, figures.naive_step_ratio);
  EXPECT_GT(figures.naive_step_ratio, 1.5) << "the test signal must have a discontinuity";
  EXPECT_LT(std::abs(figures.level_db), 0.1);
  EXPECT_LE(figures.max_step_ratio, 1.0);
}

TEST(SeamlessLoop, EdgeCases) {
  const Eigen::VectorXd long_enough = Eigen::VectorXd::Ones(300);
  EXPECT_EQ(loop_to_duration(long_enough, 100.0, 2.5), long_enough);
  const Eigen::VectorXd tiny = Eigen::VectorXd::LinSpaced(5, 0.0, 1.0);
  const Eigen::VectorXd tiled = loop_to_duration(tiny, 10.0, 2.0);
  ASSERT_EQ(tiled.size(), 20);  // 4 whole periods
  EXPECT_EQ(tiled[7], tiny[2]);
  EXPECT_THROW(loop_to_duration(Eigen::VectorXd(), 48000.0, 5.0), std::invalid_argument);
  EXPECT_THROW(loop_to_duration(tiny, 0.0, 5.0), std::invalid_argument);
  // A constant stays constant (correlation 1: equal-gain fade).
  const Eigen::VectorXd c = loop_to_duration(Eigen::VectorXd::Constant(1000, 0.7), 1000.0, 3.0);
  EXPECT_NEAR(c.minCoeff(), 0.7, 1e-12);
  EXPECT_NEAR(c.maxCoeff(), 0.7, 1e-12);
}

}  // namespace
}  // namespace rollnoise
