#pragma once
// OpenBLAS (with its LAPACK) serves the radiation's least squares and the contact's dense LU. It
// runs single-threaded: its threaded kernels may split sums differently with the thread count,
// and rollnoise's results must not depend on it (the stages that need threads run their own).

namespace rollnoise {

// Makes the BLAS single-threaded for this process (idempotent, thread-safe).
void use_single_threaded_blas();

}  // namespace rollnoise
