// 2D vector used by every engine. A plain aggregate so that arrays of it stay POD and
// checkpoint as raw doubles.
#pragma once
#include <cmath>

namespace granrepro {

struct Vec2 {
    double x = 0.0;
    double y = 0.0;

    constexpr Vec2& operator+=(const Vec2& o) { x += o.x; y += o.y; return *this; }
    constexpr Vec2& operator-=(const Vec2& o) { x -= o.x; y -= o.y; return *this; }
    constexpr Vec2& operator*=(double s) { x *= s; y *= s; return *this; }
    friend constexpr Vec2 operator+(Vec2 a, const Vec2& b) { return a += b; }
    friend constexpr Vec2 operator-(Vec2 a, const Vec2& b) { return a -= b; }
    friend constexpr Vec2 operator-(const Vec2& a) { return {-a.x, -a.y}; }
    friend constexpr Vec2 operator*(Vec2 a, double s) { return a *= s; }
    friend constexpr Vec2 operator*(double s, Vec2 a) { return a *= s; }
    friend constexpr Vec2 operator/(const Vec2& a, double s) { return {a.x / s, a.y / s}; }
    friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
};

constexpr double dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }
// z-component of the 3D cross product of two in-plane vectors.
constexpr double cross(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
// Rotate by +90 degrees: the tangent t = (-n_y, n_x) belonging to a normal n.
constexpr Vec2 perp(const Vec2& a) { return {-a.y, a.x}; }
constexpr double norm2(const Vec2& a) { return dot(a, a); }
inline double norm(const Vec2& a) { return std::sqrt(dot(a, a)); }

} // namespace granrepro
