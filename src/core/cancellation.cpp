#include "core/cancellation.hpp"

#include <unistd.h>

#include <string>

namespace rollnoise {
namespace {

// Set by the handlers (async-signal-safe: a lock-free atomic store), read by the tokens.
std::atomic<int> signal_received{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal flag must be lock-free");
// The RunCancellation objects alive (the Python module's runs on several threads).
std::atomic<int> runs_cancellable{0};

extern "C" void on_stop_signal(int signal_number) {
  signal_received.store(signal_number, std::memory_order_relaxed);
}

std::string signal_name(int signal_number) {
  if (signal_number == SIGINT) return "SIGINT";
  if (signal_number == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal_number);
}

}  // namespace

Interrupted::Interrupted(int signal_number)
    : std::runtime_error("interrupted by " + signal_name(signal_number)), signal_(signal_number) {}

CancellationToken::CancellationToken() noexcept : flag_(&signal_received) {}

SignalCancellation::SignalCancellation(std::chrono::milliseconds grace) {
  signal_received.store(0, std::memory_order_relaxed);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
  watchdog_ = std::jthread([grace](std::stop_token stop) {
    using namespace std::chrono_literals;
    while (!stop.stop_requested() && signal_received.load(std::memory_order_relaxed) == 0) std::this_thread::sleep_for(20ms);
    const auto deadline = std::chrono::steady_clock::now() + grace;
    while (!stop.stop_requested() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(10ms);
    if (stop.stop_requested()) return;
    const int signal_number = signal_received.load(std::memory_order_relaxed);
    std::string line = "rollnoise: interrupted by " + signal_name(signal_number);
    line += ": stopped at once (busy in a step that polls no cancellation); the destination is untouched\n";
    (void)!::write(STDERR_FILENO, line.data(), line.size());
    ::_exit(128 + signal_number);
  });
}

SignalCancellation::~SignalCancellation() {
  watchdog_.request_stop();
  if (watchdog_.joinable()) watchdog_.join();
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

RunCancellation::RunCancellation() noexcept {
  if (runs_cancellable.fetch_add(1, std::memory_order_acq_rel) == 0) signal_received.store(0, std::memory_order_relaxed);
}

RunCancellation::~RunCancellation() {
  if (runs_cancellable.fetch_sub(1, std::memory_order_acq_rel) == 1) signal_received.store(0, std::memory_order_relaxed);
}

void RunCancellation::cancel(int signal_number) const noexcept {
  signal_received.store(signal_number, std::memory_order_relaxed);
}

}  // namespace rollnoise
