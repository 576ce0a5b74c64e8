#include "io/dsmc_state_file.hpp"

#include "io/h5_fields.hpp"
#include <stdexcept>

namespace granrepro {

void write_dsmc_state(const H5Object& g, const DsmcState& s) {
    g.stamp_schema(kDsmcStateSchema, kDsmcStateSchemaVersion);
    write_fields(g, s);
}

DsmcState read_dsmc_state(const H5Object& g) {
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
