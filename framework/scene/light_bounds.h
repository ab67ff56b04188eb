#pragma once
// What a light tree (light_tree.h) knows of a group of area lights: where they are, how much power
// they emit, and which way they face; and from that, how much light they may send to a point (their
// importance). The bounds of pbrt-v4's light BVH (Pharr, Jakob and Humphreys, Physically Based
// Rendering, 4th ed., section 12.6.3, LightBounds), after Estevez and Kulla, "Importance Sampling of Many
// Lights with Adaptive Tree Splitting" (2018), which Blender Cycles' light tree (3.5 on) follows.
//
// Orientation: every normal of the group lies within the angle theta_o of `axis`. Every emitter of
// this renderer is a one-sided Lambertian surface: it emits up to 90 degrees from its normal
// (pbrt's theta_e = pi/2 for all of them, so it is not stored).
#include "bbox.h"
#include "lights.h"

struct Light_Bounds {
	BBox box;                 // every point of the group's lights
	float phi = 0.0f;         // their total power (light_powers())
	Vec3 axis{0.0f, 0.0f, 1.0f};
	float cos_theta_o = 1.0f; // -1: the normals may point anywhere

	// A bound, up to a constant, on the irradiance the group can cause at p:
	//   phi * cos(theta') / d^2,  theta' = max(0, theta_w - theta_o - theta_b),
	// d the distance from the box's centre (at least the radius of the box's bounding sphere),
	// theta_w the angle between the axis and the direction from the centre to p, and theta_b the
	// half-angle the bounding sphere subtends at p: theta' is the smallest angle any emitter's
	// normal can make with the direction from it to p. 0 when theta' >= 90 degrees: p is behind
	// every emitter of the group, which then sends it no light at all.
	float importance(Vec3 p) const;
};

// The bounds of one area light of `power`: its box, and the cone of its triangles' normals (all
// directions for a sphere).
Light_Bounds light_bounds(const Area_Light& light, float power);

// The bounds of the union of two groups (pbrt-v4's Union of LightBounds and of DirectionCones).
Light_Bounds merged(const Light_Bounds& a, const Light_Bounds& b);
