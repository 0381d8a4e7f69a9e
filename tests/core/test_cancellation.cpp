// Cancellation (core/cancellation.hpp): the token that long loops poll through
// ProgressReporter, the signal handlers that set it, and the watchdog that ends a run which
// polls nothing.
#include <csignal>
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "core/cancellation.hpp"
#include "core/progress.hpp"

namespace {
using rollnoise::CancellationToken;
using rollnoise::Interrupted;
using rollnoise::ProgressReporter;
using rollnoise::SignalCancellation;

TEST(Cancellation, ProgressUpdatesThrowInterruptedOnceTheTokenIsCancelled) {
  std::atomic<int> flag{0};
  ProgressReporter progress("test", 1000, CancellationToken(flag));
  for (std::size_t i = 0; i < 600; ++i) progress.update(i);  // not cancelled: no throw
  flag = SIGTERM;
  try {
    progress.update(601);  // not a multiple of 256: polled on every call all the same
    FAIL() << "no Interrupted";
  } catch (const Interrupted& stopped) {
    EXPECT_EQ(stopped.signal_number(), SIGTERM);
    EXPECT_EQ(stopped.exit_status(), 143);
    EXPECT_STREQ(stopped.what(), "interrupted by SIGTERM");
  }
}

// A reporter that is never drawn (a study's cases) polls all the same: without it, a quiet
// loop would run on after Ctrl-C until the watchdog ended the process.
TEST(Cancellation, AReporterThatIsNotShownStillPollsTheToken) {
  std::atomic<int> flag{0};
  ProgressReporter quiet("test", 1000, CancellationToken(flag), false);
  quiet.update(1);
  flag = SIGINT;
  EXPECT_THROW(quiet.update(2), Interrupted);
}

TEST(Cancellation, ASignalSetsTheDefaultTokenAndTheHandlersAreRestored) {
  void (*before)(int) = std::signal(SIGINT, SIG_DFL);
  {
    const SignalCancellation cancellation(std::chrono::seconds(30));
    const CancellationToken token = cancellation.token();
    EXPECT_FALSE(token.cancelled());
    std::raise(SIGINT);  // the process goes on: only the flag is set
    EXPECT_TRUE(token.cancelled());
    EXPECT_THROW(token.throw_if_cancelled(), Interrupted);
    EXPECT_EQ(Interrupted(SIGINT).exit_status(), 130);
  }
  // The handler that was there before (the default) is back.
  EXPECT_EQ(std::signal(SIGINT, before), SIG_DFL);
}

TEST(Cancellation, TheWatchdogEndsARunThatPollsNothingWithin1s) {
  EXPECT_EXIT(
      {
        const SignalCancellation cancellation(std::chrono::milliseconds(300));
        std::raise(SIGTERM);
        const auto start = std::chrono::steady_clock::now();
        // Busy without polling the token for up to 5 s: the watchdog must end the process.
        while (std::chrono::steady_clock::now() - start < std::chrono::seconds(5)) std::this_thread::yield();
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(143), "interrupted by SIGTERM: stopped at once");
}

}  // namespace
