// Clean interrupts (SIGINT, SIGTERM). main() calls install_interrupt_handling() before any other
// thread exists: both signals are then blocked in every thread and a watcher thread waits for
// them. The first signal only sets a flag; the run stops at its next pause point:
//   - a long single run (RunCheckpoint) saves a final checkpoint there and throws Interrupted;
//   - a sweep (distributed_sweep) hands out no further points (finished points are already saved)
//     and abandons a point whose engine loop stops it (EngineLoopInterrupted), leaving it for the
//     rerun;
//   - a run whose computation is already over still writes and commits its results.
// The staging folder is removed as the Interrupted exception unwinds, and main() prints one line
// and exits 128 + signal (130 for SIGINT, 143 for SIGTERM). If no pause point comes within the
// grace period (kInterruptGraceSeconds), or a second signal arrives, the watcher stops the
// process itself: it removes the registered staging folders and exits the same way. It never
// cuts a commit short (it waits for the critical section) and never leaves a torn checkpoint,
// since checkpoints are only ever renamed into place when complete.
#pragma once
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>

namespace granrepro {

inline constexpr double kInterruptGraceSeconds = 8.0;
// How long an engine's inner loop leaves the run to reach its own pause point (a sample time,
// the end of a sweep point: those save a final checkpoint) before it stops the run itself.
inline constexpr double kEnginePauseSeconds = 1.0;

class Interrupted : public std::runtime_error {
public:
    Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}
    int signal() const { return signal_; }
    int exit_code() const { return 128 + signal_; }

private:
    int signal_;
};

// Thrown by an engine's inner loop (engine_pause_point): the run stopped between its own pause
// points, so nothing of the unfinished work was saved; a sweep leaves that point for the rerun.
class EngineLoopInterrupted : public Interrupted {
public:
    using Interrupted::Interrupted;
};

void install_interrupt_handling();
bool interrupt_requested();
// Throws Interrupted("interrupted by SIG...<detail>") if a signal arrived.
void throw_if_interrupted(const std::string& detail = "");

// The pause point of an engine's inner loop (an RK4 step, an event, a DSMC step), polled every
// few thousand iterations so that a run whose outer pause points are far apart (one long point, a
// sample interval of minutes, an input that makes every step crawl) still stops within about a
// second: throws Interrupted once a signal has waited kEnginePauseSeconds. Costs one relaxed load.
void engine_pause_point_slow();
inline void engine_pause_point() {
    if (interrupt_requested()) engine_pause_point_slow();
}

// Folders the watcher removes if it has to stop the process without a pause point.
void register_for_cleanup(const std::filesystem::path& p);
void unregister_for_cleanup(const std::filesystem::path& p);
// Held across a commit (and by main() while it prints the final line): the watcher waits for it.
std::mutex& interrupt_critical_mutex();

} // namespace granrepro
