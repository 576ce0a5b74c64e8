// One name for saving and restoring any engine's state, so that a sampling loop written once
// (harness/sampled_run.hpp) serves ED and DSMC alike.
#pragma once
#include "io/dsmc_state_file.hpp"
#include "io/ed_state_file.hpp"

namespace granrepro {

inline void write_engine_state(const H5Object& g, const EdState& s) { write_ed_state(g, s); }
inline void write_engine_state(const H5Object& g, const DsmcState& s) { write_dsmc_state(g, s); }
inline void read_engine_state(const H5Object& g, EdState& s) { s = read_ed_state(g); }
inline void read_engine_state(const H5Object& g, DsmcState& s) { s = read_dsmc_state(g); }

} // namespace granrepro
