#include "radiation/transfer_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rollnoise {

namespace {

void check_anchors(const std::vector<double>& anchors) {
  if (anchors.empty() || !(anchors.front() > 0.0) || !std::is_sorted(anchors.begin(), anchors.end()) ||
      std::adjacent_find(anchors.begin(), anchors.end()) != anchors.end()) {
    throw std::invalid_argument("transfer table: anchor frequencies must be positive and increasing");
  }
}

std::vector<Eigen::MatrixXcd> solve_anchors(const EquivalentSources& model, const Eigen::Matrix3Xd& receivers,
                                            const std::vector<double>& anchors, double regularisation) {
  check_anchors(anchors);
  std::vector<Eigen::MatrixXcd> transfers;
  for (double f : anchors) transfers.push_back(model.transfer(2.0 * std::numbers::pi * f, receivers, regularisation));
  return transfers;
}

}  // namespace

Eigen::VectorXd propagation_delays(const Eigen::Matrix3Xd& receivers, const Eigen::Vector3d& reference,
                                   double sound_speed) {
  Eigen::VectorXd delay(receivers.cols());
  for (Eigen::Index r = 0; r < receivers.cols(); ++r) delay(r) = (receivers.col(r) - reference).norm() / sound_speed;
  return delay;
}

TransferTable::TransferTable(std::vector<double> anchors_hz, std::vector<Eigen::MatrixXcd> transfers,
                             Eigen::VectorXd delays)
    : anchors_(std::move(anchors_hz)), delay_(std::move(delays)), reduced_(std::move(transfers)) {
  check_anchors(anchors_);
  if (reduced_.size() != anchors_.size()) throw std::invalid_argument("transfer table: one transfer per anchor");
  for (std::size_t a = 0; a < anchors_.size(); ++a) {
    if (reduced_[a].rows() != delay_.size() || reduced_[a].cols() != reduced_.front().cols())
      throw std::invalid_argument("transfer table: transfers of different sizes");
    const double omega = 2.0 * std::numbers::pi * anchors_[a];
    for (Eigen::Index r = 0; r < reduced_[a].rows(); ++r) reduced_[a].row(r) *= std::polar(1.0, omega * delay_(r));
  }
}

TransferTable::TransferTable(const EquivalentSources& model, const Eigen::Matrix3Xd& receivers,
                             std::vector<double> anchors_hz, const Eigen::Vector3d& reference, double sound_speed,
                             double regularisation)
    : TransferTable(anchors_hz, solve_anchors(model, receivers, anchors_hz, regularisation),
                    propagation_delays(receivers, reference, sound_speed)) {}

Eigen::MatrixXcd TransferTable::at(double f) const {
  Eigen::MatrixXcd t = reduced_at(f);
  const double omega = 2.0 * std::numbers::pi * f;
  for (Eigen::Index r = 0; r < t.rows(); ++r) t.row(r) *= std::polar(1.0, -omega * delay_(r));
  return t;
}

Eigen::MatrixXcd TransferTable::reduced_at(double f) const {
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
  return t;
}

void TransferTable::reduced_at(double f, Eigen::MatrixXcd& out) const {
  if (!(f >= anchors_.front() && f <= anchors_.back())) {
    throw std::out_of_range("transfer table: frequency outside the anchors");
  }
  const auto upper = std::lower_bound(anchors_.begin(), anchors_.end(), f);
  const auto i = static_cast<std::size_t>(upper - anchors_.begin());
  if (*upper == f) {
    out = reduced_[i];
  } else {
    const double w = (f - anchors_[i - 1]) / (anchors_[i] - anchors_[i - 1]);
    out = (1.0 - w) * reduced_[i - 1] + w * reduced_[i];  // coefficient-wise: no temporary
  }
}

}  // namespace rollnoise
