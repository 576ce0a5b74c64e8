// One serialization for every state and trace struct: a struct lists its fields once,
//
//   struct LoopState {
//       int next_j = 0;
//       std::vector<double> ts;
//       template <class V> void fields(V&& v) { v("next_j", next_j); v("t", ts); }
//   };
//
// and write_fields / read_fields walk that list, so save and restore cannot drift apart. The
// walk is by field type:
//   double, integers, bool, enums, std::string  -> attributes (uint64 as uint64, the others as
//                                                  int64, bool as 0/1, double as float64)
//   Vec2                                         -> attributes <name>_x, <name>_y
//   std::vector of double / int32 / uint8 / uint32 / uint64 -> 1-D datasets
//   std::vector<Vec2>                            -> datasets <name>_x, <name>_y
//   a struct with fields()                       -> a group <name>
//   std::vector of such structs                  -> a group <name> with attribute "count" and
//                                                  groups "0", "1", ...
// Every value is written at full precision and read back bit for bit.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/vec2.hpp"
#include "data/fields.hpp"
#include "io/h5_file.hpp"

namespace granrepro {

namespace h5_fields_detail {

template <class T>
constexpr bool is_array_element = std::is_same_v<T, double> || std::is_same_v<T, std::int32_t> ||
                                  std::is_same_v<T, std::uint8_t> || std::is_same_v<T, std::uint32_t> ||
                                  std::is_same_v<T, std::uint64_t>;

// An integer attribute read into T: a value T cannot hold throws rather than wrapping (a stored
// -1 would otherwise pass as 4294967295 into a uint32 field).
template <class T>
T read_integer(const H5Object& g, const std::string& name) {
    const long v = g.read_long_attr(name);
    if (!std::in_range<T>(v))
        throw std::runtime_error("HDF5 attribute " + name + " = " + std::to_string(v) + " is out of range");
    return T(v);
}

template <class T>
void put(const H5Object& g, const std::string& name, const T& x);
template <class T>
void get(const H5Object& g, const std::string& name, T& x);

template <HasFields T>
void put_fields(const H5Object& g, const T& s) {
    // fields() is one non-const member for both directions; writing only reads through it.
    const_cast<T&>(s).fields([&](const char* name, const auto& x) { put(g, name, x); });
}
template <HasFields T>
void get_fields(const H5Object& g, T& s) {
    s.fields([&](const char* name, auto& x) { get(g, name, x); });
}

template <class T>
void put(const H5Object& g, const std::string& name, const T& x) {
    if constexpr (std::is_same_v<T, double>) g.attr(name, x);
    else if constexpr (std::is_same_v<T, std::uint64_t>) g.attr_u64(name, x);
    else if constexpr (std::is_same_v<T, bool>) g.attr(name, long(x ? 1 : 0));
    else if constexpr (std::is_enum_v<T>) g.attr(name, long(x));
    else if constexpr (std::is_integral_v<T>) g.attr(name, long(x));
    else if constexpr (std::is_same_v<T, std::string>) g.attr(name, x);
    else if constexpr (std::is_same_v<T, Vec2>) {
        g.attr(name + "_x", x.x);
        g.attr(name + "_y", x.y);
    } else if constexpr (HasFields<T>) put_fields(g.group(name), x);
    else if constexpr (std::is_same_v<T, std::vector<Vec2>>) g.vec2_array(name, x);
    else if constexpr (is_array_element<typename T::value_type>) g.array(name, x);
    else {
        static_assert(HasFields<typename T::value_type>, "no HDF5 form for this field type");
        const H5Object h = g.group(name);
        h.attr("count", long(x.size()));
        for (std::size_t k = 0; k < x.size(); ++k) put_fields(h.group(std::to_string(k)), x[k]);
    }
}

template <class T>
void get(const H5Object& g, const std::string& name, T& x) {
    if constexpr (std::is_same_v<T, double>) x = g.read_double_attr(name);
    else if constexpr (std::is_same_v<T, std::uint64_t>) x = g.read_u64_attr(name);
    else if constexpr (std::is_same_v<T, bool>) x = g.read_long_attr(name) != 0;
    else if constexpr (std::is_enum_v<T>) x = T(read_integer<std::underlying_type_t<T>>(g, name));
    else if constexpr (std::is_integral_v<T>) x = read_integer<T>(g, name);
    else if constexpr (std::is_same_v<T, std::string>) x = g.read_string_attr(name);
    else if constexpr (std::is_same_v<T, Vec2>) x = {g.read_double_attr(name + "_x"), g.read_double_attr(name + "_y")};
    else if constexpr (HasFields<T>) get_fields(g.open_group(name), x);
    else if constexpr (std::is_same_v<T, std::vector<Vec2>>) x = g.read_vec2_array(name);
    else if constexpr (is_array_element<typename T::value_type>) x = g.template read_array<typename T::value_type>(name);
    else {
        const H5Object h = g.open_group(name);
        x.assign(read_integer<std::size_t>(h, "count"), typename T::value_type{});
        for (std::size_t k = 0; k < x.size(); ++k) get_fields(h.open_group(std::to_string(k)), x[k]);
    }
}

} // namespace h5_fields_detail

// Writes every field of s into group g (attributes, datasets, subgroups; see above).
template <HasFields T>
void write_fields(const H5Object& g, const T& s) {
    h5_fields_detail::put_fields(g, s);
}

// Reads every field of s from group g; throws (naming the missing link) if one is absent.
template <HasFields T>
void read_fields(const H5Object& g, T& s) {
    h5_fields_detail::get_fields(g, s);
}

} // namespace granrepro
