// The result schema "granrepro-result" (version 2), written into a run's directory; docs/schema.md
// describes every group, dataset and attribute (a test checks it names all that the writer emits):
//   data.h5       root attributes: schema, schema_version, experiment, paper, scale, seed (uint64),
//                 code_version, wall_time_s, threads, created_utc, experiment_file (its full text),
//                 summary_json_hash (version 2: the content hash of summary.json);
//                 /parameters/<name>  scalar (float64, int64, uint8 flag) or 1-D float64 dataset
//                                     with unit, description; text parameters as attributes
//                 /scalars/<name>     scalar float64 dataset, attributes unit, description
//                 /tables/<table>/<column>  1-D float64 datasets with unit; the first column is a
//                                     dimension scale of the others; the group has a description
//                 /provenance         command line, --set overrides, library versions, the text of
//                                     expected/<experiment>.toml and of the plots/ scripts used
//                 Links and attributes are created with creation order tracked.
//   tables/<table>.tsv   the same columns as text: a header line of names, a comment line of units
//   summary.json  scalars, provenance, claim verdicts and data_h5_hash (version 2)
//   run.log       command, resolved parameters, progress, warnings, wall times
// Tables and scalars are stored in the order the experiment produced them, so the datasets
// are bit-identical for the same seed and inputs.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "data/parameter_set.hpp"
#include "data/result.hpp"

namespace granrepro {

struct Provenance {
    std::string experiment, paper, experiment_file_text;
    Scale scale = Scale::Quick;
    std::uint64_t seed = 0;
    double wall_time_s = 0;
    int threads = 1;
    std::string command_line;                                      // as typed
    std::string expected_file_text;                                // expected/<experiment>.toml
    std::vector<std::pair<std::string, std::string>> plot_texts;   // figure id, plots/<id>.gp
};

// summary_hash: summary_content_hash() of the summary.json written beside it (root attribute
// summary_json_hash).
void write_result_h5(const std::filesystem::path& file, const Provenance& prov, const ParameterSet& params,
                     const Result& result, const std::string& summary_hash);
void write_tables_tsv(const std::filesystem::path& dir, const Result& result);
nlohmann::json scalars_json(const Result& result);
// Carries data_h5_hash (data_content_hash of the result); the caller adds the claims.
nlohmann::json summary_json(const Provenance& prov, const ParameterSet& params, const Result& result);

// The two files of a run vouch for each other (docs/schema.md, "Content hashes"): summary.json
// records the hash of data.h5's scalars and of each table, data.h5 the hash of summary.json's
// content. FNV-1a 64 over a canonical serialization: it detects an edit of one file (or of both
// that does not redo the hashes), not a forgery; a keyless hash of any strength can be recomputed
// by whoever edits, so a cryptographic one would add nothing here.
// {"scalars": "fnv1a64:<hex>", "tables": {"<table>": "fnv1a64:<hex>", ...}}
nlohmann::json data_content_hash(const Result& result);
// The same, read from a result file (its tables as they are there); throws std::runtime_error if
// the file cannot be read whole.
nlohmann::json data_content_hash(const std::filesystem::path& h5);
// "fnv1a64:<hex>" of summary.dump(): the whole summary object as compact JSON, keys sorted
// (nlohmann::json orders them), numbers in their shortest round-trip form; independent of how
// summary.json is indented.
std::string summary_content_hash(const nlohmann::json& summary);
// summary.json's text: indented, invalid UTF-8 replaced by U+FFFD as in summary_content_hash.
std::string summary_text(const nlohmann::json& summary);

// A compact copy of a result file, small enough to commit next to the figures (paper_figures/):
// the root attributes, /parameters, /scalars and every table of at most max_values values in
// all; larger tables (particle snapshots) are left out and named, with their sizes, in the root
// attribute "omitted_tables". Returns the names of the omitted tables.
std::vector<std::string> write_compact_result_h5(const std::filesystem::path& src, const std::filesystem::path& dst,
                                                 std::size_t max_values);

} // namespace granrepro
