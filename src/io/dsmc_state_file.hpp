// DsmcState <-> HDF5 group (schema "granrepro-dsmc-state", version 3; version 2 stored the
// configuration flat, version 1 lacked the partner rules, the time-step bound and the last
// partners): the fields DsmcState::fields() lists, raw generator state included, walked by
// io/h5_fields.hpp bit for bit, so that a restored engine continues exactly as the one that
// wrote it. Layout: docs/schema.md.
#pragma once
#include "engines/dsmc/dsmc_state.hpp"
#include "io/h5_fields.hpp"

namespace granrepro {

inline constexpr const char* kDsmcStateSchema = "granrepro-dsmc-state";
inline constexpr long kDsmcStateSchemaVersion = 3;

inline void write_dsmc_state(const H5Object& g, const DsmcState& s) {
    g.stamp_schema(kDsmcStateSchema, kDsmcStateSchemaVersion);
    write_fields(g, s);
}

// Throws std::runtime_error when the group is not a DSMC state of this schema version, or names
// a choice (free_volume, partner) that does not exist.
inline DsmcState read_dsmc_state(const H5Object& g) {
    g.require_schema(kDsmcStateSchema, kDsmcStateSchemaVersion);
    DsmcState s;
    read_fields(g, s);
    // The walk reads any integer into an enum; only the named choices are states.
    const DsmcConfig& c = s.config;
    if (c.free_volume > DsmcFreeVolume::mean) throw std::runtime_error("DSMC state: unknown free_volume mode");
    if (c.partner > DsmcPartner::nearest) throw std::runtime_error("DSMC state: unknown partner rule");
    if (c.free_volume_block < 1) throw std::runtime_error("DSMC state: free_volume_block must be >= 1");
    return s;
}

} // namespace granrepro
