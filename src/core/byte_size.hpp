#pragma once
// Sizes as people write them ("4 GB", "500MB", "1.5 GiB", "2000000"), for limits given in a case
// file or on the command line: decimal units (kB, MB, GB, TB: powers of 1000, as disks are
// sold and as format_bytes prints), binary ones (KiB, MiB, GiB, TiB), B or none for bytes.
#include <cstdint>
#include <optional>
#include <string>

namespace rollnoise {

// The size in bytes (rounded down), or std::nullopt when `text` is not a positive number with
// one of the units above (case-insensitive, space before the unit optional) or overflows 64 bits.
std::optional<std::uint64_t> parse_byte_size(const std::string& text);

// What parse_byte_size accepts, for messages.
inline constexpr char kByteSizeForms[] = "a size such as \"4 GB\", \"500 MB\" or \"2 GiB\"";

}  // namespace rollnoise
