#pragma once
// The [rolling] table of a case: speed, duration, time step, static load and the solver's
// choices.
#include <string>

#include "contact/history_engine.hpp"
#include "greens/discrete_kernel.hpp"

namespace rollnoise {

class ConfigTable;

struct RollingSettings {
  double speed = 1.0;        // v, m/s
  double duration = 1.0;     // s
  double time_step = 1e-4;   // Δt, s
  double static_load = 0.0;  // W, N
  HistoryKind history = HistoryKind::automatic;
  Discretisation discretisation = Discretisation::step;

  // Number of steps after t = 0 (the run has steps + 1 samples, t = 0 … duration).
  std::size_t steps() const;
};

// Reads and validates [rolling]; unknown keys are rejected.
RollingSettings read_rolling_settings(const ConfigTable& rolling);

}  // namespace rollnoise
