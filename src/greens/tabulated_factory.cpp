#include "greens/tabulated_factory.hpp"

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "core/config_table.hpp"
#include "greens/modal_table_hdf5.hpp"

namespace rollnoise {

void reject_unknown_tabulated_keys(const ConfigTable& tyre) {
  // [tyre.tread]: the local compliance a rolling tabulated tyre adds (rolling_tyre_model.hpp).
  for (const std::string_view key : std::array<std::string_view, 4>{"model", "file", "pattern", "tread"}) tyre.contains(key);
  tyre.reject_unknown_keys();
}

ModalReceptanceTable read_tabulated_tyre(const ConfigTable& tyre) {
  namespace fs = std::filesystem;
  // Unknown keys first: a misspelt key is then reported as such, not as a missing one.
  reject_unknown_tabulated_keys(tyre);
  tyre.choice("model", {"tabulated"});
  if (!tyre.contains("file")) tyre.fail("file", "is required: the HDF5 file of the modal receptance table");
  const std::string name = tyre.text("file");
  if (name.empty()) tyre.fail("file", "must name an HDF5 file (the modal receptance table)");
  // Relative to the file that names it, not to the current folder: a model file and its table
  // move together.
  const fs::path named(name);
  const fs::path folder = fs::path(tyre.source_of("file")).parent_path();
  const fs::path path = named.is_absolute() ? named : folder / named;
  // Listed in the summary when ".." or a symlink takes it outside the model file's folder.
  tyre.note_referenced_file(
      "file", ReferencedFile{path, named.is_absolute() ? fs::path() : folder.empty() ? fs::path(".") : folder});
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    tyre.fail("file", "no such file: " + path.string() + " (a relative path is taken from the model file's folder)");
  }
  return read_modal_table(path);
}

}  // namespace rollnoise
