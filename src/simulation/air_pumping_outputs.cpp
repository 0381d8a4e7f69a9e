#include "simulation/air_pumping_outputs.hpp"

#include <fstream>

#include "core/csv.hpp"
#include "core/output_directory.hpp"

namespace rollnoise {

MonopoleSources air_pumping_sources(const AirPumpingTrace& pumped) {
  MonopoleSources air;
  air.positions.resize(3, 2);
  air.positions.col(0) = Eigen::Vector3d(pumped.front_edge_x, 0.0, air_pumping_source_height);
  air.positions.col(1) = Eigen::Vector3d(pumped.rear_edge_x, 0.0, air_pumping_source_height);
  air.flows.resize(pumped.front_flow.size(), 2);
  air.flows.col(0) = pumped.front_flow;
  air.flows.col(1) = pumped.rear_flow;
  return air;
}

void write_air_pumping_csv(const std::filesystem::path& path, const Eigen::VectorXd& time, const AirPumpingTrace& a) {
  std::ofstream out(path, std::ios::binary);
  CsvWriter csv(out, {"time", "front_flow", "rear_flow", "closed_flow", "thin_flow", "closed_volume", "enclosed_volume"});
  for (Eigen::Index n = 0; n < time.size(); ++n) {
    const double row[] = {time(n), a.front_flow(n), a.rear_flow(n), a.closed_flow(n), a.thin_flow(n), a.closed_volume(n), a.enclosed_volume(n)};
    csv.row(row, std::size(row));
  }
  close_output_file(out, path);
}

void add_air_pumping_contact_summary(const AirPumpingTrace& pumped, nlohmann::json& entry) {
  entry["front_edge_x_m"] = pumped.front_edge_x;
  entry["rear_edge_x_m"] = pumped.rear_edge_x;
  entry["source_height_m"] = air_pumping_source_height;
  entry["sealing_gap_m"] = air_sealing_gap;
  entry["most_closed_regions"] = pumped.most_closed_regions;
  entry["mean_enclosed_volume_m3"] = pumped.enclosed_volume.mean();
  entry["mean_closed_volume_m3"] = pumped.closed_volume.mean();
  entry["time_s"] = pumped.seconds;
}

}  // namespace rollnoise
