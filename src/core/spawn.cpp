#include "core/spawn.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace granrepro {

namespace {

// Closes a descriptor on every path out of a function.
struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

// Starts argv with stdout and stderr on out_fd (ours if out_fd < 0; stdin /dev/null) in cwd; the
// pid, or -1.
pid_t start(const std::vector<std::string>& argv, const std::filesystem::path& cwd, int out_fd) {
    if (argv.empty()) return -1;
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawnattr_t attr;
    posix_spawn_file_actions_init(&fa);
    posix_spawnattr_init(&attr);
    // Our SIGINT/SIGTERM are blocked for the watcher thread; a child must start as from a shell.
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    for (int s : {SIGINT, SIGTERM, SIGPIPE}) sigaddset(&defaults, s);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    if (out_fd >= 0) {
        posix_spawn_file_actions_adddup2(&fa, out_fd, 1);
        posix_spawn_file_actions_adddup2(&fa, out_fd, 2);
    }
    if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&fa, cwd.c_str());
    pid_t pid = -1;
    // glibc reports a failed chdir or exec (e.g. no such program) as posix_spawnp's result.
    if (posix_spawnp(&pid, args[0], &fa, &attr, args.data(), environ) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&fa);
    posix_spawnattr_destroy(&attr);
    return pid;
}

int wait_for(pid_t pid) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return kNotStarted;
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : kNotStarted;
}

} // namespace

int run_program(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                const std::filesystem::path& output) {
    const Fd out{::open(output.empty() ? "/dev/null" : output.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644)};
    if (out.fd < 0) return kNotStarted; // O_NOFOLLOW: a log in a results folder is never written through a link
    const pid_t pid = start(argv, cwd, out.fd);
    return pid < 0 ? kNotStarted : wait_for(pid);
}

int run_program_with_our_output(const std::vector<std::string>& argv) {
    std::fflush(nullptr);
    const pid_t pid = start(argv, {}, -1);
    return pid < 0 ? kNotStarted : wait_for(pid);
}

std::string program_output(const std::vector<std::string>& argv) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) return "";
    const Fd read_end{fds[0]};
    pid_t pid = -1;
    {
        const Fd write_end{fds[1]}; // closed before reading, so the read ends when the child exits
        pid = start(argv, {}, write_end.fd);
    }
    if (pid < 0) return "";
    std::string text;
    char buf[4096];
    for (ssize_t n; (n = ::read(read_end.fd, buf, sizeof buf)) != 0;) {
        if (n > 0) text.append(buf, std::size_t(n));
        else if (errno != EINTR) break;
    }
    wait_for(pid);
    return text;
}

std::string find_in_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    const std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
    for (std::size_t at = 0;;) {
        const std::size_t colon = dirs.find(':', at);
        const std::string dir = dirs.substr(at, colon == std::string::npos ? std::string::npos : colon - at);
        const std::string file = (dir.empty() ? std::string(".") : dir) + "/" + name;
        struct stat st {};
        if (::stat(file.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(file.c_str(), X_OK) == 0) return file;
        if (colon == std::string::npos) return "";
        at = colon + 1;
    }
}

std::string argv_text(const std::vector<std::string>& argv) {
    std::string line;
    for (const std::string& arg : argv) {
        std::string a = arg;
        if (a.empty() || a.find_first_of(" \t\n'\"\\$`*?[]{}()<>|&;#~") != std::string::npos) {
            std::string q = "'";
            for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
            a = q + "'";
        }
        line += (line.empty() ? "" : " ") + a;
    }
    return line;
}

} // namespace granrepro
