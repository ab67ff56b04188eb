#include "shape_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace task2 {

namespace {

DVec3 dvec(Vec3 v) {
	return DVec3(v);
}

// The judge's own arithmetic is double: the error of its exact answers, relative to the size of
// the numbers, is a few 2^-53, added to every bound so that the bound holds for the true answer.
constexpr double BOUND = ROUNDING + 16.0 * 0x1p-53;

// ---- Triangles: Möller–Trumbore's four determinants (handout §2.1) ----
//
// The system [e1 e2 -d] (u, v, t)^T = s has, by Cramer's rule, the determinants
//   D = [e1, d, e2] (= -d . n),  U = [s, d, e2],  V = [e1, d, s],  T = [e1, e2, s] (= s . n),
// [a, b, c] = a . (b x c), and u = U / D, v = V / D, t = T / D.
//
// Forward-error bound (Higham, Accuracy and Stability of Numerical Algorithms, §3.1). Each
// determinant expands into six terms +-a_i b_j c_k. e1, e2 and s are float differences (one rounding
// each, relative error <= eps = 2^-24); d is an input. A float evaluation of a triple product in any
// grouping the handout allows (a cross product, each component a*b - c*d, then a three-term dot
// product; or the regroupings of §2.1) rounds at most 2 + 3 times along each term's path, and the
// inputs add at most 3 more: every term carries a relative error <= gamma_8 ~ 8 eps, and the
// determinant an absolute error <= 8 eps |[a, b, c]|, where |[a, b, c]| = sum |a_i b_j c_k| is the
// triple product of the absolute values with every sign +. ROUNDING (16 eps) doubles that. The
// ray's conditioning is D against |[e1, d, e2]|: a ray nearly parallel to the triangle has |D|
// within that error of 0, and then no float formula is sure of the sign of det, of u, v or t.

double triple(DVec3 a, DVec3 b, DVec3 c) {
	return glm::dot(a, glm::cross(b, c));
}

double abs_triple(DVec3 a, DVec3 b, DVec3 c) {
	a = glm::abs(a), b = glm::abs(b), c = glm::abs(c);
	return a.x * (b.y * c.z + b.z * c.y) + a.y * (b.z * c.x + b.x * c.z) + a.z * (b.x * c.y + b.y * c.x);
}

// A real number known to lie in [lo, hi].
struct Interval {
	double lo, hi;
	double mid() const { return 0.5 * (lo + hi); }
	double radius() const { return 0.5 * (hi - lo); }
};

// (x +- ex) / (y +- ey) for an interval y that excludes 0, widened by the at most two roundings of
// the division itself (x / y, or x * (1 / y)).
Interval quotient(double x, double ex, double y, double ey) {
	double q[4] = {(x - ex) / (y - ey), (x - ex) / (y + ey), (x + ex) / (y - ey), (x + ex) / (y + ey)};
	double lo = *std::min_element(q, q + 4), hi = *std::max_element(q, q + 4);
	double widen = 2.0 * FLOAT_EPS * std::max(std::abs(lo), std::abs(hi));
	return {lo - widen, hi + widen};
}

// Where an interval t lies against the ray's bounds (both ends inclusive, handout §2.3).
enum class Bounds { inside, outside, unsure };
Bounds against_bounds(const Ray& ray, Interval t) {
	double lo = ray.dist_bounds.x, hi = ray.dist_bounds.y;
	if (t.lo >= lo && t.hi <= hi && t.hi < INFINITY) return Bounds::inside;
	if (t.hi < lo || t.lo > hi) return Bounds::outside;
	return Bounds::unsure;
}

// The unit normal m / |m| of a vector m known to within dm, and its error: |m/|m| - m'/|m'|| <=
// 2 |m - m'| / |m| (plus the roundings of normalizing); unchecked when m could be 0.
void set_normal(Allowed_Hit& hit, DVec3 m, double dm) {
	double length = glm::length(m);
	if (!(length > dm)) {
		hit.normal = DVec3{0.0}, hit.normal_error = INFINITY;
		return;
	}
	hit.normal = m / length;
	hit.normal_error = 2.0 * dm / length + 4.0 * FLOAT_EPS;
}

std::string show_number(double x) {
	std::ostringstream out;
	out.precision(9);
	out << x;
	return out.str();
}

const char* EITHER = "the ray passes within rounding error (or the allowed edge slack) of an edge, the silhouette "
                     "or an end of dist_bounds";

} // namespace

Expectation expect_hit(const Triangle& tri, const Ray& ray) {
	Expectation e;
	DVec3 p0 = dvec(tri.v0.position), e1 = dvec(tri.v1.position) - p0, e2 = dvec(tri.v2.position) - p0;
	DVec3 d = dvec(ray.dir), s = dvec(ray.point) - p0;
	// A zero-area triangle (e1 x e2 = 0; exact in double, whose products of floats are exact) or a
	// zero direction has nothing to hit (handout §2.3).
	if (glm::cross(e1, e2) == DVec3{0.0} || d == DVec3{0.0}) {
		e.why = "the triangle has zero area or the ray no direction";
		return e;
	}
	double D = triple(e1, d, e2), U = triple(s, d, e2), V = triple(e1, d, s), T = triple(e1, e2, s);
	double eD = BOUND * abs_triple(e1, d, e2), eU = BOUND * abs_triple(s, d, e2),
	       eV = BOUND * abs_triple(e1, d, s), eT = BOUND * abs_triple(e1, e2, s);
	if (!(std::abs(D) > eD)) {
		// Parallel within rounding: the sign of det, and so u, v and t, are anybody's guess.
		e.verdict = D == 0.0 && eD == 0.0 ? Verdict::miss : Verdict::either;
		if (e.verdict == Verdict::either) e.hits.push_back({0.0, INFINITY, DVec3{0.0}, INFINITY});
		e.why = e.verdict == Verdict::miss ? "the ray is parallel to the triangle"
		                                   : "the ray is parallel to the triangle within rounding error";
		return e;
	}
	Interval u = quotient(U, eU, D, eD), v = quotient(V, eV, D, eD), w = quotient(U + V, eU + eV, D, eD);
	Interval t = quotient(T, eT, D, eD);
	// Inside for any slack in [0, MAX_EDGE_SLACK] the handout allows, or outside for all of them.
	bool surely_inside = u.lo >= 0.0 && v.lo >= 0.0 && w.hi <= 1.0;
	bool surely_outside = u.hi < -MAX_EDGE_SLACK || v.hi < -MAX_EDGE_SLACK || w.lo > 1.0 + MAX_EDGE_SLACK;
	Bounds bounds = against_bounds(ray, t);
	if (surely_outside || bounds == Bounds::outside) {
		std::ostringstream why;
		if (surely_outside)
			why << "the ray passes outside the triangle (u = " << show_number(U / D) << ", v = " << show_number(V / D)
			    << ")";
		else
			why << "its hit at t = " << show_number(T / D) << " is outside dist_bounds [" << ray.dist_bounds.x << ", "
			    << ray.dist_bounds.y << "]";
		e.why = why.str();
		return e;
	}
	e.verdict = surely_inside && bounds == Bounds::inside ? Verdict::hit : Verdict::either;
	e.why = e.verdict == Verdict::hit ? "the ray passes inside the triangle, within dist_bounds" : EITHER;
	// The normal (1 - u - v) n0 + u n1 + v n2 at the exact (u, v), known to within what the errors of
	// u and v move it, plus the roundings of the weighted sum.
	DVec3 n0 = dvec(tri.v0.normal), n1 = dvec(tri.v1.normal), n2 = dvec(tri.v2.normal);
	double exact_u = U / D, exact_v = V / D;
	DVec3 m = (1.0 - exact_u - exact_v) * n0 + exact_u * n1 + exact_v * n2;
	double du = std::max(u.hi - exact_u, exact_u - u.lo), dv = std::max(v.hi - exact_v, exact_v - v.lo);
	double dm = du * glm::length(n1 - n0) + dv * glm::length(n2 - n0) +
	            4.0 * FLOAT_EPS * (glm::length(n0) * (1.0 + std::abs(exact_u) + std::abs(exact_v)) +
	                               std::abs(exact_u) * glm::length(n1) + std::abs(exact_v) * glm::length(n2));
	Allowed_Hit hit;
	hit.t = T / D, hit.t_error = std::max(t.hi - hit.t, hit.t - t.lo);
	set_normal(hit, m, dm);
	e.hits.push_back(hit);
	return e;
}

// ---- Spheres: the roots of a t^2 + 2 b t + c = 0 (handout §2.2) ----
//
// a = d . d, b = o . d, c = o . o - r^2, disc = b^2 - a c = a (r^2 - l^2) with l the distance from
// the centre to the ray's line, roots t = (-b -+ sqrt(disc)) / a.
//
// Bound: a correct float implementation returns the exact root for inputs moved by a few rounding
// errors: o and d componentwise by ROUNDING, and r^2 by ROUNDING (|o|^2 + r^2), which also covers
// the cancellation of the textbook b^2 - a c (its error is a few eps times |o|^2 |d|^2). To first
// order these moves change
//   a    by <= 2 ROUNDING a,
//   b    by <= 2 ROUNDING |o| |d|,
//   disc by <= ROUNDING (2 a l |o| + 2 |d| (|b| |o| + |c| |d|) + a (|o|^2 + r^2))
// (the gradients of disc: -2 a (o - (b/a) d) in o, 2 b o - 2 c d in d, a in r^2), each doubled for
// the second-order terms. The roots are then bounded by evaluating (-b -+ sqrt(disc)) / a on those
// intervals; near tangency sqrt(disc) is ill-conditioned and the interval wide, and where disc
// could be negative, a miss is right too.
Expectation expect_hit(const Sphere& sphere, const Ray& ray) {
	Expectation e;
	DVec3 o = dvec(ray.point), d = dvec(ray.dir);
	double r = sphere.radius, a = glm::dot(d, d);
	if (!(a > 0.0) || !(r > 0.0)) {
		e.why = "the ray has no direction or the sphere no radius";
		return e;
	}
	double b = glm::dot(o, d), c = glm::dot(o, o) - r * r;
	DVec3 foot = o - (b / a) * d; // the point of the line nearest the centre
	double l = glm::length(foot), disc = a * (r - l) * (r + l);
	double length_o = glm::length(o), length_d = std::sqrt(a);
	double o2_r2 = length_o * length_o + r * r;
	double da = 2.0 * 2.0 * BOUND * a, db = 2.0 * 2.0 * BOUND * length_o * length_d;
	double ddisc = 2.0 * BOUND *
	               (2.0 * a * l * length_o + 2.0 * length_d * (std::abs(b) * length_o + std::abs(c) * length_d) +
	                a * o2_r2);
	if (disc + ddisc < 0.0) {
		e.why = "the ray's line passes beside the sphere";
		return e;
	}
	bool surely_real = disc - ddisc > 0.0;
	Interval root_of_disc{std::sqrt(std::max(0.0, disc - ddisc)), std::sqrt(disc + ddisc)};
	auto root = [&](double sign) { // (-b + sign sqrt(disc)) / a on the intervals, a > da
		Interval numerator = sign < 0 ? Interval{-b - db - root_of_disc.hi, -b + db - root_of_disc.lo}
		                              : Interval{-b - db + root_of_disc.lo, -b + db + root_of_disc.hi};
		Interval t = quotient(numerator.mid(), numerator.radius(), a, da);
		Allowed_Hit hit;
		hit.t = (-b + sign * std::sqrt(std::max(0.0, disc))) / a;
		hit.t_error = std::max(t.hi - hit.t, hit.t - t.lo);
		// The student's hit point o + t' d is within t_error |d| (and the roundings of o + t d) of the
		// exact one, which is at distance r from the centre.
		set_normal(hit, o + hit.t * d,
		           hit.t_error * length_d + 2.0 * BOUND * (length_o + std::abs(hit.t) * length_d));
		return std::pair{hit, against_bounds(ray, t)};
	};
	// The nearer root if it is in bounds, else the farther one, else a miss (handout §2.2); where a
	// root's place against the bounds (or its existence) is unsure, both choices are right.
	bool miss_allowed = !surely_real;
	auto [near, near_bounds] = root(-1.0);
	if (near_bounds != Bounds::outside) e.hits.push_back(near);
	if (near_bounds != Bounds::inside) {
		auto [far, far_bounds] = root(1.0);
		if (far_bounds != Bounds::outside) e.hits.push_back(far);
		if (far_bounds != Bounds::inside) miss_allowed = true;
	}
	e.verdict = e.hits.empty() ? Verdict::miss : (miss_allowed ? Verdict::either : Verdict::hit);
	if (e.verdict == Verdict::miss) {
		std::ostringstream why;
		why << "its roots t = " << show_number(near.t) << " and " << show_number((-b + std::sqrt(std::max(0.0, disc))) / a)
		    << " are outside dist_bounds [" << ray.dist_bounds.x << ", " << ray.dist_bounds.y << "]";
		e.why = why.str();
	} else {
		e.why = e.verdict == Verdict::hit ? "a root is within dist_bounds" : EITHER;
	}
	return e;
}

double exact_near_root(const Sphere& sphere, const Ray& ray) {
	DVec3 o = dvec(ray.point), d = dvec(ray.dir);
	double r = sphere.radius, a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - r * r;
	double l = glm::length(o - (b / a) * d), disc = a * (r - l) * (r + l);
	if (!(disc >= 0.0)) return NAN;
	double q = -(b + std::copysign(std::sqrt(disc), b));
	return std::min(q / a, c / q);
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
		why << "missed, but " << e.why << " (expected t = " << e.hits.front().t << ") (" << where << ")";
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
	                          [&](const Allowed_Hit& h) { return std::abs(t - h.t) <= h.t_error; });
	if (match == e.hits.end()) {
		const Allowed_Hit& expected = e.hits.front();
		why << "t = " << t << ", expected " << expected.t << " (the exact answer for these inputs, +- "
		    << expected.t_error << ", what float rounding allows for this ray)";
		// A distance off by the direction's length: t measured along a unit direction.
		double length_d = glm::length(dvec(ray.dir));
		if (std::abs(length_d - 1.0) > 1e-3 && (std::abs(t - expected.t * length_d) <= 1e-3 * std::abs(t) ||
		                                        std::abs(t - expected.t / length_d) <= 1e-3 * std::abs(t)))
			why << ". t is measured in the ray's parameter, position = point + t dir, and dir need not be unit length";
		why << " (" << section << ")";
		return why.str();
	}
	DVec3 o = dvec(ray.point), d = dvec(ray.dir);
	DVec3 at = o + t * d;
	if (!(glm::length(dvec(got.position) - at) <= 2.0 * ROUNDING * (glm::length(o) + std::abs(t) * glm::length(d)))) {
		why << "trace.position " << show(got.position) << " is not ray.at(trace.distance) = " << show(at) << " ("
		    << section << ")";
		return why.str();
	}
	DVec3 n = dvec(got.normal);
	if (!(std::abs(glm::length(n) - 1.0) <= 1e-5)) {
		why << "trace.normal " << show(n) << " has length " << glm::length(n) << "; it must be a unit vector ("
		    << section << ")";
		return why.str();
	}
	if (!(glm::length(n - match->normal) <= match->normal_error)) {
		why << "trace.normal = " << show(n) << ", expected " << show(match->normal) << " (+- " << match->normal_error
		    << ") (" << section << ")";
		return why.str();
	}
	return "";
}

} // namespace task2
