// Progress on stderr for long runs: only when stderr is a terminal, not --quiet, and the run has
// lasted more than two seconds. Thread-safe; sweep workers call tick().
#pragma once
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace granrepro {

class Progress {
public:
    Progress(std::string label, long total, bool quiet);
    ~Progress();
    void tick(long n = 1);
    void set_total(long total) { total_ = total; }

private:
    std::string label_;
    std::atomic<long> done_{0};
    long total_;
    bool enabled_;
    bool printed_ = false;
    std::chrono::steady_clock::time_point start_, last_;
    std::mutex mutex_;
};

} // namespace granrepro
