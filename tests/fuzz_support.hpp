#pragma once
// What the fuzz tests of the input readers share: reading a seed file, showing an input that
// broke a reader, classifying what a reader did with an input (returned, threw an InputError
// naming the source, or did anything else), and drawing random text and mutations.
//
// Everything here draws from the caller's std::mt19937_64 in a fixed order, so that a fuzz
// test built on it sees the same inputs on every run.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace rollnoise::fuzz {

// The whole file, byte for byte ("" if it cannot be read).
inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The regular files in `dir`, sorted (directory order is unspecified).
inline std::vector<std::filesystem::path> sorted_files(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The first `limit` bytes in hex ("0a 41 "), for failure messages.
inline std::string hex_dump(const std::string& bytes, std::size_t limit = 300) {
  std::string out;
  char buffer[4];
  for (std::size_t i = 0; i < std::min(bytes.size(), limit); ++i) {
    std::snprintf(buffer, sizeof buffer, "%02x ", static_cast<unsigned char>(bytes[i]));
    out += buffer;
  }
  return out;
}

// What a reader did with an input.
enum class Outcome {
  accepted,     // returned a result
  input_error,  // threw an InputError
  other,        // threw anything else: always a defect
};

// Runs `read`, which reads an input and checks what it returns, giving "" when the result
// keeps its invariants and else a description of the violation; classifies the outcome. On
// return `problem` holds the violation, an InputError whose message does not start with
// `source`, or the exception that was not an InputError; it is untouched when a reader that
// throws an InputError names the source.
template <class Read>
Outcome classify(const std::string& source, Read&& read, std::string& problem) {
  try {
    problem = std::forward<Read>(read)();
    return Outcome::accepted;
  } catch (const InputError& e) {
    if (std::string(e.what()).rfind(source, 0) != 0) problem = std::string("message without the source: ") + e.what();
    return Outcome::input_error;
  } catch (const std::exception& e) {
    problem = std::string("unexpected exception: ") + e.what();
    return Outcome::other;
  } catch (...) {
    problem = "unexpected non-standard exception";
    return Outcome::other;
  }
}

// A random byte: 7 times in 10 one of `alphabet` (the bytes the format has to think about),
// else any byte; always any byte when `alphabet` is empty.
inline char random_byte(std::mt19937_64& rng, std::string_view alphabet) {
  if (!alphabet.empty() && rng() % 10 < 7) return alphabet[rng() % alphabet.size()];
  return static_cast<char>(static_cast<unsigned char>(rng() % 256));
}

// 0 to `max_length` random bytes (random_byte over `alphabet`).
inline std::string random_text(std::mt19937_64& rng, std::string_view alphabet, std::size_t max_length) {
  std::string text;
  const std::size_t length = rng() % (max_length + 1);
  for (std::size_t j = 0; j < length; ++j) text += random_byte(rng, alphabet);
  return text;
}

// How a format's inputs are mutated: `count` mutations, each at a random place `at`, of one of
// these kinds: overwrite a byte, insert a byte (both random_byte over `alphabet`), delete a run
// of 1 to `max_erase` bytes, duplicate a chunk of 1 to `max_chunk` bytes somewhere, insert one
// of `tokens`, the format's own mutation `extra` if it has one, and truncate at `at` (one time
// in `truncate_one_in`: truncation ends every other change).
struct Mutations {
  std::string alphabet = {};
  std::vector<std::string> tokens = {};
  std::size_t max_erase = 8;
  std::size_t max_chunk = 16;
  unsigned truncate_one_in = 1;
  std::function<void(std::string& text, std::size_t at, std::mt19937_64& rng)> extra = {};

  std::string apply(std::string text, std::mt19937_64& rng, int count) const {
    const std::uint64_t kinds = extra ? 7 : 6;
    for (int i = 0; i < count; ++i) {
      const std::size_t at = text.empty() ? 0 : rng() % (text.size() + 1);
      const std::uint64_t kind = rng() % kinds;
      if (kind == 0) {  // overwrite a byte
        if (at < text.size()) text[at] = random_byte(rng, alphabet);
      } else if (kind == 1) {  // insert a byte
        text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), random_byte(rng, alphabet));
      } else if (kind == 2) {  // delete a run
        if (at < text.size()) text.erase(at, 1 + rng() % max_erase);
      } else if (kind == 3) {  // duplicate a chunk somewhere
        if (at < text.size()) {
          const std::string chunk = text.substr(at, 1 + rng() % max_chunk);
          text.insert(rng() % (text.size() + 1), chunk);
        }
      } else if (kind == 4) {  // insert a token
        text.insert(at, tokens[rng() % tokens.size()]);
      } else if (kind == 5 && extra) {  // the format's own
        extra(text, at, rng);
      } else {  // truncate
        if (truncate_one_in <= 1 || rng() % truncate_one_in == 0) text.resize(at);
      }
    }
    return text;
  }
};

}  // namespace rollnoise::fuzz
