#include "contact/bordered_lu.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace rollnoise {

BorderedLu::BorderedLu(std::shared_ptr<const Eigen::MatrixXd> matrix, Eigen::Index capacity)
    : m_(std::move(matrix)),
      n_(m_ ? m_->rows() : 0),
      capacity_(std::min(capacity, n_)),
      base_lu_(n_),
      base_(static_cast<std::size_t>(n_)),
      base_position_(static_cast<std::size_t>(n_), -1),
      change_index_(static_cast<std::size_t>(capacity_)),
      change_added_(static_cast<std::size_t>(capacity_)),
      change_slot_(static_cast<std::size_t>(n_), -1),
      x_(n_, capacity_),
      d_(n_, capacity_),
      s_(capacity_, capacity_),
      schur_lu_(capacity_),
      y0_(n_),
      y_(capacity_) {
  if (!m_ || m_->rows() != m_->cols()) throw std::invalid_argument("bordered LU: need a square matrix");
  if (capacity < 0) throw std::invalid_argument("bordered LU: the capacity must be ≥ 0");
}

void BorderedLu::rebase(const std::vector<char>& set) {
  const Eigen::MatrixXd& m = *m_;
  for (Eigen::Index slot = 0; slot < changes_; ++slot) change_slot_[static_cast<std::size_t>(change_index_[slot])] = -1;
  changes_ = 0;
  base_count_ = 0;
  std::fill(base_position_.begin(), base_position_.end(), -1);
  for (Eigen::Index i = 0; i < n_; ++i)
    if (set[static_cast<std::size_t>(i)]) {
      base_[static_cast<std::size_t>(base_count_)] = i;
      base_position_[static_cast<std::size_t>(i)] = base_count_++;
    }
  Eigen::MatrixXd& block = base_lu_.matrix();
  for (Eigen::Index b = 0; b < base_count_; ++b) {
    const Eigen::Index column = base_[static_cast<std::size_t>(b)];
    for (Eigen::Index a = 0; a < base_count_; ++a) block(a, b) = m(base_[static_cast<std::size_t>(a)], column);
  }
  base_lu_.factorise(base_count_);
  base_valid_ = true;
  ++factorisations_;
}

void BorderedLu::drop_change(Eigen::Index slot) {
  const Eigen::Index last = changes_ - 1;
  change_slot_[static_cast<std::size_t>(change_index_[slot])] = -1;
  if (slot != last) {
    change_index_[slot] = change_index_[last];
    change_added_[slot] = change_added_[last];
    change_slot_[static_cast<std::size_t>(change_index_[slot])] = slot;
    x_.col(slot).head(base_count_) = x_.col(last).head(base_count_);
    d_.col(slot).head(base_count_) = d_.col(last).head(base_count_);
    // Column first, then row: the row copy carries the corner S(last, last) over too.
    s_.col(slot).head(changes_) = s_.col(last).head(changes_);
    s_.row(slot).head(changes_) = s_.row(last).head(changes_);
  }
  changes_ = last;
}

void BorderedLu::add_changes(const std::vector<char>& set) {
  const Eigen::MatrixXd& m = *m_;
  const Eigen::Index first = changes_, nb = base_count_;
  for (Eigen::Index i = 0; i < n_; ++i) {
    const auto index = static_cast<std::size_t>(i);
    const Eigen::Index position = base_position_[index];
    if ((set[index] != 0) == (position >= 0) || change_slot_[index] >= 0) continue;
    const Eigen::Index slot = changes_++;
    change_index_[slot] = i;
    change_added_[slot] = position < 0;
    change_slot_[index] = slot;
    if (position < 0) {  // added: C's column M_{B,i}, D's row M_{i,B}
      for (Eigen::Index b = 0; b < nb; ++b) {
        const Eigen::Index j = base_[static_cast<std::size_t>(b)];
        x_(b, slot) = m(j, i);
        d_(b, slot) = m(i, j);
      }
    } else {  // removed: e_position in both
      x_.col(slot).head(nb).setZero();
      d_.col(slot).head(nb).setZero();
      x_(position, slot) = 1.0;
      d_(position, slot) = 1.0;
    }
  }
  const Eigen::Index added = changes_ - first;
  if (added == 0) return;
  base_lu_.solve_in_place(x_, first, added);
  // S = [M_NN 0; 0 0] − Dᵀᵀ·X: the new columns against every row, the new rows against the old
  // columns.
  if (nb > 0) {
    s_.block(0, first, changes_, added).noalias() =
        -d_.topLeftCorner(nb, changes_).transpose() * x_.block(0, first, nb, added);
    s_.block(first, 0, added, first).noalias() =
        -d_.block(0, first, nb, added).transpose() * x_.topLeftCorner(nb, first);
  } else {
    s_.block(0, first, changes_, added).setZero();
    s_.block(first, 0, added, first).setZero();
  }
  for (Eigen::Index b = first; b < changes_; ++b) {
    if (!change_added_[b]) continue;
    for (Eigen::Index a = 0; a < changes_; ++a) {
      if (!change_added_[a]) continue;
      s_(a, b) += m(change_index_[a], change_index_[b]);
      if (a < first) s_(b, a) += m(change_index_[b], change_index_[a]);
    }
  }
}

void BorderedLu::solve(const std::vector<char>& set, const Eigen::VectorXd& q, Eigen::VectorXd& z) {
  if (static_cast<Eigen::Index>(set.size()) != n_ || q.size() != n_)
    throw std::invalid_argument("bordered LU: one flag and one q per index");
  if (!base_valid_) {
    rebase(set);
  } else {
    for (Eigen::Index slot = changes_ - 1; slot >= 0; --slot) {
      const bool in_set = set[static_cast<std::size_t>(change_index_[slot])] != 0;
      if (change_added_[slot] ? !in_set : in_set) drop_change(slot);
    }
    Eigen::Index needed = 0;
    for (Eigen::Index i = 0; i < n_; ++i) {
      const auto index = static_cast<std::size_t>(i);
      needed += (set[index] != 0) != (base_position_[index] >= 0) && change_slot_[index] < 0;
    }
    if (changes_ + needed > capacity_) rebase(set);
    else if (needed > 0) add_changes(set);
  }
  const Eigen::Index nb = base_count_, k = changes_;
  for (Eigen::Index b = 0; b < nb; ++b) y0_(b) = -q(base_[static_cast<std::size_t>(b)]);
  base_lu_.solve_in_place(y0_);
  if (k > 0) {
    for (Eigen::Index a = 0; a < k; ++a)
      y_(a) = (change_added_[a] ? -q(change_index_[a]) : 0.0) - d_.col(a).head(nb).dot(y0_.head(nb));
    schur_lu_.matrix().topLeftCorner(k, k) = s_.topLeftCorner(k, k);
    schur_lu_.factorise(k);
    schur_lu_.solve_in_place(y_);
    y0_.head(nb).noalias() -= x_.topLeftCorner(nb, k) * y_.head(k);
  }
  if (z.size() != n_) z.resize(n_);
  z.setZero();
  for (Eigen::Index b = 0; b < nb; ++b) z(base_[static_cast<std::size_t>(b)]) = y0_(b);
  for (Eigen::Index a = 0; a < k; ++a) z(change_index_[a]) = change_added_[a] ? y_(a) : 0.0;
}

void BorderedLu::relabel(const std::vector<Eigen::Index>& new_index) {
  if (static_cast<Eigen::Index>(new_index.size()) != n_) throw std::invalid_argument("bordered LU: one new index per index");
  if (!base_valid_) return;
  for (Eigen::Index b = 0; b < base_count_; ++b)
    if (new_index[static_cast<std::size_t>(base_[static_cast<std::size_t>(b)])] < 0) {
      base_valid_ = false;  // the base cannot follow: refactorise at the next solve
      return;
    }
  for (Eigen::Index slot = changes_ - 1; slot >= 0; --slot)
    if (new_index[static_cast<std::size_t>(change_index_[slot])] < 0) drop_change(slot);
  std::fill(base_position_.begin(), base_position_.end(), -1);
  for (Eigen::Index b = 0; b < base_count_; ++b) {
    Eigen::Index& index = base_[static_cast<std::size_t>(b)];
    index = new_index[static_cast<std::size_t>(index)];
    base_position_[static_cast<std::size_t>(index)] = b;
  }
  std::fill(change_slot_.begin(), change_slot_.end(), -1);
  for (Eigen::Index slot = 0; slot < changes_; ++slot) {
    change_index_[slot] = new_index[static_cast<std::size_t>(change_index_[slot])];
    change_slot_[static_cast<std::size_t>(change_index_[slot])] = slot;
  }
}

}  // namespace rollnoise
