#include "harness/run_checkpoint.hpp"

#include "harness/run_log.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <unistd.h>

#include "core/interrupt.hpp"
#include "core/stable_hash.hpp"
#include "io/durable_file.hpp"
#include "io/write_error.hpp"

namespace granrepro {

namespace fs = std::filesystem;

namespace {
// Runs of one process (e.g. cooling's ED and DSMC on two threads) may save at the same time; the
// HDF5 C library is only safe for that when built thread-safe, which we do not rely on.
std::mutex& h5_mutex() {
    static std::mutex m;
    return m;
}
} // namespace

std::string checkpoint_fingerprint(const RunContext& ctx) {
    const nlohmann::json j = {{"parameters", ctx.params.to_json()}, {"scale", to_string(ctx.scale)}, {"seed", ctx.seed}};
    return hex64(fnv1a64(j.dump())); // nlohmann::json keeps object keys sorted: canonical text
}

std::string sweep_point_inputs_hash(const RunContext& ctx, const std::string& label, long index, long count,
                                    const std::vector<std::string>& without) {
    nlohmann::json values = nlohmann::json::object();
    const nlohmann::json all = ctx.params.to_json();
    for (auto it = all.begin(); it != all.end(); ++it)
        if (std::find(without.begin(), without.end(), it.key()) == without.end()) values[it.key()] = it.value()["value"];
    const nlohmann::json j = {{"parameters", values}, {"scale", to_string(ctx.scale)}, {"seed", ctx.seed},
                              {"sweep", label}, {"point", index}, {"points", count}};
    return "fnv1a64:" + hex64(fnv1a64(j.dump()));
}

RunCheckpoint::RunCheckpoint(const RunContext& ctx, const std::string& name)
    : interval_(ctx.checkpoint_interval), quiet_(ctx.quiet), last_(std::chrono::steady_clock::now()) {
    fs::create_directories(ctx.work_dir);
    file_ = ctx.work_dir / ("run-" + checkpoint_fingerprint(ctx) + "-" + name + ".h5");
}

bool RunCheckpoint::due() const {
    return interrupt_requested() ||
           std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count() >= interval_;
}

void RunCheckpoint::save(const std::function<void(const H5Object&)>& fill) {
    const fs::path tmp = file_.string() + ".partial-" + std::to_string(::getpid());
    std::error_code gone;
    fs::remove(tmp, gone); // HDF5 creates it by name: a link planted there goes, never its target
    try {
        {
            const std::lock_guard<std::mutex> lock(h5_mutex());
            H5File f = H5File::create(tmp.string());
            fill(f);
            f.close();
        }
        fsync_path(tmp);
        if (::rename(tmp.c_str(), file_.c_str()) != 0) throw WriteError(file_.string(), errno_text(errno));
        fsync_path(file_.parent_path());
    } catch (const WriteError& e) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw WriteError(file_.string(), e.reason()); // name the checkpoint, not its temporary
    } catch (...) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw;
    }
    ++saves_;
    last_ = std::chrono::steady_clock::now();
    if (const char* k = std::getenv("GRANREPRO_INTERRUPT_AFTER_CHECKPOINTS"); k && std::atol(k) == saves_)
        throw std::runtime_error("interrupted after checkpoint " + std::to_string(saves_) + " (" + file_.string() +
                                 ") as GRANREPRO_INTERRUPT_AFTER_CHECKPOINTS asks");
    throw_if_interrupted("; final checkpoint written");
}

bool RunCheckpoint::load(const std::function<void(const H5Object&)>& read) const {
    std::error_code ec;
    if (!fs::exists(file_, ec)) return false;
    try {
        const std::lock_guard<std::mutex> lock(h5_mutex());
        const H5File f = H5File::open(file_.string());
        read(f);
    } catch (const std::exception& e) {
        warn("ignoring unreadable checkpoint " + file_.string() + " (" + e.what() + "); starting afresh");
        return false;
    }
    if (!quiet_) std::fprintf(stderr, "granrepro: resuming from checkpoint %s\n", file_.c_str());
    run_log().line("resuming from checkpoint " + file_.string());
    return true;
}

} // namespace granrepro
