// EdState <-> HDF5 group (schema "granrepro-ed-state", version 1): every field of the state and
// of its EdConfig, stored bit for bit, so that an engine restored from the file continues exactly
// as the one that wrote it (issue 3: checkpoint/restart to HDF5, bit-identical resumption).
// Scalars are attributes; per-particle and per-wall data are 1-D datasets in native types.
#pragma once
#include "engines/ed/ed_state.hpp"
#include "io/h5_file.hpp"

namespace granrepro {

inline constexpr const char* kEdStateSchema = "granrepro-ed-state";
inline constexpr long kEdStateSchemaVersion = 1;

void write_ed_state(const H5Object& group, const EdState& s);
// Throws std::runtime_error when the group is not an ED state of this schema version.
EdState read_ed_state(const H5Object& group);

} // namespace granrepro
