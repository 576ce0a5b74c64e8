// External programs (gnuplot, LAMMPS, mpirun) started without a shell: an argument vector, a
// working directory and output by file descriptor, so no path or name is ever read as shell code
// (a results folder named "x';touch PWNED;'y" is just a folder).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace granrepro {

// Exit status of a program that could not be started (not found, not executable, or its output
// file could not be created); -1 never collides with an exit code.
inline constexpr int kNotStarted = -1;

// Runs argv (argv[0] looked up in $PATH unless it holds a '/') in `cwd` (empty: ours), stdin from
// /dev/null, stdout and stderr into `output` (truncated; empty: /dev/null; a relative path is
// taken from our working directory, not from cwd), and waits for it.
// Returns its exit code, 128 + N if signal N ended it, or kNotStarted. The child starts with no
// blocked signals (ours are blocked for the interrupt watcher, see core/interrupt.hpp).
int run_program(const std::vector<std::string>& argv, const std::filesystem::path& cwd = {},
                const std::filesystem::path& output = {});

// Like run_program, with our stdout and stderr (a program whose messages are meant for the user).
int run_program_with_our_output(const std::vector<std::string>& argv);

// Like run_program, and returns what it wrote on stdout and stderr ("" if it could not start).
std::string program_output(const std::vector<std::string>& argv);

// Where `name` is found in $PATH (as the shell's `command -v`), "" if nowhere.
std::string find_in_path(const std::string& name);

// argv as one line for messages (shell-quoted where needed, for reading, never run).
std::string argv_text(const std::vector<std::string>& argv);

} // namespace granrepro
