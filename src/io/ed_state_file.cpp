#include "io/ed_state_file.hpp"

#include "io/h5_fields.hpp"

namespace granrepro {

void write_ed_state(const H5Object& g, const EdState& s) {
    g.stamp_schema(kEdStateSchema, kEdStateSchemaVersion);
    write_fields(g, s);
}

EdState read_ed_state(const H5Object& g) {
    g.require_schema(kEdStateSchema, kEdStateSchemaVersion);
    EdState s;
    read_fields(g, s);
    return s;
}

} // namespace granrepro
