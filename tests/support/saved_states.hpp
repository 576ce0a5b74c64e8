// For tests of save and restore: a temporary folder for state files, an engine state through a
// file, and two states compared field by field.
#pragma once
#include "data/fields.hpp"
#include "io/engine_state_file.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <type_traits>
#include <unistd.h>
#include <vector>

namespace granrepro::test {

// A folder of its own for the running test, removed with its contents at the end.
struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& tag = "")
        : path(std::filesystem::temp_directory_path() /
               ("granrepro-test-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name() + tag)) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() { std::filesystem::remove_all(path); }
};

// An HDF5 file in `dir` that `write` fills (and closes), opened again for reading.
template <class Write>
H5File written_h5(const TempDir& dir, Write write) {
    const std::string file = (dir.path / "f.h5").string();
    write(H5File::create(file));
    return H5File::open(file);
}

// An ED or DSMC state written to an HDF5 file and read back.
template <class State>
State through_file(const State& s) {
    const TempDir dir("-state");
    const H5File f = written_h5(dir, [&](const H5File& w) { write_engine_state(w.group("state"), s); });
    State read;
    read_engine_state(f.open_group("state"), read);
    return read;
}

// Every field of two values of a type that lists its fields (data/fields.hpp) holds the same bits
// (NaN and the sign of zero included): nested structs and lists of them field by field, vectors
// and strings element by element.
template <HasFields T>
void expect_same_fields(T a, T b, const std::string& at = "") {
    std::vector<void*> in_b;
    b.fields([&](const char*, auto& f) { in_b.push_back(&f); });
    std::size_t k = 0;
    a.fields([&](const char* name, auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        F& g = *static_cast<F*>(in_b[k++]);
        const std::string field = at + name;
        if constexpr (HasFields<F>) {
            expect_same_fields(f, g, field + "/");
        } else if constexpr (requires { requires HasFields<typename F::value_type>; }) {
            ASSERT_EQ(f.size(), g.size()) << field;
            for (std::size_t i = 0; i < f.size(); ++i) expect_same_fields(f[i], g[i], field + "/" + std::to_string(i) + "/");
        } else if constexpr (requires { f.data(); f.size(); }) {
            ASSERT_EQ(f.size(), g.size()) << field;
            std::size_t i = 0;
            while (i < f.size() && std::memcmp(&f[i], &g[i], sizeof f[i]) == 0) ++i;
            EXPECT_EQ(i, f.size()) << field << " differs first at " << i << ": " << ::testing::PrintToString(f[i])
                                   << " vs " << ::testing::PrintToString(g[i]);
        } else {
            EXPECT_EQ(std::memcmp(&f, &g, sizeof f), 0)
                << field << ": " << ::testing::PrintToString(f) << " vs " << ::testing::PrintToString(g);
        }
    });
}

} // namespace granrepro::test
