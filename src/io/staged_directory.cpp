#include "io/staged_directory.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <linux/magic.h>
#include <mutex>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <system_error>
#include <unistd.h>
#include <vector>

#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "data/parameter_set.hpp"
#include "io/durable_file.hpp"
#include "io/write_error.hpp"

namespace fs = std::filesystem;

namespace granrepro {

namespace {
fs::path parent_of(const fs::path& p) { return p.parent_path().empty() ? fs::path(".") : p.parent_path(); }

bool test_hook(const char* point) {
    const char* v = std::getenv("GRANREPRO_TEST_KILL_IN_COMMIT");
    return v && std::strcmp(v, point) == 0;
}

// Digits after `prefix` in `name`, or -1.
long pid_suffix(const std::string& name, const std::string& prefix) {
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return -1;
    const std::string digits = name.substr(prefix.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return -1;
    return std::stol(digits);
}

// A folder that cannot be removed (a file in it we may not delete) would stay hidden beside the
// results for ever, each run trying again in silence: say so, in one line per process.
void remove_or_warn(const std::vector<fs::path>& folders, const char* what) {
    static bool warned = false;
    std::vector<std::string> left;
    std::string reason;
    for (const auto& p : folders) {
        std::error_code ec;
        fs::remove_all(p, ec);
        if (ec && fs::exists(p)) {
            left.push_back(p.string());
            if (reason.empty()) reason = ec.message();
        }
    }
    if (left.empty() || warned) return;
    warned = true;
    std::fprintf(stderr, "granrepro: warning: cannot remove %s %s (%s); remove %s by hand\n", what,
                 joined(left).c_str(), reason.c_str(), left.size() == 1 ? "it" : "them");
}

void rename_or_throw(const fs::path& from, const fs::path& to, const fs::path& shown) {
    if (::rename(from.c_str(), to.c_str()) != 0) throw WriteError(shown.string(), errno_text(errno));
}
} // namespace

namespace {
// The kernel's pseudo-filesystems: a directory there may pass access(2) for root, but nothing a
// run writes can be created in it (`--out /proc/self` used to pass --dry-run, then fail).
bool on_kernel_pseudo_fs(const fs::path& dir) {
    struct statfs s {};
    if (::statfs(dir.c_str(), &s) != 0) return false;
    for (const auto magic : {PROC_SUPER_MAGIC, SYSFS_MAGIC, CGROUP_SUPER_MAGIC, CGROUP2_SUPER_MAGIC, DEBUGFS_MAGIC})
        if (s.f_type == decltype(s.f_type)(magic)) return true;
    return false;
}
} // namespace

void check_output_directory(const fs::path& dir, const std::string& flag) {
    const std::string shown = flag + " " + dir.string() + ": ";
    // The nearest existing ancestor: what a run would create its folders in.
    std::error_code ec;
    fs::path existing = dir.empty() ? fs::path(".") : dir;
    while (!fs::exists(existing, ec))
        existing = existing.has_parent_path() && existing.parent_path() != existing ? existing.parent_path() : fs::path(".");
    const std::string which = existing == dir ? std::string() : " (" + existing.string() + ")";
    if (!fs::is_directory(existing, ec)) throw InputError(shown + "not a directory" + which);
    if (on_kernel_pseudo_fs(existing))
        throw InputError(shown + "on a kernel pseudo-filesystem (/proc, /sys), not a place for results" + which);
    if (::access(existing.c_str(), W_OK | X_OK) != 0) throw InputError(shown + "directory is not writable" + which);
}

bool existing_entry(const fs::path& path, Entry kind, const std::string& role) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) {
        if (errno == ENOENT || errno == ENOTDIR) return false;
        throw InputError(path.string() + ": " + role + " cannot be examined (" + errno_text(errno) + ")");
    }
    if (S_ISLNK(st.st_mode))
        throw InputError(path.string() + ": " + role +
                         " is a symbolic link; a results folder is read and written without following links (remove it)");
    if (kind == Entry::File ? !S_ISREG(st.st_mode) : !S_ISDIR(st.st_mode))
        throw InputError(path.string() + ": " + role + " is not a " + (kind == Entry::File ? "regular file" : "folder"));
    return true;
}

void refuse_links_below(const fs::path& dir, const std::string& role) {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
        if (it->is_symlink(ec))
            throw InputError(it->path().string() + ": a symbolic link in the " + role +
                             "; a results folder is read and written without following links (remove it)");
}

void ensure_writable_directory(const fs::path& dir, const std::string& flag) {
    check_output_directory(dir, flag);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw InputError(flag + " " + dir.string() + ": cannot create directory (" +
                         (ec ? ec.message() : "not a directory") + ")");
    if (access(dir.c_str(), W_OK | X_OK) != 0)
        throw InputError(flag + " " + dir.string() + ": directory is not writable");
}

StagedDirectory::StagedDirectory(fs::path final_path) : final_(std::move(final_path)) {
    ensure_writable_directory(parent_of(final_), "--out");
    staging_ = final_.parent_path() / ("." + final_.filename().string() + ".partial-" + std::to_string(getpid()));
    std::error_code ec;
    fs::remove_all(staging_, ec); // a link planted under this name goes, not what it points to
    // mkdir, not create_directories: a fresh folder of our own, never one that was already there.
    if (::mkdir(staging_.c_str(), 0755) != 0)
        throw InputError("--out " + final_.parent_path().string() + ": cannot create " + staging_.string());
    register_for_cleanup(staging_);
}

StagedDirectory::~StagedDirectory() {
    if (!committed_) {
        std::error_code ec;
        fs::remove_all(staging_, ec);
    }
    unregister_for_cleanup(staging_);
}

fs::path StagedDirectory::shown(const fs::path& staged) const {
    const fs::path rel = staged.lexically_relative(staging_);
    if (rel.empty() || *rel.begin() == "..") return staged;
    return rel == "." ? final_ : final_ / rel;
}

void StagedDirectory::commit() {
    // Everything staged must be on disk before it can replace the old results.
    try {
        fsync_tree(staging_);
    } catch (const WriteError& e) {
        throw WriteError(shown(e.path()).string(), e.reason());
    }
    const fs::path parent = parent_of(final_);
    const std::lock_guard<std::mutex> critical(interrupt_critical_mutex()); // a signal never cuts a commit
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(final_, ec))) { // a link is replaced, never followed
        rename_or_throw(staging_, final_, final_);
        committed_ = true;
        fsync_path(parent);
        return;
    }
    const bool exchange_refused_for_test = std::getenv("GRANREPRO_TEST_COMMIT_NO_EXCHANGE") != nullptr;
    if (!exchange_refused_for_test &&
        ::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, final_.c_str(), RENAME_EXCHANGE) == 0) {
        committed_ = true;
        fsync_path(parent);
        if (test_hook("after-exchange")) ::raise(SIGKILL);
        remove_or_warn({staging_}, "the previous results, now in"); // the next run tries again
        return;
    }
    if (!exchange_refused_for_test && errno != EINVAL && errno != ENOSYS)
        throw WriteError(final_.string(), errno_text(errno));
    // The filesystem cannot exchange: two renames, with a window that clean_staging_leftovers() repairs.
    const fs::path old = final_.parent_path() / ("." + final_.filename().string() + ".old-" + std::to_string(getpid()));
    fs::remove_all(old, ec);
    rename_or_throw(final_, old, final_);
    if (test_hook("between-renames")) ::raise(SIGKILL);
    if (::rename(staging_.c_str(), final_.c_str()) != 0) {
        const int err = errno;
        ::rename(old.c_str(), final_.c_str()); // put the old results back
        throw WriteError(final_.string(), errno_text(err));
    }
    committed_ = true;
    fsync_path(parent);
    remove_or_warn({old}, "the previous results, now in");
}

void clean_staging_leftovers(const fs::path& final_path, bool quiet) {
    const fs::path parent = parent_of(final_path);
    const std::string name = final_path.filename().string();
    const std::string partial = "." + name + ".partial-", old = "." + name + ".old-";
    const long me = long(getpid());
    std::vector<fs::path> partials, olds;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(parent, ec)) {
        const std::string n = e.path().filename().string();
        if (const long pid = pid_suffix(n, partial); pid >= 0 && pid != me) partials.push_back(e.path());
        if (const long pid = pid_suffix(n, old); pid >= 0 && pid != me) olds.push_back(e.path());
    }
    if (!fs::exists(fs::symlink_status(final_path, ec)) && !olds.empty() &&
        fs::is_directory(fs::symlink_status(olds.front(), ec))) {
        // Only an old copy is left: a run was killed between the two renames of a fallback commit.
        if (::rename(olds.front().c_str(), final_path.c_str()) == 0) {
            if (!quiet)
                std::fprintf(stderr, "granrepro: restored %s from %s (a run was killed while committing)\n",
                             final_path.c_str(), olds.front().c_str());
            olds.erase(olds.begin());
        }
    }
    partials.insert(partials.end(), olds.begin(), olds.end());
    remove_or_warn(partials, "what an earlier run left:");
}

void clean_temporary_leftovers(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return;
    const std::string me = std::to_string(getpid());
    std::vector<fs::path> stale;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        const std::string n = it->path().filename().string();
        for (const char* marker : {".partial-", ".tmp-"}) {
            const auto at = n.rfind(marker);
            if (at == std::string::npos) continue;
            const std::string pid = n.substr(at + std::strlen(marker));
            if (!pid.empty() && pid.find_first_not_of("0123456789") == std::string::npos && pid != me)
                stale.push_back(it->path());
        }
    }
    for (const auto& p : stale) fs::remove_all(p, ec);
}

void write_file_atomically(const fs::path& path, const std::string& content) {
    const fs::path tmp = path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(getpid()));
    std::error_code gone;
    fs::remove(tmp, gone); // a link planted under our temporary name: removed, never written through
    try {
        write_file_durably(tmp, content);
    } catch (const WriteError& e) {
        throw WriteError(path.string(), e.reason());
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        std::error_code ec;
        fs::remove(tmp, ec);
        throw WriteError(path.string(), errno_text(err));
    }
    fsync_path(parent_of(path));
}

} // namespace granrepro
