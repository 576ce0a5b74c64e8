// Progress of long runs. On stderr, only when stderr is a terminal and not --quiet: one line,
// redrawn every second by a timer thread (not only when a sweep point ends), with the points
// done, the engine time of the runs in flight and an estimate of the time left. Into the run's
// run.log (RunLog), whatever the terminal: a line after 1 s, then every 10 s and whenever a point
// ends, and a last one when the run has lasted a second or more.
// Thread-safe; sweep workers call done(slot), engines' loops report_engine_time().
#pragma once
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <string>
#include <thread>

namespace granrepro {

class Progress {
public:
    Progress(std::string label, long total, bool quiet);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void tick(long n = 1);                       // n units done
    void done(long slot);                        // sweep point `slot` done (one unit)
    // Engine time t of t_end reached by sweep point `slot` (which counts as t / t_end of a unit
    // towards the estimate), or, with slot < 0, by a run whose units are ticked separately (shown,
    // not counted).
    void engine_time(long slot, double t, double t_end);

    std::string line() const; // the current progress line (without terminal control codes)
    double elapsed_seconds() const;

private:
    void timer_loop();
    void draw(bool to_log);

    std::string label_;
    std::atomic<long> done_{0};
    std::atomic<long> total_;
    bool on_terminal_;
    const std::chrono::steady_clock::time_point start_;
    mutable std::mutex mutex_;
    std::map<long, std::pair<double, double>> in_flight_; // slot -> (t, t_end)
    bool printed_ = false, stop_ = false;
    std::condition_variable wake_;
    std::chrono::steady_clock::time_point last_log_;
    std::thread timer_;
};

// The engine time of the current sweep point, to the Progress of the sweep running it (a no-op
// outside a sweep): the engines' loops of the long single runs call this.
void report_engine_time(double t, double t_end);

// Sets, for this thread, the Progress and sweep slot that report_engine_time() reports to, and
// restores the previous ones when it goes out of scope (distributed_sweep uses it per point).
class ProgressSlot {
public:
    ProgressSlot(Progress* p, long slot);
    ~ProgressSlot();
    ProgressSlot(const ProgressSlot&) = delete;
    ProgressSlot& operator=(const ProgressSlot&) = delete;

private:
    Progress* prev_;
    long prev_slot_;
};

} // namespace granrepro
