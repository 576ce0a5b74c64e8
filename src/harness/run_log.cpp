#include "harness/run_log.hpp"

#include <cstdio>

namespace granrepro {

void RunLog::open(const std::filesystem::path& file) {
    std::lock_guard<std::mutex> lock(mutex_);
    out_ = std::ofstream(file);
    start_ = std::chrono::steady_clock::now();
    active_ = bool(out_);
}

void RunLog::close() {
    std::lock_guard<std::mutex> lock(mutex_);
    active_ = false;
    out_.close();
}

void RunLog::line(const std::string& text) {
    if (!active_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (!active_) return;
    char stamp[32];
    std::snprintf(stamp, sizeof stamp, "[%9.1f s] ",
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    out_ << stamp << text << '\n';
    out_.flush();
}

RunLog& run_log() {
    static RunLog log;
    return log;
}

void warn(const std::string& text) {
    std::fprintf(stderr, "granrepro: %s\n", text.c_str());
    run_log().line("warning: " + text);
}

} // namespace granrepro
