// core/untrusted_file: the bounded readers every results-folder reader goes through (issue 40).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sys/stat.h>
#include <unistd.h>

#include "core/input_error.hpp"
#include "core/untrusted_file.hpp"

namespace fs = std::filesystem;
using namespace granrepro;

namespace {
struct Dir {
    fs::path p = fs::temp_directory_path() / ("granrepro-untrusted-" + std::to_string(::getpid()));
    Dir() {
        fs::remove_all(p);
        fs::create_directories(p);
    }
    ~Dir() { fs::remove_all(p); }
};
std::string refusal(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}
} // namespace

TEST(UntrustedFile, ReadsARegularFileWhole) {
    Dir d;
    std::ofstream(d.p / "a.json") << "{\"x\": 1}";
    EXPECT_EQ(read_untrusted_file(d.p / "a.json", 100, "summary.json"), "{\"x\": 1}");
}

TEST(UntrustedFile, RefusesSymlinkFifoDeviceDirectoryAndOversize) {
    Dir d;
    std::ofstream(d.p / "target") << "secret";
    fs::create_symlink(d.p / "target", d.p / "link");
    ASSERT_EQ(::mkfifo((d.p / "fifo").c_str(), 0600), 0);
    fs::create_symlink("/dev/zero", d.p / "zero");
    std::ofstream(d.p / "big") << std::string(101, 'x');
    EXPECT_NE(refusal([&] { read_untrusted_file(d.p / "link", 100, "summary.json"); }).find("symbolic link"), std::string::npos);
    EXPECT_NE(refusal([&] { read_untrusted_file(d.p / "fifo", 100, "summary.json"); }).find("a FIFO"), std::string::npos);
    EXPECT_NE(refusal([&] { read_untrusted_file("/dev/zero", 100, "summary.json"); }).find("a device"), std::string::npos);
    EXPECT_NE(refusal([&] { read_untrusted_file(d.p / "zero", 100, "summary.json"); }).find("symbolic link"), std::string::npos);
    EXPECT_NE(refusal([&] { read_untrusted_file(d.p, 100, "summary.json"); }).find("directory"), std::string::npos);
    EXPECT_NE(refusal([&] { read_untrusted_file(d.p / "big", 100, "summary.json"); }).find("cap"), std::string::npos);
    EXPECT_NE(refusal([&] { require_regular_file(d.p / "link", "data.h5"); }).find("symbolic link"), std::string::npos);
    EXPECT_NE(refusal([&] { require_regular_file(d.p / "fifo", "data.h5"); }).find("a FIFO"), std::string::npos);
    EXPECT_EQ(refusal([&] { require_regular_file(d.p / "target", "data.h5"); }), "");
}

TEST(UntrustedFile, JsonDepthSkipsStringsAndRefusesDeepNesting) {
    EXPECT_EQ(json_depth(R"({"a": [1, {"b": "[[[{{{\"]]"}]})"), 3);
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    EXPECT_EQ(json_depth(deep), 100000);
    EXPECT_NE(refusal([&] { parse_untrusted_json(deep, "summary.json"); }).find("summary.json: JSON nested deeper"),
              std::string::npos);
    EXPECT_NE(refusal([&] { parse_untrusted_json("{", "x.json"); }).find("x.json: not valid JSON"), std::string::npos);
    EXPECT_EQ(parse_untrusted_json(R"({"a": [1, 2]})", "x.json").at("a").size(), 2u);
}

TEST(UntrustedFile, TomlDepthCountsArraysInlineTablesAndDottedKeysNotHeadersOrStrings) {
    EXPECT_EQ(toml_depth("[[figure]]\nid = \"a[[[b\" # [[[\nx = [[1.5, 2], {y = 3}]\n"), 2);
    EXPECT_EQ(toml_depth("a.b.c = 1.25\n[t.u]\nv = '''x[[[\n]]]'''\n"), 3);
    EXPECT_EQ(toml_depth("x = [\n  [1],\n  [2],\n]\n"), 2);
    const std::string deep = "x = " + std::string(10000, '[') + std::string(10000, ']') + "\n";
    EXPECT_NE(refusal([&] { check_toml_depth(deep, "e.toml"); }).find("e.toml: TOML nested deeper"), std::string::npos);
    std::string dotted = "a";
    for (int i = 0; i < 10000; ++i) dotted += ".a";
    EXPECT_NE(refusal([&] { check_toml_depth(dotted + " = 1\n", "e.toml"); }).find("nested deeper"), std::string::npos);
    EXPECT_EQ(refusal([&] { check_toml_depth("x = [[[1]]]\n", "e.toml"); }), "");
}
