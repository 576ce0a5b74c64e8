// Runs independent sweep points on up to `threads` threads. Each point writes only its own slot,
// so the result does not depend on the number of threads or on scheduling.
// After SIGINT/SIGTERM (core/interrupt.hpp) no further point is started; the points under way
// finish (and save their checkpoints), then Interrupted is thrown if points were left undone.
#pragma once
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/interrupt.hpp"
#include "harness/progress.hpp"

namespace granrepro {

template <class Fn>
void parallel_sweep(long n, int threads, Progress* progress, Fn&& fn) {
    std::atomic<long> next{0}, done{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto worker = [&] {
        for (long i; !interrupt_requested() && (i = next++) < n;) {
            try {
                const ProgressSlot slot(progress, i);
                fn(i);
                ++done;
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
                next = n; // stop handing out work
            }
            if (progress) progress->done(i);
        }
    };
    const int t = std::max(1, std::min<int>(threads, int(n)));
    std::vector<std::thread> pool;
    for (int k = 1; k < t; ++k) pool.emplace_back(worker);
    worker();
    for (auto& th : pool) th.join();
    if (error) std::rethrow_exception(error);
    if (done < n) throw_if_interrupted("; " + std::to_string(n - done) + " of " + std::to_string(n) +
                                       " sweep points left for the rerun");
}

} // namespace granrepro
