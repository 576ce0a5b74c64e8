// Resumable sweeps: each finished sweep point is saved as JSON in the run's work directory
// (OUT/.<experiment>.checkpoint/), keyed by a fingerprint of the resolved parameters, scale and
// seed. Re-running the same command after an interruption loads the finished points instead of
// recomputing them; any change of inputs changes the fingerprint and starts afresh. The runner
// deletes the directory once the results are written. Each point is its own file, written through
// a rename, so concurrent --points shards and MPI ranks never need a lock to share one --out.
#pragma once
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "harness/experiment.hpp"

namespace granrepro {

class SweepCheckpoint {
public:
    // `label` tells apart the sweeps of one run (an experiment may sweep twice).
    explicit SweepCheckpoint(const RunContext& ctx, const std::string& label = "");
    std::optional<nlohmann::json> load(long point) const;
    void save(long point, const nlohmann::json& value);
    long resumed() const { return resumed_; }

private:
    std::filesystem::path dir_;
    mutable long resumed_ = 0;
    mutable std::mutex mutex_;
};

} // namespace granrepro
