// EdState <-> HDF5 group (schema "granrepro-ed-state", version 2; version 1 stored the walls as
// per-field arrays and the configuration flat): the fields EdState::fields() lists, walked by
// io/h5_fields.hpp bit for bit, so that an engine restored from the file continues exactly as
// the one that wrote it (issue 3). Layout: docs/schema.md.
#pragma once
#include "engines/ed/ed_state.hpp"
#include "io/h5_fields.hpp"

namespace granrepro {

inline constexpr const char* kEdStateSchema = "granrepro-ed-state";
inline constexpr long kEdStateSchemaVersion = 2;

inline void write_ed_state(const H5Object& g, const EdState& s) {
    g.stamp_schema(kEdStateSchema, kEdStateSchemaVersion);
    write_fields(g, s);
}

// Throws std::runtime_error when the group is not an ED state of this schema version.
inline EdState read_ed_state(const H5Object& g) {
    g.require_schema(kEdStateSchema, kEdStateSchemaVersion);
    EdState s;
    read_fields(g, s);
    return s;
}

} // namespace granrepro
