#pragma once
// What a run with air pumping ([radiation] air_pumping, contact/air_pumping.hpp) adds to its
// outputs: the flows as the radiation's monopoles, air_pumping.csv, and the contact side of
// summary.json's "air_pumping" (the radiation adds the powers: tyre_sound.hpp).
#include <filesystem>

#include <nlohmann/json.hpp>

#include "contact/air_pumping.hpp"
#include "radiation/monopole_radiation.hpp"

namespace rollnoise {

// A monopole at each edge of the steady patch, on the centre plane, air_pumping_source_height
// above the road, carrying the flow that leaves there.
MonopoleSources air_pumping_sources(const AirPumpingTrace& pumped);

// air_pumping.csv: per step (`time`, s) the flows out of the patch at its edges, the closed
// regions' share and the air inside.
void write_air_pumping_csv(const std::filesystem::path& path, const Eigen::VectorXd& time, const AirPumpingTrace& pumped);

// Where the flows leave, the sealing gap, the regions and volumes, and what following the air
// cost inside the step loop: merged into summary.json's "air_pumping".
void add_air_pumping_contact_summary(const AirPumpingTrace& pumped, nlohmann::json& entry);

}  // namespace rollnoise
