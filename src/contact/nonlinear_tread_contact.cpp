#include "contact/nonlinear_tread_contact.hpp"

#include <cmath>
#include <stdexcept>

#include "contact/nonlinear_spring_contact.hpp"

namespace rollnoise {

NonlinearTreadContact::NonlinearTreadContact(Eigen::MatrixXd structural, Eigen::VectorXd stiffness, double exponent,
                                             bool require_symmetric)
    : a_(std::move(structural)), k_(std::move(stiffness)), exponent_(exponent), require_symmetric_(require_symmetric) {
  const Eigen::Index n = a_.rows();
  if (a_.cols() != n || k_.size() != n) throw std::invalid_argument("nonlinear tread: sizes differ");
  force_ = Eigen::VectorXd::Zero(n);
  compression_ = Eigen::VectorXd::Zero(n);
  gap_ = Eigen::VectorXd::Zero(n);
  candidate_.assign(static_cast<std::size_t>(n), 0);
}

const Eigen::VectorXd& NonlinearTreadContact::solve(const Eigen::Ref<const Eigen::VectorXd>& q) {
  const Eigen::Index n = a_.rows();
  iterations_ = 0;
  for (Eigen::Index p = 0; p < n; ++p) candidate_[static_cast<std::size_t>(p)] = q(p) < 0.0 || force_(p) > 0.0;
  // Each sub-problem starts from the last step's compressions (Newton then needs a few
  // iterations instead of a solve from δ = 0), or, within a step, from the last round's.
  previous_compression_ = compression_;
  const double tolerance = 1e-12 * std::max(q.cwiseAbs().maxCoeff(), 1e-300);
  for (int round = 0; round <= n; ++round) {
    std::vector<Eigen::Index> set;
    for (Eigen::Index p = 0; p < n; ++p)
      if (candidate_[static_cast<std::size_t>(p)]) set.push_back(p);
    force_.setZero();
    compression_.setZero();
    const auto m = static_cast<Eigen::Index>(set.size());
    if (m > 0) {
      Eigen::MatrixXd a(m, m);
      Eigen::VectorXd k(m), qc(m);
      for (Eigen::Index b = 0; b < m; ++b) {
        k(b) = k_(set[b]);
        qc(b) = q(set[b]);
        for (Eigen::Index c = 0; c < m; ++c) a(c, b) = a_(set[c], set[b]);
      }
      // A new solver per sub-problem: its size changes from step to step. (This allocates in
      // the step loop, which the linear treads do not.)
      NonlinearSpringContact sub(std::move(a), std::move(k), exponent_, require_symmetric_);
      Eigen::VectorXd start(m);
      for (Eigen::Index b = 0; b < m; ++b) start(b) = previous_compression_(set[b]);
      sub.warm_start(start);
      const Eigen::VectorXd& f = sub.solve(qc);
      iterations_ += sub.iterations();
      for (Eigen::Index b = 0; b < m; ++b) {
        force_(set[b]) = f(b);
        compression_(set[b]) = sub.compression()(b);
        previous_compression_(set[b]) = sub.compression()(b);
      }
    }
    gap_.noalias() = a_ * force_;
    gap_ += q + compression_;
    // Points left out that the solution presses into the road join the candidates.
    bool grown = false;
    for (Eigen::Index p = 0; p < n; ++p) {
      if (!candidate_[static_cast<std::size_t>(p)] && gap_(p) < -tolerance) {
        candidate_[static_cast<std::size_t>(p)] = 1;
        grown = true;
      }
    }
    if (!grown) return force_;
  }
  throw std::runtime_error("nonlinear tread: the candidate set did not settle");
}

}  // namespace rollnoise
