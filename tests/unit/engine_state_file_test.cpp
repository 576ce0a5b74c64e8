// Engine states through HDF5 files (schemas granrepro-ed-state / granrepro-dsmc-state) and the
// mid-run RunCheckpoint: a run resumed from a file is bit-identical to an uninterrupted one.
#include "gas.hpp"
#include "harness/run_checkpoint.hpp"
#include "io/dsmc_state_file.hpp"
#include "io/ed_state_file.hpp"
#include "saved_states.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace granrepro;
using namespace granrepro::test;
namespace fs = std::filesystem;

namespace {

// Rough, inelastic with TC, gravity, two walls (one disabled later): every EdConfig field differs
// from its default, so a field the file forgets changes the resumed run.
EdEngine rough_pipe() {
    const double l = box_for(300, 0.3);
    EdConfig cfg;
    cfg.periodic_y = false;
    cfg.gravity = {0.3, -9.81};
    cfg.law = RoughDiskCollision{0.8, 0.5, 0.2, 0.5};
    cfg.t_c = 1e-3;
    cfg.tc_keep_friction = true;
    cfg.tc_both = true;
    cfg.cell_size_factor = 1.2;
    cfg.collapse_limit = 5000;
    cfg.collapse_window = 1e-9;
    cfg.walls = {EdWall{1, 0.0, +1, 0.9, 0.4, 0.1, true}, EdWall{1, l, -1, 0.7, 0.0, -1.0, true}};
    return random_ed_gas(300, 0.3, 3, cfg, 0.5);
}

} // namespace

TEST(EdStateFile, ResumedFromFileIsBitIdentical) {
    EdEngine whole = rough_pipe();
    whole.run_until(0.01);
    const EdState read = through_file(whole.save_state());
    whole.set_wall_enabled(0, false); // a run-time change after the checkpoint, replayed below
    whole.run_until(0.03);
    EXPECT_EQ(read.config.walls.size(), 2u);
    EXPECT_EQ(read.config.walls[0].mu, 0.4);
    EXPECT_EQ(read.config.gravity.x, 0.3);
    EXPECT_TRUE(read.config.tc_keep_friction);
    EXPECT_TRUE(read.config.tc_both);
    EXPECT_EQ(read.config.collapse_limit, 5000u);
    EdEngine resumed(read);
    resumed.set_wall_enabled(0, false);
    resumed.run_until(0.03);
    EXPECT_GT(whole.total_collisions(), 1000u);
    EXPECT_GT(whole.elastic_collisions(), 0u);
    expect_same_fields(whole.save_state(), resumed.save_state());
}

TEST(EdStateFile, RejectsOtherGroups) {
    TempDir dir;
    const H5File f = written_h5(dir, [](const H5File& w) {
        w.group("empty");
        write_dsmc_state(w.group("dsmc"), DsmcState{});
    });
    EXPECT_THROW(read_ed_state(f.open_group("empty")), std::runtime_error);
    EXPECT_THROW(read_ed_state(f.open_group("dsmc")), std::runtime_error);
    EXPECT_THROW(read_dsmc_state(f.open_group("empty")), std::runtime_error);
}

TEST(DsmcStateFile, RejectsUnknownChoices) {
    // The walk reads any integer the field can hold; the reader then refuses what is no choice.
    TempDir dir;
    DsmcState mode, partner, block;
    mode.config.free_volume = DsmcFreeVolume(3);
    partner.config.partner = DsmcPartner(2);
    block.config.free_volume_block = 0;
    const H5File f = written_h5(dir, [&](const H5File& w) {
        write_dsmc_state(w.group("good"), DsmcState{});
        write_dsmc_state(w.group("mode"), mode);
        write_dsmc_state(w.group("partner"), partner);
        write_dsmc_state(w.group("block"), block);
    });
    EXPECT_NO_THROW(read_dsmc_state(f.open_group("good")));
    EXPECT_THROW(read_dsmc_state(f.open_group("mode")), std::runtime_error);
    EXPECT_THROW(read_dsmc_state(f.open_group("partner")), std::runtime_error);
    EXPECT_THROW(read_dsmc_state(f.open_group("block")), std::runtime_error);
}

TEST(DsmcStateFile, ResumedFromFileIsBitIdentical) {
    DsmcConfig cfg;
    cfg.r = 0.8;
    cfg.t_c = 2e-4;
    cfg.seed = 77;
    cfg.stream = 3;
    cfg.free_volume = DsmcFreeVolume::cell;
    cfg.displacement = true;
    cfg.resample_interval = 7;
    cfg.min_cell_diameters = 3.0;
    DsmcEngine whole = uniform_dsmc_gas(1500, 0.25, cfg, 5, 5);
    whole.run_steps(93); // not a multiple of the re-sampling interval
    DsmcEngine resumed(through_file(whole.save_state()));
    whole.run_steps(107);
    resumed.run_steps(107);
    EXPECT_GT(whole.elastic_collisions(), 0u);
    expect_same_fields(whole.save_state(), resumed.save_state());
}

TEST(RunCheckpoint, SavesLoadsAndIgnoresTornFiles) {
    TempDir dir;
    ParameterSet params;
    RunContext ctx{params, Scale::Quick, 7, 1, true, dir.path, 0.0};
    RunCheckpoint cp(ctx, "ed");
    EXPECT_TRUE(cp.due()); // interval 0: every offer is taken
    EXPECT_FALSE(cp.load([](const H5Object&) { FAIL() << "no file yet"; }));
    cp.save([](const H5Object& root) { root.attr("answer", 42.0); });
    EXPECT_EQ(cp.saves(), 1);
    double answer = 0;
    EXPECT_TRUE(cp.load([&](const H5Object& root) { answer = root.read_double_attr("answer"); }));
    EXPECT_EQ(answer, 42.0);
    // A checkpoint of another seed is a different file.
    RunContext other{params, Scale::Quick, 8, 1, true, dir.path, 0.0};
    EXPECT_NE(RunCheckpoint(other, "ed").path(), cp.path());
    // A torn file is ignored: the run starts afresh.
    {
        std::ofstream out(cp.path(), std::ios::trunc);
        out << "not hdf5";
    }
    EXPECT_FALSE(cp.load([](const H5Object&) {}));
    // No temporary files are left behind.
    for (const auto& e : fs::directory_iterator(dir.path))
        EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos);
}
