#include "harness/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace granrepro {

Progress::Progress(std::string label, long total, bool quiet)
    : label_(std::move(label)), total_(total), enabled_(!quiet && isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() {
    if (printed_) std::fprintf(stderr, "\r\033[K");
}

void Progress::tick(long n) {
    const long done = done_ += n;
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    std::lock_guard<std::mutex> lock(mutex_);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (elapsed < 2.0 || std::chrono::duration<double>(now - last_).count() < 0.25) return;
    last_ = now;
    const double eta = done > 0 ? elapsed * double(total_ - done) / double(done) : 0.0;
    std::fprintf(stderr, "\r\033[K[%s] %ld/%ld  %.0f s elapsed, ~%.0f s left", label_.c_str(), done, total_,
                 elapsed, eta);
    std::fflush(stderr);
    printed_ = true;
}

} // namespace granrepro
