// `rollnoise analyse` run as a user would: a calibrated 1 kHz tone must read 94.0 dB in the
// 1 kHz band and as Leq (1 Pa RMS = 93.98 dB re 20 µPa), UFF time records of sound pressure are
// analysed, and recordings that are not sound pressure, or lack a calibration, are refused.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "audio/wav_file.hpp"

namespace fs = std::filesystem;

namespace {

struct AnalyseRun {
  int status;
  std::string err;
};

fs::path fresh_folder(const std::string& name) {
  // (Built with a stream: GCC 12 warns falsely, -Wrestrict, on chains of string + string.)
  std::ostringstream folder;
  folder << "rollnoise_analyse_" << name << "_" << ::getpid();
  const fs::path dir = fs::temp_directory_path() / folder.str();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

AnalyseRun run(const fs::path& dir, const std::string& args) {
  std::ostringstream command;
  command << "cd '" << dir.string() << "' && CI=true '" << ROLLNOISE_BINARY << "' analyse " << args
          << " > out.txt 2> err.txt";
  const int raw = std::system(command.str().c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(dir / "err.txt")};
}

std::string quoted(const fs::path& path) {
  std::ostringstream q;
  q << "'" << path.string() << "'";
  return q.str();
}

// The value in spectrum.csv for a receiver and band label.
double band_level(const fs::path& csv, const std::string& receiver, const std::string& band, int column) {
  std::istringstream lines(read_text(csv));
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> f;
    std::istringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ',')) f.push_back(cell);
    if (f.size() == 4 && f[0] == receiver && f[1] == band) return std::stod(f[static_cast<std::size_t>(column)]);
  }
  ADD_FAILURE() << "no band " << band << " for " << receiver;
  return 0.0;
}

TEST(AnalyseCli, CalibratedToneReads94dB) {
  const fs::path dir = fresh_folder("tone");
  const double fs_hz = 48000.0;
  Eigen::VectorXd p(static_cast<Eigen::Index>(4 * fs_hz));
  for (Eigen::Index n = 0; n < p.size(); ++n)
    p(n) = std::sqrt(2.0) * std::sin(2 * std::numbers::pi * 1000.0 * static_cast<double>(n) / fs_hz);
  rollnoise::WavWriteOptions options;
  options.full_scale_pa = 2.0;
  rollnoise::write_wav(dir / "tone.wav", p, fs_hz, options);

  // rollnoise writes the full scale into the comment: no --full-scale needed.
  const AnalyseRun r = run(dir, "tone.wav --out result");
  ASSERT_EQ(r.status, 0) << r.err;
  const double expected = 20 * std::log10(1.0 / 20e-6);  // 93.98 dB
  EXPECT_NEAR(band_level(dir / "result" / "spectrum.csv", "ch1", "1000", 2), expected, 0.05);
  // The A-weighting is 0 dB at 1 kHz (IEC 61672-1), to within the table's 0.1 dB.
  EXPECT_NEAR(band_level(dir / "result" / "spectrum.csv", "ch1", "1000", 3), expected, 0.1);
  const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "result" / "summary.json"));
  EXPECT_NEAR(summary["levels"]["ch1"]["Leq_dB"].get<double>(), expected, 0.05);
  EXPECT_NEAR(summary["levels"]["ch1"]["LAeq_dB"].get<double>(), expected, 0.1);
  EXPECT_NEAR(summary["full_scale_pa"].get<double>(), 2.0, 0.0);
  EXPECT_TRUE(fs::exists(dir / "result" / "spectrum.gp"));

  // --full-scale overrides the comment: twice the full scale reads 6.02 dB more.
  const AnalyseRun doubled = run(dir, "tone.wav --full-scale 4 --out doubled");
  ASSERT_EQ(doubled.status, 0) << doubled.err;
  EXPECT_NEAR(band_level(dir / "doubled" / "spectrum.csv", "ch1", "1000", 2), expected + 20 * std::log10(2.0), 0.05);
  fs::remove_all(dir);
}

TEST(AnalyseCli, UffTimeRecordsOfSoundPressure) {
  const fs::path data = fs::path(ROLLNOISE_SOURCE_DIR) / ".." / "shared" / "data" / "uff";
  if (!fs::exists(data)) GTEST_SKIP() << "no ../shared/data/uff";
  const fs::path dir = fresh_folder("uff");
  const AnalyseRun ascii = run(dir, quoted(data / "Sample_UFF58_ascii.uff") + " --out ascii");
  ASSERT_EQ(ascii.status, 0) << ascii.err;
  const AnalyseRun binary = run(dir, quoted(data / "Sample_UFF58b_bin.uff") + " --out binary");
  ASSERT_EQ(binary.status, 0) << binary.err;
  // The ASCII and binary files hold the same record (to the ASCII file's printed digits).
  const auto level = [&](const std::string& out) {
    return nlohmann::json::parse(read_text(dir / out / "summary.json"))["levels"]["Mic 01:1"]["Leq_dB"].get<double>();
  };
  EXPECT_NEAR(level("ascii"), level("binary"), 1e-4);

  // Acceleration is not sound pressure; a PSD is not a time record.
  const AnalyseRun acceleration = run(dir, quoted(data / "binary8byte.uff") + " --out a");
  EXPECT_EQ(acceleration.status, 2);
  EXPECT_NE(acceleration.err.find("needs pressure in Pa"), std::string::npos) << acceleration.err;
  const AnalyseRun psd = run(dir, quoted(data / "sample_dataset58_psd.uff") + " --out b");
  EXPECT_EQ(psd.status, 2);
  EXPECT_NE(psd.err.find("no time record"), std::string::npos) << psd.err;
  EXPECT_FALSE(fs::exists(dir / "a"));
  EXPECT_FALSE(fs::exists(dir / "b"));
  fs::remove_all(dir);
}

TEST(AnalyseCli, UncalibratedWavNeedsFullScale) {
  const fs::path dir = fresh_folder("uncalibrated");
  // A 16-bit PCM WAV of one sample, with no comment: nothing says what pressure full scale is.
  const unsigned char bytes[] = {'R', 'I', 'F', 'F', 38, 0, 0, 0, 'W', 'A', 'V', 'E', 'f', 'm', 't', ' ',
                                 16, 0, 0, 0, 1, 0, 1, 0, 0x80, 0xbb, 0, 0, 0, 0x77, 1, 0, 2, 0, 16, 0,
                                 'd', 'a', 't', 'a', 2, 0, 0, 0, 0, 0x10};
  std::ofstream(dir / "plain.wav", std::ios::binary).write(reinterpret_cast<const char*>(bytes), sizeof bytes);
  const AnalyseRun r = run(dir, "plain.wav --out x");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("plain.wav"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--full-scale"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x"));
  const AnalyseRun missing = run(dir, "missing.wav");
  EXPECT_EQ(missing.status, 2);
  fs::remove_all(dir);
}

}  // namespace
