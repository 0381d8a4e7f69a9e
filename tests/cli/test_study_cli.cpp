// End-to-end tests of `rollnoise study` (issue 12): the real program on a 2 x 2 study of cheap
// cases (a 0.01 s roll, a coarse radiation mesh, no WAV files or plots in the cases). They
// check that the results do not depend on the threads or the MPI ranks, that a killed study
// resumes without redoing its finished cases, that a failing case is reported while the others
// finish, and the bad study files.
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_workspace.hpp"
#include "study/mpi_session.hpp"

namespace {
namespace fs = std::filesystem;
using namespace cli_test;

std::string quoted_model_path(const std::string& folder, const std::string& name) {
  std::string out = "\"";
  out += (fs::path(ROLLNOISE_SOURCE_DIR) / "models" / folder / name).string();
  out += '"';
  return out;
}

// A plate-tyre case on a flat road, made cheap: 0.01 s of rolling on a coarse grid (the band to
// 1 kHz, 6 points across, a 0.15 m window), a coarse radiation mesh
// with anchors 500 Hz apart, two CPX receivers, no WAV files and no plots.
std::string cheap_base_case() {
  std::ostringstream text;
  text << "[tyre]\nfile = " << quoted_model_path("tyres", "passenger_205_55R16.toml") << "\n"
       << "[road]\ntype = \"flat\"\n"
       << "[rolling]\nspeed = 22.222\nduration = 0.01\nstatic_load = 3200.0\npoints_lateral = 6\n"
       << "contact_window = 0.15\nband_top = 1000\n"
       << "[radiation]\nreceivers = [\"cpx_front\", \"cpx_rear\"]\nmesh_around = 32\nmesh_across = 2\n"
       << "sidewall_rings = 4\nanchor_spacing = 500\ncontact_refinement = 3\n"
       << "[output]\nplots = false\nwav = false\n";
  return text.str();
}

// The 2 x 2 study: two library surfaces (replacing the base case's flat road) at two speeds.
std::string two_by_two_study(const std::string& speeds = "[22.222, 30.556]") {
  std::ostringstream text;
  text << "[study]\nname = \"two_by_two\"\ncase = \"base.toml\"\nreference_surface = "
       << quoted_model_path("surfaces", "dac11.toml") << "\n"
       << "[set]\nrolling.duration = 0.01\n"
       << "[vary]\nroad.surface = [" << quoted_model_path("surfaces", "dac11.toml") << ", "
       << quoted_model_path("surfaces", "sma11.toml") << "]\nrolling.speed = " << speeds << "\n";
  return text.str();
}

// results.csv without its wall_time_s column (the only one that may differ between runs).
std::string results_without_wall_times(const fs::path& file) {
  std::istringstream in(read_text(file));
  std::string out, line;
  std::size_t column = std::string::npos;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    if (column == std::string::npos)
      for (std::size_t c = 0; c < cells.size(); ++c)
        if (cells[c] == "wall_time_s") column = c;
    for (std::size_t c = 0; c < cells.size(); ++c)
      if (c != column) out += cells[c] + ",";
    out += "\n";
  }
  return out;
}

std::vector<std::string> case_ids() {
  return {"surface-dac11_speed-22.222", "surface-dac11_speed-30.556", "surface-sma11_speed-22.222",
          "surface-sma11_speed-30.556"};
}

// A build without MPI under `mpirun -n N` would run the whole study N times into one folder:
// refused (every rank says why); one rank, or a build with MPI, runs.
TEST(StudyCli, MpirunWithoutMpiIsRefused) {
  EXPECT_EQ(rollnoise::mpi_launch_problem(true, 4), "");
  EXPECT_EQ(rollnoise::mpi_launch_problem(false, 1), "");
  const std::string problem = rollnoise::mpi_launch_problem(false, 2);
  EXPECT_NE(problem.find("built without MPI"), std::string::npos) << problem;
  EXPECT_NE(problem.find("2 ranks"), std::string::npos) << problem;
  ::setenv("OMPI_COMM_WORLD_SIZE", "3", 1);
  EXPECT_EQ(rollnoise::ranks_from_launcher(), 3);
  ::setenv("OMPI_COMM_WORLD_SIZE", "x3", 1);
  EXPECT_EQ(rollnoise::ranks_from_launcher(), 1) << "not a number: no launcher";
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  if (!std::getenv("PMI_SIZE")) {
    EXPECT_EQ(rollnoise::ranks_from_launcher(), 1);
  }
}

TEST(StudyCli, SameResultsWithOneThreadTwoThreadsAndTwoMpiRanks) {
  Workspace ws;
  ws.write("base.toml", cheap_base_case());
  ws.write("study.toml", two_by_two_study());
  const RunResult one = ws.run({"study", "study.toml", "--out", "one", "--threads", "1"});
  ASSERT_EQ(one.status, 0) << describe(one);
  EXPECT_TRUE(contains(one.out, "4 cases, 4 ok")) << one.out;
  EXPECT_TRUE(one.err.empty()) << "quiet when not on a terminal: " << one.err;
  const std::string expected = results_without_wall_times(ws.path("one") / "results.csv");
  EXPECT_EQ(first_line(ws.path("one") / "results.csv"),
            "road.surface,rolling.speed,LAeq_cpx_front_dB,LAeq_cpx_rear_dB,LWA_dB,rolling_resistance_N,wall_time_s,status");
  EXPECT_EQ(count_lines(read_text(ws.path("one") / "results.csv")), 5u);
  EXPECT_TRUE(contains(expected, "dac11,22.222,")) << expected;
  for (const std::string& id : case_ids()) {
    EXPECT_TRUE(fs::is_regular_file(ws.path("one") / "cases" / id / "summary.json")) << id;
    EXPECT_TRUE(fs::is_regular_file(ws.path("one") / "cases" / id / "case.toml")) << id;
  }
  EXPECT_EQ(first_line(ws.path("one") / "spectra.csv"), "road.surface,rolling.speed,receiver,band_hz,Lp_dB,LpA_dB");
  const nlohmann::json summary = read_json(ws.path("one") / "summary.json");
  EXPECT_EQ(summary["cases"]["ok"], 4);
  ASSERT_EQ(summary["level_fits"].size(), 4u) << "one fit per surface and receiver";
  if (gnuplot_installed()) {
    EXPECT_TRUE(fs::is_regular_file(ws.path("one") / "level_speed_cpx_front.png"));
    EXPECT_TRUE(fs::is_regular_file(ws.path("one") / "level_speed_cpx_front.gp"));
    EXPECT_TRUE(fs::is_regular_file(ws.path("one") / "difference_to_reference.png"));
    EXPECT_TRUE(fs::is_regular_file(ws.path("one") / "spectra_speed_22.222.png"));
  }

  // Each case is a normal simulation: its case.toml, run by `simulate`, gives the same sound.
  const fs::path sma = ws.path("one") / "cases" / "surface-sma11_speed-30.556";
  const RunResult single = ws.run({"simulate", (sma / "case.toml").string(), "--out", "single"});
  ASSERT_EQ(single.status, 0) << describe(single);
  EXPECT_EQ(read_text(ws.path("single") / "spectrum.csv"), read_text(sma / "spectrum.csv"));

  const RunResult two = ws.run({"study", "study.toml", "--out", "two", "--threads", "2"});
  ASSERT_EQ(two.status, 0) << describe(two);
  EXPECT_EQ(results_without_wall_times(ws.path("two") / "results.csv"), expected);
  EXPECT_EQ(read_text(ws.path("two") / "spectra.csv"), read_text(ws.path("one") / "spectra.csv"));

#if ROLLNOISE_TEST_MPI
  // As root, OpenMPI needs its allow-run-as-root settings; --oversubscribe for 2 ranks anywhere.
  const RunResult mpi = ws.run({"study", "study.toml", "--out", "mpi"},
                               "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " MPIEXEC_EXECUTABLE
                               " -n 2 --oversubscribe ");
  ASSERT_EQ(mpi.status, 0) << describe(mpi);
  EXPECT_EQ(results_without_wall_times(ws.path("mpi") / "results.csv"), expected);
  EXPECT_EQ(read_text(ws.path("mpi") / "spectra.csv"), read_text(ws.path("one") / "spectra.csv"));
  EXPECT_EQ(read_json(ws.path("mpi") / "summary.json")["ranks"], 2);
  // Both ranks on this machine share its cores: each case's radiation takes half of them.
  const unsigned half = std::max(1u, std::max(1u, std::thread::hardware_concurrency()) / 2);
  for (const auto& entry : fs::directory_iterator(ws.path("mpi") / "cases")) {
    if (!fs::is_regular_file(entry.path() / "summary.json")) continue;
    EXPECT_EQ(read_json(entry.path() / "summary.json")["radiation"]["threads"].get<unsigned>(), half) << entry.path();
  }
#else
  GTEST_SKIP() << "built without MPI (ROLLNOISE_MPI=OFF): the mpirun part is not run";
#endif
}

// The radiation cache in a study (issue 12): the cases use the folder given by --cache; a study
// run again (--restart: every case simulated again) finds every anchor of every case, and gives
// the results of the first run and of a run with --no-cache.
TEST(StudyCli, RerunFindsTheRadiationCacheAndNoCacheGivesTheSameResults) {
  Workspace ws;
  ws.write("base.toml", cheap_base_case());
  ws.write("study.toml", two_by_two_study());
  const std::string cache = ws.path("cache").string();
  const RunResult cold = ws.run({"study", "study.toml", "--out", "out", "--cache", cache});
  ASSERT_EQ(cold.status, 0) << describe(cold);
  const std::string expected = results_without_wall_times(ws.path("out") / "results.csv");
  const std::string spectra = read_text(ws.path("out") / "spectra.csv");
  const RunResult warm = ws.run({"study", "study.toml", "--out", "out", "--cache", cache, "--restart"});
  ASSERT_EQ(warm.status, 0) << describe(warm);
  for (const std::string& id : case_ids()) {
    const nlohmann::json radiation = read_json(ws.path("out") / "cases" / id / "summary.json")["radiation"];
    EXPECT_EQ(radiation["anchors_from_cache"], radiation["anchors"]) << id;
    EXPECT_EQ(radiation["cache"], cache) << id;
  }
  EXPECT_EQ(results_without_wall_times(ws.path("out") / "results.csv"), expected);
  EXPECT_EQ(read_text(ws.path("out") / "spectra.csv"), spectra);
  const RunResult none = ws.run({"study", "study.toml", "--out", "none", "--no-cache"});
  ASSERT_EQ(none.status, 0) << describe(none);
  EXPECT_EQ(results_without_wall_times(ws.path("none") / "results.csv"), expected);
  EXPECT_EQ(read_text(ws.path("none") / "spectra.csv"), spectra);
  EXPECT_EQ(read_json(ws.path("none") / "cases" / case_ids()[2] / "summary.json")["radiation"]["cache"], "");
}

// A study killed (SIGKILL) once its first case is finished, then run again: the finished case
// is kept (its files untouched), the rest are run, and the results equal those of a study run
// from the start (--restart).
TEST(StudyCli, KilledStudyResumesWithoutRedoingFinishedCases) {
  Workspace ws;
  ws.write("base.toml", cheap_base_case());
  ws.write("study.toml", two_by_two_study("[22.222, 30.556, 27.778]"));
  // Started in the background; killed as soon as one case folder is committed.
  std::string command = "cd ";
  command += shell_quote(ws.work().string());
  command += " && (";
  command += shell_quote(ROLLNOISE_BINARY);
  command += " study study.toml --out s --threads 1 >/dev/null 2>&1 & pid=$!; "
             "for i in $(seq 1 1200); do [ -n \"$(ls s/cases 2>/dev/null | head -n 1)\" ] && break; sleep 0.05; done; "
             "kill -9 $pid; wait $pid; true)";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::vector<fs::path> done;
  for (const auto& entry : fs::directory_iterator(ws.path("s") / "cases"))
    if (entry.path().filename().string()[0] != '.') done.push_back(entry.path());
  ASSERT_EQ(done.size(), 1u) << "killed after its first case";
  EXPECT_FALSE(fs::exists(ws.path("s") / "results.csv")) << "killed before the end";
  const fs::path first = done.front();
  const auto written = fs::last_write_time(first / "summary.json");
  const std::string first_summary = read_text(first / "summary.json");

  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a rewrite would show in the time
  const RunResult rerun = ws.run({"study", "study.toml", "--out", "s", "--threads", "1"});
  ASSERT_EQ(rerun.status, 0) << describe(rerun);
  EXPECT_TRUE(contains(rerun.out, "6 cases, 6 ok (1 from an earlier run)")) << rerun.out;
  EXPECT_EQ(fs::last_write_time(first / "summary.json"), written) << "the finished case was not redone";
  EXPECT_EQ(read_text(first / "summary.json"), first_summary);
  for (const auto& entry : fs::directory_iterator(ws.path("s") / "cases"))
    EXPECT_NE(entry.path().filename().string()[0], '.') << "a cut-off case's staging folder is left: " << entry.path();

  const RunResult fresh = ws.run({"study", "study.toml", "--out", "fresh", "--threads", "2", "--restart"});
  ASSERT_EQ(fresh.status, 0) << describe(fresh);
  EXPECT_EQ(results_without_wall_times(ws.path("s") / "results.csv"),
            results_without_wall_times(ws.path("fresh") / "results.csv"));
  EXPECT_EQ(read_text(ws.path("s") / "spectra.csv"), read_text(ws.path("fresh") / "spectra.csv"));
}

// A case that fails (a negative speed) is reported with its message; the others finish, and
// the exit status is 1. With --fail-fast no case starts after it.
TEST(StudyCli, FailingCaseIsReportedAndTheOthersFinish) {
  Workspace ws;
  ws.write("base.toml", cheap_base_case());
  ws.write("study.toml", "[study]\nname = \"failing\"\ncase = \"base.toml\"\n[vary]\nrolling.speed = [-5.0, 22.222]\n");
  const RunResult r = ws.run({"study", "study.toml", "--out", "s", "--threads", "1"});
  EXPECT_EQ(r.status, 1) << describe(r);
  EXPECT_TRUE(contains(r.err, "case speed--5 failed")) << r.err;
  EXPECT_TRUE(contains(r.err, "[rolling] speed")) << r.err;
  const std::string results = read_text(ws.path("s") / "results.csv");
  EXPECT_TRUE(contains(results, "-5,,,,,")) << results;
  EXPECT_TRUE(contains(results, ",failed\n")) << results;
  EXPECT_TRUE(contains(results, ",ok\n")) << results;
  const nlohmann::json summary = read_json(ws.path("s") / "summary.json");
  EXPECT_EQ(summary["cases"]["failed"], 1);
  EXPECT_TRUE(contains(summary["case_list"][0]["message"].get<std::string>(), "speed"));

  const RunResult fast = ws.run({"study", "study.toml", "--out", "f", "--threads", "1", "--fail-fast"});
  EXPECT_EQ(fast.status, 1) << describe(fast);
  EXPECT_TRUE(contains(read_text(ws.path("f") / "results.csv"), ",not run\n"));
  EXPECT_FALSE(fs::exists(ws.path("f") / "cases" / "speed-22.222"));
}

#if ROLLNOISE_TEST_MPI
// As root, OpenMPI needs its allow-run-as-root settings; --oversubscribe for 2 ranks anywhere.
const std::string mpirun_two_ranks =
    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " MPIEXEC_EXECUTABLE " -n 2 --oversubscribe ";
#endif

// --fail-fast under mpirun -n 2: case i runs on rank i mod 2. Rank 0 runs a short case (0.01 s
// rolled, about 0.8 s of work), then the failing one (a negative contact window, found at once;
// the [vary] keys are taken in sorted order, the last varying fastest). Rank 1 starts a long case
// (1 s rolled, about 4 s of work) beside rank 0's first, so that it is still running when the
// failure comes. The failure must stop the case neither rank has started, rank 1's second; before
// the fix rank 1 went on with it. The long case, already running, finishes and stays. (The
// failing case used to come first: whether rank 1 had started its case by then depended on the
// ranks' start-up skew, and the test failed about once in four runs.)
TEST(StudyCli, FailFastUnderMpiStopsTheCasesOfEveryRank) {
#if ROLLNOISE_TEST_MPI
  Workspace ws;
  ws.write("base.toml", cheap_base_case());
  ws.write("study.toml", "[study]\nname = \"failing\"\ncase = \"base.toml\"\n[vary]\nrolling.contact_window = [0.15, -0.15]\n"
                         "rolling.duration = [0.01, 1.0]\n");
  const RunResult r = ws.run({"study", "study.toml", "--out", "s", "--fail-fast"}, mpirun_two_ranks);
  EXPECT_NE(r.status, 0) << describe(r);
  EXPECT_TRUE(contains(r.out, "4 cases, 2 ok (0 from an earlier run), 1 failed")) << describe(r);
  EXPECT_TRUE(contains(r.err, "case contact_window--0.15_duration-0.01 failed")) << r.err;
  const nlohmann::json summary = read_json(ws.path("s") / "summary.json");
  const auto& list = summary["case_list"];
  ASSERT_EQ(list.size(), 4u);
  const std::vector<std::string> expected = {"ok", "ok", "failed", "not run"};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(list[i]["status"], expected[i]) << "case " << i << ": " << list[i];
  EXPECT_TRUE(contains(list[3]["message"].get<std::string>(), "--fail-fast")) << list[3];
  // Only the finished cases' folders, and no hidden leftover (staging folder or marker).
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(ws.path("s") / "cases")) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"contact_window-0.15_duration-0.01", "contact_window-0.15_duration-1"}));
  EXPECT_TRUE(fs::is_regular_file(ws.path("s") / "cases" / "contact_window-0.15_duration-1" / "summary.json"));

  // A rerun without --fail-fast keeps the finished cases and runs the two others, which fail.
  const RunResult rerun = ws.run({"study", "study.toml", "--out", "s"}, mpirun_two_ranks);
  EXPECT_NE(rerun.status, 0) << describe(rerun);
  EXPECT_TRUE(contains(rerun.out, "4 cases, 2 ok (2 from an earlier run), 2 failed")) << describe(rerun);
#else
  GTEST_SKIP() << "built without MPI (ROLLNOISE_MPI=OFF)";
#endif
}

// Bad study files: exit status 2 and one message naming the file and the key.
TEST(StudyCli, BadStudyFilesAreRejectedBeforeAnyCaseRuns) {
  Workspace ws;
  ws.write("base.toml", cheap_base_case());
  struct Bad {
    std::string text;
    std::vector<std::string> expect;
  };
  std::string many = "[";
  for (int i = 0; i < 201; ++i) {
    if (i) many += ", ";
    many += std::to_string(10 + i);
  }
  many += "]";
  const std::vector<Bad> cases = {
      {"[study]\nname = \"x\"\ncase = \"base.toml\"\n[vary]\nrolling.sped = [1.0, 2.0]\n",
       {"study.toml", "[vary] rolling.sped", "unknown key", "speed"}},
      {"[study]\nname = \"x\"\ncase = \"base.toml\"\n[vary]\nrolling.speed = []\n",
       {"study.toml", "[vary] rolling.speed", "empty list"}},
      {"[study]\nname = \"x\"\ncase = \"base.toml\"\n[vary]\nrolling.speed = " + many + "\n",
       {"study.toml", "vary", "201 cases", "--yes"}},
      {"[study]\nname = \"x\"\ncase = \"base.toml\"\n[vary]\nroad.surface = [\"nowhere.toml\"]\n",
       {"study.toml", "[vary] road.surface", "nowhere.toml"}},
      {"[study]\nname = \"x\"\ncase = \"base.toml\"\n[vary]\nwheel.speed = [1.0]\n",
       {"study.toml", "[vary] wheel", "unknown case section"}},
      {"[study]\nname = \"x\"\ncase = \"base.toml\"\nreference = 1\n[vary]\nrolling.speed = [1.0]\n",
       {"study.toml", "[study] reference", "unknown key"}},
  };
  for (const Bad& bad : cases) {
    ws.write("study.toml", bad.text);
    const RunResult r = ws.run({"study", "study.toml", "--out", "s"});
    EXPECT_EQ(r.status, 2) << bad.text << describe(r);
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    for (const std::string& part : bad.expect) EXPECT_TRUE(contains(r.err, part)) << bad.text << r.err;
    EXPECT_FALSE(fs::exists(ws.path("s") / "results.csv"));
  }
}

}  // namespace

namespace {

// On a terminal the study shows the cases done out of the total and the time left; with CI
// set it does not. (Two cases that fail at once: the line shows without any case running.)
TEST(StudyCli, ProgressOnATerminalQuietInCi) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "needs script(1) for a terminal";
  if (std::system("script -qec true /dev/null >/dev/null 2>&1") != 0) GTEST_SKIP() << "no pseudo-terminal here";
  Workspace ws;
  ws.write("base.toml", cheap_base_case());
  ws.write("study.toml", "[study]\nname = \"quick\"\ncase = \"base.toml\"\n[vary]\nrolling.speed = [-5.0, -6.0]\n");
  const auto on_terminal = [&](const std::string& env, const std::string& out) {
    std::string inner = env;
    inner += ' ';
    inner += shell_quote(ROLLNOISE_BINARY);
    inner += " study study.toml --threads 1 --out ";
    inner += out;
    std::string command = "cd ";
    command += shell_quote(ws.work().string());
    command += " && script -qec ";
    command += shell_quote(inner);
    command += " /dev/null > ../terminal.txt 2>&1";
    EXPECT_NE(std::system(command.c_str()), -1);
    return read_text(ws.work() / ".." / "terminal.txt");
  };
  const std::string shown = on_terminal("env -u CI", "a");
  EXPECT_TRUE(contains(shown, "study quick: 2/2 cases, 2 failed")) << shown;
  EXPECT_TRUE(contains(shown, "left")) << shown;
  const std::string quiet = on_terminal("env CI=true", "b");
  EXPECT_FALSE(contains(quiet, "2/2 cases")) << quiet;
  EXPECT_TRUE(contains(quiet, "case speed--5 failed")) << "failures are reported also in CI:\n" << quiet;
}

}  // namespace
