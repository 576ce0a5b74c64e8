#include "harness/sweep_checkpoint.hpp"

#include <fstream>
#include <functional>

#include "io/staged_directory.hpp"

namespace granrepro {

SweepCheckpoint::SweepCheckpoint(const RunContext& ctx, const std::string& label) {
    const std::string fingerprint = ctx.params.to_json().dump() + to_string(ctx.scale) + std::to_string(ctx.seed) + label;
    const std::size_t h = std::hash<std::string>{}(fingerprint);
    dir_ = ctx.work_dir / ("sweep-" + std::to_string(h));
    std::filesystem::create_directories(dir_);
}

std::optional<nlohmann::json> SweepCheckpoint::load(long point) const {
    const auto file = dir_ / (std::to_string(point) + ".json");
    std::ifstream in(file);
    if (!in) return std::nullopt;
    try {
        nlohmann::json j = nlohmann::json::parse(in);
        std::lock_guard<std::mutex> lock(mutex_);
        ++resumed_;
        return j;
    } catch (const std::exception&) {
        return std::nullopt; // a torn file is recomputed
    }
}

void SweepCheckpoint::save(long point, const nlohmann::json& value) {
    write_file_atomically(dir_ / (std::to_string(point) + ".json"), value.dump());
}

} // namespace granrepro
