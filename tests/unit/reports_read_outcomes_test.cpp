// Reports read outcomes only (issue 44, item 3): physics runs in a protocol's compute (a sweep
// point: spread over ranks, resumed from point files, re-verified by `granrepro verify`) or at most
// in prepare, never in report. This test reads the sources: the report files
// (experiments/*/report*.cpp) and the body of every protocol's `static Result report(` with the
// functions of its own file that body calls must name no engine header, no engine and no runner.
//
// The names are derived, not kept by hand: an engine is a class of src/engines/**/*.hpp with a
// member that advances time (step, run_until, run_collisions), or an alias of one; a runner is a
// function defined in src/scenarios or in an experiment's non-report file whose body names an
// engine or a runner (to a fixed point: shoot, build_pipe, run_pipe, impact_mean, construct...).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = GRANREPRO_SOURCE_DIR;

std::string text_of(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The code without comments, string and character literals (each replaced by a space; newlines
// kept), so that a word in a description or a comment is not a call.
std::string code_only(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        if (s.compare(i, 2, "//") == 0) {
            while (i < s.size() && s[i] != '\n') ++i;
        } else if (s.compare(i, 2, "/*") == 0) {
            const std::size_t end = s.find("*/", i + 2);
            i = end == std::string::npos ? s.size() : end + 2;
            out += ' ';
        } else if (s[i] == '"' || s[i] == '\'') {
            const char q = s[i++];
            while (i < s.size() && s[i] != q) i += s[i] == '\\' ? 2 : 1;
            ++i;
            out += ' ';
        } else {
            out += s[i++];
        }
    }
    return out;
}

// The text from the '{' at open to its matching '}' (inclusive).
std::string braced(const std::string& s, std::size_t open) {
    int depth = 0;
    for (std::size_t i = open; i < s.size(); ++i) {
        depth += s[i] == '{' ? 1 : s[i] == '}' ? -1 : 0;
        if (depth == 0) return s.substr(open, i - open + 1);
    }
    return s.substr(open);
}

// Functions defined at namespace scope (their name's line starts in column 0): name -> bodies.
std::multimap<std::string, std::string> functions(const std::string& text) {
    const std::string code = "\n" + text;
    static const std::regex def(R"(\n[A-Za-z_][\w:<>,&\*\s]*?\b([A-Za-z_]\w*)\s*\([^;{}]*\)\s*(const\s*)?(->[^{;]*)?\{)");
    std::multimap<std::string, std::string> out;
    for (std::sregex_iterator it(code.begin(), code.end(), def), end; it != end; ++it) {
        const std::string name = (*it)[1];
        if (name == "if" || name == "for" || name == "while" || name == "switch" || name == "return") continue;
        out.emplace(name, braced(code, std::size_t(it->position(0) + it->length(0) - 1)));
    }
    return out;
}

bool names_any(const std::string& code, const std::set<std::string>& names, std::string* which = nullptr) {
    static const std::regex word(R"([A-Za-z_]\w*)");
    for (std::sregex_iterator it(code.begin(), code.end(), word), end; it != end; ++it)
        if (names.count(it->str())) {
            if (which) *which = it->str();
            return true;
        }
    return false;
}

std::vector<fs::path> files_under(const fs::path& dir, const std::vector<std::string>& exts) {
    std::vector<fs::path> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        for (const auto& x : exts)
            if (e.is_regular_file() && e.path().extension() == x) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

bool is_report_file(const fs::path& p) { return p.filename().string().starts_with("report"); }

// Engines: classes with a member that advances time, and aliases of them (EdEngine, DsmcEngine).
std::set<std::string> engine_names() {
    static const std::regex cls(R"(\bclass\s+(\w+)\s*(final\s*)?\{)"), alias(R"(\busing\s+(\w+)\s*=\s*(\w+)\b)");
    static const std::regex advances(R"(\b(step|run_until|run_collisions)\s*\()");
    std::set<std::string> names;
    std::vector<std::string> codes;
    for (const fs::path& p : files_under(kRoot / "src" / "engines", {".hpp"})) codes.push_back(code_only(text_of(p)));
    for (const std::string& code : codes)
        for (std::sregex_iterator it(code.begin(), code.end(), cls), end; it != end; ++it)
            if (std::regex_search(braced(code, std::size_t(it->position(0) + it->length(0) - 1)), advances)) names.insert((*it)[1]);
    for (const std::string& code : codes)
        for (std::sregex_iterator it(code.begin(), code.end(), alias), end; it != end; ++it)
            if (names.count((*it)[2])) names.insert((*it)[1]);
    return names;
}

// Engines and runners: to a fixed point over the scenarios and the experiments' non-report files
// (a file's own aliases of an engine, `using Engine = PipeEngine<...>`, count there).
std::set<std::string> physics_names() {
    std::set<std::string> names = engine_names();
    std::vector<std::string> codes;
    for (const fs::path& p : files_under(kRoot / "src" / "scenarios", {".hpp", ".cpp"})) codes.push_back(code_only(text_of(p)));
    for (const fs::path& p : files_under(kRoot / "experiments", {".hpp", ".cpp"}))
        if (!is_report_file(p)) codes.push_back(code_only(text_of(p)));
    static const std::regex alias(R"(\busing\s+(\w+)\s*=\s*(\w+)\b)");
    for (std::size_t before = 0; before != names.size();) {
        before = names.size();
        for (const std::string& code : codes) {
            for (std::sregex_iterator it(code.begin(), code.end(), alias), end; it != end; ++it)
                if (names.count((*it)[2])) names.insert((*it)[1]);
            for (const auto& [name, body] : functions(code))
                if (names_any(body, names)) names.insert(name);
        }
    }
    return names;
}

// What a protocol file's report runs: the body of `static Result report(` and, to a fixed point,
// the bodies of the functions of that file it calls.
std::string report_part(const std::string& code) {
    const std::size_t at = code.find("static Result report(");
    if (at == std::string::npos) return {};
    std::string part = braced(code, code.find('{', at));
    const auto defs = functions(code);
    std::set<std::string> taken;
    for (bool more = true; more;) {
        more = false;
        for (const auto& [name, body] : defs)
            if (!taken.count(name) && std::regex_search(part, std::regex("\\b" + name + "\\s*\\("))) {
                taken.insert(name);
                part += body;
                more = true;
            }
    }
    return part;
}

} // namespace

TEST(ReportsReadOutcomes, DerivedNamesCoverTheKnownEnginesAndRunners) {
    const std::set<std::string> names = physics_names();
    for (const char* n : {"FewBodyEngine", "PipeEngine", "BasicEdEngine", "EdEngine", "BasicDsmcEngine", "DsmcEngine",
                          "HardSphereGas3D", "shoot", "build_pipe", "equilibrated_gas", "run_pipe", "impact_mean",
                          "construct", "run_method"})
        EXPECT_TRUE(names.count(n)) << n << " is not derived as an engine or a runner";
    for (const char* n : {"pipe_spec", "pipe_law", "log_space", "with_pbd", "sonine_a2"})
        EXPECT_FALSE(names.count(n)) << n << " runs no physics but is derived as a runner";
}

TEST(ReportsReadOutcomes, NoReportConstructsAnEngineOrRunsAScenario) {
    const std::set<std::string> names = physics_names();
    int scanned = 0, protocols = 0;
    for (const fs::path& p : files_under(kRoot / "experiments", {".cpp"})) {
        const std::string text = text_of(p), code = code_only(text);
        std::string part;
        if (is_report_file(p)) {
            part = code;
            EXPECT_EQ(text.find("#include \"engines/"), std::string::npos) << p << " includes an engine header";
            ++scanned;
        } else {
            part = report_part(code);
            protocols += !part.empty();
        }
        std::string which;
        EXPECT_FALSE(names_any(part, names, &which)) << p << ": a report names " << which
                                                     << " (physics belongs in compute or prepare)";
    }
    EXPECT_GE(scanned, 10);
    EXPECT_GE(protocols, 8);
}
