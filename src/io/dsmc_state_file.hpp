// DsmcState <-> HDF5 group (schema "granrepro-dsmc-state", version 3; version 2 stored the
// configuration flat, version 1 lacked the partner rules, the time-step bound and the last
// partners): the fields DsmcState::fields() lists, raw generator state included, walked by
// io/h5_fields.hpp bit for bit, so that a restored engine continues exactly as the one that
// wrote it. Layout: docs/schema.md.
#pragma once
#include "engines/dsmc/dsmc_state.hpp"
#include "io/h5_file.hpp"

namespace granrepro {

inline constexpr const char* kDsmcStateSchema = "granrepro-dsmc-state";
inline constexpr long kDsmcStateSchemaVersion = 3;

void write_dsmc_state(const H5Object& group, const DsmcState& s);
// Throws std::runtime_error when the group is not a DSMC state of this schema version, or names
// a choice (free_volume, partner) that does not exist.
DsmcState read_dsmc_state(const H5Object& group);

} // namespace granrepro
