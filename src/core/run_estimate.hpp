#pragma once
// Whether a run fits the machine, decided before it starts: a long run that needs more memory
// than the machine has, or writes more than the destination's disk holds, would die hours in
// (the out-of-memory killer, a full disk). The caller counts what the run holds and writes
// (steps, contact points, fields) with checked products, which turn an overflow into an
// InputError; check_run_fits() compares the totals with the memory available now and the free
// space where the output goes and refuses with a message naming the keys to change.
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace rollnoise {

// a · b, or an InputError (source, keys: "the product of ... overflows") when it does not fit
// 64 bits. For sizes read from files and case keys.
std::uint64_t checked_product(std::initializer_list<std::uint64_t> factors, const std::string& source,
                              const std::string& keys);
std::uint64_t checked_sum(std::initializer_list<std::uint64_t> terms, const std::string& source,
                          const std::string& keys);

struct RunEstimate {
  std::uint64_t memory_bytes = 0;  // held at once at the peak
  std::uint64_t disk_bytes = 0;    // written into the output folder
  std::string what;                // "2.1e9 steps × 640 contact points", for the message
  std::string source;              // the case file
  std::vector<std::string> keys;   // the keys that set the size, such as "[rolling] duration"
};

// What the machine offers: MemAvailable of /proc/meminfo (0 when unknown: not checked), and the
// free space of the nearest existing folder at or above `destination`, or the file-size limit
// (RLIMIT_FSIZE, ulimit -f) when that is smaller.
std::uint64_t available_memory_bytes();
std::uint64_t available_disk_bytes(const std::filesystem::path& destination);

// "1.5 GB", "820 MB", "12 kB" (decimal units).
std::string format_bytes(std::uint64_t bytes);

// Refuses (InputError, exit status 2) a run that needs more than `memory_available` or writes
// more than `disk_available` (a limit of 0 is not checked), unless `force`. The message gives
// both figures, the sizes behind them, the keys to change and --force.
void check_run_fits(const RunEstimate& estimate, std::uint64_t memory_available, std::uint64_t disk_available,
                    bool force);

}  // namespace rollnoise
