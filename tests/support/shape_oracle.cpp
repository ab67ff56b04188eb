#include "shape_oracle.h"

#include <algorithm>
#include <cmath>
#include <sstream>

// Error bounds. A float implementation evaluates a short chain of products and sums of its float
// inputs; each correctly rounded operation has relative error <= eps = 2^-24. The forward error
// of such a chain is at most gamma_k = k eps / (1 - k eps) times the same chain evaluated on
// ABSOLUTE values (Higham, "Accuracy and Stability of Numerical Algorithms", §3.1-3.5), e.g.
//   cross product component  a_y b_z - a_z b_y:   <= gamma_2 |a| |b|
//   dot(d, cross(a, b)) (a triple product):        <= (gamma_3 + sqrt(3) gamma_2) |d| |a| |b|
// with Euclidean norms in place of the absolute chains (Cauchy-Schwarz). Counting the rounding of
// the input differences (e1, e2, s) as well, every triple product below is within ~12 eps of its
// norm product; quotients add their relative errors. K = 32 covers that with a margin of ~2.5
// for other orders of evaluation (standard Möller–Trumbore, 1/det then products, the textbook or
// the stable quadratic). These are bounds on what rounding CAN do; a wrong formula is off by far
// more (an edge missed by 1e-2, a distance off by a factor |d|, ...). ROUNDING = K eps.
//
// Spheres: b^2 - a c evaluated in float, by the textbook or the stable form, is within a few eps
// (|o|^2 + r^2) |d|^2 of the truth. A ray whose discriminant is that close to 0 is tangent within
// rounding: it may hit or miss, and its root may lie up to sqrt(2 * that) from the tangent point.
// Accepting the textbook form here is deliberate; its failure on small and distant spheres has a
// test of its own, with a tighter bound (test_sphere.cpp).
namespace shape_oracle {
namespace {

DVec3 dvec(Vec3 v) {
	return DVec3(v);
}

enum class Range { inside, outside, unsure };

// Whether t (known to +- err) lies in the ray's inclusive bounds.
Range bounds_status(const Ray& ray, double t, double err) {
	double lo = ray.dist_bounds.x, hi = ray.dist_bounds.y;
	if (t - err >= lo && t + err <= hi) return Range::inside;
	if (t + err < lo || t - err > hi) return Range::outside;
	return Range::unsure;
}

Expectation miss(std::string why) {
	Expectation e;
	e.verdict = Verdict::miss;
	e.why = std::move(why);
	return e;
}
} // namespace

bool distance_ok(const Expectation& e, double distance) {
	if (std::abs(distance - e.t) <= e.t_error) return true;
	return e.has_other && std::abs(distance - e.t_other) <= e.t_error;
}

DVec3 normal_for(const Expectation& e, double distance) {
	bool other = e.has_other && std::abs(distance - e.t) > std::abs(distance - e.t_other);
	return other ? e.normal_other : e.normal;
}

Expectation expect_hit(const Triangle& tri, const Ray& ray) {
	// Differences of floats are exact in double (for exponents less than 29 apart).
	DVec3 p0 = dvec(tri.v0.position);
	DVec3 e1 = dvec(tri.v1.position) - p0, e2 = dvec(tri.v2.position) - p0;
	DVec3 d = dvec(ray.dir), s = dvec(ray.point) - p0;
	DVec3 n = glm::cross(e1, e2);
	if (n == DVec3(0.0)) return miss("the triangle has zero area");

	// Cramer's rule for o + t d = p0 + u e1 + v e2, and the rounding bounds of each quantity.
	double D = glm::length(d), E1 = glm::length(e1), E2 = glm::length(e2), S = glm::length(s);
	double det = -glm::dot(d, n);
	double det_error = ROUNDING * D * E1 * E2;
	Expectation e;
	if (!(std::abs(det) > det_error)) {
		e.verdict = Verdict::either;
		e.why = "the ray is parallel to the triangle's plane within rounding error";
		e.t_error = INFINITY;
		e.normal_error = 2.0; // any unit vector
		return e;
	}
	double u = glm::dot(d, glm::cross(e2, s)) / det;
	double v = glm::dot(d, glm::cross(s, e1)) / det;
	double t = glm::dot(s, n) / det;
	double w = 1.0 - u - v;
	double u_error = ROUNDING * (D * E2 * S + std::abs(u) * D * E1 * E2) / std::abs(det);
	double v_error = ROUNDING * (D * E1 * S + std::abs(v) * D * E1 * E2) / std::abs(det);
	double w_error = u_error + v_error;
	e.t = t;
	e.t_error = ROUNDING * (S * E1 * E2 + std::abs(t) * D * E1 * E2) / std::abs(det);

	bool surely_inside = u >= u_error && v >= v_error && w >= w_error;
	double slack = MAX_EDGE_SLACK;
	bool surely_outside = u < -(slack + u_error) || v < -(slack + v_error) || w < -(slack + w_error);
	Range range = bounds_status(ray, t, e.t_error);
	if (surely_outside) {
		e.verdict = Verdict::miss;
		e.why = "the ray passes outside the triangle";
	} else if (range == Range::outside) {
		e.verdict = Verdict::miss;
		e.why = "the plane hit is outside dist_bounds";
	} else if (surely_inside && range == Range::inside) {
		e.verdict = Verdict::hit;
		e.why = "the ray passes inside the triangle, within dist_bounds";
	} else {
		e.verdict = Verdict::either;
		e.why = "the hit is within rounding error (or the allowed slack) of an edge or of dist_bounds";
	}

	// A float normal interpolates with u, v that are off by up to u_error, v_error.
	DVec3 n0 = dvec(tri.v0.normal), n1 = dvec(tri.v1.normal), n2 = dvec(tri.v2.normal);
	DVec3 blend = w * n0 + u * n1 + v * n2;
	e.normal = glm::normalize(blend);
	double blend_error = u_error * glm::length(n1 - n0) + v_error * glm::length(n2 - n0);
	e.normal_error = 2.0 * blend_error / glm::length(blend) + ROUNDING;
	return e;
}

bool sphere_roots(const Sphere& sphere, const Ray& ray, double& t0, double& t1) {
	DVec3 o = dvec(ray.point), d = dvec(ray.dir);
	double r = sphere.radius, D = glm::length(d);
	DVec3 dn = d / D;
	double b = glm::dot(o, dn), l = glm::length(o - b * dn);
	double disc = (r - l) * (r + l);
	if (!(disc >= 0.0)) return false;
	t0 = (-b - std::sqrt(disc)) / D;
	t1 = (-b + std::sqrt(disc)) / D;
	return true;
}

Expectation expect_hit(const Sphere& sphere, const Ray& ray) {
	DVec3 o = dvec(ray.point), d = dvec(ray.dir);
	double r = sphere.radius, D = glm::length(d), O = glm::length(o);
	DVec3 dn = d / D;
	// o + tau dn (tau = t D, a length) meets the sphere at tau = -b +- sqrt(disc), where b = o.dn and
	// disc = r^2 - l^2 with l the distance from the centre to the line.
	double b = glm::dot(o, dn);
	double l = glm::length(o - b * dn);
	double disc = (r - l) * (r + l);
	// b^2 - c computed in float (textbook or stable form) is within a few eps (O^2 + r^2).
	double disc_error = ROUNDING * (O * O + r * r);
	Expectation e;
	if (disc < -disc_error) return miss("the ray's line passes outside the sphere");

	if (disc <= disc_error) {
		// Tangent within rounding: a float root may be anywhere within sqrt(2 disc_error) of the
		// tangent point.
		e.t = -b / D;
		e.t_error = (ROUNDING * (O + r) + std::sqrt(2.0 * disc_error)) / D + ROUNDING * std::abs(e.t);
		if (bounds_status(ray, e.t, e.t_error) == Range::outside)
			return miss("the tangent point is outside dist_bounds");
		e.verdict = Verdict::either;
		e.why = "the ray is tangent to the sphere within rounding error";
	} else {
		double root = std::sqrt(disc);
		double t0 = (-b - root) / D, t1 = (-b + root) / D;
		// sqrt(disc) moves by at most disc_error / sqrt(disc) when disc moves by disc_error.
		double tau_error = ROUNDING * (O + r) + disc_error / root;
		e.t_error = tau_error / D + ROUNDING * std::max(std::abs(t0), std::abs(t1));
		Range near = bounds_status(ray, t0, e.t_error), far = bounds_status(ray, t1, e.t_error);
		if (near == Range::inside) {
			e.verdict = Verdict::hit, e.t = t0;
			e.why = "the nearer root is within dist_bounds";
		} else if (near == Range::outside && far == Range::inside) {
			e.verdict = Verdict::hit, e.t = t1;
			e.why = "the nearer root is outside dist_bounds, the farther one inside";
		} else if (near == Range::outside && far == Range::outside) {
			return miss("both roots are outside dist_bounds");
		} else {
			e.verdict = Verdict::either;
			e.why = "a root is within rounding error of an end of dist_bounds";
			e.t = near == Range::outside ? t1 : t0;
			e.t_other = t1;
			e.has_other = near != Range::outside && far != Range::outside;
		}
	}
	// Normal at the expected root: the position error over the radius, plus rounding.
	e.normal = glm::normalize(o + e.t * d);
	e.normal_other = glm::normalize(o + e.t_other * d);
	double t_max = std::max(std::abs(e.t), std::abs(e.t_other));
	e.normal_error = 2.0 * (e.t_error * D + ROUNDING * (O + t_max * D)) / r + ROUNDING;
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
		why << "missed, but " << e.why << " (expected t = " << e.t << ") (" << where << ")";
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
	if (!distance_ok(e, t)) {
		why << "t = " << t << ", expected " << e.t;
		if (e.has_other) why << " or " << e.t_other;
		why << " (+- " << e.t_error << " for float rounding). t is measured in the ray's parameter, position = "
		    << "point + t dir, and dir need not be unit length (" << section << ")";
		return why.str();
	}
	DVec3 o = dvec(ray.point), d = dvec(ray.dir);
	DVec3 at = o + t * d;
	if (!(glm::length(dvec(got.position) - at) <= ROUNDING * (glm::length(o) + std::abs(t) * glm::length(d)))) {
		why << "trace.position " << show(got.position) << " is not ray.at(trace.distance) = " << show(at) << " ("
		    << section << ")";
		return why.str();
	}
	DVec3 n = dvec(got.normal), expected = normal_for(e, t);
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

} // namespace shape_oracle
