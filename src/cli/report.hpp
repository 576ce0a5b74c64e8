// `granrepro report [--out DIR] [--to REPORTDIR]`: a static site of the results in DIR (every
// figure, claim and deviation), written by the Python package granrepro.report (Jinja2).
#pragma once
#include <CLI/CLI.hpp>

namespace granrepro {

// Registers the subcommand; its callback sets rc (0 written, 2 bad input, 3 not written,
// 4 python3, jinja2 or h5py missing).
void add_report_subcommand(CLI::App& app, int& rc);

} // namespace granrepro
