// Running the granrepro binary from tests (GRANREPRO_BINARY is set by tests/CMakeLists.txt), and
// reading back what it wrote.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <string>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/h5_file.hpp"

namespace cli_support {

struct Outcome {
    int code;        // exit code, -1 if killed
    std::string err; // everything written to stderr
    std::string out; // everything written to stdout
};

// The whole file, byte for byte ("" if it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The summary.json of a result directory.
inline nlohmann::json summary(const std::filesystem::path& dir) {
    return nlohmann::json::parse(slurp(dir / "summary.json"));
}

inline int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

// An exit as the user meets it (a refusal, a failed write, a signal): exit `code` and one line on
// stderr that contains every part.
inline void expect_one_line_exit(const Outcome& o, int code, const std::vector<std::string>& parts) {
    EXPECT_EQ(o.code, code) << o.err;
    EXPECT_EQ(lines(o.err), 1) << o.err;
    for (const std::string& part : parts) EXPECT_NE(o.err.find(part), std::string::npos) << part << " not in: " << o.err;
}

// Runs a shell command with its stdout and stderr captured.
inline Outcome shell(const std::string& cmd) {
    const std::string base =
        (std::filesystem::temp_directory_path() / ("granrepro-cli-" + std::to_string(::getpid()))).string();
    const int status = std::system((cmd + " > " + base + "-out 2> " + base + "-err").c_str());
    Outcome o{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(base + "-err"), slurp(base + "-out")};
    std::filesystem::remove(base + "-out");
    std::filesystem::remove(base + "-err");
    return o;
}

// Runs granrepro with `args` (and an environment prefix such as "VAR=1").
inline Outcome run(const std::string& args, const std::string& env = "") {
    return shell(env + " " + GRANREPRO_BINARY + " " + args);
}

// Runs granrepro with an argument vector, no shell (arguments may hold quotes, $(...), newlines),
// in the working directory `cwd` (empty: ours), with `env` ("NAME=value") added to the
// environment; stdout and stderr captured.
inline Outcome run_argv(const std::vector<std::string>& args, const std::filesystem::path& cwd = {},
                        const std::vector<std::string>& env = {}) {
    const std::string base =
        (std::filesystem::temp_directory_path() / ("granrepro-cli-argv-" + std::to_string(::getpid()))).string();
    std::vector<std::string> argv{GRANREPRO_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> cargs;
    for (std::string& a : argv) cargs.push_back(a.data());
    cargs.push_back(nullptr);
    // env's entries replace ours of the same name; built before fork (the child only execs).
    std::vector<char*> envp;
    for (const std::string& e : env) envp.push_back(const_cast<char*>(e.c_str()));
    for (char** e = environ; *e; ++e) {
        const std::string entry = *e, name = entry.substr(0, entry.find('=') + 1);
        if (std::none_of(env.begin(), env.end(), [&](const std::string& x) { return x.rfind(name, 0) == 0; }))
            envp.push_back(*e);
    }
    envp.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int out = ::open((base + "-out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        const int err = ::open((base + "-err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0 || (!cwd.empty() && ::chdir(cwd.c_str()) != 0))
            ::_exit(126);
        ::execve(cargs[0], cargs.data(), envp.data());
        ::_exit(127);
    }
    int status = 0;
    while (pid > 0 && ::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    Outcome o{pid > 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(base + "-err"), slurp(base + "-out")};
    std::filesystem::remove(base + "-out");
    std::filesystem::remove(base + "-err");
    return o;
}

// A path in the temporary directory, unique to this process, removed if it exists.
inline std::filesystem::path fresh(const std::string& name) {
    const std::filesystem::path p =
        std::filesystem::temp_directory_path() / ("granrepro-cli-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(p);
    return p;
}

// A fresh() path that is removed again when the test leaves its scope (also on a failed ASSERT).
struct TempPath : std::filesystem::path {
    explicit TempPath(const std::string& name) : std::filesystem::path(fresh(name)) {}
    TempPath(const TempPath&) = delete;
    TempPath& operator=(const TempPath&) = delete;
    ~TempPath() { std::filesystem::remove_all(*this); }
};

// How many .h5 files (checkpoints) a folder holds; 0 if it does not exist.
inline int h5_files(const std::filesystem::path& dir) {
    std::error_code ec;
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) n += e.path().extension() == ".h5";
    return n;
}

// The named datasets of two data.h5 files hold the same bits, each more than `more_than` values.
inline void expect_same_datasets(const std::filesystem::path& a, const std::filesystem::path& b,
                                 std::initializer_list<const char*> datasets, std::size_t more_than = 0) {
    const granrepro::H5File fa = granrepro::H5File::open(a.string()), fb = granrepro::H5File::open(b.string());
    for (const char* ds : datasets) {
        const auto va = fa.read_dataset(ds), vb = fb.read_dataset(ds);
        ASSERT_EQ(va.size(), vb.size()) << ds;
        EXPECT_GT(va.size(), more_than) << ds;
        EXPECT_EQ(0, std::memcmp(va.data(), vb.data(), va.size() * sizeof(double))) << ds;
    }
}

// Wall-clock measures, which differ between any two runs. Physics with "wall" in its name
// (plug_wall_load, e_N_wall_over_free, ...) is not one.
inline bool wall_clock(const std::string& name) {
    for (const char* clock : {"wall_seconds", "wall_time", "per_second", "seconds_per"})
        if (name.find(clock) != std::string::npos) return true;
    return false;
}

// The scalars in the summary.json of two result directories are the same, but the wall-clock ones
// and `skip`; more than `more_than` are compared.
inline void expect_same_scalars(const std::filesystem::path& a, const std::filesystem::path& b,
                                const std::string& skip = "", int more_than = 0) {
    const auto sa = summary(a).at("scalars"), sb = summary(b).at("scalars");
    ASSERT_EQ(sa.size(), sb.size());
    int compared = 0;
    for (auto it = sa.begin(); it != sa.end(); ++it)
        if (!wall_clock(it.key()) && it.key() != skip) {
            EXPECT_EQ(it.value().dump(), sb.at(it.key()).dump()) << it.key();
            ++compared;
        }
    EXPECT_GT(compared, more_than);
}

} // namespace cli_support
