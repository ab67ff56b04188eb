#include "lights.h"
#include "error.h"

#include <algorithm>

namespace {
float triangle_area(const Light_Triangle& t) {
	return 0.5f * glm::length(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
}

// Solid-angle density of a point p (unit normal n) chosen with area density 1/area:
// pdf_omega = dist^2 / (|cos theta_light| * area).
float area_to_solid_angle(Vec3 from, Vec3 p, Vec3 n, float area) {
	Vec3 d = p - from;
	float dist2 = glm::dot(d, d);
	float cos_light = std::abs(glm::dot(n, d)) / std::sqrt(dist2);
	float pdf = dist2 / (cos_light * area);
	return std::isfinite(pdf) ? pdf : 0.0f;
}

// Barycentric slack of triangle_distance. Area_Lights::sample picks points anywhere on a triangle,
// its edges included, and returns the float direction towards them; found again along that
// direction, a point on an edge may lie a rounding error outside. Its pdf must not be 0 (the
// one-sample mixture would then divide a light hit by the BSDF's half alone: a firefly), so points
// up to 1e-5 of the triangle outside an edge count as on it, as in Triangle::hit.
constexpr double EDGE_SLACK = 1e-5;

// Möller–Trumbore in double precision: the distance to triangle t along from + s * dir, or -1.
double triangle_distance(const Light_Triangle& t, Vec3 from, Vec3 dir) {
	glm::dvec3 e1 = glm::dvec3(t.p1) - glm::dvec3(t.p0), e2 = glm::dvec3(t.p2) - glm::dvec3(t.p0);
	glm::dvec3 d(dir), s = glm::dvec3(from) - glm::dvec3(t.p0);
	glm::dvec3 p = glm::cross(d, e2);
	double det = glm::dot(e1, p);
	if (det == 0.0) return -1.0;
	double u = glm::dot(s, p) / det;
	glm::dvec3 q = glm::cross(s, e1);
	double v = glm::dot(d, q) / det;
	double dist = glm::dot(e2, q) / det;
	bool inside = u >= -EDGE_SLACK && v >= -EDGE_SLACK && u + v <= 1.0 + EDGE_SLACK;
	return (inside && dist > 0.0) ? dist : -1.0;
}

Area_Light mesh_light(const Tri_Mesh& mesh, const Mat4& to_world) {
	Area_Light light;
	for (const Triangle& tri : mesh.bvh.primitives) {
		Light_Triangle t{transform_point(to_world, tri.v0.position), transform_point(to_world, tri.v1.position),
		                 transform_point(to_world, tri.v2.position), Vec3{0.0f}};
		float area = triangle_area(t);
		if (!(area > 0.0f)) continue; // zero-area triangles emit nothing
		t.normal = glm::normalize(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
		light.triangles.push_back(t);
		light.area += area;
		light.cdf.push_back(light.area);
	}
	return light;
}

Area_Light sphere_light(const Sphere& sphere, const Mat4& to_world, uint32_t object) {
	Vec3 sx = transform_direction(to_world, Vec3{1, 0, 0}), sy = transform_direction(to_world, Vec3{0, 1, 0}),
	     sz = transform_direction(to_world, Vec3{0, 0, 1});
	float scale = glm::length(sx);
	auto close = [&](float s) { return std::abs(s - scale) <= 1e-4f * scale; };
	if (!close(glm::length(sy)) || !close(glm::length(sz))) {
		throw Input_Error("objects[" + std::to_string(object) +
		                  "]: an emissive sphere must be scaled uniformly (found a non-uniform scale)");
	}
	Area_Light light;
	light.center = transform_point(to_world, Vec3{0.0f});
	light.radius = sphere.radius * scale;
	light.inside_out = glm::determinant(Mat3(to_world)) < 0.0f; // as Instance turns its normals
	light.area = 4.0f * PI_F * light.radius * light.radius;
	return light;
}
} // namespace

void Area_Lights::build(const std::vector<Instance>& objects, const std::vector<Material>& materials) {
	lights.clear();
	light_of_object.clear();
	for (const Instance& object : objects) {
		if (!materials.at(object.material).is_emissive()) continue;
		Area_Light light = std::holds_alternative<Tri_Mesh>(object.shape)
		                       ? mesh_light(std::get<Tri_Mesh>(object.shape), object.to_world)
		                       : sphere_light(std::get<Sphere>(object.shape), object.to_world, object.index);
		light.material = object.material;
		if (!(light.area > 0.0f && std::isfinite(light.area))) continue;
		if (light_of_object.size() <= object.index) light_of_object.resize(object.index + 1, -1);
		light_of_object[object.index] = int(lights.size());
		lights.push_back(std::move(light));
	}
}

Area_Lights::Point Area_Lights::sample_point(size_t i, RNG& rng) const {
	const Area_Light& light = lights[i];
	if (light.triangles.empty()) {
		// Uniform point on the sphere: z = 1 - 2u, phi = 2 pi v.
		Vec2 u = rng.unit2();
		float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * PI_F * u.y;
		Vec3 outwards{r * std::cos(phi), r * std::sin(phi), z};
		return Point{light.center + light.radius * outwards, light.inside_out ? -outwards : outwards};
	}
	// A triangle with probability proportional to its area, then a uniform point on it
	// (square-root parametrization: b0 = 1 - sqrt(u1), b1 = u2 sqrt(u1)), both from one 2D point:
	// u.x picks the triangle and, rescaled to its share of the area, is the u1 of the point on it
	// (as pbrt-v4's SampleDiscrete returns its u remapped), so that a pixel's low-discrepancy
	// samples stay stratified over the whole light, and one number fewer is drawn. Rescaled, u1 keeps
	// about 2^24 / (number of triangles) of u.x's 2^24 steps: a light of more triangles than
	// RESCALED_MAX_TRIANGLES draws its u1 anew rather than put its points on a few lines.
	constexpr size_t RESCALED_MAX_TRIANGLES = size_t(1) << 12;
	Vec2 u = rng.unit2();
	float target = u.x * light.area;
	size_t t = size_t(std::upper_bound(light.cdf.begin(), light.cdf.end(), target) - light.cdf.begin());
	t = std::min(t, light.triangles.size() - 1);
	const Light_Triangle& tri = light.triangles[t];
	float below = t > 0 ? light.cdf[t - 1] : 0.0f, share = light.cdf[t] - below;
	float u1 = light.triangles.size() > RESCALED_MAX_TRIANGLES ? rng.unit()
	           : share > 0.0f                                  ? std::clamp((target - below) / share, 0.0f, 1.0f)
	                                                           : 0.0f;
	float su = std::sqrt(u1), b0 = 1.0f - su, b1 = u.y * su;
	return Point{b0 * tri.p0 + b1 * tri.p1 + (1.0f - b0 - b1) * tri.p2, tri.normal};
}

Vec3 Area_Lights::sample(size_t i, RNG& rng, Vec3 from) const {
	return glm::normalize(sample_point(i, rng).position - from);
}

float Area_Lights::pdf(size_t i, Vec3 from, Vec3 dir) const {
	const Area_Light& light = lights[i];
	float pdf = 0.0f;
	if (light.triangles.empty()) {
		// Both crossings of the sphere |from + s dir - c| = r (dir is unit): s = -b +- sqrt(disc),
		// b = f.dir with f = from - c. The discriminant r^2 - |f - b dir|^2 (the squared half-chord)
		// is computed as (r - |v|)(r + |v|) from the perpendicular part v = f - b dir, not as
		// b^2 - (|f|^2 - r^2), which cancels catastrophically for rays that graze the sphere.
		glm::dvec3 f = glm::dvec3(from) - glm::dvec3(light.center), d(dir);
		double b = glm::dot(f, d), r = light.radius, v = glm::length(f - b * d);
		double disc = (r - v) * (r + v);
		if (!(disc > 0.0)) return 0.0f;
		for (double s : {-b - std::sqrt(disc), -b + std::sqrt(disc)}) {
			if (s <= 0.0) continue;
			Vec3 p = from + float(s) * dir;
			pdf += area_to_solid_angle(from, p, glm::normalize(p - light.center), light.area);
		}
		return pdf;
	}
	// Every point of the light on the ray adds its density, but a point on an edge is claimed by
	// both triangles that share it (EDGE_SLACK): hits at the same distance along the ray, to within
	// ten times the slack (neighbours that are not coplanar meet the ray a little apart in the
	// slack band), are the same point and count once. The list of distances is kept per thread and
	// reused: this runs for every light-sampled and BSDF-sampled direction.
	thread_local std::vector<double> counted;
	counted.clear();
	for (const Light_Triangle& tri : light.triangles) {
		double s = triangle_distance(tri, from, dir);
		if (s <= 0.0) continue;
		auto same_point = [s](double other) { return std::abs(s - other) <= 10.0 * EDGE_SLACK * s; };
		if (std::any_of(counted.begin(), counted.end(), same_point)) continue;
		counted.push_back(s);
		Vec3 n = glm::normalize(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
		pdf += area_to_solid_angle(from, from + float(s) * dir, n, light.area);
	}
	return pdf;
}

float Area_Lights::point_pdf(size_t i, Vec3 from, Vec3 point, Vec3 normal) const {
	return area_to_solid_angle(from, point, normal, lights[i].area);
}

int Area_Lights::light_of(uint32_t object) const {
	return object < light_of_object.size() ? light_of_object[object] : -1;
}
