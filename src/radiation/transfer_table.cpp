#include "radiation/transfer_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollnoise {

TransferTable::TransferTable(const EquivalentSources& model, const Eigen::Matrix3Xd& receivers,
                             std::vector<double> anchors_hz, const Eigen::Vector3d& reference, double sound_speed,
                             double regularisation)
    : anchors_(std::move(anchors_hz)) {
  if (anchors_.empty() || !(anchors_.front() > 0.0) || !std::is_sorted(anchors_.begin(), anchors_.end()) ||
      std::adjacent_find(anchors_.begin(), anchors_.end()) != anchors_.end()) {
    throw std::invalid_argument("transfer table: anchor frequencies must be positive and increasing");
  }
  delay_.resize(receivers.cols());
  for (Eigen::Index r = 0; r < receivers.cols(); ++r) delay_(r) = (receivers.col(r) - reference).norm() / sound_speed;
  for (double f : anchors_) {
    const double omega = 2.0 * std::numbers::pi * f;
    Eigen::MatrixXcd t = model.transfer(omega, receivers, regularisation);
    for (Eigen::Index r = 0; r < t.rows(); ++r) t.row(r) *= std::polar(1.0, omega * delay_(r));
    reduced_.push_back(std::move(t));
  }
}

Eigen::MatrixXcd TransferTable::at(double f) const {
  if (!(f >= anchors_.front() && f <= anchors_.back())) {
    throw std::out_of_range("transfer table: frequency outside the anchors");
  }
  const auto upper = std::lower_bound(anchors_.begin(), anchors_.end(), f);
  Eigen::MatrixXcd t;
  if (*upper == f) {
    t = reduced_[static_cast<std::size_t>(upper - anchors_.begin())];
  } else {
    const auto i = static_cast<std::size_t>(upper - anchors_.begin());
    const double w = (f - anchors_[i - 1]) / (anchors_[i] - anchors_[i - 1]);
    t = (1.0 - w) * reduced_[i - 1] + w * reduced_[i];
  }
  const double omega = 2.0 * std::numbers::pi * f;
  for (Eigen::Index r = 0; r < t.rows(); ++r) t.row(r) *= std::polar(1.0, -omega * delay_(r));
  return t;
}

}  // namespace rollnoise
