// A write that did not reach the disk (full disk, quota, I/O error, a file that cannot be created).
// The CLI prints it as one line, "granrepro: error: <reason> writing <path>", and exits 3; nothing
// was renamed into place, so the previous results are untouched.
#pragma once
#include <stdexcept>
#include <string>

namespace granrepro {

class WriteError : public std::runtime_error {
public:
    WriteError(std::string path, std::string reason)
        : std::runtime_error(reason + " writing " + path), path_(std::move(path)), reason_(std::move(reason)) {}
    const std::string& path() const { return path_; }
    const std::string& reason() const { return reason_; }

private:
    std::string path_, reason_;
};

} // namespace granrepro
