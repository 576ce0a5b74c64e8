#include "harness/plotter.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

#include "core/stable_hash.hpp"
#include "harness/experiment.hpp"
#include "harness/run_log.hpp"
#include "io/durable_file.hpp"

namespace granrepro {

namespace {

const char* const kHashTag = "# granrepro-emitted-hash: ";

// Stable across toolchains (std::hash is not); it detects edits, it does not guard against forgery.
std::string fnv1a_hex(const std::string& text) { return hex64(fnv1a64(text)); }

// An emitted script is "<first line with the hash of the rest>\n<rest>". True if the file has
// that form and the rest is unchanged since it was emitted, or if it was emitted before scripts
// carried a hash (granrepro 0.1.0 before 2026-12; its header is recognised and replaced).
bool unedited(const std::string& text) {
    if (text.rfind("# Emitted by granrepro from plots/", 0) == 0 && text.find("datadir = 'tables'\n") != std::string::npos)
        return true;
    const auto eol = text.find('\n');
    if (text.rfind(kHashTag, 0) != 0 || eol == std::string::npos) return false;
    return text.substr(std::string(kHashTag).size(), eol - std::string(kHashTag).size()) ==
           fnv1a_hex(text.substr(eol + 1));
}

void remove_figure(const std::filesystem::path& dir, const std::string& id) {
    std::error_code ec;
    for (const char* ext : {".png", ".pdf"}) std::filesystem::remove(dir / (id + ext), ec);
}

} // namespace

std::string missing_table(const std::string& script, const std::filesystem::path& tables_dir) {
    static const std::regex named(R"(datadir\.'/([A-Za-z0-9_]+)\.tsv')");
    for (std::sregex_iterator it(script.begin(), script.end(), named), end; it != end; ++it)
        if (!std::filesystem::exists(tables_dir / ((*it)[1].str() + ".tsv"))) return (*it)[1].str();
    return "";
}

namespace {

// "steady_k200" before "steady_k2000" before "steady_k30000": runs of digits (with a decimal point
// or exponent, as in "tc1e-06") compare by value, so scripts can take tables in numeric order.
bool natural_less(const std::string& a, const std::string& b) {
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (std::isdigit(static_cast<unsigned char>(a[i])) && std::isdigit(static_cast<unsigned char>(b[j]))) {
            double x = 0, y = 0;
            const auto ra = std::from_chars(a.data() + i, a.data() + a.size(), x);
            const auto rb = std::from_chars(b.data() + j, b.data() + b.size(), y);
            if (x != y) return x < y;
            i = std::size_t(ra.ptr - a.data());
            j = std::size_t(rb.ptr - b.data());
        } else {
            if (a[i] != b[j]) return a[i] < b[j];
            ++i, ++j;
        }
    }
    if (a.size() - i != b.size() - j) return a.size() - i < b.size() - j;
    return a < b; // equal values written differently ("0.8", "0.80"): still a strict order
}

// The tables (names without .tsv) in tables_dir, in natural order, as one gnuplot string: the
// scripts choose from it instead of listing the folder through a shell. Our code makes every name;
// one with any other character is left out all the same, as it could end the quoted string.
std::string table_list(const std::filesystem::path& tables_dir) {
    static const std::regex safe("[A-Za-z0-9_.-]+");
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(tables_dir, ec)) {
        const std::string name = e.path().stem().string();
        if (e.path().extension() == ".tsv" && e.is_regular_file(ec) && std::regex_match(name, safe)) names.push_back(name);
    }
    std::sort(names.begin(), names.end(), natural_less);
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : " ") + n;
    return out;
}

} // namespace

std::string emitted_script(const std::string& id, const std::string& body, const std::filesystem::path& tables_dir) {
    // The data and output are found next to the script (gnuplot sets ARG0 to the script's path),
    // so `gnuplot path/to/<id>.gp` works from any working directory.
    const std::string rest =
        "# Emitted by granrepro from plots/" + id + ".gp; `gnuplot " + id +
        ".gp` re-renders it from any directory. Edit it freely: `granrepro plot` then renders your\n"
        "# version instead of overwriting it (the line above is the hash of the emitted text).\n"
        "here = ''\n"
        "if (exists('ARG0') && strlen(ARG0) > 0) {\n"
        "  _i = strlen(ARG0)\n"
        "  while (_i > 0 && ARG0[_i:_i] ne '/') { _i = _i - 1 }\n"
        "  if (_i > 0) { here = ARG0[1:_i] }\n"
        "}\n"
        "datadir = here.'tables'\noutbase = here.'" + id + "'\n"
        "# The tables that were in datadir when this was emitted; has(name) tells if one was.\n"
        "tables = '" + table_list(tables_dir) + "'\n"
        "has(name) = strstrt(' '.tables.' ', ' '.name.' ') > 0\n\n" + body;
    return kHashTag + fnv1a_hex(rest) + "\n" + rest;
}

RenderOutcome render_figure(const std::string& id, const std::filesystem::path& run_dir,
                            const std::filesystem::path& shown_dir) {
    const auto script = project_root() / "plots" / (id + ".gp");
    std::ifstream in(script);
    if (!in) {
        warn("no plot script " + script.string());
        return RenderOutcome::Failed;
    }
    std::stringstream body;
    body << in.rdbuf();
    // A table the script names that this run did not make (e.g. cooling with run_ed = false has
    // no ED tables): the figure is not drawn, and no figure of an earlier run stays beside the data.
    std::error_code ec;
    if (const std::string table = missing_table(body.str(), run_dir / "tables"); !table.empty()) {
        remove_figure(run_dir, id);
        warn(id + " not drawn: the run made no table " + table);
        return RenderOutcome::Skipped;
    }
    const auto emitted = run_dir / (id + ".gp");
    // A script the user edited (in the run folder, or in the folder a new run replaces) is kept
    // and rendered instead of the one from plots/.
    const auto previous = (shown_dir.empty() ? run_dir : shown_dir) / (id + ".gp");
    if (std::filesystem::exists(previous, ec) && !unedited(read_file(previous))) {
        if (previous != emitted) std::filesystem::copy_file(previous, emitted, std::filesystem::copy_options::overwrite_existing);
        warn(previous.string() + " was edited: rendering the edited script, not plots/" + id +
             ".gp (delete it to get the current one)");
    } else {
        write_file_durably(emitted, emitted_script(id, body.str(), run_dir / "tables")); // a full disk is a WriteError, not a 0-byte script
    }
    const std::string cmd = "cd '" + run_dir.string() + "' && gnuplot '" + id + ".gp' > '" + id +
                            ".gnuplot.log' 2>&1";
    const int rc = std::system(cmd.c_str());
    const auto log = run_dir / (id + ".gnuplot.log");
    const auto shown_log = (shown_dir.empty() ? run_dir : shown_dir) / (id + ".gnuplot.log");
    if (rc != 0 || !std::filesystem::exists(run_dir / (id + ".png"))) {
        // Whatever gnuplot wrote before it failed is not a figure (and not a sign of a full disk).
        remove_figure(run_dir, id);
        warn("gnuplot failed for " + id + " (see " + shown_log.string() + ")");
        return RenderOutcome::Failed;
    }
    if (std::filesystem::file_size(log, ec) == 0) {
        std::filesystem::remove(log, ec);
        return RenderOutcome::Clean;
    }
    // Name the warning itself: gnuplot echoes the offending command and a caret line first.
    std::ifstream log_in(log);
    std::string line, first, warning;
    while (std::getline(log_in, line)) {
        const auto b = line.find_first_not_of(" \t\r^");
        if (b == std::string::npos) continue;
        if (first.empty()) first = line.substr(b);
        if (warning.empty() && (line.find("warning") != std::string::npos || line.find("Warning") != std::string::npos))
            warning = line.substr(b);
    }
    if (!warning.empty()) first = warning;
    if (first.size() > 160) first = first.substr(0, 157) + "...";
    warn("gnuplot warned for " + id + ": " + first + " (see " + shown_log.string() + ")");
    return RenderOutcome::Warned;
}

} // namespace granrepro
