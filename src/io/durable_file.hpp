// Writes that are known to have reached the disk before anything is renamed into place. Every
// failure (open, short write, fsync, close) throws WriteError naming the file and the reason
// ("no space left on device"); a file that failed is removed, never left truncated.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

namespace granrepro {

// strerror(err) with a lower-case first letter, as it reads inside a sentence.
std::string errno_text(int err);

// Creates or truncates `path`, writes all of `content`, fsyncs and closes it.
void write_file_durably(const std::filesystem::path& path, std::string_view content);
// The whole file as text; empty if it cannot be read.
std::string read_file(const std::filesystem::path& path);
// fsync of an existing file or directory (a directory's fsync makes the renames in it durable).
void fsync_path(const std::filesystem::path& path);
// fsync of every regular file and directory below `dir`, and of `dir` itself.
void fsync_tree(const std::filesystem::path& dir);

} // namespace granrepro
