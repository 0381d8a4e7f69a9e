#pragma once
// FNV-1a, 64 bits (Fowler–Noll–Vo): the digest of the caches' keys and of their files' contents
// (greens/modal_table_cache, greens/fitted_modes_cache). Numbers go in as their little-endian
// bytes, so a digest does not depend on the machine's byte order. Not a cryptographic hash: it
// tells apart inputs, it does not defend against forged ones.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace rollnoise {

class FnvDigest {
 public:
  void byte(unsigned char b) {
    hash_ ^= b;
    hash_ *= 0x100000001b3ULL;
  }
  void bytes(const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) byte(static_cast<unsigned char>(data[i]));
  }
  void unsigned_integer(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) byte(static_cast<unsigned char>(v >> (8 * i)));
  }
  void integer(std::int64_t v) { unsigned_integer(static_cast<std::uint64_t>(v)); }
  void real(double v) { unsigned_integer(std::bit_cast<std::uint64_t>(v)); }
  // Length first, so that consecutive strings cannot run into each other.
  void text(std::string_view s) {
    unsigned_integer(s.size());
    bytes(s.data(), s.size());
  }
  // FNV-1a over 8-byte little-endian words (the last one zero-padded), then the length: one
  // mixing step per word instead of per byte, 8 times faster, for the caches' checksums of
  // large files (radiation_cache.cpp), where it tells damage apart. Each step also folds the
  // high half into the low one (h ^= h >> 32, invertible like the multiply): the multiply alone
  // carries a change only upwards, so flips of the top bit of two words would cancel.
  void words(const char* data, std::size_t n) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
      std::uint64_t w = 0;
      for (int b = 0; b < 8; ++b) w |= static_cast<std::uint64_t>(static_cast<unsigned char>(data[i + static_cast<std::size_t>(b)])) << (8 * b);
      mix_word(w);
    }
    std::uint64_t w = 0;
    for (int b = 0; i < n; ++i, ++b) w |= static_cast<std::uint64_t>(static_cast<unsigned char>(data[i])) << (8 * b);
    mix_word(w);
    unsigned_integer(n);
  }
  std::uint64_t value() const noexcept { return hash_; }
  // 16 lower-case hex digits.
  std::string hex() const {
    static constexpr char digits[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int i = 0; i < 16; ++i) out[static_cast<std::size_t>(15 - i)] = digits[(hash_ >> (4 * i)) & 0xf];
    return out;
  }

 private:
  void mix_word(std::uint64_t w) {
    hash_ ^= w;
    hash_ *= 0x100000001b3ULL;
    hash_ ^= hash_ >> 32;
  }
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace rollnoise
