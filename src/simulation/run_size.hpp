#pragma once
// What a simulate run holds in memory and writes to disk, counted from its sizes before it
// starts (core/run_estimate.hpp refuses the run when it cannot fit). Rough but on the safe
// side: the large arrays only, each counted once.
#include <cstdint>
#include <string>

#include "core/run_estimate.hpp"
#include "simulation/tyre_step_outputs.hpp"

namespace rollnoise {

// A point model (sdof, coupled_sdof): `samples` time samples of `points` contact points, four
// fields in memory (road, displacement, force, gap), three in contact.csv.
RunEstimate estimate_point_run(std::uint64_t samples, std::uint64_t points, const std::string& source);

// A tyre model. The contact loop streams its fields (tyre_step_outputs.hpp): memory holds the
// per-step totals, the road under the window by column, and the tread velocity on the radiation
// mesh; contact.h5 holds what [output] fields asks for, counted uncompressed (deflate only helps).
struct TyreRunSize {
  std::uint64_t samples = 0;          // steps
  std::uint64_t window_points = 0;    // the contact window, Nw·Ny
  std::uint64_t window_columns = 0;   // Nw
  std::uint64_t lateral = 0;          // the belt, Ny × Nθ
  std::uint64_t circumferential = 0;
  bool radiating = false;             // whether the tread velocity is kept for the radiation
  std::uint64_t receivers = 0;        // WAV files
  std::uint64_t audio_frames = 0;     // of each
  ContactFields fields = ContactFields::contact;
  SurfaceBlock block;                 // the belt velocity's decimation for ContactFields::contact
};
RunEstimate estimate_tyre_run(const TyreRunSize& size, const std::string& source);

}  // namespace rollnoise
