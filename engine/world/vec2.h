// Vec2: the value type for every 2D vector in the engine (positions in m, velocities in m/s,
// momenta in kg·m/s). Plain data, constexpr where the standard library allows.
#pragma once

#include <cmath>

struct Vec2 {
    double x = 0.0;
    double y = 0.0;

    constexpr Vec2() = default;
    constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}

    // Component access by axis index: 0 is x, 1 is y (the collision axis of a block collision).
    constexpr double operator[](int axis) const { return axis == 0 ? x : y; }
    constexpr double& operator[](int axis) { return axis == 0 ? x : y; }

    constexpr Vec2 operator-() const { return {-x, -y}; }
    constexpr Vec2& operator+=(Vec2 o) {
        x += o.x;
        y += o.y;
        return *this;
    }
    constexpr Vec2& operator-=(Vec2 o) {
        x -= o.x;
        y -= o.y;
        return *this;
    }
    constexpr Vec2& operator*=(double s) {
        x *= s;
        y *= s;
        return *this;
    }
    constexpr Vec2& operator/=(double s) {
        x /= s;
        y /= s;
        return *this;
    }
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) {
    return {a.x + b.x, a.y + b.y};
}
constexpr Vec2 operator-(Vec2 a, Vec2 b) {
    return {a.x - b.x, a.y - b.y};
}
constexpr Vec2 operator*(Vec2 a, double s) {
    return {a.x * s, a.y * s};
}
constexpr Vec2 operator*(double s, Vec2 a) {
    return {a.x * s, a.y * s};
}
constexpr Vec2 operator/(Vec2 a, double s) {
    return {a.x / s, a.y / s};
}
constexpr bool operator==(Vec2 a, Vec2 b) {
    return a.x == b.x && a.y == b.y;
}
constexpr bool operator!=(Vec2 a, Vec2 b) {
    return !(a == b);
}

constexpr double dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}
// 2D cross product: the z component of (a.x, a.y, 0) × (b.x, b.y, 0).
constexpr double cross(Vec2 a, Vec2 b) {
    return a.x * b.y - a.y * b.x;
}
constexpr double lengthSquared(Vec2 a) {
    return dot(a, a);
}
inline double length(Vec2 a) {
    return std::sqrt(lengthSquared(a));
}
// a rotated by +90 degrees (counter-clockwise, y up).
constexpr Vec2 perpendicular(Vec2 a) {
    return {-a.y, a.x};
}
// Unit vector along a; the zero vector stays zero instead of becoming NaN.
inline Vec2 normalized(Vec2 a) {
    const double len = length(a);
    return len > 0.0 ? a / len : Vec2{};
}
// Component-wise comparison within an absolute tolerance (for tests and tolerances in m).
inline bool approxEqual(Vec2 a, Vec2 b, double tolerance) {
    return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance;
}
