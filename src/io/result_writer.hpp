// The result schema "granrepro-result" (version 3; 3 adds /points and the run totals), written into a run's directory; docs/schema.md
// describes every group, dataset and attribute (a test checks it names all that the writer emits):
//   data.h5       root attributes: schema, schema_version, experiment, paper, scale, seed (uint64),
//                 code_version, wall_time_s, threads, created_utc, experiment_file (its full text),
//                 summary_json_hash (the content hash of summary.json);
//                 /parameters/<name>  scalar (float64, int64, uint8 flag) or 1-D float64 dataset
//                                     with unit, description; text parameters as attributes
//                 /scalars/<name>     scalar float64 dataset, attributes unit, description
//                 /tables/<table>/<column>  1-D float64 datasets with unit; the first column is a
//                                     dimension scale of the others; the group has a description
//                 /provenance         command line, --set overrides, library versions, the text of
//                                     expected/<experiment>.toml and of the plots/ scripts used
//                 Links and attributes are created with creation order tracked.
//   tables/<table>.tsv   the same columns as text: a header line of names, a comment line of units
//   summary.json  scalars, provenance, claim verdicts and data_h5_hash
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
#include "data/sweep_points.hpp"

namespace granrepro {

class H5Object;

struct Provenance {
    std::string experiment, paper, experiment_file_text;
    Scale scale = Scale::Quick;
    std::uint64_t seed = 0;
    double wall_time_s = 0;
    int threads = 1;
    std::string command_line;                                      // as typed
    std::string expected_file_text;                                // expected/<experiment>.toml
    std::vector<std::pair<std::string, std::string>> plot_texts;   // figure id, plots/<id>.gp
    // Schema 3: the cost of the whole run, resumed points included (run_totals()), and every
    // sweep point (data.h5 /points; null: none recorded).
    double cpu_time_s = 0;        // this invocation's process CPU time [s]
    double total_wall_time_s = 0; // wall_time_s + the wall time of earlier invocations it resumed
    double total_cpu_time_s = 0;  // cpu_time_s + the CPU time of the points it resumed (and of other ranks)
    long resumed_points = 0;
    long points_without_cost = 0; // resumed points from files before costs were recorded: totals are lower bounds
    const SweepPoints* points = nullptr;
};

// The results' record of every sweep point: the text of data.h5's /points/records, a JSON array
// of {"sweep", "point", "inputs", "resumed", "persisted", "cost": {cpu_s, wall_s, started_unix,
// part, rank}, "outcome"} (docs/schema.md), and its content hash "fnv1a64:<hex>".
std::string points_records_text(const SweepPoints& points);
std::string points_hash(const std::string& records_text);
// The run's totals from its points: fills cpu_time_s (given), total_wall_time_s,
// total_cpu_time_s, resumed_points, points_without_cost of prov. wall_s and cpu_s: this
// invocation's wall and process CPU time. Earlier invocations' wall time is the union of the
// spans of the points each computed (start of its first to end of its last), so concurrent
// shards count once; their serial parts outside points are not known and left out.
void run_totals(Provenance& prov, const SweepPoints& points, double wall_s, double cpu_s);
// The stored points of a result file (empty if it has none), read
// bounded (kMaxPointFileBytes, kMaxJsonDepth); refused (InputError) if they are not an array.
nlohmann::json read_points_records(const std::filesystem::path& h5);
// data.h5's /parameters as {name: value} (reals and integers as numbers, flags as booleans, lists
// as arrays, text as strings); refused (std::runtime_error naming the parameter) if /parameters is
// missing or holds a value of another layout.
nlohmann::json read_stored_parameters(const H5Object& root);
// A stored value as a parameter of `reference`'s kind: files before 2026-12 stored a number as a
// 1-D dataset of one value.
nlohmann::json stored_parameter_as(const nlohmann::json& stored, const nlohmann::json& reference);

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
// (nlohmann::json orders them), numbers as dump() writes them (Grisu2: round-trip, not always the
// shortest digits; python/granrepro/reader.py ports it); independent of how
// summary.json is indented.
std::string summary_content_hash(const nlohmann::json& summary);
// summary.json's text: indented, invalid UTF-8 replaced by U+FFFD as in summary_content_hash.
std::string summary_text(const nlohmann::json& summary);

// In a compact copy, a stored point's arrays of more numbers than this (cluster-growth's
// per-particle counts and positions: 79524 at paper scale; traces of a few thousand samples) are replaced by
// a digest (compact_outcome): paper_figures/ holds 14 MB, 23 MB with 10000 and positions kept.
inline constexpr std::size_t kMaxPointArrayValues = 1000;
// The outcome with every array of more than max_values numbers replaced by its digest
// {"omitted_values": n, "fnv1a64": "fnv1a64:<hex of the array's compact JSON>"}; *changed tells
// whether one was. `verify` compacts a recomputed outcome the same way to compare it.
nlohmann::json compact_outcome(const nlohmann::json& outcome, std::size_t max_values, bool* changed = nullptr);

// A compact copy of a result file, small enough to commit next to the figures (paper_figures/):
// the root attributes, /parameters, /scalars and every table of at most max_values values in
// all; larger tables (particle snapshots) are left out and named, with their sizes, in the root
// attribute "omitted_tables". /points is kept, its large arrays digested (kMaxPointArrayValues;
// /points attributes compacted_arrays_over and full_records_hash, the hash summary.json
// recorded). Returns the names of the omitted tables.
std::vector<std::string> write_compact_result_h5(const std::filesystem::path& src, const std::filesystem::path& dst,
                                                 std::size_t max_values);

} // namespace granrepro
