// Resumable sweeps: each finished sweep point is saved as JSON in the run's work directory
// (OUT/.<experiment>.checkpoint/), keyed by a fingerprint of the resolved parameters, scale and
// seed. Re-running the same command after an interruption loads the finished points instead of
// recomputing them; any change of inputs changes the fingerprint and starts afresh. The runner
// deletes the directory once the results are written.
// A point file is {"schema": "granrepro-sweep-point", "schema_version": 3, "point": i,
// "fnv1a64": <FNV-1a 64 of value.dump()>, "outcome_schema": <hash of the outcome's layout>,
// "value": ..., "cost": {cpu_s, wall_s, started_unix, part, rank}}; version 1 files (without
// "cost") and 2 (without "outcome_schema") are read too, their cost unknown in version 1.
// Written durably (fsync, rename). A file that is torn, not JSON, another point's, whose value
// does not match its hash (`{}`, garbage) or that was saved for another outcome layout (a build
// whose outcome struct had other fields; a file without the layout when the sweep states one) is
// recomputed with a note on stderr, never trusted and never a permanent failure.
// Each point is its own file, written through a rename, so concurrent --points shards and MPI
// ranks never need a lock to share one --out.
#pragma once
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "data/sweep_points.hpp"
#include "harness/experiment.hpp"

namespace granrepro {

class SweepCheckpoint {
public:
    // `label` tells apart the sweeps of one run (an experiment may sweep twice). outcome_schema:
    // the hash of the points' layout (json_fields_schema), or empty when the sweep states none.
    explicit SweepCheckpoint(const RunContext& ctx, const std::string& label = "", std::string outcome_schema = "");
    struct Loaded {
        nlohmann::json value;
        PointCost cost; // as recorded when the point was computed (unknown: -1)
    };
    std::optional<Loaded> load(long point) const;
    void save(long point, const nlohmann::json& value, const PointCost& cost);
    long resumed() const { return resumed_; }

private:
    std::filesystem::path dir_;
    std::string outcome_schema_;
    bool quiet_ = false;
    mutable long resumed_ = 0;
    mutable std::mutex mutex_;
};

} // namespace granrepro
