#include "core/child_process.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <system_error>

#include "core/error.hpp"

namespace rollnoise {
namespace {

// Message: one tag byte, then length-prefixed strings.
constexpr char tag_result = 'R';
constexpr char tag_input_error = 'E';
constexpr char tag_other_error = 'X';

void append_string(std::string& out, const std::string& s) {
  const std::uint64_t n = s.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  out += s;
}

bool take_string(const std::string& in, std::size_t& pos, std::string& s) {
  std::uint64_t n = 0;
  if (in.size() - pos < sizeof n) return false;
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  if (in.size() - pos < n) return false;
  s.assign(in, pos, static_cast<std::size_t>(n));
  pos += static_cast<std::size_t>(n);
  return true;
}

void write_all(int fd, const std::string& data) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

[[noreturn]] void child_main(int fd, const std::function<std::string()>& work, std::size_t max_bytes) {
  // A crash here must not leave a core file per bad input.
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  std::string message;
  try {
    std::string result = work();
    if (result.size() > max_bytes) {
      message = std::string(1, tag_other_error);
      append_string(message, "the result is larger than the bound");
    } else {
      message = std::string(1, tag_result);
      append_string(message, result);
    }
  } catch (const InputError& e) {
    message = std::string(1, tag_input_error);
    append_string(message, e.source());
    append_string(message, e.key());
    append_string(message, e.problem());
  } catch (const std::exception& e) {
    message = std::string(1, tag_other_error);
    append_string(message, e.what());
  } catch (...) {
    message = std::string(1, tag_other_error);
    append_string(message, "unknown exception");
  }
  write_all(fd, message);
  ::close(fd);
  ::_exit(0);  // no atexit handlers, no destructors of the parent's objects
}

}  // namespace

std::string run_in_child_process(const std::function<std::string()>& work, const std::string& source,
                                 const std::string& what, std::size_t max_bytes,
                                 std::chrono::milliseconds timeout) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("run_in_child_process: pipe failed");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error("run_in_child_process: fork failed");
  }
  if (pid == 0) {
    ::close(fds[0]);
    child_main(fds[1], work, max_bytes);
  }
  ::close(fds[1]);
  const std::size_t limit = max_bytes + 64 * 1024;  // the result, and room for a message
  std::string received;
  bool too_large = false, timed_out = false;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  char buffer[64 * 1024];
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<std::int64_t>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the child closed its end (done, or died)
    received.append(buffer, static_cast<std::size_t>(n));
    if (received.size() > limit) {
      too_large = true;
      break;
    }
  }
  ::close(fds[0]);
  if (timed_out || too_large) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string failed = "cannot be read: " + what;
  if (timed_out) throw InputError(source, "", failed + " took longer than the time allowed (a corrupted file?)");
  if (too_large) throw InputError(source, "", failed + " produced more data than allowed (a corrupted file?)");
  if (WIFSIGNALED(status)) {
    throw InputError(source, "", failed + " crashed on it (signal " + std::to_string(WTERMSIG(status)) +
                                     "): the file is corrupted or not what it claims to be");
  }
  std::size_t pos = 1;
  if (received.empty()) throw InputError(source, "", failed + " ended without a result (a corrupted file?)");
  std::string a, b, c;
  switch (received[0]) {
    case tag_result:
      if (take_string(received, pos, a)) return a;
      break;
    case tag_input_error:
      if (take_string(received, pos, a) && take_string(received, pos, b) && take_string(received, pos, c)) {
        throw InputError(a, b, c);
      }
      break;
    case tag_other_error:
      if (take_string(received, pos, a)) throw std::runtime_error(what + ": " + a);
      break;
    default:
      break;
  }
  throw InputError(source, "", failed + " sent back a malformed result");
}

std::chrono::milliseconds time_to_read(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  const auto megabytes = ec ? 0 : static_cast<std::int64_t>(size >> 20);
  return std::chrono::milliseconds(2000 + 1000 * megabytes);
}

void ChildResultWriter::count(std::uint64_t n) { bytes_.append(reinterpret_cast<const char*>(&n), sizeof n); }

void ChildResultWriter::doubles(const double* values, std::size_t n) {
  bytes_.append(reinterpret_cast<const char*>(values), n * sizeof(double));
}

void ChildResultReader::take(void* out, std::size_t n) {
  if (bytes_.size() - pos_ < n) throw std::runtime_error(what_ + ": short result from the reading process");
  if (n > 0) std::memcpy(out, bytes_.data() + pos_, n);
  pos_ += n;
}

std::uint64_t ChildResultReader::count() {
  std::uint64_t n = 0;
  take(&n, sizeof n);
  return n;
}

void ChildResultReader::doubles(double* out, std::size_t n) {
  // Checked before multiplying, so that a huge n cannot wrap around.
  if ((bytes_.size() - pos_) / sizeof(double) < n) {
    throw std::runtime_error(what_ + ": short result from the reading process");
  }
  take(out, n * sizeof(double));
}

}  // namespace rollnoise
