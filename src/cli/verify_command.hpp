// The `verify` subcommand (harness/verify.hpp), registered by main.cpp with one call.
#pragma once

namespace CLI {
class App;
}

namespace granrepro {
// Adds `verify EXPERIMENT [--point I] [--out DIR] [--list] [--threads N]`; its callback sets rc.
void add_verify_command(CLI::App& app, int& rc);
} // namespace granrepro
