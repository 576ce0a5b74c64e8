// Running the granrepro binary from tests (GRANREPRO_BINARY is set by tests/CMakeLists.txt).
#pragma once
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace cli_support {

struct Outcome {
    int code;        // exit code, -1 if killed
    std::string err; // everything written to stderr
};

// Runs granrepro with `args` (and an environment prefix such as "VAR=1"); stdout is discarded.
inline Outcome run(const std::string& args, const std::string& env = "") {
    const std::filesystem::path err =
        std::filesystem::temp_directory_path() / ("granrepro-cli-err-" + std::to_string(::getpid()));
    const std::string cmd = env + " " + GRANREPRO_BINARY + " " + args + " > /dev/null 2> " + err.string();
    const int status = std::system(cmd.c_str());
    std::ifstream in(err);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove(err);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

// A path in the temporary directory, unique to this process, removed if it exists.
inline std::filesystem::path fresh(const std::string& name) {
    const std::filesystem::path p =
        std::filesystem::temp_directory_path() / ("granrepro-cli-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(p);
    return p;
}

} // namespace cli_support
