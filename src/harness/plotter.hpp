// Figures are gnuplot scripts in plots/<figure-id>.gp that a person can open and edit. A run
// copies the script next to its data with variables set at the top (where the tables are, which
// tables there are, the output base name, and the run's values of the parameters the script
// declares) and runs gnuplot there, producing <figure-id>.png and .pdf.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace granrepro {

// Clean: gnuplot printed nothing. Warned: it rendered but printed something (our scripts print
// nothing themselves, so anything is a warning such as "Skipping data file with no valid points");
// <id>.gnuplot.log keeps it. Failed: gnuplot is missing or failed, or a parameter the script
// needs is missing (no PNG is left); the data are still complete. Skipped: the run made no table
// the script names (see missing_table). Failed and Skipped: the figure was not drawn.
enum class RenderOutcome { Clean, Warned, Failed, Skipped };

// The first table that `script` names literally (datadir.'/<name>.tsv') and tables_dir lacks;
// "" if none. Names the script builds at run time are not checked.
std::string missing_table(const std::string& script, const std::filesystem::path& tables_dir);
// The tables a script names literally (datadir.'/<name>.tsv'), in order of appearance.
std::vector<std::string> literal_tables(const std::string& script);

// The gnuplot assignments of the parameters that `script` declares in a line
// "# Parameters set by granrepro: a, b", with their values in the run's summary.json: a number as
// the drivers write it in table names (number_text: fig8_t_c = '1e-06'), a list as words. So a
// script names the tables of the run's --set values, not of the defaults. "" if it declares none;
// throws std::runtime_error naming the parameter or file if a value is missing or not numbers.
std::string parameter_assignments(const std::string& script, const std::filesystem::path& summary_file);

// The emitted <id>.gp: a hash line, the variables datadir and outbase (found next to the script
// from gnuplot's ARG0, so it runs from any directory), `tables` (the names, without .tsv, of the
// tables in tables_dir, space-separated in natural order: "steady_k200 steady_k2000") and the
// function has(name), the parameter assignments, then the body of plots/<id>.gp. The scripts
// learn which tables exist from `tables`, not from a shell (they call no system()).
std::string emitted_script(const std::string& figure_id, const std::string& body,
                           const std::filesystem::path& tables_dir, const std::string& assignments = "");

// Emits <run_dir>/<id>.gp and renders it in run_dir with gnuplot (no shell: see core/spawn.hpp).
// A results folder is data, not code: if <id>.gp in shown_dir (or else in run_dir) was edited
// since it was emitted, it is kept as <run_dir>/<id>.edited.gp (as is an <id>.edited.gp of
// shown_dir), a warning says so, and the emitted script is rendered; only `edited` (plot --edited)
// renders <id>.edited.gp instead. A warning or failure is reported on stderr in one line naming the
// figure and the log (as it will be found in shown_dir, if given: a run renders in its staging
// directory).
// A results folder is untrusted input (docs/schema.md, "Trust model"): throws InputError naming
// the first entry of `dir` that drawing the figures `ids` would read or write through a link,
// or that is not what granrepro writes there: `dir` itself, tables/ (and any link in it),
// summary.json, and each figure's .png, .pdf, .gnuplot.log, .gp and .edited.gp. Missing ones pass.
void check_plot_entries(const std::filesystem::path& dir, const std::vector<std::string>& ids);

RenderOutcome render_figure(const std::string& figure_id, const std::filesystem::path& run_dir,
                            const std::filesystem::path& shown_dir = {}, bool edited = false);

} // namespace granrepro
