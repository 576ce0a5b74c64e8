#include "io/ed_state_file.hpp"

#include <stdexcept>
#include <string>

namespace granrepro {

namespace {

void write_law(const H5Object& g, const std::string& prefix, const RoughDiskCollision& l) {
    g.attr(prefix + "r", l.r);
    g.attr(prefix + "mu", l.mu);
    g.attr(prefix + "beta0", l.beta0);
    g.attr(prefix + "q", l.q);
}
RoughDiskCollision read_law(const H5Object& g, const std::string& prefix) {
    RoughDiskCollision l;
    l.r = g.read_double_attr(prefix + "r");
    l.mu = g.read_double_attr(prefix + "mu");
    l.beta0 = g.read_double_attr(prefix + "beta0");
    l.q = g.read_double_attr(prefix + "q");
    return l;
}

void write_config(const H5Object& g, const EdConfig& c) {
    g.attr("lx", c.lx);
    g.attr("ly", c.ly);
    g.attr("periodic_x", long(c.periodic_x));
    g.attr("periodic_y", long(c.periodic_y));
    g.attr("gravity_x", c.gravity.x);
    g.attr("gravity_y", c.gravity.y);
    write_law(g, "law_", c.law);
    g.attr("t_c", c.t_c);
    g.attr("tc_keep_friction", long(c.tc_keep_friction));
    g.attr("tc_both", long(c.tc_both));
    g.attr("cell_size_factor", c.cell_size_factor);
    g.attr("collapse_limit", long(c.collapse_limit));
    g.attr("collapse_window", c.collapse_window);
    std::vector<std::int32_t> axis, side;
    std::vector<std::uint8_t> enabled;
    std::vector<double> position, r, mu, beta0;
    for (const EdWall& w : c.walls) {
        axis.push_back(w.axis);
        side.push_back(w.side);
        enabled.push_back(w.enabled ? 1 : 0);
        position.push_back(w.position);
        r.push_back(w.r);
        mu.push_back(w.mu);
        beta0.push_back(w.beta0);
    }
    g.array("wall_axis", axis);
    g.array("wall_side", side);
    g.array("wall_enabled", enabled);
    g.array("wall_position", position);
    g.array("wall_r", r);
    g.array("wall_mu", mu);
    g.array("wall_beta0", beta0);
}

EdConfig read_config(const H5Object& g) {
    EdConfig c;
    c.lx = g.read_double_attr("lx");
    c.ly = g.read_double_attr("ly");
    c.periodic_x = g.read_long_attr("periodic_x") != 0;
    c.periodic_y = g.read_long_attr("periodic_y") != 0;
    c.gravity = {g.read_double_attr("gravity_x"), g.read_double_attr("gravity_y")};
    c.law = read_law(g, "law_");
    c.t_c = g.read_double_attr("t_c");
    c.tc_keep_friction = g.read_long_attr("tc_keep_friction") != 0;
    c.tc_both = g.read_long_attr("tc_both") != 0;
    c.cell_size_factor = g.read_double_attr("cell_size_factor");
    c.collapse_limit = static_cast<std::uint32_t>(g.read_long_attr("collapse_limit"));
    c.collapse_window = g.read_double_attr("collapse_window");
    const auto axis = g.read_array<std::int32_t>("wall_axis");
    const auto side = g.read_array<std::int32_t>("wall_side");
    const auto enabled = g.read_array<std::uint8_t>("wall_enabled");
    const auto position = g.read_array<double>("wall_position");
    const auto r = g.read_array<double>("wall_r");
    const auto mu = g.read_array<double>("wall_mu");
    const auto beta0 = g.read_array<double>("wall_beta0");
    const std::size_t n = axis.size();
    if (side.size() != n || enabled.size() != n || position.size() != n || r.size() != n || mu.size() != n ||
        beta0.size() != n)
        throw std::runtime_error("ED state file: wall arrays differ in length");
    for (std::size_t k = 0; k < n; ++k)
        c.walls.push_back(EdWall{axis[k], position[k], side[k], r[k], mu[k], beta0[k], enabled[k] != 0});
    return c;
}

} // namespace

void write_ed_state(const H5Object& g, const EdState& s) {
    g.stamp_schema(kEdStateSchema, kEdStateSchemaVersion);
    write_config(g, s.config);
    g.attr("time", s.time);
    g.array("x", s.x);
    g.array("y", s.y);
    g.array("vx", s.vx);
    g.array("vy", s.vy);
    g.array("spin", s.spin);
    g.array("local_time", s.local_time);
    g.array("radius", s.radius);
    g.array("mass", s.mass);
    g.array("last_collision_time", s.last_collision_time);
    g.array("burst_start", s.burst_start);
    g.array("predicted_time", s.predicted_time);
    g.array("collision_time", s.collision_time);
    g.array("collision_count", s.collision_count);
    g.array("partner_count", s.partner_count);
    g.array("last_partner", s.last_partner);
    g.array("partner", s.partner);
    g.array("event_kind", s.event_kind);
    g.array("event_arg", s.event_arg);
    g.array("burst_count", s.burst_count);
    g.array("cell", s.cell);
    g.array("cell_next", s.cell_next);
    g.array("cell_prev", s.cell_prev);
    g.array("cell_head", s.cell_head);
    g.attr_u64("pair_collisions", s.pair_collisions);
    g.attr_u64("wall_collisions", s.wall_collisions);
    g.attr_u64("elastic_collisions", s.elastic_collisions);
    g.attr_u64("events", s.events);
    g.attr_u64("crossings", s.crossings);
    g.attr_u64("stale_events", s.stale_events);
    g.attr("max_overlap", s.max_overlap);
}

EdState read_ed_state(const H5Object& g) {
    g.require_schema(kEdStateSchema, kEdStateSchemaVersion);
    EdState s;
    s.config = read_config(g);
    s.time = g.read_double_attr("time");
    s.x = g.read_array<double>("x");
    s.y = g.read_array<double>("y");
    s.vx = g.read_array<double>("vx");
    s.vy = g.read_array<double>("vy");
    s.spin = g.read_array<double>("spin");
    s.local_time = g.read_array<double>("local_time");
    s.radius = g.read_array<double>("radius");
    s.mass = g.read_array<double>("mass");
    s.last_collision_time = g.read_array<double>("last_collision_time");
    s.burst_start = g.read_array<double>("burst_start");
    s.predicted_time = g.read_array<double>("predicted_time");
    s.collision_time = g.read_array<double>("collision_time");
    s.collision_count = g.read_array<std::uint64_t>("collision_count");
    s.partner_count = g.read_array<std::uint64_t>("partner_count");
    s.last_partner = g.read_array<std::int32_t>("last_partner");
    s.partner = g.read_array<std::int32_t>("partner");
    s.event_kind = g.read_array<std::uint8_t>("event_kind");
    s.event_arg = g.read_array<std::uint8_t>("event_arg");
    s.burst_count = g.read_array<std::uint32_t>("burst_count");
    s.cell = g.read_array<std::int32_t>("cell");
    s.cell_next = g.read_array<std::int32_t>("cell_next");
    s.cell_prev = g.read_array<std::int32_t>("cell_prev");
    s.cell_head = g.read_array<std::int32_t>("cell_head");
    s.pair_collisions = g.read_u64_attr("pair_collisions");
    s.wall_collisions = g.read_u64_attr("wall_collisions");
    s.elastic_collisions = g.read_u64_attr("elastic_collisions");
    s.events = g.read_u64_attr("events");
    s.crossings = g.read_u64_attr("crossings");
    s.stale_events = g.read_u64_attr("stale_events");
    s.max_overlap = g.read_double_attr("max_overlap");
    return s;
}

} // namespace granrepro
