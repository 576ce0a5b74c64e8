// The hostile_results suite (issue 40): a results folder is untrusted input. Each test crafts one
// damaged or malicious folder in a temporary directory, runs a reader (check, verify, report,
// plot, export, a rerun) on it and asserts the exit code, the one-line message, and that nothing
// outside the folder changed: a sentinel tree of victim files beside it is hashed before and after.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <sys/stat.h>

#include "cli_support.hpp"
#include "core/stable_hash.hpp"

namespace hostile {

namespace fs = std::filesystem;
using cli_support::Outcome;
using cli_support::run_argv;
using cli_support::slurp;

// A fresh quick brake-failure result (about a second), made once per process and copied for
// each test into `dir`/brake-failure (so `--out dir`).
inline void copy_fresh_result(const fs::path& dir, const std::string& experiment = "brake-failure") {
    struct Pristine : std::map<std::string, fs::path> { // removed when the test process ends
        ~Pristine() {
            std::error_code ec;
            for (const auto& [name, p] : *this) fs::remove_all(p, ec);
        }
    };
    static Pristine pristine;
    fs::create_directories(dir);
    auto it = pristine.find(experiment);
    // ctest makes it once for every test process (fixture hostile_results.pristine: under ASan one
    // quick run costs about 20 s, and ctest starts each test in a process of its own).
    if (const char* shared = std::getenv("GRANREPRO_HOSTILE_PRISTINE");
        it == pristine.end() && shared && *shared && fs::exists(fs::path(shared) / experiment / "summary.json")) {
        fs::copy(fs::path(shared) / experiment, dir / experiment, fs::copy_options::recursive);
        return;
    }
    if (it == pristine.end()) {
        const fs::path p = cli_support::fresh("hostile-pristine-" + experiment);
        const Outcome o = run_argv({experiment, "--quiet", "--scale", "quick", "--out", p.string()});
        if (o.code != 0) throw std::runtime_error("hostile: could not make a fresh " + experiment + ": " + o.err);
        it = pristine.emplace(experiment, p).first;
    }
    fs::copy(it->second / experiment, dir / experiment, fs::copy_options::recursive);
}

// A folder of victim files (and one victim folder) that no reader may touch. `digest()` covers
// every entry below the root: its path, type, mode, size, content and, for a symlink, its target.
struct SentinelTree {
    fs::path root;
    explicit SentinelTree(const fs::path& r) : root(r) {
        fs::create_directories(root / "victim_dir");
        write("victim.txt", "a victim file: never overwritten, truncated or read into a results folder\n");
        write("secret.txt", "secret: never copied into a report\n");
        write("victim_dir/keep.txt", "a file in a victim folder\n");
    }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(root / name, std::ios::binary) << text;
    }
    fs::path victim() const { return root / "victim.txt"; }
    fs::path secret() const { return root / "secret.txt"; }
    fs::path victim_dir() const { return root / "victim_dir"; }
    std::string digest() const {
        std::uint64_t h = granrepro::kFnv1a64Start;
        std::vector<fs::path> entries;
        for (const auto& e : fs::recursive_directory_iterator(root)) entries.push_back(e.path());
        std::sort(entries.begin(), entries.end());
        for (const fs::path& p : entries) {
            struct stat st {};
            ::lstat(p.c_str(), &st);
            std::string rec = fs::relative(p, root).string() + '\0' + std::to_string(st.st_mode) + '\0' +
                              std::to_string(st.st_size) + '\0';
            if (S_ISLNK(st.st_mode)) rec += fs::read_symlink(p).string();
            else if (S_ISREG(st.st_mode)) rec += slurp(p);
            h = granrepro::fnv1a64(rec, h);
        }
        return granrepro::hex64(h) + " (" + std::to_string(entries.size()) + " entries)";
    }
};

// One crafted folder per test: `out` (the --out folder, holding `out/brake-failure`) and a
// sentinel tree beside it, both removed at the end; the sentinel must be unchanged.
struct Crafted {
    cli_support::TempPath base;
    fs::path out;
    SentinelTree sentinel;
    std::string before;
    explicit Crafted(const std::string& name, const std::string& experiment = "brake-failure")
        : base("hostile-" + name), out(base / "out"), sentinel((fs::create_directories(base), base / "sentinel")) {
        copy_fresh_result(out, experiment);
        before = sentinel.digest();
    }
    fs::path dir(const std::string& experiment = "brake-failure") const { return out / experiment; }
    void expect_sentinel_unchanged() const { EXPECT_EQ(sentinel.digest(), before) << "a file outside the folder changed"; }
};

// An exit as the user meets it: `code`, one line on stderr containing every part, no internal
// text (nlohmann's "[json.exception", HDF5's stack, a Python traceback).
inline void expect_refusal(const Outcome& o, int code, const std::vector<std::string>& parts) {
    cli_support::expect_one_line_exit(o, code, parts);
    for (const char* internal : {"[json.exception", "HDF5-DIAG", "Traceback", "H5E", "terminate called"})
        EXPECT_EQ(o.err.find(internal), std::string::npos) << internal << " in: " << o.err;
}

} // namespace hostile
