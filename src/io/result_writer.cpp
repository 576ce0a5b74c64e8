#include "io/result_writer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <map>
#include <sstream>

#include "core/input_error.hpp"
#include "core/provenance.hpp"
#include "core/stable_hash.hpp"
#include "core/untrusted_file.hpp"
#include "io/durable_file.hpp"
#include "io/h5_file.hpp"

#include <hdf5_hl.h>

namespace granrepro {

namespace {
// A scalar (rank-0) dataset of one value with its unit and description.
template <class T>
void scalar_dataset(const H5Object& g, const std::string& name, hid_t file_type, hid_t mem_type, T value,
                    const std::string& unit, const std::string& description) {
    const H5Object space(H5Screate(H5S_SCALAR), &H5Sclose);
    const H5Object dcpl(H5Pcreate(H5P_DATASET_CREATE), &H5Pclose);
    H5Pset_attr_creation_order(dcpl.id(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
    const hid_t id = H5Dcreate2(g.id(), name.c_str(), file_type, space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT);
    if (id < 0) throw std::runtime_error("HDF5: dataset " + name);
    const H5Object d(id, &H5Dclose);
    if (H5Dwrite(d.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) < 0)
        throw std::runtime_error("HDF5: write " + name);
    d.attr("unit", unit);
    if (!description.empty()) d.attr("description", description);
}

// The table's first column becomes an HDF5 dimension scale (H5DS) attached to the others.
void attach_x_scale(const H5Object& table, const Table& t) {
    if (t.columns.size() < 1) return;
    const H5Object x(H5Dopen2(table.id(), t.columns[0].name.c_str(), H5P_DEFAULT), &H5Dclose);
    if (x.id() < 0 || H5DSset_scale(x.id(), t.columns[0].name.c_str()) < 0)
        throw std::runtime_error("HDF5: dimension scale " + t.name + "/" + t.columns[0].name);
    for (std::size_t c = 1; c < t.columns.size(); ++c) {
        if (t.columns[c].values.size() != t.columns[0].values.size()) continue; // not a function of x
        const H5Object y(H5Dopen2(table.id(), t.columns[c].name.c_str(), H5P_DEFAULT), &H5Dclose);
        if (y.id() < 0 || H5DSattach_scale(y.id(), x.id(), 0) < 0)
            throw std::runtime_error("HDF5: attach scale to " + t.name + "/" + t.columns[c].name);
    }
}

// The links of a group in creation order where it was tracked (files before 2026-12: by name).
std::vector<std::string> links_in_creation_order(const H5Object& g) {
    try {
        return g.children(H5_INDEX_CRT_ORDER);
    } catch (const std::runtime_error&) {
        return g.children();
    }
}

// Copies one table to another file: H5Ocopy would carry the dimension-scale attributes, whose
// object references then point nowhere, so the columns are copied without them and the scales
// attached again as they were.
void copy_table(const H5Object& tables_in, const std::string& name, const H5Object& tables_out) {
    const H5Object in = tables_in.open_group(name);
    const H5Object out = tables_out.group(name);
    for (const auto& a : in.attribute_names()) in.copy_attr_to(a, out);
    const auto columns = links_in_creation_order(in);
    const H5Object ocpypl(H5Pcreate(H5P_OBJECT_COPY), &H5Pclose);
    H5Pset_copy_object(ocpypl.id(), H5O_COPY_WITHOUT_ATTR_FLAG);
    auto open = [](const H5Object& g, const std::string& c) {
        const hid_t id = H5Dopen2(g.id(), c.c_str(), H5P_DEFAULT);
        if (id < 0) throw std::runtime_error("HDF5: open " + c);
        return H5Object(id, &H5Dclose);
    };
    std::vector<std::string> scales;
    for (const auto& c : columns) {
        if (H5Ocopy(in.id(), c.c_str(), out.id(), c.c_str(), ocpypl.id(), H5P_DEFAULT) < 0)
            throw std::runtime_error("HDF5: copy " + name + "/" + c);
        const H5Object din = open(in, c), dout = open(out, c);
        for (const auto& a : din.attribute_names())
            if (a != "CLASS" && a != "NAME" && a != "REFERENCE_LIST" && a != "DIMENSION_LIST") din.copy_attr_to(a, dout);
        if (H5DSis_scale(din.id()) > 0) {
            if (H5DSset_scale(dout.id(), c.c_str()) < 0) throw std::runtime_error("HDF5: dimension scale " + c);
            scales.push_back(c);
        }
    }
    for (const auto& s : scales) {
        const H5Object sin = open(in, s), sout = open(out, s);
        for (const auto& c : columns) {
            if (c == s) continue;
            const H5Object din = open(in, c);
            if (H5DSis_attached(din.id(), sin.id(), 0) > 0 && H5DSattach_scale(open(out, c).id(), sout.id(), 0) < 0)
                throw std::runtime_error("HDF5: attach scale to " + name + "/" + c);
        }
    }
}

// The canonical bytes of a hash: every text ends with a NUL, so no two sequences of names run
// together into the same bytes; numbers are their 8 little-endian bytes, NaN payloads included.
struct ContentHash {
    std::uint64_t h = kFnv1a64Start;
    void text(const std::string& s) { h = fnv1a64(std::string_view(s.c_str(), s.size() + 1), h); }
    void u64(std::uint64_t x) {
        char b[8];
        for (int i = 0; i < 8; ++i) b[i] = char((x >> (8 * i)) & 0xff);
        h = fnv1a64(std::string_view(b, 8), h);
    }
    void column(const std::string& name, const std::string& unit, const std::vector<double>& values) {
        text(name);
        text(unit);
        u64(values.size());
        for (const double v : values) u64(std::bit_cast<std::uint64_t>(v));
    }
    std::string hex() const { return "fnv1a64:" + hex64(h); }
};

H5Object open_dataset(const H5Object& g, const std::string& name) {
    const hid_t id = H5Dopen2(g.id(), name.c_str(), H5P_DEFAULT);
    if (id < 0) throw std::runtime_error("cannot open dataset " + name);
    return H5Object(id, &H5Dclose);
}

std::string utc_now() {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    std::ostringstream os;
    os << std::put_time(&tm, "%Y-%m-%dT%H:%M:%SZ");
    return os.str();
}
} // namespace

void write_result_h5(const std::filesystem::path& file, const Provenance& prov, const ParameterSet& params,
                     const Result& result, const std::string& summary_hash) {
    H5File f = H5File::create(file.string());
    f.stamp_schema("granrepro-result", 3);
    f.attr("experiment", prov.experiment);
    f.attr("paper", prov.paper);
    f.attr("scale", std::string(to_string(prov.scale)));
    f.attr_u64("seed", prov.seed);
    f.attr("code_version", std::string(code_version()));
    f.attr("physics_hash", std::string(physics_hash()));
    f.attr("wall_time_s", prov.wall_time_s);
    f.attr("threads", long(prov.threads));
    f.attr("created_utc", utc_now());
    f.attr("experiment_file", prov.experiment_file_text);
    f.attr("summary_json_hash", summary_hash);
    f.attr("cpu_time_s", prov.cpu_time_s);
    f.attr("total_wall_time_s", prov.total_wall_time_s);
    f.attr("total_cpu_time_s", prov.total_cpu_time_s);
    f.attr("resumed_points", prov.resumed_points);
    f.attr("points_without_cost", prov.points_without_cost);
    {
        const H5Object g = f.group("parameters");
        for (const auto& p : params.all()) {
            switch (p.kind) {
            case Parameter::Kind::Real:
                scalar_dataset(g, p.name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, p.real, p.unit, p.help);
                break;
            case Parameter::Kind::Integer:
                scalar_dataset(g, p.name, H5T_STD_I64LE, H5T_NATIVE_LONG, p.integer, p.unit, p.help);
                break;
            case Parameter::Kind::Flag:
                scalar_dataset(g, p.name, H5T_STD_U8LE, H5T_NATIVE_UINT8, std::uint8_t(p.flag ? 1 : 0), p.unit, p.help);
                break;
            case Parameter::Kind::RealList: g.dataset(p.name, p.reals, p.unit, p.help); break;
            case Parameter::Kind::Text: g.attr(p.name, p.text); break;
            }
        }
        for (const auto& p : params.all()) g.attr(p.name + ".source", p.source);
    }
    {
        const H5Object g = f.group("scalars");
        for (const auto& s : result.scalars)
            scalar_dataset(g, s.name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, s.value, s.unit, s.description);
    }
    const H5Object tables = f.group("tables");
    for (const auto& t : result.tables) {
        const H5Object g = tables.group(t.name);
        g.attr("description", t.description);
        for (const auto& c : t.columns) g.dataset(c.name, c.values, c.unit);
        attach_x_scale(g, t);
    }
    if (prov.points && !prov.points->points.empty()) {
        const H5Object g = f.group("points");
        g.attr("count", long(prov.points->points.size()));
        std::string sweeps;
        for (const auto& p : prov.points->points)
            if (("," + sweeps + ",").find("," + p.sweep + ",") == std::string::npos) sweeps += (sweeps.empty() ? "" : ",") + p.sweep;
        g.attr("sweeps", sweeps);
        g.compressed_text("records", points_records_text(*prov.points));
    }
    {
        const H5Object g = f.group("provenance");
        g.attr("command_line", prov.command_line);
        std::string sets;
        for (const auto& p : params.all())
            if (p.overridden) sets += (sets.empty() ? "" : "\n") + p.name + "=" + p.value_text();
        g.attr("overridden_parameters", sets);
        for (const auto& [what, version] : library_versions()) g.attr("version_" + what, version);
        g.attr("expected_file", prov.expected_file_text);
        for (const auto& [id, text] : prov.plot_texts) g.attr("plot_" + id, text);
    }
    f.close();
}

void write_tables_tsv(const std::filesystem::path& dir, const Result& result) {
    std::filesystem::create_directories(dir);
    for (const auto& t : result.tables) {
        std::ostringstream out;
        out << std::setprecision(10);
        std::size_t rows = 0;
        for (std::size_t c = 0; c < t.columns.size(); ++c) {
            out << (c ? "\t" : "") << t.columns[c].name;
            rows = std::max(rows, t.columns[c].values.size());
        }
        // Units as a comment line, which gnuplot skips: the column names stay usable as
        // columnhead and column("name").
        out << "\n#";
        for (std::size_t c = 0; c < t.columns.size(); ++c) out << (c ? "\t[" : " [") << t.columns[c].unit << "]";
        out << "\n";
        for (std::size_t r = 0; r < rows; ++r) {
            for (std::size_t c = 0; c < t.columns.size(); ++c) {
                const auto& v = t.columns[c].values;
                out << (c ? "\t" : "");
                if (r < v.size() && std::isfinite(v[r])) out << v[r];
                else out << "NaN";
            }
            out << "\n";
        }
        write_file_durably(dir / (t.name + ".tsv"), out.str());
    }
}

nlohmann::json scalars_json(const Result& result) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& s : result.scalars) j[s.name] = std::isfinite(s.value) ? nlohmann::json(s.value) : nlohmann::json();
    return j;
}

nlohmann::json summary_json(const Provenance& prov, const ParameterSet& params, const Result& result) {
    nlohmann::json sets = nlohmann::json::object(), units = nlohmann::json::object();
    for (const auto& p : params.all())
        if (p.overridden) sets[p.name] = p.value_text();
    for (const auto& s : result.scalars) units[s.name] = s.unit;
    nlohmann::json hashes = data_content_hash(result);
    if (prov.points && !prov.points->points.empty()) hashes["points"] = points_hash(points_records_text(*prov.points));
    return {{"schema", "granrepro-summary"}, {"schema_version", 3}, {"experiment", prov.experiment},
            {"scale", to_string(prov.scale)}, {"seed", prov.seed}, {"code_version", code_version()},
            {"physics_hash", physics_hash()}, {"wall_time_s", prov.wall_time_s}, {"cpu_time_s", prov.cpu_time_s},
            {"total_wall_time_s", prov.total_wall_time_s}, {"total_cpu_time_s", prov.total_cpu_time_s},
            {"resumed_points", prov.resumed_points}, {"points_without_cost", prov.points_without_cost},
            {"stored_points", prov.points ? long(prov.points->points.size()) : 0L},
            {"command_line", prov.command_line},
            {"overridden_parameters", sets}, {"scalars", scalars_json(result)}, {"units", units},
            {"parameters", params.to_json()}, {"data_h5_hash", hashes}};
}

std::string points_records_text(const SweepPoints& points) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& p : points.points) {
        const PointCost& c = p.cost;
        a.push_back({{"sweep", p.sweep},
                     {"point", p.index},
                     {"inputs", p.inputs},
                     {"resumed", p.resumed},
                     {"persisted", p.persisted},
                     {"cost", {{"cpu_s", c.cpu_s}, {"wall_s", c.wall_s}, {"started_unix", c.started_unix},
                               {"part", c.part}, {"rank", c.rank}}},
                     {"outcome", p.outcome}});
    }
    return a.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::json compact_outcome(const nlohmann::json& outcome, std::size_t max_values, bool* changed) {
    if (outcome.is_array()) {
        // Arrays of numbers, and arrays of small tuples of numbers (positions as [x, y]), count
        // their numbers.
        const auto number = [](const nlohmann::json& x) { return x.is_number() || x.is_null(); };
        const bool numbers = std::all_of(outcome.begin(), outcome.end(), [&](const auto& x) {
            return number(x) || (x.is_array() && x.size() <= 4 && std::all_of(x.begin(), x.end(), number));
        });
        if (numbers && outcome.size() > max_values) {
            if (changed) *changed = true;
            return {{"omitted_values", outcome.size()}, {"fnv1a64", points_hash(outcome.dump())}};
        }
        nlohmann::json a = nlohmann::json::array();
        for (const auto& x : outcome) a.push_back(compact_outcome(x, max_values, changed));
        return a;
    }
    if (outcome.is_object()) {
        nlohmann::json o = nlohmann::json::object();
        for (auto it = outcome.begin(); it != outcome.end(); ++it) o[it.key()] = compact_outcome(it.value(), max_values, changed);
        return o;
    }
    return outcome;
}

std::string points_hash(const std::string& records_text) { return "fnv1a64:" + hex64(fnv1a64(records_text)); }

void run_totals(Provenance& prov, const SweepPoints& points, double wall_s, double cpu_s) {
    prov.cpu_time_s = cpu_s;
    double cpu_here = 0, cpu_all = 0;
    long resumed = 0, unknown = 0;
    struct Span { double a = INFINITY, b = -INFINITY; };
    std::map<std::string, Span> parts; // earlier invocations
    for (const auto& p : points.points) {
        const PointCost& c = p.cost;
        resumed += p.resumed;
        if (c.cpu_s < 0) {
            unknown += p.resumed;
            continue;
        }
        cpu_all += c.cpu_s;
        if (!p.resumed && c.rank == 0) cpu_here += c.cpu_s; // inside this process's CPU time
        if (p.resumed && c.started_unix >= 0 && c.wall_s >= 0) {
            Span& span = parts[c.part];
            span.a = std::min(span.a, c.started_unix);
            span.b = std::max(span.b, c.started_unix + c.wall_s);
        }
    }
    // The union of the earlier invocations' spans (shards may have run at the same time).
    std::vector<Span> spans;
    for (const auto& [id, sp] : parts) spans.push_back(sp);
    std::sort(spans.begin(), spans.end(), [](const Span& x, const Span& y) { return x.a < y.a; });
    double earlier = 0, end = -INFINITY;
    for (const auto& sp : spans) {
        const double from = std::max(sp.a, end);
        if (sp.b > from) earlier += sp.b - from;
        end = std::max(end, sp.b);
    }
    prov.total_wall_time_s = wall_s + earlier;
    prov.total_cpu_time_s = cpu_s - cpu_here + cpu_all;
    prov.resumed_points = resumed;
    prov.points_without_cost = unknown;
}

nlohmann::json read_points_records(const std::filesystem::path& h5) {
    const H5File f = H5File::open(h5.string());
    if (!f.has("points")) return nlohmann::json::array();
    const std::string where = h5.string() + ": /points/records";
    std::string text;
    try {
        text = f.open_group("points").read_text("records", kMaxPointFileBytes);
    } catch (const std::runtime_error& e) {
        throw InputError(where + ": cannot be read (" + e.what() + ")");
    }
    nlohmann::json records = parse_untrusted_json(text, where);
    if (!records.is_array()) throw InputError(where + ": not a JSON array of point records");
    return records;
}

namespace {
// One dataset of /parameters as written by write_result_h5: scalar float64 (real), scalar int64
// (integer), scalar uint8 (flag), 1-D float64 (list of reals). Files before 2026-12 stored every
// one as a 1-D dataset; read alike, as an array (see stored_parameter_as).
nlohmann::json stored_parameter(const H5Object& g, const std::string& name) {
    const H5Object d = open_dataset(g, name);
    const H5Object t(H5Dget_type(d.id()), &H5Tclose);
    const H5Object sp(H5Dget_space(d.id()), &H5Sclose);
    if (t.id() < 0 || sp.id() < 0) throw std::runtime_error("parameter " + name + ": unreadable");
    const H5S_class_t shape = H5Sget_simple_extent_type(sp.id());
    const H5T_class_t kind = H5Tget_class(t.id());
    const bool scalar = shape == H5S_SCALAR;
    const bool list = shape == H5S_SIMPLE && H5Sget_simple_extent_ndims(sp.id()) == 1 &&
                      H5Sget_simple_extent_npoints(sp.id()) <= (1 << 20);
    if ((!scalar && !list) || (kind != H5T_FLOAT && kind != H5T_INTEGER))
        throw std::runtime_error("parameter " + name + " in /parameters is neither a number, a flag nor a list of numbers");
    nlohmann::json values;
    if (kind == H5T_FLOAT) values = g.read_dataset(name);
    else if (H5Tget_size(t.id()) == 1 && H5Tget_sign(t.id()) == H5T_SGN_NONE)
        for (const std::uint8_t b : g.read_array<std::uint8_t>(name)) values.push_back(b != 0);
    else values = g.read_array<long>(name);
    if (!values.is_array()) values = nlohmann::json::array();
    return scalar ? values.at(0) : values;
}
} // namespace

nlohmann::json stored_parameter_as(const nlohmann::json& stored, const nlohmann::json& reference) {
    if (stored.is_array() && stored.size() == 1 && !reference.is_array()) return stored[0];
    return stored;
}

nlohmann::json read_stored_parameters(const H5Object& root) {
    if (!root.has("parameters")) throw std::runtime_error("has no /parameters group");
    const H5Object g = root.open_group("parameters");
    nlohmann::json out = nlohmann::json::object();
    for (const auto& name : g.children()) out[name] = stored_parameter(g, name);
    for (const auto& a : g.attribute_names()) // text parameters, beside each parameter's source
        if (!a.ends_with(".source") && a != "schema" && a != "schema_version") out[a] = g.read_string_attr(a);
    return out;
}

nlohmann::json data_content_hash(const Result& result) {
    ContentHash scalars;
    for (const auto& s : result.scalars) scalars.column(s.name, s.unit, {s.value});
    nlohmann::json tables = nlohmann::json::object();
    for (const auto& t : result.tables) {
        ContentHash h;
        h.text(t.name);
        for (const auto& c : t.columns) h.column(c.name, c.unit, c.values);
        tables[t.name] = h.hex();
    }
    return {{"scalars", scalars.hex()}, {"tables", tables}};
}

nlohmann::json data_content_hash(const std::filesystem::path& h5) {
    const H5File f = H5File::open(h5.string());
    auto column = [](ContentHash& h, const H5Object& g, const std::string& name) {
        h.column(name, open_dataset(g, name).read_string_attr("unit"), g.read_dataset(name));
    };
    ContentHash scalars;
    const H5Object sg = f.open_group("scalars");
    for (const auto& s : links_in_creation_order(sg)) column(scalars, sg, s);
    nlohmann::json tables = nlohmann::json::object();
    const H5Object tg = f.open_group("tables");
    for (const auto& t : links_in_creation_order(tg)) {
        const H5Object g = tg.open_group(t);
        ContentHash h;
        h.text(t);
        for (const auto& c : links_in_creation_order(g)) column(h, g, c);
        tables[t] = h.hex();
    }
    nlohmann::json out = {{"scalars", scalars.hex()}, {"tables", tables}};
    if (f.has("points")) {
        // A compact copy whose large arrays were digested vouches with the full records' hash.
        const H5Object g = f.open_group("points");
        const std::string records = g.read_text("records", kMaxPointFileBytes);
        out["points"] = g.has_attr("full_records_hash") ? g.read_string_attr("full_records_hash") : points_hash(records);
    }
    return out;
}

// Bytes that are not UTF-8 (an --out path in Latin-1, in command_line) become U+FFFD: dump() would
// throw, and the replacement reads back as itself, so the hash still matches the file.
std::string summary_content_hash(const nlohmann::json& summary) {
    return "fnv1a64:" + hex64(fnv1a64(summary.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
}

std::string summary_text(const nlohmann::json& summary) {
    return summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::vector<std::string> write_compact_result_h5(const std::filesystem::path& src, const std::filesystem::path& dst,
                                                 std::size_t max_values) {
    const H5File in = H5File::open(src.string());
    in.require_schema("granrepro-result", 3);
    H5File out = H5File::create(dst.string());
    // A compact copy of a compact copy (export of paper_figures/): its own omissions carry over
    // into the new listing, the two compaction attributes are written once, below.
    std::string listing = in.has_attr("omitted_tables") ? in.read_string_attr("omitted_tables") : "none";
    if (listing == "none") listing.clear();
    if (in.has_attr("compacted_to_max_values")) max_values = std::min<std::size_t>(max_values, std::size_t(std::max(0L, in.read_long_attr("compacted_to_max_values"))));
    for (const auto& a : in.attribute_names())
        if (a != "omitted_tables" && a != "compacted_to_max_values") in.copy_attr_to(a, out);
    for (const char* g : {"parameters", "scalars", "provenance"})
        if (in.has(g)) in.copy_to(g, out);
    if (in.has("points")) {
        const H5Object pin = in.open_group("points");
        const H5Object pout = out.group("points");
        for (const auto& a : pin.attribute_names()) pin.copy_attr_to(a, pout);
        const std::string text = pin.read_text("records", kMaxPointFileBytes);
        nlohmann::json records = parse_untrusted_json(text, src.string() + ": /points/records");
        if (!records.is_array()) throw std::runtime_error("/points/records: not a JSON array");
        bool any = false;
        for (auto& r : records) {
            if (!r.is_object()) throw std::runtime_error("/points/records: a record is not a JSON object");
            bool changed = false;
            nlohmann::json c = compact_outcome(r["outcome"], kMaxPointArrayValues, &changed);
            if (!changed) continue;
            r["outcome"] = std::move(c);
            r["compacted"] = true;
            any = true;
        }
        if (any) {
            if (!pin.has_attr("compacted_arrays_over")) pout.attr("compacted_arrays_over", long(kMaxPointArrayValues));
            if (!pin.has_attr("full_records_hash")) pout.attr("full_records_hash", points_hash(text));
            pout.compressed_text("records", records.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
        } else {
            pout.compressed_text("records", text);
        }
    }
    const H5Object tables_in = in.open_group("tables");
    const H5Object tables_out = out.group("tables");
    std::vector<std::string> omitted;
    for (const auto& t : tables_in.children()) {
        const H5Object g = tables_in.open_group(t);
        std::size_t n = 0;
        for (const auto& c : g.children()) n += g.dataset_size(c);
        if (n <= max_values) {
            copy_table(tables_in, t, tables_out);
        } else {
            omitted.push_back(t);
            listing += (listing.empty() ? "" : ", ") + t + " (" + std::to_string(n) + " values)";
        }
    }
    out.attr("omitted_tables", listing.empty() ? std::string("none") : listing);
    out.attr("compacted_to_max_values", long(max_values));
    out.close();
    return omitted;
}

} // namespace granrepro
