#include "greens/greens_model.hpp"

#include <limits>

namespace rollnoise {

Eigen::MatrixXd GreensModel::static_compliance() const {
  return local_compliance() + smooth_integral(0.0, std::numeric_limits<double>::infinity());
}

}  // namespace rollnoise
