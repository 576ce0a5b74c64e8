#include "harness/run_checkpoint.hpp"
#include "harness/run_log.hpp"

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <unistd.h>

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

RunCheckpoint::RunCheckpoint(const RunContext& ctx, const std::string& name)
    : interval_(ctx.checkpoint_interval), quiet_(ctx.quiet), last_(std::chrono::steady_clock::now()) {
    const std::string fingerprint = ctx.params.to_json().dump() + to_string(ctx.scale) + std::to_string(ctx.seed);
    const std::size_t h = std::hash<std::string>{}(fingerprint);
    fs::create_directories(ctx.work_dir);
    file_ = ctx.work_dir / ("run-" + std::to_string(h) + "-" + name + ".h5");
}

bool RunCheckpoint::due() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - last_).count() >= interval_;
}

void RunCheckpoint::save(const std::function<void(const H5Object&)>& fill) {
    const fs::path tmp = file_.string() + ".partial-" + std::to_string(::getpid());
    try {
        {
            const std::lock_guard<std::mutex> lock(h5_mutex());
            const H5File f = H5File::create(tmp.string());
            fill(f);
        }
        fs::rename(tmp, file_);
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
