#include "contact/rolling_settings.hpp"

#include <cmath>

#include "core/config_table.hpp"
#include "core/csv.hpp"

namespace rollnoise {

std::size_t RollingSettings::steps() const {
  return static_cast<std::size_t>(std::llround(duration / time_step));
}

RollingSettings read_rolling_settings(const ConfigTable& rolling) {
  RollingSettings s;
  s.speed = rolling.positive("speed");
  s.duration = rolling.positive("duration");
  s.time_step = rolling.positive("time_step");
  s.static_load = rolling.non_negative("static_load");
  s.history = parse_history_kind(
      rolling.choice("history", {"auto", "direct", "modal", "fft"}, "auto"));
  s.discretisation =
      parse_discretisation(rolling.choice("discretisation", {"step", "rectangle"}, "step"));
  rolling.reject_unknown_keys();
  const double steps = s.duration / s.time_step;
  if (steps < 1.0) {
    rolling.fail("time_step", "must be smaller than the duration (" + std::to_string(s.duration) + " s)");
  }
  // The direct engine keeps the whole history: past ~2·10⁷ steps it no longer fits in memory.
  if (steps > 2e7) {
    rolling.fail("time_step", "gives " + format_number(steps) +
                                  " steps; at most 2e7 are allowed (raise time_step or shorten duration)");
  }
  if (!std::isfinite(s.speed * s.duration)) {
    rolling.fail("duration", "speed × duration (the length of road rolled over, m) must be a finite number");
  }
  return s;
}

TyreRollingSettings read_tyre_rolling_settings(const ConfigTable& rolling) {
  TyreRollingSettings s;
  s.speed = rolling.positive("speed");
  s.duration = rolling.positive("duration");
  s.static_load = rolling.positive("static_load");
  s.history = parse_history_kind(rolling.choice("history", {"auto", "direct", "modal", "fft"}, "auto"));
  s.points_circumferential = static_cast<int>(rolling.integer("points_circumferential", 512, 8, 1 << 16));
  if (s.points_circumferential % 2 != 0) rolling.fail("points_circumferential", "must be even");
  s.points_lateral = static_cast<int>(rolling.integer("points_lateral", 16, 1, 1024));
  s.contact_window = rolling.positive("contact_window", 0.2);
  if (rolling.contains("time_step")) {
    rolling.fail("time_step", "is derived from the grid for a tyre (Δt = 2πR/points_circumferential/speed); remove it");
  }
  if (rolling.contains("discretisation") && rolling.text("discretisation") != "step") {
    rolling.fail("discretisation", "only \"step\" is available for a tyre (its modes recur exactly on it)");
  }
  rolling.reject_unknown_keys();
  if (!std::isfinite(s.speed * s.duration)) {
    rolling.fail("duration", "speed × duration (the length of road rolled over, m) must be a finite number");
  }
  return s;
}

}  // namespace rollnoise
