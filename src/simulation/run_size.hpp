#pragma once
// What a simulate run holds in memory and writes to disk, counted from its sizes before it
// starts (core/run_estimate.hpp refuses the run when it cannot fit). Rough but on the safe
// side: the large arrays only, each counted once.
#include <cstdint>
#include <string>

#include "core/run_estimate.hpp"

namespace rollnoise {

// A point model (sdof, coupled_sdof): `samples` time samples of `points` contact points, four
// fields in memory (road, displacement, force, gap), three in contact.csv.
RunEstimate estimate_point_run(std::uint64_t samples, std::uint64_t points, const std::string& source);

// A tyre model: `samples` steps over a contact window of `window_points` points, the belt surface
// of `lateral` × `circumferential` points (contact.h5), the tread velocity on the radiation mesh
// and `receivers` WAV files of `audio_frames` frames.
RunEstimate estimate_tyre_run(std::uint64_t samples, std::uint64_t window_points, std::uint64_t lateral,
                              std::uint64_t circumferential, std::uint64_t receivers, std::uint64_t audio_frames,
                              const std::string& source);

}  // namespace rollnoise
