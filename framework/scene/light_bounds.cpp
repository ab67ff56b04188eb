#include "light_bounds.h"

#include <algorithm>
#include <cmath>

namespace {
float sine_of(float cosine) {
	return std::sqrt(std::max(0.0f, 1.0f - cosine * cosine));
}

// An angle given by its cosine and sine, both needed to subtract angles without acos.
struct Angle {
	float cos, sin;
};

// max(0, a - b), for angles in [0, pi]: cos(a - b) = cos a cos b + sin a sin b,
// sin(a - b) = sin a cos b - cos a sin b.
Angle difference_clamped(Angle a, Angle b) {
	if (a.cos >= b.cos) return Angle{1.0f, 0.0f}; // a <= b
	return Angle{a.cos * b.cos + a.sin * b.sin, a.sin * b.cos - a.cos * b.sin};
}

constexpr float ALL_DIRECTIONS = -1.0f; // cos_theta_o of a cone that holds every direction
} // namespace

float Light_Bounds::importance(Vec3 p) const {
	Vec3 centre = box.center(), to_p = p - centre;
	float radius2 = 0.25f * glm::dot(box.max - box.min, box.max - box.min); // bounding sphere's radius^2
	float d2 = glm::dot(to_p, to_p);
	// pbrt-v4 keeps d^2 at least half the box's diagonal; this keeps d at least the bounding
	// sphere's radius, so that the distance has the same unit as in the rest of the formula.
	if (d2 <= radius2) return phi / std::max(radius2, 1e-30f); // p inside: theta_b = pi, theta' = 0
	float cos_w = glm::dot(axis, to_p) / std::sqrt(d2);
	Angle theta_w{cos_w, sine_of(cos_w)}, theta_o{cos_theta_o, sine_of(cos_theta_o)};
	float sin_b2 = radius2 / d2;
	Angle theta_b{std::sqrt(1.0f - sin_b2), std::sqrt(sin_b2)};
	Angle theta = difference_clamped(difference_clamped(theta_w, theta_o), theta_b);
	if (theta.cos <= 0.0f) return 0.0f; // theta' >= theta_e = 90 degrees
	return phi * theta.cos / d2;
}

Light_Bounds light_bounds(const Area_Light& light, float power) {
	Light_Bounds bounds;
	bounds.phi = power;
	if (light.triangles.empty()) { // a sphere faces every way
		bounds.box = BBox(light.center - light.radius, light.center + light.radius);
		bounds.cos_theta_o = ALL_DIRECTIONS;
		return bounds;
	}
	Vec3 area_weighted{0.0f};
	for (const Light_Triangle& t : light.triangles) {
		bounds.box.enclose(t.p0);
		bounds.box.enclose(t.p1);
		bounds.box.enclose(t.p2);
		area_weighted += glm::cross(t.p1 - t.p0, t.p2 - t.p0); // normal * 2 area
	}
	// The cone around the mean normal that holds every triangle's normal.
	float length = glm::length(area_weighted);
	if (!(length > 0.0f)) {
		bounds.cos_theta_o = ALL_DIRECTIONS;
		return bounds;
	}
	bounds.axis = area_weighted / length;
	for (const Light_Triangle& t : light.triangles)
		bounds.cos_theta_o = std::min(bounds.cos_theta_o, glm::dot(bounds.axis, t.normal));
	bounds.cos_theta_o = std::max(bounds.cos_theta_o, ALL_DIRECTIONS);
	return bounds;
}

Light_Bounds merged(const Light_Bounds& a, const Light_Bounds& b) {
	Light_Bounds m;
	m.box = a.box;
	m.box.enclose(b.box);
	m.phi = a.phi + b.phi;
	// The smallest cone around both cones (pbrt-v4's Union(DirectionCone, DirectionCone)): if one
	// holds the other, that one; else the cone from a's far side to b's, turned from a's axis
	// towards b's.
	float theta_a = std::acos(std::clamp(a.cos_theta_o, -1.0f, 1.0f));
	float theta_b = std::acos(std::clamp(b.cos_theta_o, -1.0f, 1.0f));
	float theta_d = std::acos(std::clamp(glm::dot(a.axis, b.axis), -1.0f, 1.0f));
	if (std::min(theta_d + theta_b, PI_F) <= theta_a) {
		m.axis = a.axis, m.cos_theta_o = a.cos_theta_o;
		return m;
	}
	if (std::min(theta_d + theta_a, PI_F) <= theta_b) {
		m.axis = b.axis, m.cos_theta_o = b.cos_theta_o;
		return m;
	}
	float theta_o = 0.5f * (theta_a + theta_d + theta_b);
	Vec3 across = b.axis - glm::dot(a.axis, b.axis) * a.axis; // towards b's axis, perpendicular to a's
	if (theta_o >= PI_F || !(glm::length(across) > 0.0f)) {
		m.cos_theta_o = ALL_DIRECTIONS;
		return m;
	}
	float turn = theta_o - theta_a;
	m.axis = glm::normalize(std::cos(turn) * a.axis + std::sin(turn) * glm::normalize(across));
	m.cos_theta_o = std::cos(theta_o);
	return m;
}
