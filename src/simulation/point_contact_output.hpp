#pragma once
// The outputs of a point-model run: contact.csv, summary.json and a plot (ARCHITECTURE.md,
// "Outputs").
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

namespace rollnoise {

struct ContactTrace;

// contact.csv: time, then per point i (from 1) road_i, displacement_i, force_i.
void write_contact_csv(const std::filesystem::path& path, const ContactTrace& trace);

// summary.json's "lcp_iterations": total, max and mean per step of the solver's changes.
nlohmann::json summarise_iterations(const std::vector<int>& per_step);

// Per-point and overall figures for summary.json: max and mean force, fraction of time in
// contact, minimum gap, LCP iterations.
nlohmann::json summarise_contact(const ContactTrace& trace);

// contact.gp and contact.png: contact point against the reference surface (the paper's Fig. 3
// style), and the contact forces.
void plot_contact(const std::filesystem::path& dir, const ContactTrace& trace, const std::string& title);

}  // namespace rollnoise
