// run.log in a run's output folder: the command, the resolved parameters, progress lines,
// warnings and the wall times, each line stamped with the seconds since the run started. One
// log per process (a run is one experiment at a time); a no-op while none is open.
#pragma once
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>

namespace granrepro {

class RunLog {
public:
    void open(const std::filesystem::path& file);
    void close();
    bool active() const { return active_; }
    void line(const std::string& text);

private:
    std::mutex mutex_;
    std::ofstream out_;
    std::atomic<bool> active_{false};
    std::chrono::steady_clock::time_point start_;
};

RunLog& run_log();

// A warning: one line on stderr (prefixed "granrepro: ") and in run.log.
void warn(const std::string& text);

} // namespace granrepro
