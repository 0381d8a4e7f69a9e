#pragma once
// out = m·x for a compressed row-major sparse matrix, several rows at a time: each row's sum
// runs in its own register, term by term in column order from +0 and is then added to +0, the
// operations of Eigen's row-major product (and of its column-major scatter) in the same order,
// so the result is theirs bit for bit (test_sparse_rows_product). One row's sum is a chain of
// dependent additions; four independent chains side by side keep the adder busy (the product
// had been half of a tyre run's TyreStepOutputs::use() time: perf, issue 12).
#include <algorithm>
#include <cstddef>

#include <Eigen/SparseCore>

namespace rollnoise {

inline void multiply_sparse_rows(const Eigen::SparseMatrix<double, Eigen::RowMajor>& m, const double* x, double* out) {
  const auto* starts = m.outerIndexPtr();
  const auto* columns = m.innerIndexPtr();
  const double* values = m.valuePtr();
  const Eigen::Index rows = m.rows();
  // A row's own terms, from k to end, added to the running sum `sum`.
  const auto finish = [&](double sum, Eigen::Index k, Eigen::Index end) {
    for (; k < end; ++k) sum += values[k] * x[columns[k]];
    return 0.0 + sum;
  };
  Eigen::Index r = 0;
  for (; r + 4 <= rows; r += 4) {
    Eigen::Index k0 = starts[r], k1 = starts[r + 1], k2 = starts[r + 2], k3 = starts[r + 3];
    const Eigen::Index common = std::min({k1 - k0, k2 - k1, k3 - k2, starts[r + 4] - k3});
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (Eigen::Index t = 0; t < common; ++t, ++k0, ++k1, ++k2, ++k3) {
      s0 += values[k0] * x[columns[k0]];
      s1 += values[k1] * x[columns[k1]];
      s2 += values[k2] * x[columns[k2]];
      s3 += values[k3] * x[columns[k3]];
    }
    out[r] = finish(s0, k0, starts[r + 1]);
    out[r + 1] = finish(s1, k1, starts[r + 2]);
    out[r + 2] = finish(s2, k2, starts[r + 3]);
    out[r + 3] = finish(s3, k3, starts[r + 4]);
  }
  for (; r < rows; ++r) out[r] = finish(0.0, starts[r], starts[r + 1]);
}

}  // namespace rollnoise
