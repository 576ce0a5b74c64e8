// What `granrepro list --json` prints of each experiment, and the same object the report's claims
// file carries: one listing, read from experiments/<name>.toml (ExperimentInfo), for the Python
// report and scripts/test.sh alike.
#pragma once
#include <nlohmann/json.hpp>

#include "harness/experiment.hpp"

namespace granrepro {

// {name, description, paper, paper_key, paper_short, paper_citation, figures: [{id, caption}],
// smoke: ["name=value", ...]}
nlohmann::json experiment_listing(const ExperimentInfo& info);

// {"experiments": [experiment_listing of each registered experiment, in registry order]}
nlohmann::json experiments_listing();

} // namespace granrepro
