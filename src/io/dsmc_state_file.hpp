// DsmcState <-> HDF5 group (schema "granrepro-dsmc-state", version 2; version 1 lacked the
// partner rules, the time-step bound and the last partners): every field of the state,
// its DsmcConfig and the raw generator state, bit for bit, so that a restored engine continues
// exactly as the one that wrote it.
#pragma once
#include "engines/dsmc/dsmc_state.hpp"
#include "io/h5_file.hpp"

namespace granrepro {

inline constexpr const char* kDsmcStateSchema = "granrepro-dsmc-state";
inline constexpr long kDsmcStateSchemaVersion = 2;

void write_dsmc_state(const H5Object& group, const DsmcState& s);
// Throws std::runtime_error when the group is not a DSMC state of this schema version.
DsmcState read_dsmc_state(const H5Object& group);

} // namespace granrepro
