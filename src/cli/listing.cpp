#include "cli/listing.hpp"

#include "harness/runner.hpp"

namespace granrepro {

nlohmann::json experiment_listing(const ExperimentInfo& info) {
    nlohmann::json figures = nlohmann::json::array();
    for (const auto& f : info.figures) figures.push_back({{"id", f.id}, {"caption", f.caption}});
    return {{"name", info.name},
            {"description", info.description},
            {"paper", info.paper},
            {"paper_key", info.paper_key},
            {"paper_short", info.paper_short},
            {"paper_citation", info.paper_citation},
            {"figures", figures},
            {"smoke", info.smoke},
            // every scalar and table a run can write, <n> a number (the handles of data/outputs.hpp)
            {"outputs", {{"scalars", info.outputs.scalars}, {"tables", info.outputs.tables}}}};
}

nlohmann::json experiments_listing() {
    nlohmann::json experiments = nlohmann::json::array();
    for (const auto& e : experiment_registry()) experiments.push_back(experiment_listing(experiment_info(e.name)));
    return {{"experiments", experiments}};
}

} // namespace granrepro
