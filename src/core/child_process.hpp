#pragma once
// Running a piece of work in a child process (fork), for libraries that may crash on untrusted
// input: the HDF5 library (1.10) dereferences corrupted offsets in a file and can end the whole
// program with a segmentation fault. The child does the work and sends its result back through
// a pipe; a crash, a hang or a result too large is an InputError in the parent.
//
// The work must not rely on other threads (the child has only the calling thread) and should
// touch no state the parent needs afterwards (the child's changes are lost). POSIX only.
#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace rollnoise {

// Runs `work` in a child process and returns the bytes it returned. An InputError thrown by
// `work` is thrown again here, with the same source, key and problem; any other exception is a
// std::runtime_error. If the child dies (a signal, such as a segmentation fault), returns more
// than `max_bytes` or takes longer than `timeout`, the result is
// InputError(source, "", "cannot be read: " + what + " ...").
std::string run_in_child_process(const std::function<std::string()>& work, const std::string& source,
                                 const std::string& what, std::size_t max_bytes,
                                 std::chrono::milliseconds timeout = std::chrono::seconds(120));

}  // namespace rollnoise
