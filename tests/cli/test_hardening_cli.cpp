// Issue 14 end to end: a run stopped by SIGINT or SIGTERM, a run whose disk fills, and a case
// too large for the machine. The program is run as a user runs it (ROLLNOISE_BINARY).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "background_run.hpp"
#include "cli_workspace.hpp"

namespace {
using namespace cli_test;
using Clock = std::chrono::steady_clock;

const std::string sdof_case = std::string(ROLLNOISE_SOURCE_DIR) + "/models/cases/larsson2000_sdof_sine.toml";
const std::string plate_case = std::string(ROLLNOISE_SOURCE_DIR) + "/models/cases/plate_smooth_80kmh.toml";

// An earlier output in work()/result: what the stopped or failed run must leave as it was.
void write_earlier_output(const Workspace& ws) {
  fs::create_directories(ws.path("result"));
  ws.write("result/summary.json", "{\"earlier\": true}\n");
  ws.write("result/contact.csv", "time,road_1\n0,0\n");
}

void expect_earlier_output(const Workspace& ws) {
  EXPECT_EQ(read_text(ws.path("result/summary.json")), "{\"earlier\": true}\n");
  EXPECT_EQ(read_text(ws.path("result/contact.csv")), "time,road_1\n0,0\n");
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(ws.path("result"))) names.insert(entry.path().filename().string());
  EXPECT_EQ(names, (std::set<std::string>{"contact.csv", "summary.json"}));
}

// The staging folder of a run writing work()/result: ".result.partial-PID".
fs::path staging_of(const Workspace& ws, pid_t pid) {
  return ws.work() / (".result.partial-" + std::to_string(pid));
}

// Sends `signal_number` to a simulate run once it is in its time-step loop (its staging folder
// exists, then a little longer); checks that it stops within a second with 128 + the signal,
// removes its staging folder and leaves the earlier output as it was.
void stop_running_simulate(int signal_number) {
  Workspace ws;
  write_earlier_output(ws);
  // About a minute of time steps for the direct history engine: the run is still going when
  // the signal comes.
  const pid_t pid = start_rollnoise(ws, {"simulate", sdof_case, "--out", "result", "--set", "rolling.duration=400",
                               "--set", "rolling.time_step=1e-4", "--set", "output.plots=false"});
  ASSERT_GT(pid, 0);
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  while (!fs::exists(staging_of(ws, pid)) && Clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(fs::exists(staging_of(ws, pid))) << "the run never created its staging folder";
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  int raw = 0;
  ASSERT_EQ(::waitpid(pid, &raw, WNOHANG), 0) << "the run ended before the signal; make it longer";
  const auto sent = Clock::now();
  ASSERT_EQ(::kill(pid, signal_number), 0);
  ASSERT_EQ(::waitpid(pid, &raw, 0), pid);
  const double seconds = std::chrono::duration<double>(Clock::now() - sent).count();
  const std::string err = read_text(ws.work().parent_path() / "stderr.txt");
  ASSERT_TRUE(WIFEXITED(raw)) << "killed by signal " << WTERMSIG(raw) << " instead of stopping; stderr: " << err;
  EXPECT_EQ(WEXITSTATUS(raw), 128 + signal_number) << err;
  EXPECT_LT(seconds, 1.0) << "took " << seconds << " s to stop";
  EXPECT_TRUE(contains(err, signal_number == SIGINT ? "interrupted by SIGINT" : "interrupted by SIGTERM")) << err;
  EXPECT_TRUE(contains(err, "the partial output was removed")) << err;  // not the watchdog
  EXPECT_EQ(count_lines(err), 1u) << err;
  EXPECT_FALSE(fs::exists(staging_of(ws, pid)));
  EXPECT_TRUE(ws.leftovers().empty()) << ws.leftovers().front();
  expect_earlier_output(ws);
}

TEST(InterruptedRun, SigintStopsSimulateWithin1sAndLeavesTheDestination) { stop_running_simulate(SIGINT); }

TEST(InterruptedRun, SigtermStopsSimulateWithin1sAndLeavesTheDestination) { stop_running_simulate(SIGTERM); }

// A file-size limit (ulimit -f, in 512-byte blocks for /bin/sh) stands in for a full disk: the
// write fails the same way (EFBIG rather than ENOSPC), without root and without filling a disk.
TEST(DiskFull, AWriteThatFailsGivesOneMessageRemovesThePartialOutputAndExits1) {
  Workspace ws;
  write_earlier_output(ws);
  // contact.csv of 5001 steps is about 250 kB; the limit is 16 kB.
  // --force: the estimate would refuse the run up front (OversizedCase below).
  const RunResult r =
      ws.run({"simulate", sdof_case, "--out", "result", "--set", "output.plots=false", "--force"}, "ulimit -f 32; ");
  EXPECT_EQ(r.status, 1) << describe(r);
  EXPECT_TRUE(contains(r.err, "cannot write ")) << r.err;
  EXPECT_TRUE(contains(r.err, "contact.csv")) << r.err;
  EXPECT_TRUE(contains(r.err, "File too large")) << r.err;
  EXPECT_TRUE(contains(r.err, "file-size limit is full")) << r.err;
  EXPECT_TRUE(contains(r.err, "the partial output was removed")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_TRUE(ws.leftovers().empty()) << ws.leftovers().front();
  expect_earlier_output(ws);
  // The same run without the limit succeeds: the limit, not the case, made it fail.
  const RunResult ok = ws.run({"simulate", sdof_case, "--out", "result", "--set", "output.plots=false"});
  EXPECT_EQ(ok.status, 0) << describe(ok);
}

// The same for a tyre run, whose contact.h5 is written by HDF5 as the run goes: the failed write
// is named with the system's reason, and the process exits with 1 (libhdf5's exit handler
// crashed on the file it could not close, until it was switched off: hdf5_writer.cpp).
TEST(DiskFull, ATyreRunWhoseContactH5CannotBeWrittenExits1) {
  Workspace ws;
  write_earlier_output(ws);
  const RunResult r = ws.run({"simulate", plate_case, "--out", "result", "--set", "rolling.duration=0.005", "--set",
                              "output.plots=false", "--force"},
                             "ulimit -f 32; ");
  EXPECT_EQ(r.status, 1) << describe(r);
  EXPECT_TRUE(contains(r.err, "contact.h5")) << r.err;
  EXPECT_TRUE(contains(r.err, "File too large")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_TRUE(ws.leftovers().empty()) << ws.leftovers().front();
  expect_earlier_output(ws);
}

// A tyre run of a million seconds: about 5e10 steps over a 20 × 40 contact window, far beyond
// any machine's memory and disk. Refused at once, naming the keys; --force would run it.
TEST(OversizedCase, ATyreRunThatCannotFitIsRefusedInWellUnderASecond) {
  Workspace ws;
  const auto started = Clock::now();
  const RunResult r = ws.run({"simulate", plate_case, "--out", "result", "--set", "rolling.duration=1e6"});
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_LT(seconds, 0.5) << "took " << seconds << " s to refuse";
  EXPECT_TRUE(contains(r.err, "of memory")) << r.err;
  EXPECT_TRUE(contains(r.err, "[rolling] duration")) << r.err;
  EXPECT_TRUE(contains(r.err, "points_lateral")) << r.err;
  EXPECT_TRUE(contains(r.err, "--force")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_FALSE(fs::exists(ws.path("result")));
  EXPECT_TRUE(ws.leftovers().empty());
}

// The direct history engine on the default 5 kHz grid: 0.1 s is 1147 steps, and the engine keeps
// one 2060 × 2060 kernel matrix a step, twice (about 78 GB). Before the estimate counted the
// engine, this case ran for 98 s and died of std::bad_alloc (or the kernel's OOM killer). Now it
// is refused up front, naming [rolling] history first; the time it takes is measured in
// bench/cache_footprint.sh, not here.
TEST(OversizedCase, TheDirectEngineOnTheDefaultGridIsRefusedNamingTheHistoryKey) {
  Workspace ws;
  const std::string rough = std::string(ROLLNOISE_SOURCE_DIR) + "/models/cases/plate_rough_80kmh.toml";
  const std::vector<std::string> args{"simulate", rough, "--out", "result", "--set", "rolling.duration=0.1",
                                      "--set", "rolling.history=direct", "--set", "radiation.enabled=false"};
  const RunResult r = ws.run(args);
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "plate_rough_80kmh.toml: [rolling] history, [rolling] duration")) << r.err;
  EXPECT_TRUE(contains(r.err, "the direct history engine holds")) << r.err;
  EXPECT_TRUE(contains(r.err, "GB of kernel")) << r.err;
  EXPECT_TRUE(contains(r.err, "of memory")) << r.err;
  EXPECT_TRUE(contains(r.err, "--force")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_FALSE(fs::exists(ws.path("result")));
  EXPECT_TRUE(ws.leftovers().empty());
  // The same run with the modal engine (history = "auto") fits: the engine, not the grid or the
  // duration, made it too large.
  const RunResult fits = ws.run({"simulate", rough, "--out", "modal", "--set", "rolling.duration=0.1", "--set",
                                 "rolling.history=auto", "--set", "radiation.enabled=false", "--set",
                                 "output.plots=false", "--set", "output.fields=\"none\""});
  EXPECT_EQ(fits.status, 0) << describe(fits);
  // --force skips the estimate: the run starts and makes its kernel until the address-space limit
  // (1.5 GB, so that the test does not take the machine's memory) stops it, an internal error.
  std::vector<std::string> forced(args);
  forced[3] = "forced";
  forced.push_back("--force");
  const RunResult f = ws.run(forced, "ulimit -v 1500000; ");
  EXPECT_EQ(f.status, 1) << describe(f);
  EXPECT_FALSE(contains(f.err, "--force")) << "not refused: " << f.err;
  EXPECT_FALSE(fs::exists(ws.path("forced")));
}

// The output of a point run measured against the space it may take: under a file-size limit of
// 16 kB its 250 kB contact.csv cannot be written, so the run is refused before it starts.
TEST(OversizedCase, APointRunLargerThanTheFileSizeLimitIsRefusedAndForceRunsIt) {
  Workspace ws;
  const RunResult r = ws.run({"simulate", sdof_case, "--out", "result", "--set", "output.plots=false"}, "ulimit -f 32; ");
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "of output")) << r.err;
  EXPECT_TRUE(contains(r.err, "[rolling] duration, [rolling] time_step")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_FALSE(fs::exists(ws.path("result")));
  // --force runs it, and the write fails (DiskFull above); without the limit it fits.
  const RunResult forced =
      ws.run({"simulate", sdof_case, "--out", "result", "--set", "output.plots=false", "--force"}, "ulimit -f 32; ");
  EXPECT_EQ(forced.status, 1) << describe(forced);
  const RunResult ok = ws.run({"simulate", sdof_case, "--out", "result", "--set", "output.plots=false"});
  EXPECT_EQ(ok.status, 0) << describe(ok);
}

TEST(OversizedCase, SizesWhoseProductOverflowsAreExitStatus2) {
  // 9.1e14 steps × (3 × 2040 window + 2 × 20 × 1016 belt values) × 4 bytes of contact.h5 with
  // [output] fields = "all" overflows 64 bits.
  Workspace ws;
  const RunResult r = ws.run({"simulate", plate_case, "--out", "result", "--set", "rolling.duration=8e10", "--set",
                              "output.fields=\"all\""});
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_TRUE(contains(r.err, "overflows 64 bits")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  const RunResult huge = ws.run({"simulate", plate_case, "--out", "result", "--set", "rolling.duration=1e300"});
  EXPECT_EQ(huge.status, 2) << describe(huge);
  EXPECT_EQ(count_lines(huge.err), 1u) << huge.err;
}

// A generated road of 6.5e7 samples on 1000 lines: about 500 GB in memory and 1.6 TB of
// road.csv. Refused before a stone is placed, naming the options and --force.
TEST(OversizedCase, ARoadTooLargeForTheMachineIsRefusedInWellUnderASecond) {
  Workspace ws;
  const std::string dac11 = std::string(ROLLNOISE_SOURCE_DIR) + "/models/surfaces/dac11.toml";
  const auto started = Clock::now();
  const RunResult r = ws.run({"road", dac11, "--length", "13000", "--lines", "1000", "--out", "result"});
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  EXPECT_EQ(r.status, 2) << describe(r);
  EXPECT_LT(seconds, 0.5) << "took " << seconds << " s to refuse";
  EXPECT_TRUE(contains(r.err, "dac11.toml: --length, --spacing, --lines: the run (6.5e+07 samples × 1000 lines)"))
      << r.err;
  EXPECT_TRUE(contains(r.err, "--force")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_FALSE(fs::exists(ws.path("result")));
  EXPECT_TRUE(ws.leftovers().empty());
}

// road, greens and calibrate under a 16 kB file-size limit: each output is larger (road.csv
// 1.75 MB, receptance.csv 27 kB, fit.csv 190 kB), so each is refused up front (exit 2, the
// options that set the size, --force); with --force each runs and its write fails (exit 1,
// the partial output removed); without the limit each succeeds.
void expect_refused_then_forced(const Workspace& ws, const std::vector<std::string>& args, const std::string& keys) {
  const std::string limit = "ulimit -f 32; ";
  const auto started = Clock::now();
  const RunResult refused = ws.run(args, limit);
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  EXPECT_EQ(refused.status, 2) << describe(refused);
  EXPECT_LT(seconds, 0.5) << "took " << seconds << " s to refuse";
  EXPECT_TRUE(contains(refused.err, keys + ": the run (")) << refused.err;
  EXPECT_TRUE(contains(refused.err, "of output, and the disk has")) << refused.err;
  EXPECT_TRUE(contains(refused.err, "--force")) << refused.err;
  EXPECT_EQ(count_lines(refused.err), 1u) << refused.err;
  EXPECT_FALSE(fs::exists(ws.path("result")));

  std::vector<std::string> forced_args(args);
  forced_args.push_back("--force");
  const RunResult forced = ws.run(forced_args, limit);
  EXPECT_EQ(forced.status, 1) << describe(forced);
  EXPECT_TRUE(contains(forced.err, "File too large")) << forced.err;
  EXPECT_TRUE(contains(forced.err, "the partial output was removed")) << forced.err;
  EXPECT_FALSE(fs::exists(ws.path("result")));
  EXPECT_TRUE(ws.leftovers().empty()) << ws.leftovers().front();

  const RunResult ok = ws.run(args);
  EXPECT_EQ(ok.status, 0) << describe(ok);
}

TEST(OversizedCase, RoadLargerThanTheFileSizeLimitIsRefusedAndForceRunsIt) {
  Workspace ws;
  ws.write("sine.toml", "[road]\ntype = \"sine\"\namplitude = 1e-3\nwavelength = 0.1\n");
  expect_refused_then_forced(ws, {"road", "sine.toml", "--out", "result"}, "sine.toml: --length, --spacing, --lines");
}

TEST(OversizedCase, GreensLargerThanTheFileSizeLimitIsRefusedAndForceRunsIt) {
  Workspace ws;
  expect_refused_then_forced(
      ws, {"greens", std::string(ROLLNOISE_SOURCE_DIR) + "/models/tyres/larsson2000_sdof.toml", "--out", "result"},
      "command line: --frequencies, --distances");
}

TEST(OversizedCase, CalibrateLargerThanTheFileSizeLimitIsRefusedAndForceRunsIt) {
  Workspace ws;
  const std::string data = std::string(ROLLNOISE_SOURCE_DIR) + "/data/mobility/sdof_point_mobility.csv";
  expect_refused_then_forced(
      ws, {"calibrate", std::string(ROLLNOISE_SOURCE_DIR) + "/models/tyres/larsson2000_sdof.toml", "--data", data,
           "--out", "result"},
      data + ": --data, --frequency-range");
}

// Files a case names outside its folder are allowed but listed in summary.json: here the tyre
// through "../lib/..." and the road profile through a symlink beside the case that points out
// of its folder. A second case in the same folder names files inside it (one through a ".."
// that stays inside): its list is empty.
TEST(CaseFilePaths, SimulateSummaryListsPathsThatLeaveTheCaseFolder) {
  Workspace ws;
  fs::create_directories(ws.path("lib"));
  fs::create_directories(ws.path("cases/inside"));
  fs::copy_file(std::string(ROLLNOISE_SOURCE_DIR) + "/models/tyres/larsson2000_sdof.toml", ws.path("lib/sdof.toml"));
  fs::copy_file(ws.path("lib/sdof.toml"), ws.path("cases/inside/sdof.toml"));
  std::string profile = "x,z\n";
  for (int i = 0; i <= 200; ++i) profile += std::to_string(i * 0.005) + "," + (i % 2 ? "1e-4" : "0") + "\n";
  ws.write("lib/profile.csv", profile);
  ws.write("cases/inside/profile.csv", profile);
  fs::create_symlink("../lib/profile.csv", ws.path("cases/profile.csv"));
  const std::string rest =
      "[rolling]\nspeed = 1.0\nduration = 0.2\ntime_step = 1e-3\nstatic_load = 4.0\n[output]\nplots = false\n";
  ws.write("cases/outside.toml",
           "[tyre]\nfile = \"../lib/sdof.toml\"\n[road]\ntype = \"file\"\nfile = \"profile.csv\"\n" + rest);
  ws.write("cases/inside.toml", "[tyre]\nfile = \"inside/../inside/sdof.toml\"\n[road]\ntype = \"file\"\nfile = "
                                "\"inside/profile.csv\"\n" + rest);

  const RunResult r = ws.run({"simulate", "cases/outside.toml", "--out", "outside"});
  ASSERT_EQ(r.status, 0) << describe(r);
  const nlohmann::json listed = read_json(ws.path("outside/summary.json"))["paths_outside_case_folder"];
  const std::string work = fs::canonical(ws.work()).string();
  const nlohmann::json expected = nlohmann::json::array(
      {{{"key", "[tyre] file"}, {"file", "cases/outside.toml"}, {"path", "../lib/sdof.toml"}, {"resolved", work + "/lib/sdof.toml"}},
       {{"key", "[road] file"}, {"file", "cases/outside.toml"}, {"path", "profile.csv"}, {"resolved", work + "/lib/profile.csv"}}});
  EXPECT_EQ(listed, expected) << listed.dump(2);

  const RunResult inside = ws.run({"simulate", "cases/inside.toml", "--out", "inside"});
  ASSERT_EQ(inside.status, 0) << describe(inside);
  EXPECT_EQ(read_json(ws.path("inside/summary.json"))["paths_outside_case_folder"], nlohmann::json::array());
}

}  // namespace
