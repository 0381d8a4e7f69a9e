#include "contact/direct_history_engine.hpp"

#include <algorithm>
#include <stdexcept>

namespace rollnoise {

DirectHistoryEngine::DirectHistoryEngine(std::shared_ptr<const DiscreteKernel> kernel,
                                         std::size_t steps, const Eigen::VectorXd& preload)
    : kernel_(std::move(kernel)),
      points_(kernel_->point_count()),
      lags_(kernel_->length()),
      preload_(preload) {
  if (preload_.size() != points_) throw std::invalid_argument("preload has the wrong size");
  const Eigen::Index n = points_;
  const Eigen::Index blocks = static_cast<Eigen::Index>(lags_) - 1;
  reversed_.resize(n, std::max<Eigen::Index>(blocks, 0) * n);
  for (Eigen::Index b = 0; b < blocks; ++b) {
    reversed_.middleCols(b * n, n) = kernel_->lags[static_cast<std::size_t>(blocks - b)];
  }
  forces_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(steps) * n);
  // At step 0 every lag k ≥ 1 holds the preload: Σ_{k≥1} G[k] = total − G[0].
  pre_history_ = (kernel_->total - kernel_->lags[0]) * preload_;
}

void DirectHistoryEngine::history(Eigen::Ref<Eigen::VectorXd> u0) const {
  const Eigen::Index n = points_;
  const std::size_t memory = std::min(step_, lags_ - 1);  // lags 1 … memory are stored forces
  u0 = pre_history_;
  if (memory == 0) return;
  const Eigen::Index width = static_cast<Eigen::Index>(memory) * n;
  const Eigen::Index first_block = static_cast<Eigen::Index>(lags_ - 1 - memory);
  const Eigen::Index first_force = static_cast<Eigen::Index>(step_ - memory) * n;
  u0.noalias() += reversed_.middleCols(first_block * n, width) * forces_.segment(first_force, width);
}

void DirectHistoryEngine::advance(const Eigen::Ref<const Eigen::VectorXd>& force) {
  const Eigen::Index n = points_;
  if (static_cast<Eigen::Index>(step_ + 1) * n > forces_.size()) {
    throw std::logic_error("direct history engine: more steps than reserved");
  }
  forces_.segment(static_cast<Eigen::Index>(step_) * n, n) = force;
  ++step_;
  // The preload leaves lag `step_` of the window: it now acts through Σ_{k>step_} G[k] only
  // (beyond the stored kernel, through total − Σ G[k], which is 0 for a decayed kernel).
  if (step_ < lags_) pre_history_.noalias() -= kernel_->lags[step_] * preload_;
}

}  // namespace rollnoise
