#pragma once
// FFTW's planner (plan creation and destruction) is not thread-safe, and it is one library-wide
// state: every module that plans must hold this one lock (studies run cases on threads).
// Executing a plan needs no lock.
#include <mutex>

namespace rollnoise {

inline std::mutex& fftw_planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace rollnoise
