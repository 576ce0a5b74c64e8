// Resumable sweeps: each finished sweep point is saved as JSON in the run's work directory
// (OUT/.<experiment>.checkpoint/), keyed by a fingerprint of the resolved parameters, scale and
// seed. Re-running the same command after an interruption loads the finished points instead of
// recomputing them; any change of inputs changes the fingerprint and starts afresh. The runner
// deletes the directory once the results are written.
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
    explicit SweepCheckpoint(const RunContext& ctx);
    std::optional<nlohmann::json> load(long point) const;
    void save(long point, const nlohmann::json& value);
    long resumed() const { return resumed_; }

private:
    std::filesystem::path dir_;
    mutable long resumed_ = 0;
    mutable std::mutex mutex_;
};

} // namespace granrepro
