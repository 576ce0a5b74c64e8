#include "io/output_lock.hpp"

#include <cerrno>
#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/input_error.hpp"
#include "io/durable_file.hpp"
#include "io/staged_directory.hpp"

namespace granrepro {

OutputLock::OutputLock(const std::filesystem::path& out, const std::string& name, Mode mode) {
    const std::filesystem::path file = out / ("." + name + ".lock");
    // O_CLOEXEC: gnuplot and other children must not keep the lock alive after we exit.
    // O_NOFOLLOW, O_NONBLOCK and a regular file with one link: the lock file sits in a results
    // folder someone may have sent, and we write our PID into it; a planted link (symbolic or
    // hard) would have us overwrite its target, a FIFO would block (docs/schema.md, "Trust model").
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
    if (fd_ < 0) {
        const int err = errno;
        existing_entry(file, Entry::File, "lock file"); // names a symbolic link or a non-file
        throw InputError("--out " + out.string() + ": cannot create " + file.string() + " (" + errno_text(err) + ")");
    }
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode) || st.st_nlink != 1) {
        ::close(fd_);
        fd_ = -1;
        throw InputError(file.string() + ": lock file is not a regular file of its own (" +
                         (S_ISREG(st.st_mode) ? "it has other hard links" : "not a regular file") +
                         "); a results folder is written without following links (remove it)");
    }
    if (::flock(fd_, (mode == Mode::Exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB) != 0) {
        const int err = errno;
        char buf[32] = {};
        const ssize_t n = ::pread(fd_, buf, sizeof buf - 1, 0);
        ::close(fd_);
        fd_ = -1;
        if (err != EWOULDBLOCK)
            throw InputError("--out " + out.string() + ": cannot lock " + file.string() + " (" + errno_text(err) + ")");
        std::string pid = n > 0 ? std::string(buf, std::size_t(n)) : std::string();
        while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
        throw InputError((out / name).string() + " is being written by " +
                         (pid.empty() ? std::string("another process") : "pid " + pid) +
                         "; wait for it to finish or use another --out");
    }
    const std::string me = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd_, 0) == 0) {
        [[maybe_unused]] const ssize_t w = ::pwrite(fd_, me.data(), me.size(), 0);
    }
}

OutputLock::~OutputLock() {
    if (fd_ >= 0) ::close(fd_);
}

} // namespace granrepro
