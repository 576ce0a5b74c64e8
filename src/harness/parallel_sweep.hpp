// Runs independent sweep points on up to `threads` threads. Each point writes only its own slot,
// so the result does not depend on the number of threads or on scheduling.
#pragma once
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "harness/progress.hpp"

namespace granrepro {

template <class Fn>
void parallel_sweep(long n, int threads, Progress* progress, Fn&& fn) {
    std::atomic<long> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto worker = [&] {
        for (long i; (i = next++) < n;) {
            try {
                const ProgressSlot slot(progress, i);
                fn(i);
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
}

} // namespace granrepro
