#include "road/cleat_road.hpp"

#include <cmath>

#include "core/error.hpp"

namespace rollnoise {

CleatRoad::CleatRoad(double height, double length, double position)
    : height_(height), length_(length), position_(position) {
  if (!std::isfinite(height) || height == 0.0) throw InputError("", "height", "must be a non-zero number (m)");
  if (!(length > 0.0) || !std::isfinite(length)) throw InputError("", "length", "must be > 0 (m)");
  if (!(position >= 0.0) || !std::isfinite(position)) throw InputError("", "position", "must be >= 0 (m)");
}

std::string CleatRoad::type() const { return "cleat"; }

double CleatRoad::height(double x) const {
  return x >= position_ && x < position_ + length_ ? height_ : 0.0;
}

}  // namespace rollnoise
