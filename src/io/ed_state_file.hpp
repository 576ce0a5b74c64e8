// EdState <-> HDF5 group (schema "granrepro-ed-state", version 2; version 1 stored the walls as
// per-field arrays and the configuration flat): the fields EdState::fields() lists, walked by
// io/h5_fields.hpp bit for bit, so that an engine restored from the file continues exactly as
// the one that wrote it (issue 3). Layout: docs/schema.md.
#pragma once
#include "engines/ed/ed_state.hpp"
#include "io/h5_file.hpp"

namespace granrepro {

inline constexpr const char* kEdStateSchema = "granrepro-ed-state";
inline constexpr long kEdStateSchemaVersion = 2;

void write_ed_state(const H5Object& group, const EdState& s);
// Throws std::runtime_error when the group is not an ED state of this schema version.
EdState read_ed_state(const H5Object& group);

} // namespace granrepro
