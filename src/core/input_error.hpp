// Errors in what the user gave us (parameters, files, flags). The CLI turns these into a single
// line on stderr and exit code 2; every other exception is a bug and exits 1.
#pragma once
#include <stdexcept>
#include <string>

namespace granrepro {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

} // namespace granrepro
