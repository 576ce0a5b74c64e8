#include "harness/progress.hpp"

#include <cstdio>
#include <unistd.h>

#include "harness/run_log.hpp"

namespace granrepro {

namespace {
thread_local Progress* tl_progress = nullptr;
thread_local long tl_slot = -1;

std::string duration_text(double s) {
    char buf[32];
    if (s < 120) std::snprintf(buf, sizeof buf, "%.0f s", s);
    else if (s < 7200) std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
    else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
    return buf;
}
} // namespace

Progress::Progress(std::string label, long total, bool quiet)
    : label_(std::move(label)), total_(total), on_terminal_(!quiet && isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()), last_log_(start_ - std::chrono::seconds(10)) {
    if (!tl_progress) {
        tl_progress = this;
        tl_slot = -1;
    }
    if (on_terminal_ || run_log().active()) timer_ = std::thread([this] { timer_loop(); });
}

Progress::~Progress() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (timer_.joinable()) timer_.join();
    if (tl_progress == this) tl_progress = nullptr;
    if (elapsed_seconds() >= 1.0) run_log().line("progress: " + line());
    if (printed_) std::fprintf(stderr, "\r\033[K");
}

double Progress::elapsed_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::tick(long n) {
    done_ += n;
    std::lock_guard<std::mutex> lock(mutex_);
    if (run_log().active()) last_log_ = {}; // log at the next timer tick
}

void Progress::done(long slot) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        in_flight_.erase(slot);
    }
    tick();
}

void Progress::engine_time(long slot, double t, double t_end) {
    std::lock_guard<std::mutex> lock(mutex_);
    in_flight_[slot] = {t, t_end};
}

std::string Progress::line() const {
    const double elapsed = elapsed_seconds();
    const long done = done_, total = total_;
    double fraction = double(done);
    std::string engine;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& [slot, te] : in_flight_) {
            if (slot >= 0 && te.second > 0) fraction += std::min(1.0, te.first / te.second);
            char buf[64];
            std::snprintf(buf, sizeof buf, "%st = %.4g of %.4g s", engine.empty() ? "" : ", ", te.first, te.second);
            engine += buf;
        }
    }
    char head[160];
    std::snprintf(head, sizeof head, "[%s] %ld/%ld done", label_.c_str(), done, total);
    std::string s = head;
    if (!engine.empty()) s += "; engine time " + engine;
    s += "; " + duration_text(elapsed) + " elapsed";
    if (fraction > 0 && fraction < double(total)) s += ", ~" + duration_text(elapsed * (double(total) - fraction) / fraction) + " left";
    return s;
}

void Progress::draw(bool to_log) {
    const std::string text = line();
    if (to_log) run_log().line("progress: " + text);
    if (on_terminal_) {
        std::fprintf(stderr, "\r\033[K%s", text.c_str());
        std::fflush(stderr);
        printed_ = true;
    }
}

void Progress::timer_loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
        wake_.wait_for(lock, std::chrono::seconds(1));
        if (stop_) break;
        const auto now = std::chrono::steady_clock::now();
        const bool to_log = run_log().active() && now - last_log_ >= std::chrono::seconds(10);
        if (to_log) last_log_ = now;
        lock.unlock();
        draw(to_log);
        lock.lock();
    }
}

void report_engine_time(double t, double t_end) {
    if (tl_progress) tl_progress->engine_time(tl_slot, t, t_end);
}

ProgressSlot::ProgressSlot(Progress* p, long slot) : prev_(tl_progress), prev_slot_(tl_slot) {
    tl_progress = p;
    tl_slot = slot;
}

ProgressSlot::~ProgressSlot() {
    tl_progress = prev_;
    tl_slot = prev_slot_;
}

} // namespace granrepro
