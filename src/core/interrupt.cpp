#include "core/interrupt.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <pthread.h>
#include <set>
#include <thread>
#include <unistd.h>

namespace granrepro {

namespace {
std::atomic<int> g_signal{0};
std::atomic<std::chrono::steady_clock::rep> g_signal_time{0}; // steady_clock ticks, set before g_signal

// Never destroyed: the watcher may use them while static objects are torn down at exit.
std::mutex& cleanup_mutex() {
    static auto* m = new std::mutex;
    return *m;
}
std::set<std::filesystem::path>& cleanup_paths() {
    static auto* s = new std::set<std::filesystem::path>;
    return *s;
}

const char* name_of(int sig) { return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal"; }

void watch(sigset_t set) {
    int sig = 0;
    if (sigwait(&set, &sig) != 0) return;
    g_signal_time = std::chrono::steady_clock::now().time_since_epoch().count();
    g_signal = sig;
    // Wait for the run to reach a pause point (it then exits itself), a second signal, or the
    // end of the grace period.
    timespec grace{};
    grace.tv_sec = time_t(kInterruptGraceSeconds);
    siginfo_t info;
    while (sigtimedwait(&set, &info, &grace) < 0 && errno == EINTR) {
    }
    std::lock_guard<std::mutex> commit(interrupt_critical_mutex()); // never cut a commit
    {
        std::lock_guard<std::mutex> lock(cleanup_mutex());
        for (const auto& p : cleanup_paths()) {
            std::error_code ec;
            std::filesystem::remove_all(p, ec);
        }
    }
    std::fprintf(stderr,
                 "granrepro: interrupted by %s; stopped without reaching a pause point (the checkpoints on disk "
                 "are consistent; rerun the same command to resume)\n",
                 name_of(sig));
    std::fflush(stderr);
    ::_exit(128 + sig);
}
} // namespace

void install_interrupt_handling() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread(watch, set).detach();
}

bool interrupt_requested() { return g_signal.load(std::memory_order_relaxed) != 0; }

void throw_if_interrupted(const std::string& detail) {
    if (const int sig = g_signal.load(); sig != 0)
        throw Interrupted(sig, std::string("interrupted by ") + name_of(sig) + detail);
}

void engine_pause_point_slow() {
    const int sig = g_signal.load();
    if (sig == 0) return;
    const auto since = std::chrono::steady_clock::now().time_since_epoch() -
                       std::chrono::steady_clock::duration(g_signal_time.load());
    if (std::chrono::duration<double>(since).count() >= kEnginePauseSeconds)
        throw EngineLoopInterrupted(sig, std::string("interrupted by ") + name_of(sig) +
                                             " inside a long engine loop");
}

void register_for_cleanup(const std::filesystem::path& p) {
    std::lock_guard<std::mutex> lock(cleanup_mutex());
    cleanup_paths().insert(p);
}

void unregister_for_cleanup(const std::filesystem::path& p) {
    std::lock_guard<std::mutex> lock(cleanup_mutex());
    cleanup_paths().erase(p);
}

std::mutex& interrupt_critical_mutex() {
    static auto* m = new std::mutex;
    return *m;
}

} // namespace granrepro
