#include "core/gnuplot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "core/cancellation.hpp"
#include "core/output_directory.hpp"

namespace rollnoise {

bool gnuplot_available() {
  return std::system("command -v gnuplot >/dev/null 2>&1") == 0;
}

namespace {

// Runs `gnuplot SCRIPT` in `dir`, its messages on our stdout as before. Not std::system(): that
// ignores SIGINT in the caller while it waits, and polls nothing, so a Ctrl-C while a large
// plot draws would be lost, or leave the run's staging folder to the watchdog. Here the wait
// polls the CancellationToken: on Ctrl-C gnuplot is stopped and Interrupted thrown, which
// removes the staging folder. Returns gnuplot's exit status (-1 when it could not be run).
int run_gnuplot(const std::filesystem::path& dir, const std::string& script) {
  const pid_t child = ::fork();
  if (child < 0) return -1;
  if (child == 0) {
    // Only async-signal-safe calls before exec: the parent has other threads.
    if (::chdir(dir.c_str()) != 0 || ::dup2(STDOUT_FILENO, STDERR_FILENO) < 0) ::_exit(127);
    const char* argv[] = {"gnuplot", script.c_str(), nullptr};
    ::execvp("gnuplot", const_cast<char* const*>(argv));
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
  std::fflush(stdout);  // gnuplot's messages after ours
  if (run_gnuplot(dir, name + ".gp") != 0) {
    std::fprintf(stderr, "rollnoise: warning: gnuplot failed on %s.gp; no PNG written\n", name.c_str());
    return false;
  }
  return true;
}

}  // namespace rollnoise
