// Reading a results folder (and the files a run is given), which is untrusted input: a reviewer
// downloads paper_figures/ and runs check, verify and report on it (docs/schema.md, "Trust
// model"). Every reader goes through these: a file is read only if it is a regular file reached
// without a symlink in its last component and no larger than its cap; nested text is refused
// past a depth before a recursive parser sees it. Failures are InputError: one line naming the
// file, exit 2.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace granrepro {

// Size caps, stated in docs/schema.md ("Trust model"); each is far above what any run writes
// (paper-scale summaries are < 1 MB, point files < 20 MB).
inline constexpr std::size_t kMaxSummaryBytes = std::size_t(64) << 20;    // summary.json
inline constexpr std::size_t kMaxPointFileBytes = std::size_t(256) << 20; // a sweep-point file, /points/records
inline constexpr std::size_t kMaxTextFileBytes = std::size_t(8) << 20;    // TOML, .gp scripts, logs
inline constexpr std::size_t kMaxImageBytes = std::size_t(64) << 20;      // a figure (PNG, PDF)
// Nesting caps: every file granrepro writes nests at most 6 deep.
inline constexpr int kMaxJsonDepth = 64;
inline constexpr int kMaxTomlDepth = 32;

// The whole content of `path` if it is a regular file (opened with O_NOFOLLOW | O_NONBLOCK, so a
// symlink, FIFO, device or directory is refused without blocking) of at most `max_bytes`.
// `role` names it in the message ("summary.json", "sweep-point file").
std::string read_untrusted_file(const std::filesystem::path& path, std::size_t max_bytes, const std::string& role);

// Refuses `path` unless it is a regular file reached without a symlink as its last component
// (lstat): for files opened by a library (HDF5) that takes a name, not a descriptor.
void require_regular_file(const std::filesystem::path& path, const std::string& role);

// The deepest nesting of [ and { outside strings in JSON text (strings with escapes skipped).
int json_depth(std::string_view text);
// `text` parsed as JSON, refused (InputError naming `file`) if it is not JSON or nests deeper than
// kMaxJsonDepth. Invalid UTF-8 in strings is kept as U+FFFD.
nlohmann::json parse_untrusted_json(std::string_view text, const std::string& file);

// The deepest nesting of TOML text: arrays and inline tables outside strings and comments, and
// the dotted parts of a key or table header. Refused (InputError naming `file`) past kMaxTomlDepth.
int toml_depth(std::string_view text);
void check_toml_depth(std::string_view text, const std::string& file);

} // namespace granrepro
