#pragma once
// Reads the `tabulated` tyre model: a modal receptance table from an HDF5 file
// (modal_table_hdf5.hpp, docs/greens/tabulated_layout.md) instead of a model computed from
// parameters, for tables from another program or a measurement. The keys:
//   model = "tabulated"
//   file = "table.h5"    the table; a relative path is taken from the folder of the file that
//                        sets `file` (the model file)
//   [tread]              to roll: the local compliance the table lacks (rolling_tyre_model.hpp)
// Unknown keys, a missing file and every problem of the file are an InputError naming the file,
// the key or dataset, and what is allowed.
#include "greens/modal_receptance_table.hpp"

namespace rollnoise {

class ConfigTable;

ModalReceptanceTable read_tabulated_tyre(const ConfigTable& tyre);

// The first check of read_tabulated_tyre: a misspelt key is reported as such before anything
// else (a missing key, the file).
void reject_unknown_tabulated_keys(const ConfigTable& tyre);

}  // namespace rollnoise
