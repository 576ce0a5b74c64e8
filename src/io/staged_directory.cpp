#include "io/staged_directory.hpp"

#include <fstream>
#include <system_error>
#include <unistd.h>

#include "core/input_error.hpp"

namespace fs = std::filesystem;

namespace granrepro {

void ensure_writable_directory(const fs::path& dir, const std::string& flag) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw InputError(flag + " " + dir.string() + ": cannot create directory (" +
                         (ec ? ec.message() : "not a directory") + ")");
    if (access(dir.c_str(), W_OK | X_OK) != 0)
        throw InputError(flag + " " + dir.string() + ": directory is not writable");
}

StagedDirectory::StagedDirectory(fs::path final_path) : final_(std::move(final_path)) {
    ensure_writable_directory(final_.parent_path().empty() ? fs::path(".") : final_.parent_path(), "--out");
    staging_ = final_.parent_path() / ("." + final_.filename().string() + ".partial-" + std::to_string(getpid()));
    std::error_code ec;
    fs::remove_all(staging_, ec);
    fs::create_directories(staging_, ec);
    if (ec) throw InputError("--out " + final_.parent_path().string() + ": cannot create " + staging_.string());
}

StagedDirectory::~StagedDirectory() {
    if (!committed_) {
        std::error_code ec;
        fs::remove_all(staging_, ec);
    }
}

void StagedDirectory::commit() {
    const fs::path old = final_.parent_path() / ("." + final_.filename().string() + ".old-" + std::to_string(getpid()));
    std::error_code ec;
    if (fs::exists(final_)) fs::rename(final_, old);
    fs::rename(staging_, final_);
    committed_ = true;
    fs::remove_all(old, ec);
}

void write_file_atomically(const fs::path& path, const std::string& content) {
    const fs::path tmp = path.parent_path() / ("." + path.filename().string() + ".tmp-" + std::to_string(getpid()));
    {
        std::ofstream out(tmp, std::ios::binary);
        out << content;
        if (!out) throw std::runtime_error("cannot write " + tmp.string());
    }
    fs::rename(tmp, path);
}

} // namespace granrepro
