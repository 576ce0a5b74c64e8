// A fixed team of threads for work split inside one time step: run(job) calls job(tid) on every
// member (the caller is member 0) and returns when all are done; barrier() inside a job waits for
// every member. Both spin (with a pause, then yielding) rather than sleep: a soft-sphere step of
// ~1500 grains lasts a few microseconds, and std::barrier or a condition variable parks waiting
// threads in the kernel, whose wake-up alone costs about as much as a step. Between runs, idle
// members spin for about a millisecond and then sleep on the epoch counter (atomic wait).
#pragma once
#include <atomic>
#include <functional>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace granrepro {

class SpinTeam {
public:
    explicit SpinTeam(int threads) : size_(threads < 1 ? 1 : threads) {
        for (int t = 1; t < size_; ++t) workers_.emplace_back([this, t] { work(t); });
    }
    SpinTeam(const SpinTeam&) = delete;
    SpinTeam& operator=(const SpinTeam&) = delete;
    ~SpinTeam() {
        stop_.store(true, std::memory_order_release);
        epoch_.fetch_add(1, std::memory_order_acq_rel);
        epoch_.notify_all();
        for (auto& w : workers_) w.join();
    }

    int size() const { return size_; }

    // Runs job(tid) for tid = 0 .. size()-1, tid 0 on the calling thread. The job must not throw.
    void run(const std::function<void(int)>& job) {
        if (size_ == 1) {
            job(0);
            return;
        }
        job_ = &job;
        done_.store(0, std::memory_order_relaxed);
        epoch_.fetch_add(1, std::memory_order_acq_rel);
        epoch_.notify_all();
        job(0);
        for (unsigned spins = 0; done_.load(std::memory_order_acquire) != size_ - 1;) relax(spins);
    }

    // Waits until every member has arrived (inside run only).
    void barrier() {
        if (size_ == 1) return;
        const unsigned phase = phase_.load(std::memory_order_acquire);
        if (arrived_.fetch_add(1, std::memory_order_acq_rel) == size_ - 1) {
            arrived_.store(0, std::memory_order_relaxed);
            phase_.store(phase + 1, std::memory_order_release);
            return;
        }
        for (unsigned spins = 0; phase_.load(std::memory_order_acquire) == phase;) relax(spins);
    }

private:
    static void pause() {
#if defined(__x86_64__) || defined(__i386__)
        _mm_pause();
#endif
    }
    // Spin first; yield once the wait is long (a few microseconds: another process may hold the
    // core we wait for).
    static void relax(unsigned& spins) {
        if (++spins < 256) pause();
        else std::this_thread::yield();
    }

    void work(int tid) {
        unsigned seen = 0;
        for (;;) {
            unsigned now;
            for (long spins = 0; (now = epoch_.load(std::memory_order_acquire)) == seen; ++spins) {
                if (spins < 200000) pause();
                else epoch_.wait(seen, std::memory_order_acquire);
            }
            seen = now;
            if (stop_.load(std::memory_order_acquire)) return;
            (*job_)(tid);
            done_.fetch_add(1, std::memory_order_acq_rel);
        }
    }

    int size_;
    std::vector<std::thread> workers_;
    const std::function<void(int)>* job_ = nullptr;
    alignas(64) std::atomic<unsigned> epoch_{0};
    alignas(64) std::atomic<int> done_{0};
    alignas(64) std::atomic<int> arrived_{0};
    alignas(64) std::atomic<unsigned> phase_{0};
    std::atomic<bool> stop_{false};
};

} // namespace granrepro
