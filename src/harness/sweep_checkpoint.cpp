#include "harness/sweep_checkpoint.hpp"

#include <cstdio>
#include <utility>

#include "core/input_error.hpp"
#include "core/stable_hash.hpp"
#include "core/untrusted_file.hpp"
#include "harness/run_checkpoint.hpp"
#include "io/staged_directory.hpp"

namespace granrepro {

namespace {
constexpr const char* kPointSchema = "granrepro-sweep-point";
}

SweepCheckpoint::SweepCheckpoint(const RunContext& ctx, const std::string& label, std::string outcome_schema)
    : outcome_schema_(std::move(outcome_schema)), quiet_(ctx.quiet) {
    // The label keeps two sweeps of one experiment apart; empty for the one sweep most have.
    dir_ = ctx.work_dir / ("sweep-" + checkpoint_fingerprint(ctx) + (label.empty() ? "" : "-" + label));
    std::filesystem::create_directories(dir_);
}

std::optional<SweepCheckpoint::Loaded> SweepCheckpoint::load(long point) const {
    const auto file = dir_ / (std::to_string(point) + ".json");
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(file, ec))) return std::nullopt;
    std::string problem;
    try {
        // Untrusted like any file of a results folder: a symlink, a FIFO, an oversized or
        // too deeply nested file is a damaged point, recomputed (the InputError's text says why).
        const nlohmann::json j = parse_untrusted_json(read_untrusted_file(file, kMaxPointFileBytes, "sweep-point file"), file.string());
        if (!j.is_object() || j.value("schema", "") != kPointSchema ||
            j.value("schema_version", 0) < 1 || j.value("schema_version", 0) > 3)
            problem = "not a granrepro-sweep-point v1, v2 or v3 file";
        else if (!j.contains("point") || j["point"] != point)
            problem = "holds another point";
        else if (!j.contains("value") || !j.contains("fnv1a64") || j["fnv1a64"] != hex64(fnv1a64(j["value"].dump())))
            problem = "value does not match its hash";
        else if (!outcome_schema_.empty() && j.value("outcome_schema", "") != outcome_schema_)
            problem = "saved for another layout of the point's outcome (a build with other fields)";
        else {
            Loaded loaded{j["value"], {}};
            if (const auto c = j.find("cost"); c != j.end() && c->is_object()) {
                PointCost& k = loaded.cost;
                auto num = [&](const char* f) { return c->contains(f) && (*c)[f].is_number() ? (*c)[f].get<double>() : -1.0; };
                k.cpu_s = num("cpu_s");
                k.wall_s = num("wall_s");
                k.started_unix = num("started_unix");
                k.part = c->value("part", "");
                k.rank = c->value("rank", 0);
            }
            std::lock_guard<std::mutex> lock(mutex_); // counted once the whole file has been read
            ++resumed_;
            return loaded;
        }
    } catch (const InputError& e) {
        problem = e.what();
        if (problem.starts_with(file.string() + ": ")) problem.erase(0, file.string().size() + 2);
    } catch (const std::exception&) {
        problem = "torn or not JSON";
    }
    if (!quiet_) std::fprintf(stderr, "granrepro: recomputing sweep point %ld: %s: %s\n", point, file.c_str(), problem.c_str());
    return std::nullopt;
}

void SweepCheckpoint::save(long point, const nlohmann::json& value, const PointCost& cost) {
    const nlohmann::json c = {{"cpu_s", cost.cpu_s}, {"wall_s", cost.wall_s}, {"started_unix", cost.started_unix},
                              {"part", cost.part}, {"rank", cost.rank}};
    nlohmann::json j = {{"schema", kPointSchema}, {"schema_version", 3}, {"point", point},
                        {"fnv1a64", hex64(fnv1a64(value.dump()))}, {"value", value}, {"cost", c}};
    if (!outcome_schema_.empty()) j["outcome_schema"] = outcome_schema_;
    std::filesystem::create_directories(dir_); // a shard's commit may have removed an empty folder
    write_file_atomically(dir_ / (std::to_string(point) + ".json"), j.dump());
}

} // namespace granrepro
