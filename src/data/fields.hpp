// A struct that lists its fields once, `template <class V> void fields(V&& v) { v("name", member); ... }`,
// can be read from parameters (data/spec.hpp), and written and read back in HDF5
// (io/h5_fields.hpp) and JSON (io/json_fields.hpp) by walking that one list.
#pragma once

namespace granrepro {

template <class T>
concept HasFields = requires(T& t) { t.fields([](const char*, auto&) {}); };

} // namespace granrepro
