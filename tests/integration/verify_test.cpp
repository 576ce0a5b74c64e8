// `granrepro verify` (issue 29 item 2): a stored sweep point reruns bit for bit; a stored value
// that differs from what the code computes is named (with the scalars and claims it moves);
// bad input is one line, exit 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "io/h5_file.hpp"
#include "io/result_writer.hpp"

namespace fs = std::filesystem;
using namespace granrepro;
using namespace cli_support;

namespace {

void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

H5Object open_for_edit(const fs::path& h5) { return H5Object(H5Fopen(h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), &H5Fclose); }

void replace_root_string(const H5Object& f, const std::string& name, const std::string& value) {
    ASSERT_GE(H5Adelete(f.id(), name.c_str()), 0) << name;
    f.attr(name, value);
}

// Rewrites summary.json and re-stamps data.h5's hash of it, as a careful forger (or an old writer)
// would: `check` then accepts the pair, and only a rerun can tell.
void rewrite_summary(const fs::path& dir, const nlohmann::json& summary) {
    put(dir / "summary.json", summary_text(summary));
    const H5Object f = open_for_edit(dir / "data.h5");
    ASSERT_GE(f.id(), 0);
    replace_root_string(f, "summary_json_hash", summary_content_hash(summary));
}

// Edits stored point `k`'s outcome with `edit` and keeps both content hashes consistent.
template <class Edit>
void edit_point(const fs::path& dir, long k, Edit edit) {
    nlohmann::json s = summary(dir);
    {
        const H5Object f = open_for_edit(dir / "data.h5");
        const H5Object g(H5Gopen2(f.id(), "points", H5P_DEFAULT), &H5Gclose);
        const auto bytes = g.read_bytes("records");
        nlohmann::json records = nlohmann::json::parse(std::string(bytes.begin(), bytes.end()));
        edit(records[std::size_t(k)]["outcome"]);
        const std::string text = records.dump();
        ASSERT_GE(H5Ldelete(g.id(), "records", H5P_DEFAULT), 0);
        g.compressed_text("records", text);
        s["data_h5_hash"]["points"] = points_hash(text);
    }
    rewrite_summary(dir, s);
}

const std::string kQuickBrake = "brake-failure --quiet --scale quick --out ";

} // namespace

TEST(Verify, FreshResultsReproduceBitForBitAndListTheirCosts) {
    const TempPath out("verify-fresh");
    ASSERT_EQ(run(kQuickBrake + out.string()).code, 0);
    const Outcome listed = run("verify brake-failure --list --out " + out.string());
    ASSERT_EQ(listed.code, 0) << listed.err;
    EXPECT_NE(listed.out.find("19 stored points"), std::string::npos) << listed.out;
    EXPECT_NE(listed.out.find("CPU s"), std::string::npos) << listed.out;
    for (const char* point : {"", " --point 0", " --point 14", " --point 3 --point-only"}) {
        const Outcome o = run("verify brake-failure --out " + out.string() + point);
        SCOPED_TRACE(point);
        EXPECT_EQ(o.code, 0) << o.out << o.err;
        EXPECT_NE(o.out.find("reproduced"), std::string::npos) << o.out;
        EXPECT_NE(o.out.find("as recorded"), std::string::npos) << "inputs fingerprint: " << o.out;
    }
    // The compact copy (export) keeps the points.
    const TempPath exported("verify-fresh-export");
    ASSERT_EQ(run("export brake-failure --out " + out.string() + " --to " + exported.string()).code, 0);
    EXPECT_EQ(run("verify brake-failure --point 2 --out " + exported.string()).code, 0);
    // A copy of the copy (a reviewer exporting paper_figures/): once exit 2 "attribute already
    // exists" (omitted_tables); now its omissions carry over and check accepts it.
    const TempPath again("verify-fresh-export-again");
    const Outcome twice = run("export brake-failure --max-table-values 10 --out " + exported.string() + " --to " + again.string());
    ASSERT_EQ(twice.code, 0) << twice.err;
    EXPECT_EQ(run("check brake-failure --out " + again.string()).code, 0);
    const H5File f = H5File::open((again / "brake-failure" / "data.h5").string());
    EXPECT_NE(f.read_string_attr("omitted_tables"), "none");
    EXPECT_EQ(f.read_long_attr("compacted_to_max_values"), 10);
}

// Broken on purpose: a stored value that the code does not compute is named, exit 1; a stored
// scalar that the stored points do not give is named with the claims that read it.
TEST(Verify, AStoredValueTheCodeDoesNotComputeIsNamed) {
    const TempPath out("verify-edited");
    ASSERT_EQ(run(kQuickBrake + out.string()).code, 0);
    const fs::path dir = out / "brake-failure";
    ASSERT_EQ(run("check brake-failure --out " + out.string()).code, 0);
    edit_point(dir, 4, [](nlohmann::json& o) {
        // A curve point (0 to 14; 15 to 18 are the head-on shots): its Curve under "curve".
        ASSERT_TRUE(o.contains("curve") && o["curve"]["dvy"].is_array() && !o["curve"]["dvy"].empty())
            << o.dump().substr(0, 300);
        o["curve"]["dvy"][0] = o["curve"]["dvy"][0].get<double>() * (1 + 1e-12);
    });
    ASSERT_EQ(run("check brake-failure --out " + out.string()).code, 0) << "the edit keeps the hashes consistent";
    const Outcome o = run("verify brake-failure --point 4 --out " + out.string());
    EXPECT_EQ(o.code, 1) << o.out << o.err;
    EXPECT_NE(o.out.find("point outcome: 1 of"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("/curve/dvy[0]"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("differs"), std::string::npos) << o.out;
    EXPECT_EQ(run("verify brake-failure --point 5 --point-only --out " + out.string()).code, 0) << "another point";

    // A stored scalar that the points do not give: named, with the claims that read it.
    nlohmann::json s = summary(dir);
    const double forged = s["scalars"]["e_N_measured"].get<double>() * 1.5;
    s["scalars"]["e_N_measured"] = forged;
    {
        const H5Object f = open_for_edit(dir / "data.h5");
        const H5Object d(H5Dopen2(f.id(), "scalars/e_N_measured", H5P_DEFAULT), &H5Dclose);
        ASSERT_GE(H5Dwrite(d.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &forged), 0);
    }
    s["data_h5_hash"]["scalars"] = data_content_hash(dir / "data.h5")["scalars"];
    rewrite_summary(dir, s);
    const Outcome sc = run("verify brake-failure --point 5 --out " + out.string());
    EXPECT_EQ(sc.code, 1) << sc.out << sc.err;
    EXPECT_NE(sc.out.find("/e_N_measured"), std::string::npos) << sc.out;
    EXPECT_NE(sc.out.find("claims reading them"), std::string::npos) << sc.out;
}

TEST(Verify, BadInputIsOneLineExitTwo) {
    const TempPath out("verify-bad");
    ASSERT_EQ(run(kQuickBrake + out.string()).code, 0);
    const std::string o = " --out " + out.string();
    expect_one_line_exit(run("verify brake-failure --point abc" + o), 2, {"--point abc", "integer >= 0"});
    expect_one_line_exit(run("verify brake-failure --point -1" + o), 2, {"--point -1"});
    expect_one_line_exit(run("verify brake-failure --point 99" + o), 2, {"--point 99", "stores points 0 to 18"});
    expect_one_line_exit(run("verify brake-failure --threads 0" + o), 2, {"--threads 0"});
    expect_one_line_exit(run("verify brake-failure --list --point 1" + o), 2, {"--list"});
    expect_one_line_exit(run("verify no-such-experiment" + o), 2, {"unknown experiment 'no-such-experiment'"});
    expect_one_line_exit(run("verify emergency-brake" + o), 2, {"no results of emergency-brake"});
    expect_one_line_exit(run("verify" + o), 2, {"experiment"});
    put(out / "brake-failure" / "summary.json", "garbage");
    expect_one_line_exit(run("verify brake-failure" + o), 2, {"summary.json", "not valid JSON"});
}
