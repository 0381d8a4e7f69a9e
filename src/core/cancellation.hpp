#pragma once
// Stopping a long run cleanly on Ctrl-C (SIGINT) or SIGTERM.
//
// The signal handler only sets one lock-free atomic (the one piece of process-wide mutable
// state: a handler cannot reach anything else safely). Long loops poll a CancellationToken;
// the progress reporting places do so already (ProgressReporter::update), so every loop that
// shows progress stops within one of its steps. A cancelled token throws Interrupted, which
// unwinds like any error: the StagedOutputDirectory on the way removes its staging folder and
// leaves the destination as it was, and main() exits with 128 + the signal number (130, 143).
#include <atomic>
#include <chrono>
#include <csignal>
#include <stdexcept>
#include <thread>

namespace rollnoise {

// Thrown when a run is cancelled; not an error of the input or of the program.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal_number);
  int signal_number() const noexcept { return signal_; }
  // The shell's convention for a process ended by a signal: 128 + the signal number.
  int exit_status() const noexcept { return 128 + signal_; }

 private:
  int signal_;
};

// Answers "should the run stop?". Copies share the flag they watch. The default token watches
// the flag set by the signal handlers of SignalCancellation; tests give their own flag.
class CancellationToken {
 public:
  CancellationToken() noexcept;
  // `flag` holds 0 while the run may go on, else the signal number that stops it; it must
  // outlive the token.
  explicit CancellationToken(const std::atomic<int>& flag) noexcept : flag_(&flag) {}

  bool cancelled() const noexcept { return signal_number() != 0; }
  // The signal that stops the run, 0 while it may go on.
  int signal_number() const noexcept { return flag_->load(std::memory_order_relaxed); }
  // Throws Interrupted when cancelled.
  void throw_if_cancelled() const {
    if (const int signal = signal_number()) throw Interrupted(signal);
  }

 private:
  const std::atomic<int>* flag_;
};

// While alive, SIGINT and SIGTERM set the flag of the default CancellationToken instead of
// ending the process; the handlers are reset by the first signal (SA_RESETHAND), so a second
// Ctrl-C ends the process at once. A run busy in a stretch that polls no token (a library call
// such as tabulating a two-layer tyre's modes, before any output is staged) is ended by a
// watchdog thread `grace` after the signal: it exits with 128 + the signal number, printing one
// line. The destructor puts back the handlers that were there before. One at a time.
class SignalCancellation {
 public:
  explicit SignalCancellation(std::chrono::milliseconds grace = std::chrono::milliseconds(800));
  ~SignalCancellation();
  SignalCancellation(const SignalCancellation&) = delete;
  SignalCancellation& operator=(const SignalCancellation&) = delete;

  CancellationToken token() const noexcept { return {}; }

 private:
  struct sigaction previous_int_ {};
  struct sigaction previous_term_ {};
  std::jthread watchdog_;
};

// Stops the runs of this process from code rather than from a signal handler: the Python module
// calls cancel() when Python has a KeyboardInterrupt pending (Python's own SIGINT handler takes
// the signal there, so SignalCancellation is not installed). cancel() sets the flag the default
// CancellationToken watches, so every run in the process stops, as with Ctrl-C. The flag is
// cleared when the first RunCancellation of a quiet process is made and when the last one ends,
// so a stop does not carry over to the next run. No watchdog: a stretch that polls no token
// runs to its end.
class RunCancellation {
 public:
  RunCancellation() noexcept;
  ~RunCancellation();
  RunCancellation(const RunCancellation&) = delete;
  RunCancellation& operator=(const RunCancellation&) = delete;

  void cancel(int signal_number = SIGINT) const noexcept;
};

}  // namespace rollnoise
