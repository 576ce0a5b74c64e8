// The JSON form of a struct's fields() list (data/fields.hpp): what a sweep point returns through
// distributed_sweep, so results are bit-identical whether a point was computed here, on another
// rank or read from a checkpoint. Doubles print with 17 significant digits and read back bit for
// bit; NaN and ±inf, which JSON lacks, are written as null and read back as NaN. Vec2 is [x, y],
// a vector an array, a struct with fields() an object, a nlohmann::json field itself. A type of its own JSON form provides
// `nlohmann::json to_json_value(const T&)` and `void from_json_value(const nlohmann::json&, T&)`,
// found by argument-dependent lookup.
#pragma once
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "core/vec2.hpp"
#include "data/fields.hpp"

namespace granrepro {

namespace json_fields_detail {

template <class T>
nlohmann::json put(const T& x) {
    if constexpr (std::is_same_v<T, double>) return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
    else if constexpr (std::is_arithmetic_v<T> || std::is_same_v<T, std::string> || std::is_same_v<T, nlohmann::json>)
        return x;
    else if constexpr (std::is_same_v<T, Vec2>) return {put(x.x), put(x.y)};
    else if constexpr (HasFields<T>) {
        nlohmann::json j = nlohmann::json::object();
        const_cast<T&>(x).fields([&](const char* name, const auto& f) { j[name] = put(f); });
        return j;
    } else if constexpr (requires { to_json_value(x); }) return to_json_value(x);
    else {
        nlohmann::json j = nlohmann::json::array();
        for (const auto& e : x) j.push_back(put(e));
        return j;
    }
}

// Lenient: a field the JSON lacks keeps its default (outcomes stored before the field existed).
template <bool Lenient = false, class T>
void get(const nlohmann::json& j, T& x) {
    if constexpr (std::is_same_v<T, double>) x = j.is_null() ? NAN : j.get<double>();
    else if constexpr (std::is_same_v<T, nlohmann::json>) x = j;
    else if constexpr (std::is_arithmetic_v<T> || std::is_same_v<T, std::string>) j.get_to(x);
    else if constexpr (std::is_same_v<T, Vec2>) {
        get<Lenient>(j.at(0), x.x);
        get<Lenient>(j.at(1), x.y);
    } else if constexpr (HasFields<T>) x.fields([&](const char* name, auto& f) {
        if (!Lenient || j.contains(name)) get<Lenient>(j.at(name), f);
    });
    else if constexpr (requires { from_json_value(j, x); }) from_json_value(j, x);
    else {
        x.resize(j.size());
        for (std::size_t i = 0; i < x.size(); ++i) get<Lenient>(j.at(i), x[i]);
    }
}

// The layout put() writes for a T: field names and nesting, a number's kind (a double, another
// arithmetic type), text, a Vec2, an array of what. Two types whose JSON forms could not be read
// as each other differ here (a renamed, added or removed field, a double become a list).
template <class T>
std::string schema() {
    if constexpr (std::is_same_v<T, double>) return "f";
    else if constexpr (std::is_same_v<T, bool>) return "b";
    else if constexpr (std::is_arithmetic_v<T>) return "i";
    else if constexpr (std::is_same_v<T, std::string>) return "s";
    else if constexpr (std::is_same_v<T, nlohmann::json>) return "j";
    else if constexpr (std::is_same_v<T, Vec2>) return "v";
    else if constexpr (HasFields<T>) {
        std::string out = "{";
        T x{};
        x.fields([&](const char* name, auto& f) { out += std::string(name) + ":" + schema<std::remove_cvref_t<decltype(f)>>() + ","; });
        return out + "}";
    } else if constexpr (requires(const T& x) { to_json_value(x); }) return "c";
    else return "[" + schema<typename T::value_type>() + "]";
}

} // namespace json_fields_detail

// The layout of T's JSON form as text (json_fields_detail::schema): sweep point files record its
// hash, so that a point saved by a build whose outcome struct differed is recomputed, not misread.
template <HasFields T>
std::string json_fields_schema() {
    return json_fields_detail::schema<T>();
}

template <HasFields T>
nlohmann::json to_json_fields(const T& s) {
    return json_fields_detail::put(s);
}

template <HasFields T>
T from_json_fields(const nlohmann::json& j) {
    T s{};
    json_fields_detail::get(j, s);
    return s;
}

// As from_json_fields, but a field the JSON lacks keeps its default instead of throwing: for
// outcomes stored by an earlier build (`granrepro verify` of committed results), never for resume,
// whose point files carry the layout's hash.
template <HasFields T>
T from_json_fields_lenient(const nlohmann::json& j) {
    T s{};
    json_fields_detail::get<true>(j, s);
    return s;
}

} // namespace granrepro
