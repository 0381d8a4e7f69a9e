#include "core/run_estimate.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

#include "core/error.hpp"

namespace rollnoise {
namespace fs = std::filesystem;

std::uint64_t checked_product(std::initializer_list<std::uint64_t> factors, const std::string& source,
                              const std::string& keys) {
  std::uint64_t product = 1;
  for (const std::uint64_t f : factors) {
    if (__builtin_mul_overflow(product, f, &product)) {
      throw InputError(source, keys, "the run's size (a product of these) overflows 64 bits; make them smaller");
    }
  }
  return product;
}

std::uint64_t checked_sum(std::initializer_list<std::uint64_t> terms, const std::string& source,
                          const std::string& keys) {
  std::uint64_t sum = 0;
  for (const std::uint64_t t : terms) {
    if (__builtin_add_overflow(sum, t, &sum)) {
      throw InputError(source, keys, "the run's size (a sum of these) overflows 64 bits; make them smaller");
    }
  }
  return sum;
}

std::uint64_t available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    unsigned long long kib = 0;
    if (std::sscanf(line.c_str(), "MemAvailable: %llu kB", &kib) == 1) return static_cast<std::uint64_t>(kib) * 1024u;
  }
  return 0;
}

std::uint64_t available_disk_bytes(const fs::path& destination) {
  std::error_code ec;
  fs::path p = fs::absolute(destination, ec);
  while (!p.empty() && !fs::exists(p, ec)) {
    if (p == p.parent_path()) break;
    p = p.parent_path();
  }
  const fs::space_info space = fs::space(p, ec);
  std::uint64_t available = ec ? 0 : static_cast<std::uint64_t>(space.available);
  // A file-size limit (ulimit -f) bounds what one run may write as surely as the disk does
  // (counted for the whole output: on the safe side).
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const auto cap = static_cast<std::uint64_t>(limit.rlim_cur);
    available = available == 0 ? cap : std::min(available, cap);
  }
  return available;
}

std::string format_bytes(std::uint64_t bytes) {
  static const char* const units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1000.0 && unit < 6) {
    value /= 1000.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.3g %s", value, units[unit]);
  return text;
}

void check_run_fits(const RunEstimate& estimate, std::uint64_t memory_available, std::uint64_t disk_available,
                    bool force) {
  if (force) return;
  const bool memory_short = memory_available > 0 && estimate.memory_bytes > memory_available;
  const bool disk_short = disk_available > 0 && estimate.disk_bytes > disk_available;
  if (!memory_short && !disk_short) return;
  std::ostringstream keys;
  for (std::size_t i = 0; i < estimate.keys.size(); ++i) keys << (i ? ", " : "") << estimate.keys[i];
  std::ostringstream problem;
  problem << "the run (" << estimate.what << ") needs about ";
  if (memory_short) {
    problem << format_bytes(estimate.memory_bytes) << " of memory, and " << format_bytes(memory_available)
            << " is available";
  }
  if (memory_short && disk_short) problem << "; and it writes about ";
  if (disk_short) {
    problem << format_bytes(estimate.disk_bytes) << " of output, and the disk has "
            << format_bytes(disk_available) << " free";
  }
  problem << ". Change these keys to make it smaller (or give --force to run it anyway)";
  throw InputError(estimate.source, keys.str(), problem.str());
}

}  // namespace rollnoise
