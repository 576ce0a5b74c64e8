// Mid-run checkpoints of single long runs (the counterpart of SweepCheckpoint, which saves whole
// sweep points). An experiment offers a checkpoint at its natural pause points (sample times):
// if at least ctx.checkpoint_interval wall seconds passed since the last save, it writes its
// engine state(s) and everything its observables accumulated into one HDF5 file,
// OUT/.<experiment>.checkpoint/run-<fingerprint>-<name>.h5, atomically (temporary file + rename).
// Re-running the same command loads that file and continues from it; since engine states restore
// bit for bit, the result equals an uninterrupted run's. The fingerprint covers the resolved
// parameters, scale and seed, so changed inputs never resume a stale file. The runner removes
// the directory once the results are written.
// Every write is checked and fsynced before the rename: a file that could not be written whole
// (full disk) throws WriteError and is never renamed into place. After a SIGINT/SIGTERM, due()
// is true at once and save() throws Interrupted once the final checkpoint is on disk (see
// core/interrupt.hpp).
// Testing hook: with GRANREPRO_INTERRUPT_AFTER_CHECKPOINTS=k in the environment, save() throws
// after its k-th save, as if the run had been killed there (tests resume it and compare).
#pragma once
#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "harness/experiment.hpp"
#include "io/h5_file.hpp"

namespace granrepro {

// The fingerprint of a run's inputs: FNV-1a 64 (core/stable_hash.hpp) of the canonical JSON of the
// resolved parameters, the scale and the seed, as 16 hex digits. Stable across toolchains, unlike
// std::hash. Checkpoint file and folder names carry it.
std::string checkpoint_fingerprint(const RunContext& ctx);

// The fingerprint of one sweep point's inputs, "fnv1a64:<16 hex digits>": FNV-1a 64 of the
// canonical JSON {"parameters": {name: value, ...} (resolved, as read; units and source texts
// left out), "scale", "seed", "sweep": label, "point": index, "points": count}. A point's own
// inputs (its k_N, e_N, random stream, ...) are a function of these by construction
// (distributed_sweep.hpp), so equal fingerprints mean equal inputs to the same code.
// without: parameters left out (verify's parameters added after the results were made).
std::string sweep_point_inputs_hash(const RunContext& ctx, const std::string& label, long index, long count,
                                    const std::vector<std::string>& without = {});

class RunCheckpoint {
public:
    // name distinguishes several runs of one experiment (e.g. "ed" and "dsmc").
    RunCheckpoint(const RunContext& ctx, const std::string& name);

    // True when the interval since the last save (or since construction) has passed.
    bool due() const;
    // Writes the file through fill(root group); resets the interval clock. Call it at a point
    // from which load() can continue, i.e. with everything up to here in the file.
    void save(const std::function<void(const H5Object&)>& fill);
    // If a checkpoint file exists, calls read(root group) and returns true. A file that cannot be
    // read (torn, other schema) is ignored with a warning on stderr and false is returned, so the
    // run starts afresh.
    bool load(const std::function<void(const H5Object&)>& read) const;
    const std::filesystem::path& path() const { return file_; }
    long saves() const { return saves_; }

private:
    std::filesystem::path file_;
    double interval_ = 60.0;
    bool quiet_ = false;
    long saves_ = 0;
    std::chrono::steady_clock::time_point last_;
};

} // namespace granrepro
