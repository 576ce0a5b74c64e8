#include "io/dsmc_state_file.hpp"

#include <stdexcept>
#include <string>

namespace granrepro {

namespace {

void write_config(const H5Object& g, const DsmcConfig& c) {
    g.attr("lx", c.lx);
    g.attr("ly", c.ly);
    g.attr("r", c.r);
    g.attr("q", c.q);
    g.attr("t_c", c.t_c);
    g.attr("step_factor", c.step_factor);
    g.attr("resample_interval", long(c.resample_interval));
    g.attr("min_cell_diameters", c.min_cell_diameters);
    g.attr("free_volume", long(c.free_volume));
    g.attr("rcp_fraction", c.rcp_fraction);
    g.attr("free_volume_floor", c.free_volume_floor);
    g.attr("displacement", long(c.displacement));
    g.attr("partner", long(c.partner));
    g.attr("no_repeat_partner", long(c.no_repeat_partner));
    g.attr("mft_fraction", c.mft_fraction);
    g.attr("free_volume_block", long(c.free_volume_block));
    g.attr_u64("seed", c.seed);
    g.attr_u64("stream", c.stream);
}

DsmcConfig read_config(const H5Object& g) {
    DsmcConfig c;
    c.lx = g.read_double_attr("lx");
    c.ly = g.read_double_attr("ly");
    c.r = g.read_double_attr("r");
    c.q = g.read_double_attr("q");
    c.t_c = g.read_double_attr("t_c");
    c.step_factor = g.read_double_attr("step_factor");
    c.resample_interval = static_cast<std::uint32_t>(g.read_long_attr("resample_interval"));
    c.min_cell_diameters = g.read_double_attr("min_cell_diameters");
    const long fv = g.read_long_attr("free_volume");
    if (fv < 0 || fv > long(DsmcFreeVolume::mean)) throw std::runtime_error("DSMC state: unknown free_volume mode");
    c.free_volume = static_cast<DsmcFreeVolume>(fv);
    c.rcp_fraction = g.read_double_attr("rcp_fraction");
    c.free_volume_floor = g.read_double_attr("free_volume_floor");
    c.displacement = g.read_long_attr("displacement") != 0;
    const long partner = g.read_long_attr("partner");
    if (partner < 0 || partner > long(DsmcPartner::nearest)) throw std::runtime_error("DSMC state: unknown partner rule");
    c.partner = static_cast<DsmcPartner>(partner);
    c.no_repeat_partner = g.read_long_attr("no_repeat_partner") != 0;
    c.mft_fraction = g.read_double_attr("mft_fraction");
    const long block = g.read_long_attr("free_volume_block");
    if (block < 1) throw std::runtime_error("DSMC state: free_volume_block must be >= 1");
    c.free_volume_block = static_cast<std::uint32_t>(block);
    c.seed = g.read_u64_attr("seed");
    c.stream = g.read_u64_attr("stream");
    return c;
}

} // namespace

void write_dsmc_state(const H5Object& g, const DsmcState& s) {
    g.stamp_schema(kDsmcStateSchema, kDsmcStateSchemaVersion);
    write_config(g, s.config);
    g.attr("time", s.time);
    g.attr("tau", s.tau);
    g.attr("v_max", s.v_max);
    g.attr_u64("steps", s.steps);
    g.vec2_array("position", s.position);
    g.vec2_array("velocity", s.velocity);
    g.array("radius", s.radius);
    g.array("mass", s.mass);
    g.array("last_collision_time", s.last_collision_time);
    g.array("collision_count", s.collision_count);
    g.attr_u64("collisions", s.collisions);
    g.attr_u64("elastic_collisions", s.elastic_collisions);
    g.attr_u64("candidates", s.candidates);
    g.attr_u64("vmax_raises", s.vmax_raises);
    g.attr("exposure", s.exposure);
    g.array("last_partner", s.last_partner);
    g.attr("resample_time", s.resample_time);
    g.attr_u64("resample_collisions", s.resample_collisions);
    g.array("rng_state", s.rng_state);
}

DsmcState read_dsmc_state(const H5Object& g) {
    g.require_schema(kDsmcStateSchema, kDsmcStateSchemaVersion);
    DsmcState s;
    s.config = read_config(g);
    s.time = g.read_double_attr("time");
    s.tau = g.read_double_attr("tau");
    s.v_max = g.read_double_attr("v_max");
    s.steps = g.read_u64_attr("steps");
    s.position = g.read_vec2_array("position");
    s.velocity = g.read_vec2_array("velocity");
    if (s.velocity.size() != s.position.size())
        throw std::runtime_error("DSMC state: position and velocity arrays differ in length");
    s.radius = g.read_array<double>("radius");
    s.mass = g.read_array<double>("mass");
    s.last_collision_time = g.read_array<double>("last_collision_time");
    s.collision_count = g.read_array<std::uint64_t>("collision_count");
    s.collisions = g.read_u64_attr("collisions");
    s.elastic_collisions = g.read_u64_attr("elastic_collisions");
    s.candidates = g.read_u64_attr("candidates");
    s.vmax_raises = g.read_u64_attr("vmax_raises");
    s.exposure = g.read_double_attr("exposure");
    s.last_partner = g.read_array<std::uint32_t>("last_partner");
    s.resample_time = g.read_double_attr("resample_time");
    s.resample_collisions = g.read_u64_attr("resample_collisions");
    s.rng_state = g.read_array<std::uint8_t>("rng_state");
    return s;
}

} // namespace granrepro
