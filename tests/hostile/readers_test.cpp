// The readers of a results folder (issue 40, §1, §3, §4): check, verify, verify --list and export
// on data.h5 and summary.json crafted as a hostile tester would (string attributes stored as
// arrays or variable-length strings, deep JSON and TOML, /dev/zero and FIFOs, symlinks, edited
// parameters, forged counts and records), and a rerun on a damaged sweep-point file. Each refusal
// is exit 2 and one line naming the file and the field; a damaged point file is recomputed.
#include "hostile_support.hpp"

#include <functional>
#include <hdf5.h>
#include <sys/stat.h>
#include <tuple>
#include <unistd.h>

#include "io/result_writer.hpp"

using namespace hostile;

namespace {

// ---- crafting data.h5 with the HDF5 C API ----------------------------------------------------

struct Writable {
    hid_t f;
    explicit Writable(const fs::path& h5) : f(H5Fopen(h5.c_str(), H5F_ACC_RDWR, H5P_DEFAULT)) {
        if (f < 0) throw std::runtime_error("cannot open " + h5.string() + " for writing");
    }
    ~Writable() { H5Fclose(f); }
};

// Replaces attribute `name` of object `obj` (a path in the file) by one of `type` and `space`.
void put_attr(const fs::path& h5, const std::string& obj, const std::string& name, hid_t type, hid_t space, const void* data) {
    const Writable w(h5);
    const hid_t o = H5Oopen(w.f, obj.c_str(), H5P_DEFAULT);
    ASSERT_GE(o, 0);
    if (H5Aexists(o, name.c_str()) > 0) {
        ASSERT_GE(H5Adelete(o, name.c_str()), 0);
    }
    const hid_t a = H5Acreate2(o, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(a, 0) << name;
    EXPECT_GE(H5Awrite(a, type, data), 0) << name;
    H5Aclose(a);
    H5Oclose(o);
}

// h5py's np.array([b'quick'] * n, dtype=string_dtype('utf-8', 5)): n fixed-length strings.
void string_array_attr(const fs::path& h5, const std::string& name, std::size_t n = 100000) {
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, 5);
    H5Tset_cset(t, H5T_CSET_UTF8);
    const hsize_t dims = n;
    const hid_t s = H5Screate_simple(1, &dims, nullptr);
    std::string data;
    for (std::size_t i = 0; i < n; ++i) data += "quick";
    put_attr(h5, "/", name, t, s, data.data());
    H5Sclose(s);
    H5Tclose(t);
}

// h5py's default for a str: a scalar variable-length UTF-8 string.
void vl_string_attr(const fs::path& h5, const std::string& obj, const std::string& name, const std::string& value) {
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    H5Tset_cset(t, H5T_CSET_UTF8);
    const hid_t s = H5Screate(H5S_SCALAR);
    const char* p = value.c_str();
    put_attr(h5, obj, name, t, s, &p);
    H5Sclose(s);
    H5Tclose(t);
}

// A scalar fixed-length string, as granrepro writes them.
void string_attr(const fs::path& h5, const std::string& obj, const std::string& name, const std::string& value) {
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, value.size());
    const hid_t s = H5Screate(H5S_SCALAR);
    put_attr(h5, obj, name, t, s, value.data());
    H5Sclose(s);
    H5Tclose(t);
}

void long_attr(const fs::path& h5, const std::string& name, long value) {
    const hid_t s = H5Screate(H5S_SCALAR);
    put_attr(h5, "/", name, H5T_NATIVE_LONG, s, &value);
    H5Sclose(s);
}

void delete_attr(const fs::path& h5, const std::string& name) {
    const Writable w(h5);
    ASSERT_GE(H5Adelete(w.f, name.c_str()), 0);
}

// Overwrites a scalar dataset (a parameter) in place.
template <class T>
void put_scalar(const fs::path& h5, const std::string& path, hid_t mem_type, T value) {
    const Writable w(h5);
    const hid_t d = H5Dopen2(w.f, path.c_str(), H5P_DEFAULT);
    ASSERT_GE(d, 0) << path;
    EXPECT_GE(H5Dwrite(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value), 0);
    H5Dclose(d);
}

// /points/records replaced by `text` (uint8, as compressed_text writes it).
void put_records(const fs::path& h5, const std::string& text) {
    const Writable w(h5);
    ASSERT_GE(H5Ldelete(w.f, "/points/records", H5P_DEFAULT), 0);
    const hsize_t n = text.size();
    const hid_t s = H5Screate_simple(1, &n, nullptr);
    const hid_t d = H5Dcreate2(w.f, "/points/records", H5T_STD_U8LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(d, 0);
    EXPECT_GE(H5Dwrite(d, H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()), 0);
    H5Dclose(d);
    H5Sclose(s);
}

std::string records_of(const fs::path& h5) { return granrepro::read_points_records(h5).dump(); }

// A forgery that keeps both files consistent: summary.json edited by `edit`, its hashes of
// data.h5 recomputed (points, scalars, tables) and its own hash stored in data.h5, as a forger
// who read docs/schema.md would. What is left to catch it is what no hash covers.
template <class Edit>
void forge_summary(const fs::path& dir, Edit edit) {
    nlohmann::json s = nlohmann::json::parse(slurp(dir / "summary.json"));
    const nlohmann::json found = granrepro::data_content_hash(dir / "data.h5");
    s["data_h5_hash"] = found;
    edit(s);
    std::ofstream(dir / "summary.json", std::ios::binary | std::ios::trunc) << granrepro::summary_text(s);
    string_attr(dir / "data.h5", "/", "summary_json_hash", granrepro::summary_content_hash(s));
}

std::string deep_json(int depth) { return std::string(std::size_t(depth), '[') + std::string(std::size_t(depth), ']'); }

Outcome check(const Crafted& c) { return run_argv({"check", "brake-failure", "--out", c.out.string()}); }
Outcome verify(const Crafted& c, const std::vector<std::string>& env = {}) {
    return run_argv({"verify", "brake-failure", "--point", "0", "--out", c.out.string()}, {}, env);
}
Outcome verify_list(const Crafted& c) { return run_argv({"verify", "brake-failure", "--list", "--out", c.out.string()}); }
Outcome export_to(const Crafted& c) {
    return run_argv({"export", "brake-failure", "--out", c.out.string(), "--to", (c.base / "exported").string()});
}
// A reader that might block (a FIFO) is killed after 20 s: a hang fails the test, not the suite.
Outcome guarded(const std::string& command, const Crafted& c) {
    const std::string to = command == "export" ? " --to " + (c.base / "exported").string() : "";
    return cli_support::run(command + " brake-failure --out " + c.out.string() + to, "timeout -s KILL 20");
}

} // namespace

// ---- §1: string attributes stored as arrays, variable-length strings ----------------------

// A 100000-element string array in place of a scalar string overflowed a one-element buffer
// (SIGSEGV, or SIGABRT "double free or corruption"); now every reader refuses it by name.
TEST(HostileReadersAttributes, StringArrayAttributesAreRefusedByEveryReader) {
    for (const std::string attr : {"scale", "code_version", "experiment", "summary_json_hash"}) {
        SCOPED_TRACE(attr);
        const Crafted c("readers-array-" + attr);
        string_array_attr(c.dir() / "data.h5", attr);
        const std::vector<std::string> parts{"data.h5", "attribute " + attr, "100000 values"};
        expect_refusal(check(c), 2, parts);
        expect_refusal(verify(c), 2, parts);
        expect_refusal(verify_list(c), 2, parts);
        expect_refusal(export_to(c), 2, parts);
        EXPECT_FALSE(fs::exists(c.base / "exported" / "brake-failure" / "data.h5"));
        c.expect_sentinel_unchanged();
    }
}

TEST(HostileReadersAttributes, ANumberInPlaceOfAStringIsRefused) {
    const Crafted c("readers-number-attr");
    long_attr(c.dir() / "data.h5", "scale", 7);
    expect_refusal(check(c), 2, {"data.h5", "attribute scale is not a string"});
}

// h5py writes a str as a variable-length string: read as such (the value, not heap bytes).
TEST(HostileReadersAttributes, VariableLengthStringsAreReadAsTheirValue) {
    const Crafted c("readers-vl");
    const fs::path h5 = c.dir() / "data.h5";
    vl_string_attr(h5, "/", "scale", "quick");
    vl_string_attr(h5, "/", "code_version", nlohmann::json::parse(slurp(c.dir() / "summary.json"))["code_version"].get<std::string>());
    const Outcome same = check(c);
    EXPECT_EQ(same.code, 0) << same.err;
    vl_string_attr(h5, "/", "scale", "paper");
    expect_refusal(check(c), 2, {"summary.json", "'scale' is \"quick\" but data.h5 beside it has \"paper\""});
}

TEST(HostileReadersAttributes, AHugeVariableLengthStringIsRefused) {
    const Crafted c("readers-vl-huge");
    vl_string_attr(c.dir() / "data.h5", "/", "experiment", std::string(std::size_t(9) << 20, 'x'));
    expect_refusal(check(c), 2, {"data.h5", "attribute experiment is larger than its cap"});
}

// ---- §1: summary.json: deep, /dev/zero, FIFO; data.h5: symlink, FIFO ---------------------

TEST(HostileReadersSummary, DeepJsonIsRefusedNotACrash) {
    const Crafted c("readers-deep-summary");
    std::ofstream(c.dir() / "summary.json", std::ios::trunc) << deep_json(100000);
    for (const Outcome& o : {check(c), verify(c), verify_list(c)})
        expect_refusal(o, 2, {"summary.json", "JSON nested deeper than 64 levels"});
}

TEST(HostileReadersSummary, ASymlinkToDevZeroIsRefusedUnread) {
    const Crafted c("readers-devzero");
    fs::remove(c.dir() / "summary.json");
    fs::create_symlink("/dev/zero", c.dir() / "summary.json");
    for (const char* command : {"check", "verify"})
        expect_refusal(guarded(command, c), 2, {"summary.json is a symbolic link"});
    expect_refusal(guarded("export", c), 2, {"summary.json is a symbolic link"});
    EXPECT_FALSE(fs::exists(c.base / "exported" / "brake-failure"));
}

TEST(HostileReadersSummary, AFifoIsRefusedWithoutBlocking) {
    const Crafted c("readers-fifo");
    fs::remove(c.dir() / "summary.json");
    ASSERT_EQ(::mkfifo((c.dir() / "summary.json").c_str(), 0600), 0);
    for (const char* command : {"check", "verify", "export"})
        expect_refusal(guarded(command, c), 2, {"summary.json is a FIFO, not a regular file"});
}

TEST(HostileReadersSummary, ASymlinkedOrFifoDataFileIsRefused) {
    const Crafted c("readers-h5-link");
    const fs::path h5 = c.dir() / "data.h5";
    fs::rename(h5, c.sentinel.root / "data.h5");
    const std::string before = c.sentinel.digest();
    fs::create_symlink(c.sentinel.root / "data.h5", h5);
    for (const char* command : {"check", "verify", "export"})
        expect_refusal(guarded(command, c), 2, {"data.h5: ", "is a symbolic link"});
    EXPECT_EQ(c.sentinel.digest(), before);
    fs::remove(h5);
    ASSERT_EQ(::mkfifo(h5.c_str(), 0600), 0);
    for (const char* command : {"check", "verify", "export"})
        expect_refusal(guarded(command, c), 2, {"data.h5: ", "is a FIFO"});
}

// ---- §1: a deep TOML in data.h5's experiment_file ---------------------------------------------

TEST(HostileReadersVerify, DeepTomlInExperimentFileIsRefusedAndLeavesNoTemporaryFolder) {
    const Crafted c("readers-deep-toml");
    string_attr(c.dir() / "data.h5", "/", "experiment_file", "[parameters]\nx = " + deep_json(10000) + "\n");
    const fs::path tmp = c.base / "tmp";
    fs::create_directories(tmp);
    expect_refusal(verify(c, {"TMPDIR=" + tmp.string()}), 2, {"data.h5: experiment_file", "TOML nested deeper"});
    EXPECT_TRUE(fs::is_empty(tmp)) << "a temporary folder was left in " << tmp;
    // Refused before any temporary folder is made: with none to be had (TMPDIR a file), the
    // refusal is the same.
    const fs::path not_a_dir = c.base / "tmp-file";
    std::ofstream(not_a_dir) << "not a folder\n";
    expect_refusal(verify(c, {"TMPDIR=" + not_a_dir.string()}), 2, {"data.h5: experiment_file", "TOML nested deeper"});
}

// A folder a killed verify left (SIGKILL runs no destructor) is removed by the next verify once
// its process is gone; a running one's is kept.
TEST(HostileReadersVerify, StaleTemporaryFoldersOfDeadProcessesAreRemoved) {
    const Crafted c("readers-stale-tmp");
    const fs::path tmp = c.base / "tmp";
    const fs::path dead = tmp / "granrepro-verify-999999999-AbCdEf", alive = tmp / ("granrepro-verify-" + std::to_string(::getpid()) + "-AbCdEf");
    fs::create_directories(dead / "work");
    fs::create_directories(alive);
    const Outcome o = verify(c, {"TMPDIR=" + tmp.string()});
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_TRUE(fs::exists(alive));
}

// ---- §3: parameters, schema_version, stored_points ----------------------------------------------

TEST(HostileReadersParameters, AnEditedParameterInDataH5IsRefusedByCheckAndVerify) {
    const Crafted c("readers-kN");
    put_scalar(c.dir() / "data.h5", "/parameters/k_N", H5T_NATIVE_DOUBLE, 3000.0);
    const std::vector<std::string> parts{"data.h5", "parameter 'k_N' is 3000.0 in /parameters but 2000.0 in summary.json"};
    expect_refusal(check(c), 2, parts);
    expect_refusal(verify(c), 2, parts);
}

TEST(HostileReadersParameters, AnEditedIntegerParameterIsRefused) {
    const Crafted c("readers-nvy");
    put_scalar(c.dir() / "data.h5", "/parameters/n_vy", H5T_NATIVE_LONG, 99L);
    expect_refusal(check(c), 2, {"data.h5", "parameter 'n_vy' is 99 in /parameters"});
}

// Both files edited alike and every hash forged: check cannot tell, verify recomputes the
// parameters from the stored experiment file and reports the difference, never a match.
TEST(HostileReadersParameters, AForgedParameterInBothFilesIsADifferenceForVerify) {
    const Crafted c("readers-kN-forged");
    put_scalar(c.dir() / "data.h5", "/parameters/k_N", H5T_NATIVE_DOUBLE, 3000.0);
    forge_summary(c.dir(), [](nlohmann::json& s) { s["parameters"]["k_N"]["value"] = 3000.0; });
    const Outcome ok = check(c);
    EXPECT_EQ(ok.code, 0) << ok.err; // what the hashes cannot see
    const Outcome o = verify(c);
    EXPECT_EQ(o.code, 1) << o.err << o.out;
    EXPECT_NE(o.out.find("/parameters/k_N: 3000.0 -> 2000.0"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("verify brake-failure: point 0 differs"), std::string::npos) << o.out;
    EXPECT_EQ(o.out.find("reproduced"), std::string::npos) << o.out;
}

TEST(HostileReadersSummary, SchemaVersion99IsRefused) {
    const Crafted c("readers-schema99");
    forge_summary(c.dir(), [](nlohmann::json& s) { s["schema_version"] = 99; });
    expect_refusal(check(c), 2, {"summary.json", "'schema_version' must be 3", "found 99"});
}

TEST(HostileReadersSummary, StoredPointsThatDisagreeWithDataH5AreRefused) {
    const Crafted c("readers-stored-points");
    forge_summary(c.dir(), [](nlohmann::json& s) { s["stored_points"] = s["stored_points"].get<long>() - 1; });
    expect_refusal(check(c), 2, {"summary.json", "'stored_points' is", "but data.h5 beside it stores"});
}

// ---- §4: malformed records and overrides, a missing experiment_file ---------------------------

TEST(HostileReadersVerify, MalformedRecordsAreRefusedNamingTheField) {
    struct Case {
        std::string name;
        std::function<void(nlohmann::json&)> edit;
        std::vector<std::string> parts;
    };
    const std::vector<Case> cases{
        {"point", [](nlohmann::json& r) { r[0]["point"] = "zero"; }, {"/points/records: record 0: 'point' must be an integer"}},
        {"cost", [](nlohmann::json& r) { r[1]["cost"] = 5; }, {"/points/records: record 1: 'cost' must be an object"}},
        {"cpu", [](nlohmann::json& r) { r[2]["cost"]["cpu_s"] = "fast"; }, {"record 2: 'cost/cpu_s' must be a number"}},
        {"sweep", [](nlohmann::json& r) { r[0].erase("sweep"); }, {"record 0: 'sweep' must be a string"}},
        {"record", [](nlohmann::json& r) { r[3] = 17; }, {"record 3 must be an object"}},
    };
    for (const Case& k : cases) {
        SCOPED_TRACE(k.name);
        const Crafted c("readers-records-" + k.name);
        nlohmann::json records = nlohmann::json::parse(records_of(c.dir() / "data.h5"));
        k.edit(records);
        put_records(c.dir() / "data.h5", records.dump());
        forge_summary(c.dir(), [](nlohmann::json&) {});
        std::vector<std::string> parts = k.parts;
        parts.push_back("data.h5");
        expect_refusal(verify(c), 2, parts);
        expect_refusal(verify_list(c), 2, parts);
    }
}

TEST(HostileReadersVerify, RecordsThatAreNotAnArrayOrTooDeepAreRefused) {
    for (const auto& [name, text, part] : std::vector<std::tuple<std::string, std::string, std::string>>{
             {"object", "{\"a\": 1}", "/points/records: not a JSON array"},
             {"deep", deep_json(100000), "/points/records: JSON nested deeper"},
             {"garbage", "[{", "/points/records: not valid JSON"}}) {
        SCOPED_TRACE(name);
        const Crafted c("readers-records-" + name);
        put_records(c.dir() / "data.h5", text);
        expect_refusal(check(c), 2, {"data.h5", part});
        expect_refusal(verify(c), 2, {"data.h5", part});
        expect_refusal(export_to(c), 2, {"data.h5", part});
    }
}

TEST(HostileReadersVerify, MalformedOverriddenParametersAreRefusedNamingTheField) {
    const Crafted c("readers-overrides");
    forge_summary(c.dir(), [](nlohmann::json& s) { s["overridden_parameters"] = {{"k_N", "abc"}}; });
    expect_refusal(verify(c), 2, {"summary.json: overridden_parameters/k_N"});
    forge_summary(c.dir(), [](nlohmann::json& s) { s["overridden_parameters"] = {{"k_N", {{"deep", 1}}}}; });
    expect_refusal(check(c), 2, {"summary.json", "'overridden_parameters/k_N' must be a value"});
    forge_summary(c.dir(), [](nlohmann::json& s) { s["overridden_parameters"] = nlohmann::json::array({1, 2}); });
    expect_refusal(verify(c), 2, {"summary.json", "'overridden_parameters' must be an object"});
}

TEST(HostileReadersVerify, AMissingExperimentFileIsNamed) {
    const Crafted c("readers-no-experiment-file");
    delete_attr(c.dir() / "data.h5", "experiment_file");
    expect_refusal(verify(c), 2, {"data.h5: has no 'experiment_file' attribute"});
}

// ---- §1: a damaged sweep-point file in a checkpoint is recomputed ------------------------------

// brake-failure keeps no point files (PointFiles::None); impact-parameter does and stops after
// one point in about a second (GRANREPRO_INTERRUPT_AFTER_POINTS), its point file left behind.
TEST(HostileReadersCheckpoint, ADeepSymlinkedOrFifoPointFileIsRecomputed) {
    for (const std::string kind : {"deep", "symlink", "fifo"}) {
        SCOPED_TRACE(kind);
        const Crafted c("readers-point-" + kind);
        const std::vector<std::string> run{"impact-parameter", "--scale", "quick", "--out", c.out.string()};
        const Outcome first = run_argv(run, {}, {"GRANREPRO_INTERRUPT_AFTER_POINTS=1"});
        ASSERT_EQ(first.code, 3) << first.err;
        fs::path point;
        for (const auto& e : fs::recursive_directory_iterator(c.out / ".impact-parameter.checkpoint"))
            if (e.path().extension() == ".json") point = e.path();
        ASSERT_FALSE(point.empty());
        fs::remove(point);
        // A point file in every field but its value, nested 100000 deep (its hash check dumped it
        // recursively).
        if (kind == "deep")
            std::ofstream(point) << R"({"schema": "granrepro-sweep-point", "schema_version": 3, "point": )"
                                 << point.stem().string() << R"(, "fnv1a64": "0", "value": )" << deep_json(100000) << "}";
        if (kind == "symlink") fs::create_symlink(c.sentinel.victim(), point);
        if (kind == "fifo") {
            ASSERT_EQ(::mkfifo(point.c_str(), 0600), 0);
        }
        if (kind == "symlink") { // gather and a run refuse a link in the checkpoint folder (writes guard)
            for (const char* command : {"gather impact-parameter", "impact-parameter"}) {
                const Outcome o = cli_support::run(std::string(command) + " --scale quick --out " + c.out.string(), "timeout -s KILL 60");
                expect_refusal(o, 2, {point.string(), "a symbolic link in the checkpoint folder"});
            }
            EXPECT_FALSE(fs::exists(c.out / "impact-parameter" / "summary.json"));
            c.expect_sentinel_unchanged();
            continue;
        }
        // gather computes nothing: the damaged point is missing, not a crash or a hang.
        const Outcome gather = cli_support::run("gather impact-parameter --scale quick --out " + c.out.string(), "timeout -s KILL 60");
        EXPECT_EQ(gather.code, 2) << gather.err;
        EXPECT_NE(gather.err.find("recomputing sweep point"), std::string::npos) << gather.err;
        EXPECT_NE(gather.err.find("points missing"), std::string::npos) << gather.err;
        const Outcome rerun = cli_support::run("impact-parameter --scale quick --out " + c.out.string(), "timeout -s KILL 120");
        EXPECT_EQ(rerun.code, 0) << rerun.err;
        EXPECT_NE(rerun.err.find("recomputing sweep point"), std::string::npos) << rerun.err;
        EXPECT_NE(rerun.err.find(kind == "deep" ? "JSON nested deeper" : "is a FIFO"),
                  std::string::npos)
            << rerun.err;
        EXPECT_TRUE(fs::exists(c.out / "impact-parameter" / "summary.json"));
        c.expect_sentinel_unchanged();
    }
}
