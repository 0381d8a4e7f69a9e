#pragma once
// Microphone positions that engineers use (MODEL.md §5), in the coordinates of
// tyre_surface_mesh.hpp (x along the road in the direction of travel from the wheel centre,
// y across from the tyre's centre plane, z up from the road):
//   cpx_front, cpx_rear  ISO 11819-2 (CPX): 0.1 m above the road, 0.2 m out from the sidewall,
//                        ±0.2 m along from the wheel centre;
//   spb                  ISO 11819-1 (SPB): 7.5 m from the wheel path, 1.2 m high, abeam;
// and any user-given point.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace rollnoise {

class ConfigTable;

struct Receiver {
  std::string name;
  Eigen::Vector3d position;  // m
};

// The standard receivers for a tyre of the given width (m): the CPX microphones stand 0.2 m out
// from its sidewall.
Receiver standard_receiver(const std::string& name, double tyre_width);
bool is_standard_receiver(const std::string& name);

// [radiation] receivers = ["cpx_front", "spb", {name = "mic", x = 1.0, y = 0.5, z = 0.3}, ...];
// default: cpx_front, cpx_rear, spb. Unknown names, points below the road and duplicates are
// InputErrors naming the key.
std::vector<Receiver> read_receivers(const ConfigTable& radiation, double tyre_width);

}  // namespace rollnoise
