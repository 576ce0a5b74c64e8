#include "core/untrusted_file.hpp"

#include <algorithm>
#include <cerrno>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/input_error.hpp"
#include <cstring>

namespace fs = std::filesystem;

namespace granrepro {

namespace {
std::string kind_of(mode_t m) {
    if (S_ISLNK(m)) return "a symbolic link";
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
    if (S_ISSOCK(m)) return "a socket";
    return "not a regular file";
}
std::string errno_text(int err) { // strerror, lower-case as it reads inside a sentence
    std::string s = std::strerror(err);
    if (s.size() > 1 && s[0] >= 'A' && s[0] <= 'Z' && !(s[1] >= 'A' && s[1] <= 'Z')) s[0] = char(s[0] - 'A' + 'a');
    return s;
}
std::string mib(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }
} // namespace

std::string read_untrusted_file(const fs::path& path, std::size_t max_bytes, const std::string& role) {
    const std::string where = path.string() + ": ";
    const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        const int err = errno;
        struct stat st {};
        if (err == ELOOP && ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
            throw InputError(where + role + " is a symbolic link; a results folder is read without following links");
        throw InputError(where + role + " cannot be read (" + errno_text(err) + ")");
    }
    struct Close {
        int fd;
        ~Close() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw InputError(where + role + " cannot be read (" + errno_text(errno) + ")");
    if (!S_ISREG(st.st_mode)) throw InputError(where + role + " is " + kind_of(st.st_mode) + ", not a regular file");
    if (std::size_t(st.st_size) > max_bytes)
        throw InputError(where + role + " is larger than its cap of " + mib(max_bytes) + " (docs/schema.md)");
    std::string text(std::size_t(st.st_size), '\0');
    std::size_t done = 0;
    for (;;) { // the size may change while we read: never past the cap
        if (done == text.size()) {
            if (text.size() >= max_bytes + 1) break;
            text.resize(std::min(max_bytes + 1, std::max<std::size_t>(text.size() * 2, 4096)));
        }
        const ssize_t n = ::read(fd, text.data() + done, text.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw InputError(where + role + " cannot be read (" + errno_text(errno) + ")");
        }
        if (n == 0) break;
        done += std::size_t(n);
    }
    if (done > max_bytes)
        throw InputError(where + role + " is larger than its cap of " + mib(max_bytes) + " (docs/schema.md)");
    text.resize(done);
    return text;
}

void require_regular_file(const fs::path& path, const std::string& role) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) throw InputError(path.string() + ": " + role + " cannot be read (" + errno_text(errno) + ")");
    if (S_ISLNK(st.st_mode))
        throw InputError(path.string() + ": " + role + " is a symbolic link; a results folder is read without following links");
    if (!S_ISREG(st.st_mode)) throw InputError(path.string() + ": " + role + " is " + kind_of(st.st_mode) + ", not a regular file");
}

int json_depth(std::string_view text) {
    int depth = 0, deepest = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') ++i;
            else if (c == '"') in_string = false;
        } else if (c == '"') in_string = true;
        else if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
        else if (c == ']' || c == '}') --depth;
    }
    return deepest;
}

nlohmann::json parse_untrusted_json(std::string_view text, const std::string& file) {
    if (json_depth(text) > kMaxJsonDepth)
        throw InputError(file + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (not a granrepro file)");
    nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded()) throw InputError(file + ": not valid JSON (a damaged file?)");
    return j;
}

int toml_depth(std::string_view text) {
    int depth = 0, deepest = 0, dots = 0;
    bool key_part = true; // before the line's '=' (or in a [table] header): dots nest the key
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
            key_part = depth == 0;
            dots = 0;
        } else if (c == '#') {
            while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
        } else if (c == '"' || c == '\'') {
            const bool triple = text.substr(i, 3) == std::string(3, c);
            const std::string_view close = triple ? std::string_view(c == '"' ? "\"\"\"" : "'''") : std::string_view(&text[i], 1);
            i += triple ? 3 : 1;
            while (i < text.size() && text.substr(i, close.size()) != close) {
                if (c == '"' && text[i] == '\\') ++i;
                if (!triple && text[i] == '\n') break; // an unterminated string: toml11 reports it
                ++i;
            }
            i += close.size() - 1;
        } else if (c == '=' && depth == 0) {
            key_part = false;
        } else if (c == '.' && key_part) {
            deepest = std::max(deepest, ++dots + 1);
        } else if ((c == '[' || c == '{') && !key_part) {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && !key_part) {
            --depth;
        } // a table header's brackets ([a], [[a]]) do not nest
    }
    return deepest;
}

void check_toml_depth(std::string_view text, const std::string& file) {
    if (toml_depth(text) > kMaxTomlDepth)
        throw InputError(file + ": TOML nested deeper than " + std::to_string(kMaxTomlDepth) + " levels (not a granrepro file)");
}

} // namespace granrepro
