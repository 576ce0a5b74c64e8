// Typed specs: an experiment reads its ParameterSet once into a struct and its code reads
// `spec.e_N`, never a string. A spec lists its fields once, each member named as its TOML key
// (data/fields.hpp); the TOML stays the single source of units, ranges, defaults and sources
// (ParameterSet has checked them):
//
//   struct CoolingSpec {
//       long N = 0;
//       double e_N = 0;
//       std::vector<double> snapshots;
//       GRANREPRO_FIELDS(N, e_N, snapshots)
//   };
//   const auto s = read_spec<CoolingSpec>(ctx.params);
//
// A field's C++ type picks the parameter kind: double (Real), long or int (Integer), bool (Flag),
// std::string (Text), std::vector<double> (RealList), or an enum with a
// `void parse_choice(const std::string&, E&)` found by argument-dependent lookup (Text choices).
// A name the TOML does not have, or of another kind, throws, as ParameterSet::real() does; so does
// a parameter of the TOML that the spec does not list (ParameterSet::refuse_unread): the spec is
// the experiment's whole list of what it reads.
#pragma once
#include <string>
#include <type_traits>
#include <vector>

#include "data/parameter_set.hpp"

namespace granrepro {

namespace spec_detail {

inline void assign(const ParameterSet& p, const char* name, double& x) { x = p.real(name); }
inline void assign(const ParameterSet& p, const char* name, long& x) { x = p.integer(name); }
inline void assign(const ParameterSet& p, const char* name, int& x) { x = int(p.integer(name)); }
inline void assign(const ParameterSet& p, const char* name, bool& x) { x = p.flag(name); }
inline void assign(const ParameterSet& p, const char* name, std::string& x) { x = p.text(name); }
inline void assign(const ParameterSet& p, const char* name, std::vector<double>& x) { x = p.reals(name); }
template <class E>
    requires std::is_enum_v<E>
void assign(const ParameterSet& p, const char* name, E& x) {
    parse_choice(p.text(name), x);
}

} // namespace spec_detail

template <class Spec>
Spec read_spec(const ParameterSet& p) {
    Spec s{};
    std::vector<std::string> read;
    s.fields([&](const char* name, auto& field) {
        spec_detail::assign(p, name, field);
        read.emplace_back(name);
    });
    p.refuse_unread(read);
    return s;
}

} // namespace granrepro
