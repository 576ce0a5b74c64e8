#include "io/durable_file.hpp"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "io/write_error.hpp"

namespace fs = std::filesystem;

namespace granrepro {

std::string errno_text(int err) {
    std::string s = std::strerror(err);
    if (!s.empty() && std::isupper(static_cast<unsigned char>(s[0])) && !(s.size() > 1 && std::isupper(static_cast<unsigned char>(s[1]))))
        s[0] = char(std::tolower(static_cast<unsigned char>(s[0])));
    return s;
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void write_file_durably(const fs::path& path, std::string_view content) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw WriteError(path.string(), errno_text(errno));
    auto fail = [&](int err, bool open = true) {
        if (open) ::close(fd);
        std::error_code ec;
        fs::remove(path, ec);
        throw WriteError(path.string(), errno_text(err));
    };
    std::size_t done = 0;
    while (done < content.size()) {
        const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(errno);
        }
        if (n == 0) fail(ENOSPC); // write(2) returning 0 for a non-empty buffer: nothing more fits
        done += std::size_t(n);
    }
    if (::fsync(fd) != 0) fail(errno);
    if (::close(fd) != 0) fail(errno, false);
}

void fsync_path(const fs::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw WriteError(path.string(), errno_text(errno));
    if (::fsync(fd) != 0) {
        const int err = errno;
        ::close(fd);
        // Directories on some filesystems do not support fsync; their renames are durable anyway.
        if (err == EINVAL && fs::is_directory(path)) return;
        throw WriteError(path.string(), errno_text(err));
    }
    ::close(fd);
}

void fsync_tree(const fs::path& dir) {
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file() || e.is_directory()) fsync_path(e.path());
    fsync_path(dir);
}

} // namespace granrepro
