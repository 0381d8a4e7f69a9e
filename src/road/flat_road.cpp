#include "road/flat_road.hpp"

namespace rollnoise {

std::string FlatRoad::type() const { return "flat"; }

double FlatRoad::height(double /*x*/) const { return 0.0; }

}  // namespace rollnoise
