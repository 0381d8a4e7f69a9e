#include "core/cache_folder.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <stdexcept>
#include <system_error>

namespace rollnoise {
namespace fs = std::filesystem;

std::optional<fs::path> default_cache_directory() {
  const auto variable = [](const char* name) -> std::string {
    const char* value = std::getenv(name);
    return value ? std::string(value) : std::string();
  };
  if (const std::string own = variable("ROLLNOISE_CACHE"); !own.empty()) return fs::path(own);
  if (const fs::path xdg = variable("XDG_CACHE_HOME"); xdg.is_absolute()) return xdg / "rollnoise";
  if (const std::string home = variable("HOME"); !home.empty()) return fs::path(home) / ".cache" / "rollnoise";
  return std::nullopt;
}

bool is_cache_key(const std::string& key) {
  return !key.empty() && key.front() != '.' &&
         key.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.") == std::string::npos;
}

TemporaryFile::TemporaryFile(const fs::path& target) {
  std::random_device device;
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about "." + string.
  std::string name(1, '.');
  name += target.filename().string();
  name += ".tmp";
  name += std::to_string(device());
  name += std::to_string(device());
  path_ = target.parent_path() / name;
}

TemporaryFile::~TemporaryFile() {
  std::error_code ec;
  if (!kept_) fs::remove(path_, ec);
}

void TemporaryFile::rename_to(const fs::path& target) {
  std::error_code ec;
  fs::rename(path_, target, ec);
  if (ec) throw std::runtime_error("cannot rename " + path_.string() + " to " + target.string() + ": " + ec.message());
  kept_ = true;
}

bool is_temporary_cache_file(const std::string& file_name) {
  return file_name.size() > 1 && file_name.front() == '.' && file_name.find(".tmp") != std::string::npos;
}

std::string cache_entry_kind(const fs::path& file) {
  const std::string name = file.filename().string();
  if (is_temporary_cache_file(name)) return "unfinished write";
  if (!is_cache_key(file.stem().string())) return {};
  if (name.starts_with("radiation-") && file.extension() == ".h5") return "radiation";
  if (name.starts_with("two_layer-") && file.extension() == ".h5") return "two_layer table";
  if (file.extension() == ".fits") return "mode fits";
  if (name.starts_with("contact-laws-") && file.extension() == ".h5") return "contact laws";
  return {};
}

std::string cache_folder_problem(const fs::path& directory) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) return "cannot create it: " + ec.message();
  if (!fs::is_directory(directory, ec)) return "it is not a folder";
  // Permissions alone do not tell (root ignores them, a read-only mount does not show in
  // them): try to create a file.
  const TemporaryFile probe(directory / "write-probe");
  std::ofstream out(probe.path(), std::ios::binary);
  out << "probe";
  out.close();
  if (!out) return "cannot create a file in it";
  return {};
}

std::optional<fs::path> usable_cache_folder(const fs::path& requested, bool disabled) {
  if (disabled) return std::nullopt;
  std::optional<fs::path> folder = requested.empty() ? default_cache_directory() : std::optional<fs::path>(requested);
  if (!folder) return std::nullopt;
  if (const std::string problem = cache_folder_problem(*folder); !problem.empty()) {
    std::fprintf(stderr, "rollnoise: warning: the cache folder %s cannot be written (%s): running without the cache\n",
                 folder->string().c_str(), problem.c_str());
    return std::nullopt;
  }
  return folder;
}

}  // namespace rollnoise
