// A fixed team of threads for work split inside one time step: run(job) calls job(tid) on every
// member (the caller is member 0) and returns when all are done; barrier() inside a job waits for
// every member. Waits spin for a few microseconds before they sleep (futex, via atomic wait): a
// soft-sphere step of ~1500 grains lasts a few microseconds, and std::barrier or a condition
// variable parks a waiting thread in the kernel at once, whose wake-up alone costs about as much
// as a step. On a busy machine (the partner thread descheduled) the sleep keeps a waiting thread
// from burning the core the partner needs.
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
        stop_.store(true);
        epoch_.fetch_add(1);
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
        epoch_.fetch_add(1);
        if (sleepers_.load() > 0) epoch_.notify_all();
        job(0);
        barrier();
    }

    // Waits until every member has arrived (inside run only).
    void barrier() {
        if (size_ == 1) return;
        const unsigned phase = phase_.load(std::memory_order_acquire);
        if (arrived_.fetch_add(1, std::memory_order_acq_rel) == unsigned(size_ - 1)) {
            arrived_.store(0, std::memory_order_relaxed);
            phase_.fetch_add(1);
            if (sleepers_.load() > 0) phase_.notify_all();
            return;
        }
        wait_while(phase_, phase);
    }

private:
    // Spins while a == old, then sleeps until a changes. The sleeper count is incremented before
    // the value is checked a last time and read by the writer after it changes the value (all
    // sequentially consistent), so a writer either sees the sleeper and notifies it or the
    // sleeper sees the new value.
    void wait_while(std::atomic<unsigned>& a, unsigned old) {
        for (unsigned spins = 0; a.load(std::memory_order_acquire) == old; ++spins) {
            if (spins < 2000) {
#if defined(__x86_64__) || defined(__i386__)
                _mm_pause();
#endif
                continue;
            }
            sleepers_.fetch_add(1);
            a.wait(old);
            sleepers_.fetch_sub(1);
        }
    }

    void work(int tid) {
        unsigned seen = 0;
        for (;;) {
            wait_while(epoch_, seen);
            seen = epoch_.load();
            if (stop_.load()) return;
            (*job_)(tid);
            barrier();
        }
    }

    int size_;
    std::vector<std::thread> workers_;
    const std::function<void(int)>* job_ = nullptr;
    alignas(64) std::atomic<unsigned> epoch_{0};
    alignas(64) std::atomic<unsigned> arrived_{0};
    alignas(64) std::atomic<unsigned> phase_{0};
    alignas(64) std::atomic<int> sleepers_{0};
    std::atomic<bool> stop_{false};
};

} // namespace granrepro
