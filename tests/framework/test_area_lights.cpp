// Light sampling for task 6 (framework/api/lights.h, Pathtracer::sample_area_lights/area_lights_pdf):
// the density is a density over directions (it integrates to 1), the sampler draws directions with
// exactly that density (chi-square), and a light's directions cover its solid angle (E[1/pdf] =
// Omega). Cases: a quad, a triangle mesh crossed twice by every ray (a tetrahedron), a sphere from
// far away and from close by, and mixtures (an environment plus a light; two lights); and the points
// sample_point draws on a light of few triangles and of many (chi-square over its area).
#include "cap_chi2.h"
#include "error.h"
#include "estimator.h"
#include "light_closed_forms.h"
#include "light_scenes.h"
#include "pathtracer.h"
#include "statistics.h"

#include "lab_catch2.h"
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>

namespace {

using closed_form::DVec3;

constexpr double ALPHA = 0.01;
constexpr size_t SINGLE_LIGHTS = 4; // quad, tetrahedron, far sphere, near sphere
constexpr size_t MIXTURES = 2;      // environment + sphere, quad + sphere
// Every chi-square test of this file (one per light and per mixture) shares ALPHA...
const double CHI2_ALPHA = stats::sidak(ALPHA, SINGLE_LIGHTS + MIXTURES);
// ... and so does every solid-angle z-test (one per light).
const double Z_CRITICAL = stats::two_sided_z(stats::sidak(ALPHA, SINGLE_LIGHTS));

// Where a density is smooth, the cells' midpoint rule (cap_chi2.h) is accurate to better than 1e-4
// at these resolutions (measured: 5e-5 for the sphere seen from 1.05 radii, the worst case, and
// falling as the cells shrink).
constexpr double SMOOTH_QUADRATURE_ERROR = 1e-4;

// A light seen from `from`, and the cap of directions that contains it.
struct Light_View {
	std::string name;
	Scene scene;
	Vec3 from{0.0f};
	Vec3 axis;                      // of the cap of cells
	std::vector<double> ring_edges; // of the cap of cells
	uint32_t sectors = 80;
	double silhouette = NAN;  // of a sphere light, in the cap's cos(alpha) (NaN: none)
	std::vector<Vec3> corners; // directions to a polygonal light's vertices
	double solid_angle = 0.0; // subtended by the light, in closed form
	// For a sphere light: whether a direction grazes it to within float rounding (the only
	// directions allowed a zero density). Empty for polygons: no sampled direction may have one.
	std::function<bool(Vec3)> grazes;
};

Material white_light() {
	return emitter(Spectrum{1.0f});
}

// The cap around the direction to the centroid of `points`, slightly wider than all of them (a cone
// that contains the vertices of a polygon contains the polygon).
void cap_around(Light_View& view, const std::vector<DVec3>& points, uint32_t rings) {
	DVec3 from(view.from), centroid(0.0);
	for (DVec3 p : points) centroid += p / double(points.size());
	DVec3 axis = glm::normalize(centroid - from);
	double widest = 0.0;
	for (DVec3 p : points) widest = std::max(widest, std::acos(glm::dot(axis, glm::normalize(p - from))));
	view.axis = Vec3(axis);
	view.ring_edges = stats::Cap_Cells::even_edges(std::cos(1.02 * widest), rings);
	for (DVec3 p : points) view.corners.push_back(Vec3(glm::normalize(p - from)));
}

std::vector<DVec3> world_points(const Mat4& to_world, const std::vector<Vec3>& points) {
	std::vector<DVec3> out;
	for (Vec3 p : points) out.push_back(DVec3(transform_point(to_world, p)));
	return out;
}

// A unit square light, scaled, tilted and moved by its transform, seen off-centre from the origin.
Light_View quad_view() {
	Light_View view;
	view.name = "quad light";
	Mat4 to_world = glm::translate(Mat4{1.0f}, Vec3{0.3f, 2.0f, -0.4f}) *
	                glm::rotate(Mat4{1.0f}, 0.5f, glm::normalize(Vec3{1.0f, 0.0f, 1.0f})) *
	                glm::scale(Mat4{1.0f}, Vec3{1.5f});
	add_object(view.scene, ceiling_square(0.5f, 0.0f), add_material(view.scene, white_light(), "light"), to_world);
	view.scene.commit();
	std::vector<DVec3> c =
		world_points(to_world, {{-0.5f, 0, -0.5f}, {0.5f, 0, -0.5f}, {0.5f, 0, 0.5f}, {-0.5f, 0, 0.5f}});
	DVec3 from(view.from);
	view.solid_angle =
		closed_form::triangle_solid_angle(c[0], c[1], c[2], from) +
		closed_form::triangle_solid_angle(c[0], c[2], c[3], from);
	cap_around(view, c, 40);
	return view;
}

// A closed mesh: every ray through it crosses two triangles, so the density adds two terms.
Light_View tetrahedron_view() {
	Light_View view;
	view.name = "tetrahedron light (a closed triangle mesh)";
	std::vector<Vec3> v{{1.0f, 1.0f, 0.0f}, {1.5f, 1.8f, 0.3f}, {0.6f, 1.5f, 0.7f}, {1.2f, 1.3f, -0.5f}};
	Mat4 to_world = glm::rotate(Mat4{1.0f}, 0.7f, Vec3{0.0f, 0.0f, 1.0f});
	add_object(view.scene, tetrahedron(v[0], v[1], v[2], v[3]), add_material(view.scene, white_light(), "light"),
	           to_world);
	view.scene.commit();
	std::vector<DVec3> w = world_points(to_world, v);
	DVec3 from(view.from);
	// Seen from outside a convex body, each direction that meets it crosses exactly two faces.
	double faces = closed_form::triangle_solid_angle(w[0], w[1], w[2], from) +
	               closed_form::triangle_solid_angle(w[0], w[1], w[3], from) +
	               closed_form::triangle_solid_angle(w[0], w[2], w[3], from) +
	               closed_form::triangle_solid_angle(w[1], w[2], w[3], from);
	view.solid_angle = 0.5 * faces;
	cap_around(view, w, 40);
	return view;
}

// A sphere of radius 0.5 scaled by 2 (world radius 1) at `centre`, seen from the origin. The cap is
// exactly the sphere's cone, so its outer ring edge is the silhouette.
Light_View sphere_view(const std::string& name, Vec3 centre) {
	Light_View view;
	view.name = name;
	Mat4 to_world = glm::scale(glm::translate(Mat4{1.0f}, centre), Vec3{2.0f});
	add_object(view.scene, Sphere{0.5f}, add_material(view.scene, white_light(), "light"), to_world);
	view.scene.commit();
	double d = glm::length(DVec3(centre));
	view.axis = glm::normalize(centre);
	view.silhouette = std::sqrt(1.0 - 1.0 / (d * d));
	view.ring_edges = stats::Cap_Cells::even_edges(view.silhouette, 40);
	view.solid_angle = closed_form::sphere_solid_angle(1.0, d);
	view.grazes = [centre](Vec3 dir) {
		// Distance from the centre to the line through the origin along dir, against the radius 1.
		glm::dvec3 c(centre), u = glm::normalize(glm::dvec3(dir));
		return std::abs(glm::length(c - glm::dot(c, u) * u) - 1.0) <= 1e-5;
	};
	return view;
}

std::vector<Light_View> single_lights() {
	std::vector<Light_View> views;
	views.push_back(quad_view());
	views.push_back(tetrahedron_view());
	views.push_back(sphere_view("sphere light seen from 4.6 radii", Vec3{1.0f, 4.0f, 2.0f}));
	views.push_back(sphere_view("sphere light seen from 1.05 radii", Vec3{0.0f, 1.05f, 0.0f}));
	return views;
}

stats::Cap_Cells cells_of(const Light_View& view) {
	stats::Cap_Cells cells(view.axis, view.ring_edges, view.sectors, view.silhouette);
	cells.corners = view.corners;
	return cells;
}

stats::Cap_Chi2_Result chi2_of_light_sampling(const Light_View& view, size_t samples, uint64_t seed) {
	Pathtracer pt(view.scene, Render_Settings{});
	stats::Cap_Cells cells = cells_of(view);
	return stats::cap_chi2(
		cells, [&](RNG& rng) { return pt.sample_area_lights(rng, view.from); },
		[&](Vec3 dir) { return double(pt.area_lights_pdf(view.from, dir)); }, samples, seed);
}

// The sampled directions follow area_lights_pdf (χ², 10^6 samples), and it integrates to 1.
void check_sampling_follows_density(const Light_View& view, uint64_t seed) {
	stats::Cap_Chi2_Result r = chi2_of_light_sampling(view, 1000000, seed);
	INFO(view.name << ": " << r.summary() << "; significance " << CHI2_ALPHA);
	CHECK(std::abs(r.pdf_integral - 1.0) <= r.integral_error_bound + SMOOTH_QUADRATURE_ERROR);
	CHECK(r.pass(CHI2_ALPHA));
}

// Ring edges over the whole sphere, with one edge on the silhouette of a sphere light of radius r
// at distance d along the axis (so no cell straddles it).
std::vector<double> whole_sphere_edges(double radius, double distance) {
	double silhouette = std::sqrt(1.0 - (radius / distance) * (radius / distance));
	std::vector<double> edges;
	for (int i = 0; i < 40; i++) edges.push_back(-1.0 + (silhouette + 1.0) * i / 40.0);
	for (double e : stats::Cap_Cells::even_edges(silhouette, 20)) edges.push_back(e);
	return edges;
}

} // namespace

TEST_CASE("sample_area_lights draws directions with the density area_lights_pdf, which integrates to 1",
          "[area_lights]") {
	uint64_t seed = 11;
	for (const Light_View& view : single_lights()) {
		stats::Cap_Chi2_Result r = chi2_of_light_sampling(view, 1000000, seed++);
		INFO(view.name << ": " << r.summary() << "; significance " << CHI2_ALPHA);
		// The cap contains the whole light, so the integral over the cap is the integral over the
		// sphere of directions.
		CHECK(std::abs(r.pdf_integral - 1.0) <= r.integral_error_bound + SMOOTH_QUADRATURE_ERROR);
		CHECK(r.samples_outside_support_ok());
		CHECK(r.chi2.p_value >= CHI2_ALPHA);
	}
}

TEST_CASE("sampled light directions have a finite positive density and cover the light's solid angle",
          "[area_lights]") {
	// For a sampler with density p, E[1 / p(w)] = integral over the support of p of 1 d(omega): the
	// solid angle the light covers. A density off by any factor, or one that forgets a crossing of
	// the light, misses it.
	uint64_t seed = 101;
	for (const Light_View& view : single_lights()) {
		Pathtracer pt(view.scene, Render_Settings{});
		RNG rng(seed++);
		const size_t n = 200000;
		size_t zero_pdf = 0, zero_pdf_not_grazing = 0, bad = 0;
		double sum = 0.0, sum2 = 0.0;
		for (size_t i = 0; i < n; i++) {
			Vec3 dir = pt.sample_area_lights(rng, view.from);
			double pdf = pt.area_lights_pdf(view.from, dir);
			if (!is_finite(dir) || std::abs(glm::length(dir) - 1.0f) > 1e-5f || !std::isfinite(pdf) || pdf < 0.0) bad++;
			if (pdf == 0.0) zero_pdf++;
			if (pdf == 0.0 && !(view.grazes && view.grazes(dir))) zero_pdf_not_grazing++;
			double w = pdf > 0.0 ? 1.0 / pdf : 0.0;
			sum += w, sum2 += w * w;
		}
		double mean = sum / n, variance = (sum2 - n * mean * mean) / (n - 1);
		double z = (mean - view.solid_angle) / std::sqrt(variance / n);
		INFO(view.name << ": mean of 1/pdf = " << mean << ", solid angle " << view.solid_angle << ", z = " << z
		               << " (critical " << Z_CRITICAL << "); " << zero_pdf << " samples of zero density ("
		               << zero_pdf_not_grazing << " not grazing the light), " << bad
		               << " non-unit directions or invalid densities");
		CHECK(bad == 0);
		// Only a direction that grazes a sphere (float rounding decides whether it hits) may have
		// zero density; its true weight 1/pdf is ~0 there, so nothing is lost.
		CHECK(zero_pdf_not_grazing == 0);
		CHECK(std::abs(z) <= Z_CRITICAL);
	}
}

// A path tracer that chooses every light equally often (Light_Choice::uniform).
Pathtracer uniform_choice(const Scene& scene) {
	Estimator_Choice estimator;
	estimator.light_choice = Light_Choice::uniform;
	return Pathtracer(scene, Render_Settings{}, View::path, estimator);
}

TEST_CASE("with an environment and an emissive sphere, each is chosen half the time", "[area_lights]") {
	Light_View view;
	view.name = "constant environment + sphere light";
	add_object(view.scene, Sphere{1.0f}, add_material(view.scene, white_light(), "light"),
	           glm::translate(Mat4{1.0f}, Vec3{0.0f, 3.0f, 0.0f}));
	view.scene.environment = Env_Constant{Spectrum{1.0f}};
	view.scene.commit();
	view.axis = Vec3{0.0f, 1.0f, 0.0f};
	view.ring_edges = whole_sphere_edges(1.0, 3.0);
	view.silhouette = std::sqrt(1.0 - 1.0 / 9.0);
	view.sectors = 60;
	Pathtracer pt = uniform_choice(view.scene);
	REQUIRE(pt.has_lights());

	SECTION("the density is the average of the two densities") {
		RNG rng(5);
		for (int i = 0; i < 1000; i++) {
			// Half of the directions towards the light, half anywhere.
			Vec3 dir = i % 2 ? pt.sample_area_lights(rng, view.from) : Env_Constant{}.sample(rng.unit2());
			double expected = 0.5 * (view.scene.area_lights.pdf(0, view.from, dir) + 1.0 / (4.0 * M_PI));
			CAPTURE(dir.x, dir.y, dir.z);
			REQUIRE(pt.area_lights_pdf(view.from, dir) == Approx(expected).epsilon(1e-5));
		}
	}
	SECTION("samples follow that density (chi-square over the whole sphere)") {
		check_sampling_follows_density(view, 21);
	}
}

TEST_CASE("with two emissive objects, each is chosen half the time", "[area_lights]") {
	Light_View view;
	view.name = "quad light + sphere light";
	uint32_t light = add_material(view.scene, white_light(), "light");
	add_object(view.scene, Sphere{1.0f}, light, glm::translate(Mat4{1.0f}, Vec3{0.0f, 3.0f, 0.0f}));
	// A quad beside the point, facing it: about 0.9 sr.
	Vec3 corner{1.0f, -0.5f, -0.6f}, u{0.0f, 0.0f, 1.2f}, v{0.0f, 1.0f, 0.0f};
	add_object(view.scene, parallelogram(corner, u, v), light);
	view.scene.commit();
	for (DVec3 p : parallelogram_corners(corner, u, v)) view.corners.push_back(Vec3(glm::normalize(p)));
	view.axis = Vec3{0.0f, 1.0f, 0.0f};
	view.ring_edges = whole_sphere_edges(1.0, 3.0);
	view.silhouette = std::sqrt(1.0 - 1.0 / 9.0);
	view.sectors = 80;
	Pathtracer pt = uniform_choice(view.scene);

	SECTION("the density is the average of the two densities") {
		RNG rng(6);
		for (int i = 0; i < 1000; i++) {
			Vec3 dir = pt.sample_area_lights(rng, view.from);
			const Area_Lights& lights = view.scene.area_lights;
			double expected = 0.5 * (lights.pdf(0, view.from, dir) + lights.pdf(1, view.from, dir));
			CAPTURE(dir.x, dir.y, dir.z);
			REQUIRE(pt.area_lights_pdf(view.from, dir) == Approx(expected).epsilon(1e-5));
		}
	}
	SECTION("samples follow that density (chi-square over the whole sphere)") {
		check_sampling_follows_density(view, 22);
	}
}

TEST_CASE("only emissive objects and the environment are lights", "[area_lights]") {
	Scene scene;
	add_object(scene, Sphere{1.0f}, add_material(scene, diffuse_material(Spectrum{0.8f}), "grey"));
	scene.commit();
	Pathtracer pt(scene, Render_Settings{});
	CHECK(scene.area_lights.count() == 0);
	CHECK_FALSE(pt.has_lights());
	// Without lights no direction has a light density, and sampling one is a clear error, not a crash.
	CHECK(pt.area_lights_pdf(Vec3{0.0f, 2.0f, 0.0f}, Vec3{0.0f, -1.0f, 0.0f}) == 0.0f);
	RNG rng(1);
	CHECK_THROWS_WITH(pt.sample_area_lights(rng, Vec3{0.0f, 2.0f, 0.0f}), contains_text("has_lights()"));

	scene.environment = Env_Constant{Spectrum{1.0f}};
	CHECK(pt.has_lights());
}

TEST_CASE("an emissive sphere must be scaled uniformly", "[area_lights]") {
	Scene scene;
	add_object(scene, Sphere{1.0f}, add_material(scene, white_light(), "light"),
	           glm::scale(Mat4{1.0f}, Vec3{1.0f, 2.0f, 1.0f}));
	CHECK_THROWS_AS(scene.commit(), Input_Error);
}

TEST_CASE("area_lights_pdf counts a point on the edge two triangles of a light share once", "[area_lights]") {
	// A square light is two triangles sharing a diagonal; each accepts points a little outside its
	// edges (lights.cpp, EDGE_SLACK). Along either diagonal of the square, the density seen from a
	// point below must be the same smooth d^2 / (A cos) as just beside it, not twice that.
	Scene scene = ceiling_light_scene(0.5f, 1.0f);
	Pathtracer pt(scene, Render_Settings{});
	const Vec3 from{0.2f, 0.0f, -0.1f};
	for (float sign : {1.0f, -1.0f}) {
		for (float t = 0.1f; t < 0.95f; t += 0.1f) {
			Vec3 on_diagonal{t - 0.5f, 1.0f, sign * (t - 0.5f)};
			Vec3 beside = on_diagonal + Vec3{1e-3f, 0.0f, -sign * 1e-3f};
			float pdf_on = pt.area_lights_pdf(from, glm::normalize(on_diagonal - from));
			float pdf_beside = pt.area_lights_pdf(from, glm::normalize(beside - from));
			INFO("point on a diagonal of the square light " << on_diagonal.x << ", " << on_diagonal.z
			                                                 << ": pdf " << pdf_on << ", just beside it " << pdf_beside);
			REQUIRE(pdf_beside > 0.0f);
			CHECK(std::abs(pdf_on / pdf_beside - 1.0f) < 0.01f);
		}
	}
}

TEST_CASE("a mesh light's points are uniform over its area whether it has few triangles or many",
          "[area_lights]") {
	// sample_point picks a triangle by area and the point on it with one 2D number, the triangle's
	// share of u.x rescaled (lights.cpp); a light of more than 2^12 triangles draws the point's
	// first coordinate anew. Both are checked on the unit square y = 0: as two triangles, and as a
	// grid of 2 x 46 x 46 triangles whose columns widen from left to right (unequal areas, so the
	// choice by area is tested too). Chi-square of 10^6 points over 16 x 16 equal cells.
	auto grid = [](uint32_t n) {
		std::vector<Triangle> triangles;
		auto corner = [n](uint32_t i, uint32_t k) {
			float x = float(i) / float(n), z = float(k) / float(n);
			return Vec3{x * x, 0.0f, z}; // column i spans [(i/n)^2, ((i+1)/n)^2]
		};
		Vec3 down{0.0f, -1.0f, 0.0f};
		for (uint32_t i = 0; i < n; i++) {
			for (uint32_t k = 0; k < n; k++) {
				Vec3 a = corner(i, k), b = corner(i + 1, k), c = corner(i + 1, k + 1), d = corner(i, k + 1);
				triangles.push_back(Triangle{{a, down}, {b, down}, {c, down}});
				triangles.push_back(Triangle{{a, down}, {c, down}, {d, down}});
			}
		}
		return Tri_Mesh(std::move(triangles));
	};
	constexpr uint32_t CELLS = 16;
	constexpr size_t SAMPLES = 1000000;
	const double alpha = stats::sidak(ALPHA, 2);
	uint64_t seed = 31;
	for (uint32_t n : {1u, 46u}) {
		Scene scene;
		add_object(scene, grid(n), add_material(scene, white_light(), "light"));
		scene.commit();
		REQUIRE(scene.area_lights.count() == 1);
		std::vector<double> observed(CELLS * CELLS, 0.0), expected(CELLS * CELLS, double(SAMPLES) / (CELLS * CELLS));
		RNG rng(seed++);
		for (size_t s = 0; s < SAMPLES; s++) {
			Vec3 p = scene.area_lights.sample_point(0, rng).position;
			uint32_t i = std::min(uint32_t(p.x * CELLS), CELLS - 1), k = std::min(uint32_t(p.z * CELLS), CELLS - 1);
			observed[k * CELLS + i] += 1.0;
		}
		stats::Chi2_Result r = stats::chi2_test(observed, expected);
		INFO("a unit square light of " << 2 * n * n << " triangles: chi-square " << r.statistic << " with " << r.dof
		                               << " degrees of freedom, p = " << r.p_value << " (significance " << alpha
		                               << "): its points are not uniform over its area; see Area_Lights::sample_point");
		CHECK(r.p_value >= alpha);
	}
}
