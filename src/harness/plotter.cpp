#include "harness/plotter.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <vector>

#include "core/input_error.hpp"
#include "core/spawn.hpp"
#include "core/stable_hash.hpp"
#include "core/untrusted_file.hpp"
#include "data/parameter_set.hpp"
#include "harness/experiment.hpp"
#include "harness/run_log.hpp"
#include "io/durable_file.hpp"
#include "io/staged_directory.hpp"

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

std::vector<std::string> literal_tables(const std::string& script) {
    static const std::regex named(R"(datadir\.'/([A-Za-z0-9_]+)\.tsv')");
    std::vector<std::string> names;
    for (std::sregex_iterator it(script.begin(), script.end(), named), end; it != end; ++it) names.push_back((*it)[1].str());
    return names;
}

std::string missing_table(const std::string& script, const std::filesystem::path& tables_dir) {
    for (const auto& name : literal_tables(script))
        if (!std::filesystem::exists(tables_dir / (name + ".tsv"))) return name;
    return "";
}

std::string parameter_assignments(const std::string& script, const std::filesystem::path& summary_file) {
    static const std::regex declared(R"(# Parameters set by granrepro: ([A-Za-z0-9_, ]+))");
    std::smatch m;
    if (!std::regex_search(script, m, declared)) return "";
    // summary.json belongs to a results folder: read as untrusted input (a link, a FIFO, an
    // oversize or too deeply nested file is refused, InputError naming it).
    const nlohmann::json summary =
        parse_untrusted_json(read_untrusted_file(summary_file, kMaxSummaryBytes, "summary.json"), summary_file.string());
    nlohmann::json params;
    try {
        params = summary.at("parameters");
    } catch (const std::exception& e) {
        throw std::runtime_error("its parameters are read from " + summary_file.string() + ": " + e.what());
    }
    std::string lines;
    std::istringstream names(std::regex_replace(m[1].str(), std::regex(","), " "));
    for (std::string name; names >> name;) {
        const auto p = params.find(name);
        const nlohmann::json v = p == params.end() ? nlohmann::json() : p->value("value", nlohmann::json());
        std::string words;
        bool numbers = v.is_number() || (v.is_array() && !v.empty());
        for (const auto& x : v.is_array() ? v : nlohmann::json::array({v})) {
            numbers = numbers && x.is_number() && std::isfinite(x.get<double>());
            // The drivers name tables with number_text (e.g. run_r0.6_tc1e-06.tsv), so the
            // script gets the same text.
            if (numbers) words += (words.empty() ? "" : " ") + number_text(x.get<double>());
        }
        if (!numbers) throw std::runtime_error("it needs parameter " + name + " (numbers) from " + summary_file.string());
        lines += name + " = '" + words + "'\n";
    }
    return lines;
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

void check_plot_entries(const std::filesystem::path& dir, const std::vector<std::string>& ids) {
    if (!existing_entry(dir, Entry::Folder, "results folder")) return;
    if (existing_entry(dir / "tables", Entry::Folder, "tables folder")) refuse_links_below(dir / "tables", "tables folder");
    existing_entry(dir / "summary.json", Entry::File, "summary.json");
    for (const auto& id : ids) {
        for (const char* ext : {".png", ".pdf"}) existing_entry(dir / (id + ext), Entry::File, "figure");
        existing_entry(dir / (id + ".gnuplot.log"), Entry::File, "gnuplot log");
        existing_entry(dir / (id + ".gp"), Entry::File, "plot script");
        existing_entry(dir / (id + ".edited.gp"), Entry::File, "edited plot script");
    }
}

std::string emitted_script(const std::string& id, const std::string& body, const std::filesystem::path& tables_dir,
                           const std::string& assignments) {
    // The data and output are found next to the script (gnuplot sets ARG0 to the script's path),
    // so `gnuplot path/to/<id>.gp` works from any working directory.
    const std::string rest =
        "# Emitted by granrepro from plots/" + id + ".gp; `gnuplot " + id + ".gp` re-renders it from any\n"
        "# directory. Edited, it is kept as " + id + ".edited.gp by `granrepro plot` and reruns, which render\n"
        "# this one; `granrepro plot --edited` renders yours (the line above is the hash of the emitted text).\n"
        "here = ''\n"
        "if (exists('ARG0') && strlen(ARG0) > 0) {\n"
        "  _i = strlen(ARG0)\n"
        "  while (_i > 0 && ARG0[_i:_i] ne '/') { _i = _i - 1 }\n"
        "  if (_i > 0) { here = ARG0[1:_i] }\n"
        "}\n"
        "datadir = here.'tables'\noutbase = here.'" + id + "'\n"
        "# The tables that were in datadir when this was emitted; has(name) tells if one was.\n"
        "tables = '" + table_list(tables_dir) + "'\n"
        "has(name) = strstrt(' '.tables.' ', ' '.name.' ') > 0\n" + assignments + "\n" + body;
    return kHashTag + fnv1a_hex(rest) + "\n" + rest;
}

RenderOutcome render_figure(const std::string& id, const std::filesystem::path& run_dir,
                            const std::filesystem::path& shown_dir, bool edited) {
    // No figure of an earlier run stays beside data it was not drawn from.
    auto not_drawn = [&](RenderOutcome outcome, const std::string& why) {
        remove_figure(run_dir, id);
        warn(why);
        return outcome;
    };
    const auto script = project_root() / "plots" / (id + ".gp");
    std::ifstream in(script);
    if (!in) {
        warn(id + " not drawn: no plot script " + script.string());
        return RenderOutcome::Failed;
    }
    std::stringstream body;
    body << in.rdbuf();
    const std::filesystem::path shown = shown_dir.empty() ? run_dir : shown_dir;
    // A script the user edited (in the run folder, or in the folder a new run replaces) is data
    // someone may have sent along with the results: it is kept as <id>.edited.gp, and only
    // `plot --edited` runs it.
    const auto emitted = run_dir / (id + ".gp"), kept = run_dir / (id + ".edited.gp");
    const auto previous = shown / (id + ".gp"), previous_kept = shown / (id + ".edited.gp");
    // Nothing here is read or written through a link (see check_plot_entries); the scripts are
    // read as untrusted text and written by rename, which replaces a name, never its target.
    check_plot_entries(run_dir, {id});
    if (shown != run_dir) check_plot_entries(shown, {id});
    auto script_text = [](const std::filesystem::path& p) { return read_untrusted_file(p, kMaxTextFileBytes, "plot script"); };
    std::error_code ec;
    const bool just_edited = existing_entry(previous, Entry::File, "plot script") && !unedited(script_text(previous));
    if (just_edited) {
        write_file_atomically(kept, script_text(previous));
        warn(previous.string() + " was edited; " +
             (edited ? "rendering it (--edited)" : "rendering plots/" + id + ".gp; `granrepro plot --edited` renders the edited one") +
             ", kept as " + previous_kept.string());
    } else if (previous_kept != kept && existing_entry(previous_kept, Entry::File, "edited plot script")) {
        write_file_atomically(kept, script_text(previous_kept)); // a new run keeps it too
    }
    const bool run_kept = edited && existing_entry(kept, Entry::File, "edited plot script");
    if (run_kept && !just_edited) warn("rendering the edited script " + previous_kept.string() + " (--edited)");
    const std::string text = run_kept ? script_text(kept) : body.str();
    // A table the script names that this run did not make (e.g. cooling with run_ed = false has
    // no ED tables): the figure is not drawn.
    if (const std::string table = missing_table(text, run_dir / "tables"); !table.empty())
        return not_drawn(RenderOutcome::Skipped, id + " not drawn: the run made no table " + table);
    std::string assignments;
    try {
        assignments = parameter_assignments(body.str(), run_dir / "summary.json");
    } catch (const InputError&) {
        throw; // a damaged or planted summary.json is bad input (exit 2), not a figure not drawn
    } catch (const std::runtime_error& e) {
        return not_drawn(RenderOutcome::Failed, id + " not drawn: " + e.what());
    }
    write_file_atomically(emitted, emitted_script(id, body.str(), run_dir / "tables", assignments)); // a full disk is a WriteError, not a 0-byte script
    // "./": a name is never read as an option; the working directory, not a shell, finds it.
    const auto log = run_dir / (id + ".gnuplot.log");
    // gnuplot opens its outputs by name (`set output`; the log is opened O_NOFOLLOW by
    // run_program): the old ones are removed first, so it creates fresh files in this folder.
    for (const char* ext : {".png", ".pdf", ".gnuplot.log"}) std::filesystem::remove(run_dir / (id + ext), ec);
    const int rc = run_program({"gnuplot", "./" + id + (run_kept ? ".edited.gp" : ".gp")}, run_dir, log);
    const auto shown_log = shown / (id + ".gnuplot.log");
    if (rc == kNotStarted) {
        std::filesystem::remove(log, ec);
        return not_drawn(RenderOutcome::Failed,
                         id + " not drawn: gnuplot could not be started (is it installed? Debian package gnuplot-nox)");
    }
    // Whatever gnuplot wrote before it failed is not a figure (and not a sign of a full disk).
    if (rc != 0 || !existing_entry(run_dir / (id + ".png"), Entry::File, "figure"))
        return not_drawn(RenderOutcome::Failed, "gnuplot failed for " + id + " (see " + shown_log.string() + ")");
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
