// Figures are gnuplot scripts in plots/<figure-id>.gp that a person can open and edit. A run
// copies the script next to its data with two variables set at the top (where the tables are,
// and the output base name) and runs gnuplot there, producing <figure-id>.png and .pdf.
#pragma once
#include <filesystem>
#include <string>

namespace granrepro {

// Emits <run_dir>/<id>.gp and renders it in run_dir. Returns false (with a message on stderr) if
// gnuplot is missing or fails; the data are still complete then.
bool render_figure(const std::string& figure_id, const std::filesystem::path& run_dir);

} // namespace granrepro
