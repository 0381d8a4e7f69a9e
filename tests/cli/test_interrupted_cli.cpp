// Issue 14: Ctrl-C (SIGINT) or SIGTERM during `calibrate`, `road`, `greens` and `study`, as
// InterruptedRun (test_hardening_cli.cpp) does for `simulate`. Each verb is started on an input
// long enough to be still running, into a folder holding an earlier output; the signal must
// stop it within a second with 128 + the signal and one line on stderr, remove its staging
// folder and leave the earlier output byte for byte. A study keeps the cases it finished.
//
// calibrate, road and greens create their staging folder only once their computing is done
// (to write the results), so the signal is sent a fixed 0.6 s after the start, while they
// compute: what must stop them there is the polling of their loops (Ceres' iteration callback,
// the placing of a road's stones, the frequencies of the table). One road run is stopped after
// its staging folder appears, while it writes.
#include <signal.h>

#include <chrono>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "background_run.hpp"
#include "cli_workspace.hpp"

namespace {
using namespace cli_test;
using namespace std::chrono_literals;

const fs::path source_dir = ROLLNOISE_SOURCE_DIR;

// An earlier output in work()/result: what the stopped run must leave as it was.
void write_earlier_output(const Workspace& ws) {
  fs::create_directories(ws.path("result"));
  ws.write("result/summary.json", "{\"earlier\": true}\n");
  ws.write("result/report.json", "{\"earlier\": \"report\"}\n");
}

void expect_earlier_output(const Workspace& ws) {
  EXPECT_EQ(read_text(ws.path("result/summary.json")), "{\"earlier\": true}\n");
  EXPECT_EQ(read_text(ws.path("result/report.json")), "{\"earlier\": \"report\"}\n");
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(ws.path("result"))) names.insert(entry.path().filename().string());
  EXPECT_EQ(names, (std::set<std::string>{"report.json", "summary.json"}));
}

// Starts `args` (writing work()/result), sends `signal_number` after `delay` while the verb is
// computing, and checks the stop, the staging folder and the earlier output.
void stop_verb_while_computing(const std::vector<std::string>& args, int signal_number,
                               std::chrono::milliseconds delay = 600ms) {
  Workspace ws;
  write_earlier_output(ws);
  const pid_t pid = start_rollnoise(ws, args);
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(delay);
  ASSERT_TRUE(still_running(pid)) << "the run ended before the signal; make it longer. stderr: " << stderr_of(ws);
  const StoppedRun r = stop_with(ws, pid, signal_number);
  expect_clean_stop(r, signal_number);
  EXPECT_TRUE(ws.leftovers().empty()) << ws.leftovers().front();
  expect_earlier_output(ws);
}

// Starts `args` (writing work()/result) in `ws`, which holds the earlier output, waits until its
// staging folder holds `ready` (the folder itself when empty) and `settle` more, sends
// `signal_number`, and checks the stop, that the staging folder went and the earlier output.
void stop_verb_once_staged(const Workspace& ws, const std::vector<std::string>& args, const fs::path& ready,
                           std::chrono::seconds timeout, std::chrono::milliseconds settle, int signal_number) {
  const pid_t pid = start_rollnoise(ws, args);
  ASSERT_GT(pid, 0);
  const fs::path staging = ws.work() / (".result.partial-" + std::to_string(pid));
  ASSERT_TRUE(wait_until([&] { return fs::exists(staging / ready); }, timeout))
      << "never got to " << (staging / ready) << "; stderr: " << stderr_of(ws);
  std::this_thread::sleep_for(settle);
  ASSERT_TRUE(still_running(pid)) << "the run ended before the signal; make it longer";
  const StoppedRun r = stop_with(ws, pid, signal_number);
  expect_clean_stop(r, signal_number);
  EXPECT_FALSE(fs::exists(staging));
  EXPECT_TRUE(ws.leftovers().empty()) << ws.leftovers().front();
  expect_earlier_output(ws);
}

// A plate tyre fitted to its point mobility from 400 starting points: the fit runs for tens of
// seconds, every Ceres iteration polling the signal.
TEST(InterruptedRun, SigintStopsCalibrateWithin1sAndLeavesTheDestination) {
  stop_verb_while_computing({"calibrate", (source_dir / "models/tyres/passenger_205_55R16.toml").string(), "--data",
                             (source_dir / "data/mobility/tyre_point_mobility.csv").string(), "--response", "0,0.09",
                             "--excitation", "0,0.09", "--starts", "400", "--out", "result"},
                            SIGINT);
}

// A generated dense asphalt 15 m long on 50 lines (about 3.5 s of placing stones): before the
// fix, the placing polled nothing and the watchdog ended the run ("stopped at once").
TEST(InterruptedRun, SigintStopsRoadWithin1sAndLeavesTheDestination) {
  stop_verb_while_computing({"road", (source_dir / "models/surfaces/dac11.toml").string(), "--length", "15",
                             "--lines", "50", "--out", "result"},
                            SIGINT);
}

// A sine road of 40 m on 20 lines: its staging folder is there for about a second and a half
// (road.csv of 4e6 numbers, then gnuplot). SIGTERM then, while it writes: before the fix, the
// CSV loop and std::system("gnuplot ...") polled nothing and the watchdog ended the run with
// the staging folder left behind.
TEST(InterruptedRun, SigtermStopsRoadWhileItWritesAndRemovesItsStagingFolder) {
  Workspace ws;
  write_earlier_output(ws);
  ws.write("sine.toml", "[road]\ntype = \"sine\"\namplitude = 1e-3\nwavelength = 0.1\n");
  stop_verb_once_staged(ws, {"road", "sine.toml", "--length", "40", "--lines", "20", "--out", "result"}, {}, 30s,
                        200ms, SIGTERM);
}

// The plate's receptance at 100 000 frequencies: seconds of modal sums, polled per frequency.
TEST(InterruptedRun, SigtermStopsGreensWithin1sAndLeavesTheDestination) {
  stop_verb_while_computing({"greens", (source_dir / "models/tyres/passenger_205_55R16.toml").string(),
                             "--frequencies", "1:5000:100000", "--out", "result"},
                            SIGTERM);
}

// A study of two point-model cases, the first short and the second long: Ctrl-C while the
// second runs stops the study within a second; the first case stays (a rerun takes it from
// there), the second's staging folder goes, and the study's earlier results are untouched.
TEST(InterruptedRun, SigintStopsStudyWithin1sAndKeepsItsFinishedCases) {
  Workspace ws;
  const std::string base = (source_dir / "models/cases/larsson2000_sdof_sine.toml").string();
  const auto study = [&](const std::string& durations) {
    return "[study]\nname = \"durations\"\ncase = \"" + base + "\"\n[set]\noutput.plots = false\n" +
           "[vary]\nrolling.duration = " + durations + "\n";
  };
  ws.write("study.toml", study("[0.5, 400.0]"));
  // The results of an earlier run of the study.
  fs::create_directories(ws.path("s"));
  ws.write("s/summary.json", "{\"earlier\": true}\n");
  ws.write("s/results.csv", "rolling.duration,status\n0.5,ok\n");
  const fs::path cases = ws.path("s") / "cases";
  const auto folders = [&](bool hidden) {
    std::vector<fs::path> found;
    std::error_code ec;
    for (fs::directory_iterator it(cases, ec), end; !ec && it != end; it.increment(ec))
      if ((it->path().filename().string()[0] == '.') == hidden) found.push_back(it->path());
    return found;
  };

  const pid_t pid = start_rollnoise(ws, {"study", "study.toml", "--out", "s", "--threads", "1"});
  ASSERT_GT(pid, 0);
  // The short case committed, the long one staging.
  ASSERT_TRUE(wait_until([&] { return folders(false).size() == 1 && folders(true).size() == 1; }, 60s))
      << "the study never got to its second case; stderr: " << stderr_of(ws);
  std::this_thread::sleep_for(300ms);
  ASSERT_TRUE(still_running(pid)) << "the long case ended before the signal; stderr: " << stderr_of(ws);
  const StoppedRun r = stop_with(ws, pid, SIGINT);
  expect_clean_stop(r, SIGINT);

  const std::vector<fs::path> kept = folders(false);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_TRUE(folders(true).empty()) << "the stopped case's staging folder is left: " << folders(true).front();
  EXPECT_TRUE(fs::is_regular_file(kept.front() / "summary.json"));
  EXPECT_EQ(read_text(ws.path("s/summary.json")), "{\"earlier\": true}\n") << "the study's results were rewritten";
  EXPECT_EQ(read_text(ws.path("s/results.csv")), "rolling.duration,status\n0.5,ok\n");
  EXPECT_TRUE(ws.leftovers().empty()) << ws.leftovers().front();

  // A rerun (the long case shortened) takes the finished case as it is.
  const auto written = fs::last_write_time(kept.front() / "summary.json");
  ws.write("study.toml", study("[0.5, 0.6]"));
  const RunResult rerun = ws.run({"study", "study.toml", "--out", "s", "--threads", "1"});
  ASSERT_EQ(rerun.status, 0) << describe(rerun);
  EXPECT_TRUE(contains(rerun.out, "2 cases, 2 ok (1 from an earlier run)")) << rerun.out;
  EXPECT_EQ(fs::last_write_time(kept.front() / "summary.json"), written) << "the finished case was redone";
}

// A study of two plate-tyre cases (a cheap grid, 0.01 s and 1 s of rolling): SIGTERM while the
// second is in its step loop. A study's cases show no progress bar; before the fix, the tyre's
// step loop polled only through it, so the watchdog ended the study with the case's staging
// folder left behind.
TEST(InterruptedRun, SigtermStopsAStudyOfTyreCasesInTheirStepLoop) {
  Workspace ws;
  const std::string tyre = (source_dir / "models/tyres/passenger_205_55R16.toml").string();
  ws.write("base.toml", "[tyre]\nfile = \"" + tyre +
                            "\"\n[road]\ntype = \"flat\"\n[rolling]\nspeed = 22.222\nduration = 0.01\n"
                            "static_load = 3200.0\npoints_lateral = 6\ncontact_window = 0.15\nband_top = 1000\n"
                            "[radiation]\nreceivers = [\"cpx_front\"]\nmesh_around = 32\nmesh_across = 2\n"
                            "sidewall_rings = 4\nanchor_spacing = 500\ncontact_refinement = 3\n"
                            "[output]\nplots = false\nwav = false\n");
  ws.write("study.toml", "[study]\nname = \"tyres\"\ncase = \"base.toml\"\n[vary]\nrolling.duration = [0.01, 1.0]\n");
  const fs::path cases = ws.path("s") / "cases";
  const auto count = [&](bool hidden) {
    std::size_t n = 0;
    std::error_code ec;
    for (fs::directory_iterator it(cases, ec), end; !ec && it != end; it.increment(ec))
      n += (it->path().filename().string()[0] == '.') == hidden;
    return n;
  };
  const pid_t pid = start_rollnoise(ws, {"study", "study.toml", "--out", "s", "--threads", "1"});
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_until([&] { return count(false) == 1 && count(true) == 1; }, 60s))
      << "the study never got to its second case; stderr: " << stderr_of(ws);
  std::this_thread::sleep_for(200ms);
  ASSERT_TRUE(still_running(pid)) << "the long case ended before the signal; stderr: " << stderr_of(ws);
  const StoppedRun r = stop_with(ws, pid, SIGTERM);
  expect_clean_stop(r, SIGTERM);
  EXPECT_EQ(count(false), 1u) << "the finished case is kept";
  EXPECT_EQ(count(true), 0u) << "the stopped case's staging folder is left";
  EXPECT_FALSE(fs::exists(ws.path("s/results.csv")));
}

// A cheap plate-tyre run (0.01 s of rolling) whose sound is looped to a 300 s WAV: its sound
// report (band levels, LAeq, LAFmax of 1.4e7 samples) and the WAV take about two seconds after
// the rolling's half second. SIGINT once the report has begun (spectrum.csv is in the staging
// folder): before the fix the band filters, the weighting filters and the WAV writer polled
// nothing, and the watchdog ended the run with the staging folder left behind.
TEST(InterruptedRun, SigintStopsSimulateInItsLongSoundOutputAndRemovesItsStagingFolder) {
  Workspace ws;
  write_earlier_output(ws);
  const std::string tyre = (source_dir / "models/tyres/passenger_205_55R16.toml").string();
  ws.write("case.toml", "[tyre]\nfile = \"" + tyre +
                            "\"\n[road]\ntype = \"flat\"\n[rolling]\nspeed = 22.222\nduration = 0.01\n"
                            "static_load = 3200.0\npoints_lateral = 6\ncontact_window = 0.15\nband_top = 1000\n"
                            "[radiation]\nreceivers = [\"cpx_front\"]\nmesh_around = 32\nmesh_across = 2\n"
                            "sidewall_rings = 4\nanchor_spacing = 500\ncontact_refinement = 3\n"
                            "[output]\nplots = false\nwav = true\nwav_duration = 300\n");
  stop_verb_once_staged(ws, {"simulate", "case.toml", "--out", "result", "--no-cache"}, "spectrum.csv", 60s, 100ms,
                        SIGINT);
}

// Ctrl-C of a study under `mpirun -n 2`: mpirun (OpenMPI 4) turns the SIGINT into SIGTERM to
// every rank a second later, and SIGKILL a second after that. Case i runs on rank i mod 2: rank
// 1 finishes both its short cases and waits for rank 0, which is in its third case (2 s of
// rolling, several seconds of work). Before the fix the stopped rank 0 threw past the gather
// that rank 1 waited in, and both then hung in MPI_Finalize (mpirun was tearing the job down)
// until the watchdog ended them ("stopped at once", a line per rank). Now the ranks agree that
// the study was stopped and leave without MPI_Finalize: the finished cases stay, the running
// case's staging folder goes, no results are written, one line from rank 0, mpirun's exit
// status is non-zero, and a rerun redoes only the stopped case.
TEST(InterruptedRun, SigintToMpirunStopsTheStudyOnEveryRankAndKeepsItsFinishedCases) {
#if ROLLNOISE_TEST_MPI
  Workspace ws;
  const std::string tyre = (source_dir / "models/tyres/passenger_205_55R16.toml").string();
  ws.write("base.toml", "[tyre]\nfile = \"" + tyre +
                            "\"\n[road]\ntype = \"flat\"\n[rolling]\nspeed = 22.222\nduration = 0.01\n"
                            "static_load = 3200.0\npoints_lateral = 6\ncontact_window = 0.15\nband_top = 1000\n"
                            "[radiation]\nreceivers = [\"cpx_front\"]\nmesh_around = 32\nmesh_across = 2\n"
                            "sidewall_rings = 4\nanchor_spacing = 500\ncontact_refinement = 3\n"
                            "[output]\nplots = false\nwav = false\n");
  const auto study = [&](const std::string& long_duration) {
    ws.write("study.toml", "[study]\nname = \"tyres\"\ncase = \"base.toml\"\n[vary]\nrolling.duration = [0.01, 0.011, " +
                               long_duration + ", 0.012]\n");
  };
  study("2.0");
  const fs::path cases = ws.path("s") / "cases";
  const auto folders = [&](bool hidden) {
    std::vector<fs::path> found;
    std::error_code ec;
    for (fs::directory_iterator it(cases, ec), end; !ec && it != end; it.increment(ec))
      if ((it->path().filename().string()[0] == '.') == hidden) found.push_back(it->path());
    return found;
  };
  // As root OpenMPI needs its allow-run-as-root settings; --oversubscribe for 2 ranks anywhere.
  const std::vector<std::string> mpirun = {"/usr/bin/env", "OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1",
                                           MPIEXEC_EXECUTABLE, "-n", "2", "--oversubscribe"};
  const pid_t pid = start_rollnoise(ws, {"study", "study.toml", "--out", "s"}, mpirun);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_until([&] { return folders(false).size() == 3 && folders(true).size() == 1; }, 120s))
      << "the study never got to its long case; stderr: " << stderr_of(ws);
  std::this_thread::sleep_for(300ms);
  ASSERT_TRUE(still_running(pid)) << "the long case ended before the signal; stderr: " << stderr_of(ws);
  const StoppedRun r = stop_with(ws, pid, SIGINT);
  ASSERT_TRUE(r.exited) << "mpirun killed by signal " << r.status << "; stderr: " << r.err;
  EXPECT_NE(r.status, 0) << r.err;
  // mpirun's own second before it passes the signal on, then the ranks' stop (the watchdog
  // would end them 0.8 s after the signal, mpirun's SIGKILL a second after it).
  EXPECT_LT(r.seconds, 3.0) << "took " << r.seconds << " s to stop";
  EXPECT_TRUE(contains(r.err, "interrupted by SIG")) << r.err;
  EXPECT_TRUE(contains(r.err, "the partial output was removed")) << "the watchdog ended it: " << r.err;
  EXPECT_FALSE(contains(r.err, "stopped at once")) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;

  const std::vector<fs::path> kept = folders(false);
  EXPECT_EQ(kept.size(), 3u) << "the finished cases are kept";
  EXPECT_TRUE(folders(true).empty()) << "a staging folder is left: " << folders(true).front();
  EXPECT_FALSE(fs::exists(cases / "duration-2")) << "the stopped case was committed";
  EXPECT_FALSE(fs::exists(ws.path("s/results.csv")));
  EXPECT_FALSE(fs::exists(ws.path("s/summary.json")));
  EXPECT_TRUE(ws.leftovers().empty()) << ws.leftovers().front();

  // A rerun (the long case shortened) takes the three finished cases as they are.
  std::vector<fs::file_time_type> written;
  for (const fs::path& folder : kept) written.push_back(fs::last_write_time(folder / "summary.json"));
  study("0.013");
  std::string launcher;
  for (const std::string& part : mpirun) launcher += part + " ";
  const RunResult rerun = ws.run({"study", "study.toml", "--out", "s"}, launcher);
  ASSERT_EQ(rerun.status, 0) << describe(rerun);
  EXPECT_TRUE(contains(rerun.out, "4 cases, 4 ok (3 from an earlier run)")) << rerun.out;
  for (std::size_t i = 0; i < kept.size(); ++i)
    EXPECT_EQ(fs::last_write_time(kept[i] / "summary.json"), written[i]) << kept[i] << " was redone";
#else
  GTEST_SKIP() << "built without MPI (ROLLNOISE_MPI=OFF)";
#endif
}

}  // namespace
