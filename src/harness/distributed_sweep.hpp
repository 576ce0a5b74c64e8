// The one way experiments spread independent sweep points over threads, MPI ranks and job-array
// shards, with per-point checkpoints so that a killed job resumes where it stopped.
//
// compute(i) runs point i and returns its result as JSON (the checkpoint's format); every result
// the experiment sees has been through that JSON, whether it was computed by this thread, another
// rank or an earlier run, so the results are bit-identical however the points were spread. A
// point's random stream must depend on its index and the seed only (never on rank, thread or the
// number of points computed).
//
// `order` lists every point index once, most expensive first: threads and ranks take the points
// in this order as they become free (rank 0 hands them out), and shard I of N takes every N-th.
// Modes (ctx.sweep):
//   All    - compute what the checkpoint lacks; with ranks > 1, rank 0 hands points to the other
//            ranks (and computes too) and alone returns; the other ranks throw SweepServed;
//   Shard  - compute the missing points of shard I, then throw ShardFinished;
//   Gather - compute nothing; an InputError names the missing points ("N points missing: ...").
// Each computed point's cost (CPU seconds of the thread that computed it, on whichever rank) goes
// into run.log as "sweep <label>: point <i> cost <s> CPU s (rank <r>)": `granrepro bench sweep`
// projects rank counts from these lines.
#pragma once
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/experiment.hpp"

namespace granrepro {

struct SweepResult {
    std::vector<nlohmann::json> points; // indexed by point
    long resumed = 0;                   // points loaded from the checkpoint instead of computed
    std::vector<double> cpu_seconds;    // each computed point's cost [CPU s]; -1 for resumed points
};

// Thrown on ranks > 0 once rank 0 has no more points for them: the rest is rank 0's job.
struct SweepServed : std::exception {
    const char* what() const noexcept override { return "sweep points served to rank 0"; }
};

// Thrown after a --points shard: its points are in the checkpoint; `gather` writes the results.
struct ShardFinished : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Saved: each finished point is saved (SweepCheckpoint) and a rerun resumes from them. None: for
// sweeps of millisecond points (brake-failure, emergency-brake), where fsynced files would cost
// more than recomputing; only for experiments not marked distributed (no shards to gather).
enum class PointFiles { Saved, None };

// outcome_schema: the hash of the points' JSON layout, recorded in each point file; a saved point
// of another layout is recomputed (empty: not checked). harness/protocol.hpp passes it.
SweepResult distributed_sweep(const RunContext& ctx, const std::string& label, const std::vector<long>& order,
                              const std::function<nlohmann::json(long)>& compute, PointFiles files = PointFiles::Saved,
                              const std::string& outcome_schema = "");

} // namespace granrepro
