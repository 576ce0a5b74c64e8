#include <cstdlib>
#include <toml.hpp>

#include "core/input_error.hpp"
#include "harness/experiment.hpp"

namespace granrepro {

std::filesystem::path project_root() {
    if (const char* home = std::getenv("GRANREPRO_HOME"); home && *home) return home;
    return GRANREPRO_SOURCE_DIR;
}

ExperimentInfo ExperimentInfo::load(const std::filesystem::path& file) {
    if (!std::filesystem::exists(file)) throw InputError(file.string() + ": experiment file not found");
    try {
        const auto root = toml::parse(file.string());
        ExperimentInfo info;
        info.file = file;
        info.name = toml::find<std::string>(root, "name");
        info.paper = toml::find<std::string>(root, "paper");
        info.description = toml::find<std::string>(root, "description");
        if (root.contains("figure"))
            for (const auto& f : toml::find<toml::array>(root, "figure"))
                info.figures.push_back({toml::find<std::string>(f, "id"), toml::find<std::string>(f, "caption")});
        return info;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        std::string msg = e.what();
        throw InputError(file.string() + ": " + msg.substr(0, msg.find('\n')));
    }
}

} // namespace granrepro
