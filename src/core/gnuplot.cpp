#include "core/gnuplot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "core/cancellation.hpp"
#include "core/output_directory.hpp"

namespace rollnoise {

bool gnuplot_available() {
  return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
}

namespace {

// Runs `gnuplot SCRIPT` in `dir`, its messages on our stderr beside our own warnings about it
// (stdout stays for what the command reports). Not std::system(): that
// ignores SIGINT in the caller while it waits, and polls nothing, so a Ctrl-C while a large
// plot draws would be lost, or leave the run's staging folder to the watchdog. Here the wait
// polls the CancellationToken: on Ctrl-C gnuplot is stopped and Interrupted thrown, which
// removes the staging folder. Returns gnuplot's exit status (-1 when it could not be run).
// `scripts`: one or more, `reset session` between them.
int run_gnuplot(const std::filesystem::path& dir, const std::vector<std::string>& scripts) {
  // The arguments made before the fork: only async-signal-safe calls after it.
  std::vector<const char*> argv{"gnuplot"};
  for (std::size_t i = 0; i < scripts.size(); ++i) {
    if (i > 0) argv.insert(argv.end(), {"-e", "reset session"});
    argv.push_back(scripts[i].c_str());
  }
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  if (child < 0) return -1;
  if (child == 0) {
    // Only async-signal-safe calls before exec: the parent has other threads.
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execvp("gnuplot", const_cast<char* const*>(argv.data()));
    ::_exit(127);
  }
  const CancellationToken cancel;
  int raw = 0;
  while (true) {
    const pid_t done = ::waitpid(child, &raw, WNOHANG);
    if (done == child) return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    if (done < 0 && errno != EINTR) return -1;
    if (cancel.cancelled()) {
      ::kill(child, SIGTERM);
      while (::waitpid(child, &raw, 0) < 0 && errno == EINTR) {
      }
      cancel.throw_if_cancelled();
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

bool write_plot(const std::filesystem::path& dir, const std::string& name, const std::string& script) {
  write_text_file(dir / (name + ".gp"), script);
  if (!gnuplot_available()) {
    std::fprintf(stderr, "rollnoise: warning: gnuplot is not installed; wrote %s.gp but no PNG\n", name.c_str());
    return false;
  }
  std::fflush(stderr);  // gnuplot's messages after ours
  if (run_gnuplot(dir, {name + ".gp"}) != 0) {
    std::fprintf(stderr, "rollnoise: warning: gnuplot failed on %s.gp; no PNG written\n", name.c_str());
    return false;
  }
  return true;
}

void PlotBatch::add(const std::string& name, const std::string& script) {
  write_text_file(dir_ / (name + ".gp"), script);
  names_.push_back(name);
}

bool PlotBatch::draw() {
  const std::vector<std::string> names = std::exchange(names_, {});
  if (names.empty()) return true;
  if (!gnuplot_available()) {
    for (const std::string& name : names)
      std::fprintf(stderr, "rollnoise: warning: gnuplot is not installed; wrote %s.gp but no PNG\n", name.c_str());
    return false;
  }
  std::vector<std::string> scripts;
  for (const std::string& name : names) scripts.push_back(name + ".gp");
  std::fflush(stderr);
  if (run_gnuplot(dir_, scripts) == 0) return true;
  // Which failed: each alone (gnuplot stops at the first error).
  bool all = true;
  for (const std::string& name : names) {
    if (run_gnuplot(dir_, {name + ".gp"}) != 0) {
      std::fprintf(stderr, "rollnoise: warning: gnuplot failed on %s.gp; no PNG written\n", name.c_str());
      all = false;
    }
  }
  return all;
}

bool write_plot(const std::filesystem::path& dir, const std::string& name, const std::string& script, PlotBatch* batch) {
  if (!batch) return write_plot(dir, name, script);
  if (batch->dir() != dir) throw std::logic_error("write_plot: a plot for another folder than its batch's");
  batch->add(name, script);
  return true;
}

}  // namespace rollnoise
