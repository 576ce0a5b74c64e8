// One writer per experiment output: an flock(2) on OUT/.<experiment>.lock, taken before a run
// starts computing and held until its results are committed and its checkpoint folder deleted.
// A second run of the same experiment into the same OUT is refused at once (InputError, exit 2):
//   "OUT/<experiment> is being written by pid N; wait for it to finish or use another --out"
// We refuse rather than wait: waiting would silently queue hours of work behind another run
// whose results it would then replace; refusing at the start costs nothing. (Before the lock,
// two runs 4 s apart lost the second's work when the first deleted the shared checkpoint folder,
// and two runs 1 s apart silently replaced each other's results.)
//
// Shards of one sweep (issue 13: `--points I/N`, MPI ranks) share one checkpoint folder by design.
// They take the lock Mode::Shared while computing points: shards then run side by side, but
// never beside a whole run (which needs it exclusive). The step that assembles the points,
// commits the results and deletes the checkpoint folder takes it Mode::Exclusive (after the
// shards released theirs). Within one MPI job, rank 0 alone can hold the exclusive lock.
//
// `plot` takes it Mode::Exclusive as well: it rewrites figures and scripts in OUT/<experiment>,
// which a run replaces as a whole (a plot beside a run once exited 4).
//
// The lock file sits in a results folder someone may have sent (docs/schema.md, "Trust model"):
// it is opened O_NOFOLLOW and must be a regular file of one link, or the run is refused (exit 2
// naming it), so our PID is never written into a file elsewhere.
//
// The kernel releases the lock when the process dies (kill -9 included); the lock file itself
// stays (deleting it would let two processes lock two different files). It holds the PID of the
// last process that took it, for the message.
#pragma once
#include <filesystem>
#include <string>

namespace granrepro {

class OutputLock {
public:
    enum class Mode { Exclusive, Shared };
    // Locks OUT/.<name>.lock without waiting; throws InputError naming the holder if another
    // process holds it in a conflicting mode.
    OutputLock(const std::filesystem::path& out, const std::string& name, Mode mode = Mode::Exclusive);
    ~OutputLock();
    OutputLock(const OutputLock&) = delete;
    OutputLock& operator=(const OutputLock&) = delete;

private:
    int fd_ = -1;
};

} // namespace granrepro
