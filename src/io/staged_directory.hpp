// Output is written into a hidden sibling directory and switched into place only when complete,
// so an interrupted or failed run never leaves a half-written OUT/<experiment>.
//
// commit() first fsyncs every staged file and folder (a failure throws WriteError and renames
// nothing), then swaps the staged folder with the old results in one step,
// renameat2(RENAME_EXCHANGE), fsyncs OUT, and deletes the old copy (now in the staging folder).
// At no instant is OUT/<experiment> missing or partial. On a filesystem that refuses the exchange
// (EINVAL: e.g. some network filesystems) it falls back to two renames, old -> .<name>.old-<pid>
// then staged -> final; a kill between them leaves only the hidden old copy, which
// clean_staging_leftovers() restores on the next run.
//
// Testing hooks (environment): GRANREPRO_TEST_COMMIT_NO_EXCHANGE=1 takes the two-rename path;
// GRANREPRO_TEST_KILL_IN_COMMIT=after-exchange | between-renames raises SIGKILL at that point.
#pragma once
#include <filesystem>
#include <string>

namespace granrepro {

class StagedDirectory {
public:
    // Creates <final>/../.<name>.partial-<pid>; throws InputError if the parent is not writable.
    explicit StagedDirectory(std::filesystem::path final_path);
    ~StagedDirectory();
    StagedDirectory(const StagedDirectory&) = delete;
    StagedDirectory& operator=(const StagedDirectory&) = delete;

    const std::filesystem::path& path() const { return staging_; }
    // Where a path inside the staging folder will be after the commit (for messages).
    std::filesystem::path shown(const std::filesystem::path& staged) const;
    // Makes the staged directory the final one (see above); throws WriteError if the staged
    // files cannot be made durable, leaving the old results in place.
    void commit();

private:
    std::filesystem::path final_, staging_;
    bool committed_ = false;
};

// What killed runs of `final_path` left beside it: .<name>.partial-<pid> and .<name>.old-<pid>
// of other processes. If `final_path` is missing and an old copy exists (a kill inside a
// two-rename commit), the old copy is renamed back into place (and a note printed unless quiet);
// everything else is deleted. Call it only while holding the experiment's OutputLock: then no
// other process is writing these folders, whatever their PIDs (a PID alone cannot tell, since
// PIDs are reused, and in containers the same PID comes back run after run).
void clean_staging_leftovers(const std::filesystem::path& final_path, bool quiet);
// Temporary files (<name>.partial-<pid>, .<name>.tmp-<pid>) of other processes anywhere below
// `dir` (a checkpoint folder); same rule: only while holding the OutputLock.
void clean_temporary_leftovers(const std::filesystem::path& dir);

// Creates `dir` if needed and checks that files can be created in it; throws InputError naming
// `flag` (e.g. "--out") otherwise (see check_output_directory).
void ensure_writable_directory(const std::filesystem::path& dir, const std::string& flag);
// What ensure_writable_directory checks, without creating anything (for --dry-run): `dir`, or if
// it does not exist yet its nearest existing ancestor, must be a writable directory outside /proc
// and /sys. `dir` itself may be a symbolic link: the user named it (entries inside a results
// folder may not be, see existing_entry).
void check_output_directory(const std::filesystem::path& dir, const std::string& flag);

// A results folder is untrusted input (docs/schema.md, "Trust model"): an entry granrepro reads or
// writes there must be what granrepro wrote, never a symbolic link that would lead a read or a
// write outside the folder. lstat(path): false if nothing is there, true if it is a `kind`;
// anything else (a symbolic link, a FIFO, a file where a folder belongs) is refused, InputError
// naming it as `role` ("lock file", "checkpoint folder").
enum class Entry { File, Folder };
bool existing_entry(const std::filesystem::path& path, Entry kind, const std::string& role);
// Every entry below the folder `dir` (not following links) checked the same way: a symbolic link
// anywhere inside is refused, naming it.
void refuse_links_below(const std::filesystem::path& dir, const std::string& role);

// Writes `content` to `path` through a temporary file, fsync and a rename (then fsyncs the
// folder); throws WriteError and leaves `path` untouched if anything fails.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

} // namespace granrepro
