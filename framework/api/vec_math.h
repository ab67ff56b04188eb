#pragma once
// Vector math for the lab: thin names over GLM so the code reads like the handouts.
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;

// Linear RGB radiance (or reflectance). Never sRGB: conversion happens only when writing PNGs.
using Spectrum = glm::vec3;

constexpr float PI_F = 3.14159265358979323846f;
constexpr float INF_F = std::numeric_limits<float>::infinity();

// Relative luminance of linear sRGB/Rec.709 primaries (ITU-R BT.709).
inline float luminance(Spectrum s) {
	return 0.2126f * s.r + 0.7152f * s.g + 0.0722f * s.b;
}

inline bool is_finite(Vec3 v) {
	return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Affine transforms of points and directions by a 4x4 matrix.
inline Vec3 transform_point(const Mat4& m, Vec3 p) {
	return Vec3(m * Vec4(p, 1.0f));
}
inline Vec3 transform_direction(const Mat4& m, Vec3 d) {
	return Vec3(m * Vec4(d, 0.0f));
}
