// Output is written into a hidden sibling directory and renamed into place only when complete,
// so an interrupted or failed run never leaves a half-written OUT/<experiment>.
#pragma once
#include <filesystem>

namespace granrepro {

class StagedDirectory {
public:
    // Creates <final>/../.<name>.partial-<pid>; throws InputError if the parent is not writable.
    explicit StagedDirectory(std::filesystem::path final_path);
    ~StagedDirectory();
    StagedDirectory(const StagedDirectory&) = delete;
    StagedDirectory& operator=(const StagedDirectory&) = delete;

    const std::filesystem::path& path() const { return staging_; }
    const std::filesystem::path& final_path() const { return final_; }
    // Replaces the final directory by the staged one (the old one is removed afterwards).
    void commit();

private:
    std::filesystem::path final_, staging_;
    bool committed_ = false;
};

// Creates `dir` if needed and checks that files can be created in it; throws InputError naming
// `flag` (e.g. "--out") otherwise.
void ensure_writable_directory(const std::filesystem::path& dir, const std::string& flag);

// Writes `content` to `path` through a temporary file and a rename.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

} // namespace granrepro
