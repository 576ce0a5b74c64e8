// A struct that lists its fields once can be read from parameters (data/spec.hpp), and written and
// read back in HDF5 (io/h5_fields.hpp) and JSON (io/json_fields.hpp) by walking that one list:
//
//   struct PointOutcome {
//       double t_col = 0, e_N = 0;
//       std::vector<double> dv;
//       GRANREPRO_FIELDS(t_col, e_N, dv)   // the member's name is its TOML, JSON and HDF5 name
//   };
//
// GRANREPRO_FIELDS(a, b) defines `template <class V> void fields(V&& v) { v("a", a); v("b", b); }`,
// so a name is written once, as the member, in the order given (the order is part of a point
// file's schema hash, harness/protocol.hpp). GRANREPRO_FIELDS_BASE(Base, a, b) walks Base's
// fields first. A field stored under another name than its member's (a getter, a matrix
// element) is written out by hand as `v("name", expression)`, the same walk.
#pragma once

namespace granrepro {

template <class T>
concept HasFields = requires(T& t) { t.fields([](const char*, auto&) {}); };

} // namespace granrepro

// A for-each over macro arguments (up to 256) by deferred re-expansion (C++20 __VA_OPT__).
#define GRANREPRO_PARENS ()
#define GRANREPRO_EXPAND(...) GRANREPRO_EXPAND3(GRANREPRO_EXPAND3(GRANREPRO_EXPAND3(GRANREPRO_EXPAND3(__VA_ARGS__))))
#define GRANREPRO_EXPAND3(...) GRANREPRO_EXPAND2(GRANREPRO_EXPAND2(GRANREPRO_EXPAND2(GRANREPRO_EXPAND2(__VA_ARGS__))))
#define GRANREPRO_EXPAND2(...) GRANREPRO_EXPAND1(GRANREPRO_EXPAND1(GRANREPRO_EXPAND1(GRANREPRO_EXPAND1(__VA_ARGS__))))
#define GRANREPRO_EXPAND1(...) __VA_ARGS__
#define GRANREPRO_FOR_EACH(macro, ...) __VA_OPT__(GRANREPRO_EXPAND(GRANREPRO_FOR_EACH_STEP(macro, __VA_ARGS__)))
#define GRANREPRO_FOR_EACH_STEP(macro, a, ...) macro(a) __VA_OPT__(GRANREPRO_FOR_EACH_AGAIN GRANREPRO_PARENS(macro, __VA_ARGS__))
#define GRANREPRO_FOR_EACH_AGAIN() GRANREPRO_FOR_EACH_STEP

// The visitor's name is one no member takes (a member `v` would otherwise be hidden by it).
#define GRANREPRO_FIELD_VISIT(member) granrepro_visit_(#member, member);
#define GRANREPRO_FIELDS(...) \
    template <class V> void fields(V&& granrepro_visit_) { GRANREPRO_FOR_EACH(GRANREPRO_FIELD_VISIT, __VA_ARGS__) }
#define GRANREPRO_FIELDS_BASE(Base, ...) \
    template <class V> void fields(V&& granrepro_visit_) { Base::fields(granrepro_visit_); GRANREPRO_FOR_EACH(GRANREPRO_FIELD_VISIT, __VA_ARGS__) }
