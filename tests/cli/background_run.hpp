#pragma once
// Running `rollnoise` in the background and stopping it with a signal, as a user's Ctrl-C or a
// batch system's SIGTERM would (issue 14): what the interrupted-run tests of every verb share.
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "cli_workspace.hpp"

namespace cli_test {

// Starts `launcher... rollnoise args...` in ws.work() (the launcher, such as mpirun with its
// options, may be empty); stdout and stderr go to files beside work().
inline pid_t start_rollnoise(const Workspace& ws, const std::vector<std::string>& args,
                             const std::vector<std::string>& launcher = {}) {
  const fs::path out = ws.work().parent_path() / "stdout.txt";
  const fs::path err = ws.work().parent_path() / "stderr.txt";
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(ws.work().c_str()) != 0) ::_exit(127);
    if (!std::freopen("/dev/null", "r", stdin) || !std::freopen(out.c_str(), "w", stdout) ||
        !std::freopen(err.c_str(), "w", stderr))
      ::_exit(127);
    std::vector<std::string> copies(launcher);
    copies.push_back(ROLLNOISE_BINARY);
    copies.insert(copies.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : copies) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(copies.front().c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

inline std::string stderr_of(const Workspace& ws) { return read_text(ws.work().parent_path() / "stderr.txt"); }

// Polls `done` every 20 ms until it holds or `timeout` passes; returns whether it held.
inline bool wait_until(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// True while `pid` (a child of the test) has not ended.
inline bool still_running(pid_t pid) {
  int raw = 0;
  return ::waitpid(pid, &raw, WNOHANG) == 0;
}

// A run stopped by a signal: how it ended and how long it took after the signal.
struct StoppedRun {
  bool exited = false;  // ended by exit() (not killed by the signal)
  int status = -1;      // its exit status, or the signal that killed it
  double seconds = 0.0;
  std::string err;
};

// Sends `signal_number` to the running child `pid` and waits for it to end.
inline StoppedRun stop_with(const Workspace& ws, pid_t pid, int signal_number) {
  StoppedRun r;
  const auto sent = std::chrono::steady_clock::now();
  if (::kill(pid, signal_number) != 0) return r;
  int raw = 0;
  if (::waitpid(pid, &raw, 0) != pid) return r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  r.exited = WIFEXITED(raw);
  r.status = r.exited ? WEXITSTATUS(raw) : WTERMSIG(raw);
  r.err = stderr_of(ws);
  return r;
}

// The checks every interrupted verb must pass: ended by itself (not killed) within 1 s with
// 128 + the signal, and one line on stderr saying so from main()'s handler (not the watchdog's
// "stopped at once", which leaves a staging folder behind).
inline void expect_clean_stop(const StoppedRun& r, int signal_number) {
  ASSERT_TRUE(r.exited) << "killed by signal " << r.status << " instead of stopping; stderr: " << r.err;
  EXPECT_EQ(r.status, 128 + signal_number) << r.err;
  EXPECT_LT(r.seconds, 1.0) << "took " << r.seconds << " s to stop";
  EXPECT_TRUE(contains(r.err, signal_number == SIGINT ? "interrupted by SIGINT" : "interrupted by SIGTERM")) << r.err;
  EXPECT_TRUE(contains(r.err, "the partial output was removed")) << "the watchdog ended it: " << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
}

}  // namespace cli_test
