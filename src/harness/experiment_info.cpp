#include <cstdlib>
#include <toml.hpp>

#include "core/input_error.hpp"
#include "data/toml_file.hpp"
#include "harness/experiment.hpp"

namespace granrepro {

namespace {
bool holds_data(const std::filesystem::path& dir) {
    std::error_code ec;
    return std::filesystem::is_directory(dir / "experiments", ec);
}
} // namespace

DataRoot find_data_root() {
    // An installed binary: P/bin/granrepro next to P/share/granrepro (`cmake --install`).
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const auto shared = (exe.parent_path().parent_path() / "share" / "granrepro").lexically_normal();
        if (holds_data(shared)) return {shared, "installed next to the binary"};
    }
    if (const char* home = std::getenv("GRANREPRO_HOME"); home && *home) return {home, "$GRANREPRO_HOME"};
    return {GRANREPRO_SOURCE_DIR, "source tree the binary was built from"};
}

std::filesystem::path project_root() {
    static const std::filesystem::path root = find_data_root().path;
    return root;
}

ExperimentInfo ExperimentInfo::load(const std::filesystem::path& file) {
    const auto root = parse_toml_file(file, "experiment file");
    try {
        ExperimentInfo info;
        info.file = file;
        info.name = toml::find<std::string>(root, "name");
        info.paper = toml::find<std::string>(root, "paper");
        info.paper_key = toml::find<std::string>(root, "paper_key");
        info.paper_short = toml::find<std::string>(root, "paper_short");
        info.paper_citation = toml::find<std::string>(root, "paper_citation");
        info.description = toml::find<std::string>(root, "description");
        if (root.contains("figure"))
            for (const auto& f : toml::find<toml::array>(root, "figure")) {
                info.figures.push_back({toml::find<std::string>(f, "id"), toml::find<std::string>(f, "caption")});
                // The figure id names its paper: `granrepro figure` and the report rely on it.
                if (!info.figures.back().id.starts_with(info.paper_key + "-"))
                    throw InputError(file.string() + " (line " + std::to_string(f.location().line()) + "): figure id '" +
                                     info.figures.back().id + "' does not start with paper_key '" + info.paper_key + "-'");
            }
        if (root.contains("smoke")) {
            const toml::value& s = root.at("smoke");
            for (const auto& [key, v] : s.as_table())
                if (key != "set")
                    throw InputError(file.string() + " (line " + std::to_string(v.location().line()) +
                                     "): [smoke] has unknown key '" + key + "'; allowed: set");
            for (const auto& v : toml::find<toml::array>(s, "set")) {
                const std::string assignment = toml::get<std::string>(v);
                if (assignment.find('=') == std::string::npos || assignment.front() == '=')
                    throw InputError(file.string() + " (line " + std::to_string(v.location().line()) + "): [smoke] set '" +
                                     assignment + "' is not name=value");
                info.smoke.push_back(assignment);
            }
        }
        // Outputs are declared by the handles its reports write through (data/outputs.hpp).
        info.outputs = declared_outputs(info.name);
        return info;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(toml_error_line(file.string(), e.what()));
    }
}

} // namespace granrepro
