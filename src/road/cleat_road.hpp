#pragma once
// A single cleat (or, with a long length, a step): r = height for position ≤ x < position +
// length, 0 elsewhere. The sharp edges are the point: a cleat test excites the tyre's
// transient response (the classic cleat-impact test of tyre dynamics).
#include <string>

#include "road/road_profile.hpp"

namespace rollnoise {

class CleatRoad final : public RoadProfile {
 public:
  // height in m (≠ 0; negative for a pothole), length > 0 and position ≥ 0 in m.
  CleatRoad(double height, double length, double position);

  std::string type() const override;
  double height(double x) const override;

 private:
  double height_;
  double length_;
  double position_;
};

}  // namespace rollnoise
