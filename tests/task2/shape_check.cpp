#include "shape_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace task2 {

namespace {

DVec3 dvec(Vec3 v) {
	return DVec3(v);
}

// The ray with its origin and direction moved along each axis by ROUNDING of their size, and its
// bounds by ROUNDING of theirs: the inputs a float computation might as well have had.
std::vector<Ray> moved_rays(const Ray& ray, double length_scale) {
	std::vector<Ray> rays;
	float dp = float(ROUNDING * length_scale), dd = float(ROUNDING * glm::length(dvec(ray.dir)));
	for (int axis = 0; axis < 3; axis++) {
		for (float sign : {-1.0f, 1.0f}) {
			Ray r = ray;
			r.point[axis] += sign * dp;
			rays.push_back(r);
			r = ray;
			r.dir[axis] += sign * dd;
			rays.push_back(r);
		}
	}
	return rays;
}

std::vector<Ray> moved_bounds(const Ray& ray) {
	std::vector<Ray> rays;
	for (float factor : {float(1.0 - ROUNDING), float(1.0 + ROUNDING)}) {
		Ray r = ray;
		r.dist_bounds.x *= factor;
		rays.push_back(r);
		r = ray;
		r.dist_bounds.y *= factor;
		rays.push_back(r);
	}
	return rays;
}

// A triangle grown (or shrunk) about its centroid so that each edge moves out by `slack` in
// barycentric units (the centroid is 1/3 from each edge).
Triangle scaled(const Triangle& tri, double slack) {
	Vec3 c = (tri.v0.position + tri.v1.position + tri.v2.position) / 3.0f;
	float factor = float(1.0 + 3.0 * slack);
	Triangle t = tri;
	for (Tri_Mesh_Vert* v : {&t.v0, &t.v1, &t.v2}) v->position = c + factor * (v->position - c);
	return t;
}

// The expectation from the reference's answers: `base` for the ray itself, `moved` for copies that
// measure rounding (their spread is the tolerance), `allowed` for copies any of whose hits is
// right too (other bounds, a triangle's allowed slack).
Expectation expectation(const Trace& base, const std::vector<Trace>& moved, const std::vector<Trace>& allowed) {
	Expectation e;
	bool any_hit = base.hit, any_miss = !base.hit;
	// The spread of the hits among the ray and its moved copies: the range of their distances and
	// how far their normals are from the first one's.
	double t_min = INFINITY, t_max = -INFINITY, t_size = 0.0, normal_spread = 0.0;
	std::vector<Trace> measured;
	if (base.hit) measured.push_back(base);
	for (const Trace& m : moved) {
		any_hit = any_hit || m.hit, any_miss = any_miss || !m.hit;
		if (m.hit) measured.push_back(m);
	}
	for (const Trace& h : measured) {
		e.hits.push_back(h);
		t_min = std::min(t_min, double(h.distance)), t_max = std::max(t_max, double(h.distance));
		t_size = std::max(t_size, std::abs(double(h.distance)));
		normal_spread = std::max(normal_spread, glm::length(dvec(h.normal) - dvec(measured.front().normal)));
	}
	for (const Trace& a : allowed) {
		any_hit = any_hit || a.hit, any_miss = any_miss || !a.hit;
		if (a.hit) e.hits.push_back(a);
	}
	e.verdict = any_hit && any_miss ? Verdict::either : (any_hit ? Verdict::hit : Verdict::miss);
	e.t_error = (measured.empty() ? 0.0 : 2.0 * (t_max - t_min)) + ROUNDING * t_size;
	e.normal_error = 2.0 * normal_spread + 1e-5;
	return e;
}

// Why the reference misses: where the unbounded ray would hit, if anywhere.
template<typename Shape> std::string why_missed(const Shape& shape, const Ray& ray, const char* beside) {
	Ray unbounded = ray;
	unbounded.dist_bounds = Vec2{-INF_F, INF_F};
	Trace anywhere = shape.hit(unbounded);
	if (!anywhere.hit) return beside;
	std::ostringstream why;
	why.precision(9);
	why << "its hit at t = " << anywhere.distance << " is outside dist_bounds [" << ray.dist_bounds.x << ", "
	    << ray.dist_bounds.y << "]";
	return why.str();
}

const char* EITHER = "the ray passes within rounding error (or the allowed edge slack) of an edge, the silhouette "
                     "or an end of dist_bounds";

} // namespace

Expectation expect_hit(const Triangle& tri, const Ray& ray) {
	Trace base = tri.hit(ray);
	double extent = glm::length(dvec(tri.v1.position - tri.v0.position)) +
	                glm::length(dvec(tri.v2.position - tri.v0.position)) + glm::length(dvec(tri.v0.position));
	std::vector<Trace> moved, allowed;
	for (const Ray& r : moved_rays(ray, glm::length(dvec(ray.point)) + extent)) moved.push_back(tri.hit(r));
	for (const Ray& r : moved_bounds(ray)) allowed.push_back(tri.hit(r));
	allowed.push_back(scaled(tri, MAX_EDGE_SLACK).hit(ray));
	allowed.push_back(scaled(tri, -2e-5).hit(ray)); // no slack at all, where the reference uses 1e-5
	Expectation e = expectation(base, moved, allowed);
	// A student's slack moves the barycentric weights of the normal by up to that much.
	e.normal_error += 2.0 * MAX_EDGE_SLACK * (glm::length(dvec(tri.v1.normal - tri.v0.normal)) +
	                                          glm::length(dvec(tri.v2.normal - tri.v0.normal)));
	e.why = e.verdict == Verdict::hit    ? "the ray passes inside the triangle, within dist_bounds"
	        : e.verdict == Verdict::miss ? why_missed(tri, ray, "the ray passes outside the triangle (or parallel to it)")
	                                     : EITHER;
	return e;
}

Expectation expect_hit(const Sphere& sphere, const Ray& ray) {
	Trace base = sphere.hit(ray);
	std::vector<Trace> moved, allowed;
	for (const Ray& r : moved_rays(ray, glm::length(dvec(ray.point)) + sphere.radius)) moved.push_back(sphere.hit(r));
	// The discriminant r^2 - l^2 is computed (textbook or stable form) to within a few eps
	// (|o|^2 + r^2): spheres whose r^2 differs by that much are as right.
	double o2 = glm::dot(dvec(ray.point), dvec(ray.point)), r2 = double(sphere.radius) * sphere.radius;
	for (double sign : {-1.0, 1.0}) {
		moved.push_back(Sphere{float(std::sqrt(std::max(0.0, r2 + sign * ROUNDING * (o2 + r2))))}.hit(ray));
	}
	for (const Ray& r : moved_bounds(ray)) allowed.push_back(sphere.hit(r));
	Expectation e = expectation(base, moved, allowed);
	// A hit anywhere within t_error has its normal within that distance over the radius.
	double d = glm::length(dvec(ray.dir)), t_size = 0.0;
	for (const Trace& h : e.hits) t_size = std::max(t_size, std::abs(double(h.distance)));
	e.normal_error += 2.0 * (e.t_error * d + ROUNDING * (std::sqrt(o2) + t_size * d)) / sphere.radius;
	e.why = e.verdict == Verdict::hit    ? "a root is within dist_bounds"
	        : e.verdict == Verdict::miss ? why_missed(sphere, ray, "the ray's line passes beside the sphere")
	                                     : EITHER;
	return e;
}

std::string show(DVec3 v) {
	std::ostringstream out;
	out.precision(9);
	out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
	return out.str();
}

std::string show(Vec3 v) {
	return show(dvec(v));
}

std::string show(const Ray& ray) {
	std::ostringstream out;
	out.precision(9);
	out << "point " << show(ray.point) << ", dir " << show(ray.dir) << ", dist_bounds [" << ray.dist_bounds.x << ", "
	    << ray.dist_bounds.y << "]";
	return out.str();
}

std::string hit_problem(const Expectation& e, const Trace& got, const Ray& ray, const char* section) {
	std::ostringstream why;
	why.precision(9);
	if (std::isnan(got.distance)) {
		why << "trace.distance is NaN: write the accept tests positively, if (!(t >= lo && t <= hi)) return a miss, "
		       "so that NaN fails them (handout §2.3)";
		return why.str();
	}
	if (!(dvec(got.origin) == dvec(ray.point))) {
		why << "trace.origin must be ray.point " << show(ray.point) << ", got " << show(got.origin) << " (trace.h)";
		return why.str();
	}
	// Reasons about dist_bounds are explained in §2.3, the others in the shape's own section.
	const char* where = e.why.find("dist_bounds") != std::string::npos ? "handout §2.3" : section;
	if (e.verdict == Verdict::hit && !got.hit) {
		why << "missed, but " << e.why << " (expected t = " << e.hits.front().distance << ") (" << where << ")";
		return why.str();
	}
	if (e.verdict == Verdict::miss && got.hit) {
		why << "reported a hit at t = " << got.distance << ", but " << e.why << " (" << where << ")";
		return why.str();
	}
	if (!got.hit) return "";

	double t = got.distance;
	if (!(t >= ray.dist_bounds.x && t <= ray.dist_bounds.y && std::isfinite(t))) {
		why << "reported a hit at t = " << t << ", outside dist_bounds; a hit needs dist_bounds.x <= t <= "
		    << "dist_bounds.y (handout §2.3)";
		return why.str();
	}
	auto match = std::find_if(e.hits.begin(), e.hits.end(),
	                          [&](const Trace& h) { return std::abs(t - double(h.distance)) <= e.t_error; });
	if (match == e.hits.end()) {
		why << "t = " << t << ", expected " << e.hits.front().distance << " (+- " << e.t_error
		    << " for float rounding). t is measured in the ray's parameter, position = point + t dir, and dir need "
		       "not be unit length ("
		    << section << ")";
		return why.str();
	}
	DVec3 o = dvec(ray.point), d = dvec(ray.dir);
	DVec3 at = o + t * d;
	if (!(glm::length(dvec(got.position) - at) <= ROUNDING * (glm::length(o) + std::abs(t) * glm::length(d)))) {
		why << "trace.position " << show(got.position) << " is not ray.at(trace.distance) = " << show(at) << " ("
		    << section << ")";
		return why.str();
	}
	DVec3 n = dvec(got.normal), expected = dvec(match->normal);
	if (!(std::abs(glm::length(n) - 1.0) <= 1e-5)) {
		why << "trace.normal " << show(n) << " has length " << glm::length(n) << "; it must be a unit vector ("
		    << section << ")";
		return why.str();
	}
	if (!(glm::length(n - expected) <= e.normal_error + 1e-6)) {
		why << "trace.normal = " << show(n) << ", expected " << show(expected) << " (" << section << ")";
		return why.str();
	}
	return "";
}

} // namespace task2
