#include "core/cancellation.hpp"

#include <string.h>

#include <string>

namespace rollnoise {
namespace {

// Set by the handlers (async-signal-safe: a lock-free atomic store), read by the tokens.
std::atomic<int> signal_received{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal flag must be lock-free");

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

SignalCancellation::SignalCancellation() {
  signal_received.store(0, std::memory_order_relaxed);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, &previous_int_);
  sigaction(SIGTERM, &action, &previous_term_);
}

SignalCancellation::~SignalCancellation() {
  sigaction(SIGINT, &previous_int_, nullptr);
  sigaction(SIGTERM, &previous_term_, nullptr);
}

}  // namespace rollnoise
