#include "io/result_writer.hpp"

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "core/provenance.hpp"
#include "io/durable_file.hpp"
#include "io/h5_file.hpp"

namespace granrepro {

namespace {
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
                     const Result& result) {
    H5File f = H5File::create(file.string());
    f.attr("schema", std::string("granrepro-result"));
    f.attr("schema_version", 1L);
    f.attr("experiment", prov.experiment);
    f.attr("paper", prov.paper);
    f.attr("scale", std::string(to_string(prov.scale)));
    f.attr("seed", std::to_string(prov.seed));
    f.attr("code_version", std::string(code_version()));
    f.attr("wall_time_s", prov.wall_time_s);
    f.attr("threads", long(prov.threads));
    f.attr("created_utc", utc_now());
    f.attr("experiment_file", prov.experiment_file_text);
    {
        const H5Object g = f.group("parameters");
        for (const auto& p : params.all()) {
            std::vector<double> v;
            switch (p.kind) {
            case Parameter::Kind::Real: v = {p.real}; break;
            case Parameter::Kind::Integer: v = {double(p.integer)}; break;
            case Parameter::Kind::Flag: v = {p.flag ? 1.0 : 0.0}; break;
            case Parameter::Kind::RealList: v = p.reals; break;
            case Parameter::Kind::Text: break;
            }
            if (p.kind == Parameter::Kind::Text) {
                g.attr(p.name, p.text);
            } else {
                g.dataset(p.name, v, p.unit, p.help);
            }
        }
        for (const auto& p : params.all()) g.attr(p.name + ".source", p.source);
    }
    {
        const H5Object g = f.group("scalars");
        for (const auto& s : result.scalars) g.dataset(s.name, {s.value}, s.unit, s.description);
    }
    {
        const H5Object tables = f.group("tables");
        for (const auto& t : result.tables) {
            const H5Object g = tables.group(t.name);
            g.attr("description", t.description);
            for (const auto& c : t.columns) g.dataset(c.name, c.values, c.unit);
        }
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
    nlohmann::json j;
    j["schema"] = "granrepro-summary";
    j["schema_version"] = 1;
    j["experiment"] = prov.experiment;
    j["scale"] = to_string(prov.scale);
    j["seed"] = prov.seed;
    j["code_version"] = code_version();
    j["wall_time_s"] = prov.wall_time_s;
    j["scalars"] = scalars_json(result);
    nlohmann::json units = nlohmann::json::object();
    for (const auto& s : result.scalars) units[s.name] = s.unit;
    j["units"] = units;
    j["parameters"] = params.to_json();
    return j;
}

std::vector<std::string> write_compact_result_h5(const std::filesystem::path& src, const std::filesystem::path& dst,
                                                 std::size_t max_values) {
    const H5File in = H5File::open(src.string());
    in.require_schema("granrepro-result", 1);
    H5File out = H5File::create(dst.string());
    for (const auto& a : in.attribute_names()) in.copy_attr_to(a, out);
    for (const char* g : {"parameters", "scalars"}) in.copy_to(g, out);
    const H5Object tables_in = in.open_group("tables");
    const H5Object tables_out = out.group("tables");
    std::vector<std::string> omitted;
    std::string listing;
    for (const auto& t : tables_in.children()) {
        const H5Object g = tables_in.open_group(t);
        std::size_t n = 0;
        for (const auto& c : g.children()) n += g.dataset_size(c);
        if (n <= max_values) {
            tables_in.copy_to(t, tables_out);
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
