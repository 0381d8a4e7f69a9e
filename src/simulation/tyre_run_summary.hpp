#pragma once
// summary.json of a rolling tyre's run, the contact stage's part: the case, the model and its
// fit, the road, the tread pattern's tones, the forces and the patch, the contact step's
// figures, the grid and the settings (docs/reference/outputs.md). The sound stage adds its own
// (tyre_sound.hpp) and the run its times (tyre_simulation.cpp).
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "contact/rolling_settings.hpp"
#include "contact/rolling_tyre.hpp"
#include "contact/tyre_grid.hpp"
#include "core/case_file.hpp"
#include "greens/rolling_tyre_model.hpp"
#include "simulation/tyre_step_outputs.hpp"

namespace rollnoise {

struct TreadPattern;

// What the run was, beside its trace.
struct TyreRunFacts {
  const CaseFile& file;
  const RollingTyreModel& model;
  const TyreGrid& grid;
  const TyreRollingSettings& settings;
  std::string road_type;
  const TreadPattern* pattern = nullptr;  // none: a slick
  ContactFields fields = ContactFields::contact;
  double dt = 0.0;
  int substeps = 1;
  std::size_t steps = 0;
};

nlohmann::json tyre_contact_summary(const TyreRunFacts& f, const TyreContactTrace& trace);

}  // namespace rollnoise
