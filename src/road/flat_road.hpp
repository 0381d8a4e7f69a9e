#pragma once
// The flat road, r(x) = 0 everywhere: the reference case with no excitation from the surface.
#include <string>

#include "road/road_profile.hpp"

namespace rollnoise {

class FlatRoad final : public RoadProfile {
 public:
  std::string type() const override;
  double height(double x) const override;
};

}  // namespace rollnoise
