#pragma once
// Wall-clock laps of a run's stages, for summary.json's "stage_times_s" (issue 12: where a warm
// case's time goes besides the contact and the radiation). Each lap() records the seconds since
// the previous one (or since construction) under a name; a name given twice adds up.
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace rollnoise {

class StageTimes {
 public:
  StageTimes() : last_(std::chrono::steady_clock::now()) {}

  void lap(const std::string& name) {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    for (auto& [stage, total] : laps_)
      if (stage == name) {
        total += seconds;
        return;
      }
    laps_.emplace_back(name, seconds);
  }
  // Starts the next lap now, leaving out the time since the last one (a stage timed elsewhere).
  void skip() { last_ = std::chrono::steady_clock::now(); }

  // {"stage": seconds, ...} in the order the stages first ran.
  nlohmann::json json() const {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [stage, total] : laps_) out[stage] = total;
    return out;
  }

 private:
  std::chrono::steady_clock::time_point last_;
  std::vector<std::pair<std::string, double>> laps_;
};

}  // namespace rollnoise
