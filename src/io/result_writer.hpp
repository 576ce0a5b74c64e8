// The result schema "granrepro-result" (version 1), written into a run's directory:
//   data.h5       root attributes: schema, schema_version, experiment, paper, scale, seed,
//                 code_version, wall_time_s, created_utc, experiment_file (its full text);
//                 /parameters/<name>  scalar or 1-D dataset, attributes unit, source
//                 /scalars/<name>     1-element dataset, attributes unit, description
//                 /tables/<table>/<column>  1-D datasets with unit; the group has a description
//   tables/<table>.tsv   the same columns as text (header line of names) for gnuplot
//   summary.json  scalars, provenance and claim verdicts
// Tables and scalars are stored in the order the experiment produced them, so the datasets
// are bit-identical for the same seed and inputs.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/parameter_set.hpp"
#include "harness/result.hpp"

namespace granrepro {

struct Provenance {
    std::string experiment, paper, experiment_file_text;
    Scale scale = Scale::Quick;
    std::uint64_t seed = 0;
    double wall_time_s = 0;
    int threads = 1;
};

void write_result_h5(const std::filesystem::path& file, const Provenance& prov, const ParameterSet& params,
                     const Result& result);
void write_tables_tsv(const std::filesystem::path& dir, const Result& result);
nlohmann::json scalars_json(const Result& result);
nlohmann::json summary_json(const Provenance& prov, const ParameterSet& params, const Result& result);

// A compact copy of a result file, small enough to commit next to the figures (paper_figures/):
// the root attributes, /parameters, /scalars and every table of at most max_values values in
// all; larger tables (particle snapshots) are left out and named, with their sizes, in the root
// attribute "omitted_tables". Returns the names of the omitted tables.
std::vector<std::string> write_compact_result_h5(const std::filesystem::path& src, const std::filesystem::path& dst,
                                                 std::size_t max_values);

} // namespace granrepro
