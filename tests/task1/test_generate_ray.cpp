// Task 1, handout §1.1-§1.2: Camera::generate_ray, the pinhole camera. Expected rays are the
// reference's (camera_check.h); a wrong ray is explained by the mistake it matches.
#include "camera_check.h"
#include "judge.h"
#include "rng.h"

#include "lab_catch2.h"

#include <glm/gtc/matrix_transform.hpp>

#include <utility>

using namespace task1;
using protocol::Generate_Rays;

namespace {

Camera camera_at_origin(float v_fov, float aspect_ratio) {
	Camera camera;
	camera.v_fov = v_fov;
	camera.aspect_ratio = aspect_ratio;
	return camera;
}

// The student's rays for these queries, in one request.
std::vector<Ray> student_rays(const std::vector<Generate_Rays::Query>& queries) {
	return judge::ask(Generate_Rays{queries});
}

// Checks the student's ray for a query against the reference; the message names the likely
// mistake. Returns whether it passed, so that loops can stop at the first wrong ray instead of
// repeating it.
bool check_ray(const Generate_Rays::Query& query, const Ray& ray) {
	DVec2 uv(query.film_uv);
	std::string problem = ray_problem(query.camera, uv, ray);
	INFO("generate_ray(film_uv = (" << uv.x << ", " << uv.y << ")) with v_fov = " << query.camera.v_fov
	     << " degrees, aspect_ratio = " << query.camera.aspect_ratio << ": " << problem);
	CHECK(problem.empty());
	return problem.empty();
}

bool check_rays(const std::vector<Generate_Rays::Query>& queries) {
	std::vector<Ray> rays = student_rays(queries);
	for (size_t i = 0; i < queries.size(); i++) {
		if (!check_ray(queries[i], rays[i])) return false;
	}
	return true;
}

// Films of several shapes: square, landscape, portrait, cinema; narrow to wide fields of view. With
// a grading seed, six others drawn from the same ranges.
std::vector<std::pair<float, float>> fovs_and_aspects() {
	std::optional<RNG> secret = judge::secret_inputs();
	if (!secret) {
		return {{60.0f, 1.0f}, {20.0f, 4.0f / 3.0f}, {45.0f, 16.0f / 9.0f}, {90.0f, 0.5f}, {120.0f, 2.39f}, {75.0f, 0.75f}};
	}
	std::vector<std::pair<float, float>> cases;
	for (int i = 0; i < 6; i++) cases.emplace_back(15.0f + 125.0f * secret->unit(), 0.4f + 2.1f * secret->unit());
	return cases;
}

// Film points: the four corners, the edge midpoints, and points off the axes ((0, 0) is the top-left
// corner); with a grading seed the points off the axes are drawn at random.
std::vector<DVec2> film_points() {
	std::vector<DVec2> points{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {0.5, 0.0}, {0.5, 1.0}, {0.0, 0.5}, {1.0, 0.5}};
	std::optional<RNG> secret = judge::secret_inputs();
	if (!secret) {
		points.insert(points.end(), {{0.2, 0.7}, {0.9, 0.15}});
	} else {
		for (int i = 0; i < 4; i++) points.push_back(DVec2(secret->unit2()));
	}
	return points;
}

// A point in [-r, r]^3, public or drawn from the grading seed.
Vec3 place(std::optional<RNG>& secret, Vec3 public_point, float r) {
	if (!secret) return public_point;
	return r * (2.0f * Vec3(secret->unit(), secret->unit(), secret->unit()) - 1.0f);
}

// A field of view in degrees, public or drawn from the grading seed.
float fov(std::optional<RNG>& secret, float public_fov) {
	return secret ? 15.0f + 125.0f * secret->unit() : public_fov;
}

} // namespace

TEST_CASE("generate_ray: the centre of the film looks straight ahead, down -z in camera space", "[id:t1.ray.centre][fn:generate_ray]") {
	std::vector<Generate_Rays::Query> queries;
	for (auto [fov, aspect] : fovs_and_aspects()) queries.push_back({camera_at_origin(fov, aspect), Vec2{0.5f, 0.5f}});
	std::vector<Ray> rays = student_rays(queries);
	for (size_t i = 0; i < rays.size(); i++) {
		const Camera& camera = queries[i].camera;
		const Ray& ray = rays[i];
		INFO("generate_ray(0.5, 0.5) with v_fov = " << camera.v_fov << ", aspect_ratio = " << camera.aspect_ratio
		     << " returned point " << show(DVec3(ray.point)) << ", direction " << show(DVec3(ray.dir))
		     << ": the centre of the film must look straight down -z from the origin (handout §1.1)");
		bool ok = near(DVec3(ray.point), DVec3(0.0), 1e-6) &&
		          near(DVec3(ray.dir), DVec3(0.0, 0.0, -1.0), DIRECTION_TOLERANCE);
		CHECK(ok);
		if (!ok) return;
	}
}

TEST_CASE("generate_ray: corners and edges of the film follow v_fov (degrees) and aspect_ratio", "[id:t1.ray.corners][fn:generate_ray]") {
	std::vector<Generate_Rays::Query> queries;
	for (auto [fov, aspect] : fovs_and_aspects()) {
		for (DVec2 uv : film_points()) queries.push_back({camera_at_origin(fov, aspect), Vec2(uv)});
	}
	check_rays(queries);
}

TEST_CASE("generate_ray: the film spans exactly v_fov vertically and the aspect ratio horizontally", "[id:t1.ray.field-of-view][fn:generate_ray]") {
	// A geometric restatement independent of any formula: the angle between the rays through the
	// top and bottom edge midpoints is v_fov; between left and right it is 2 atan(aspect tan(v_fov/2)).
	const Vec2 top{0.5f, 0.0f}, bottom{0.5f, 1.0f}, left{0.0f, 0.5f}, right{1.0f, 0.5f};
	std::vector<Generate_Rays::Query> queries;
	for (auto [fov, aspect] : fovs_and_aspects()) {
		for (Vec2 uv : {top, bottom, left, right}) queries.push_back({camera_at_origin(fov, aspect), uv});
	}
	std::vector<Ray> rays = student_rays(queries);
	for (size_t i = 0; i < rays.size(); i += 4) {
		float fov = queries[i].camera.v_fov, aspect = queries[i].camera.aspect_ratio;
		auto angle = [&](size_t a, size_t b) {
			DVec3 da = glm::normalize(DVec3(rays[i + a].dir));
			DVec3 db = glm::normalize(DVec3(rays[i + b].dir));
			return degrees(std::acos(glm::clamp(glm::dot(da, db), -1.0, 1.0)));
		};
		double vertical = angle(0, 1);
		double horizontal = angle(2, 3);
		double expected_horizontal = degrees(2.0 * std::atan(aspect * std::tan(0.5 * radians(fov))));
		INFO("v_fov = " << fov << " degrees, aspect_ratio = " << aspect << ": the rays through the top and bottom "
		     "edges are " << vertical << " degrees apart (expected v_fov), left and right " << horizontal
		     << " degrees (expected " << expected_horizontal << "). The plane z = -1 has half height tan(v_fov / 2) "
		     "and half width aspect_ratio times that (handout §1.2)");
		bool ok = std::abs(vertical - fov) < 1e-3 && std::abs(horizontal - expected_horizontal) < 1e-3;
		CHECK(ok);
		if (!ok) return;
	}
}

TEST_CASE("generate_ray: film (0, 0) is up and to the left as seen by the camera", "[id:t1.ray.orientation][fn:generate_ray]") {
	// A camera turned to look along a diagonal: "up" and "left" are the camera's, not the world's.
	std::optional<RNG> rng = judge::secret_inputs();
	Vec3 position = place(rng, {1.0f, 2.0f, 3.0f}, 5.0f), target = place(rng, {-2.0f, 0.5f, -1.0f}, 5.0f);
	Vec3 world_up{0.0f, 1.0f, 0.0f};
	Camera camera = Camera::look_at(position, target, world_up, fov(rng, 50.0f), 1.5f);
	DVec3 forward = glm::normalize(DVec3(target - position));
	DVec3 right = glm::normalize(glm::cross(forward, DVec3(world_up)));
	DVec3 up = glm::cross(right, forward);
	struct Corner {
		Vec2 uv;
		double right_sign, up_sign;
		const char* name;
	};
	const Corner corners[] = {{{0.0f, 0.0f}, -1.0, 1.0, "top-left"},
	                          {{1.0f, 0.0f}, 1.0, 1.0, "top-right"},
	                          {{0.0f, 1.0f}, -1.0, -1.0, "bottom-left"},
	                          {{1.0f, 1.0f}, 1.0, -1.0, "bottom-right"}};
	std::vector<Generate_Rays::Query> queries;
	for (const Corner& c : corners) queries.push_back({camera, c.uv});
	std::vector<Ray> rays = student_rays(queries);
	for (size_t i = 0; i < 4; i++) {
		const Corner& c = corners[i];
		DVec3 dir(rays[i].dir);
		// A mistake camera_check recognises (e.g. the direction transformed like a point, which only a
		// camera away from the origin shows) is named as such; otherwise the film's orientation.
		std::string problem = ray_problem(camera, DVec2(c.uv), rays[i]);
		bool recognised = !problem.empty() && problem.rfind("expected the unit direction", 0) != 0;
		INFO("film_uv (" << c.uv.x << ", " << c.uv.y << ") is the " << c.name << " corner of the image: its ray must "
		     "point " << (c.up_sign > 0 ? "up" : "down") << " and " << (c.right_sign > 0 ? "right" : "left")
		     << " relative to where the camera looks; got " << show(dir) << ". "
		     << (recognised ? problem : "Film v grows downwards (handout §1.1)"));
		CHECK(glm::dot(dir, forward) > 0.0);
		CHECK(c.right_sign * glm::dot(dir, right) > 0.0);
		CHECK(c.up_sign * glm::dot(dir, up) > 0.0);
	}
}

TEST_CASE("generate_ray: directions are unit length and dist_bounds is [0, inf)", "[id:t1.ray.unit-and-bounds][fn:generate_ray]") {
	std::optional<RNG> cases = judge::secret_inputs();
	Camera camera = Camera::look_at(place(cases, Vec3{0.0f, 1.0f, 4.0f}, 5.0f), Vec3{0.0f}, Vec3{0.0f, 1.0f, 0.0f},
	                                fov(cases, 70.0f), 16.0f / 9.0f);
	RNG rng(judge::seed_or_public(cases, 11));
	std::vector<Generate_Rays::Query> queries;
	for (int i = 0; i < 1000; i++) queries.push_back({camera, rng.unit2()});
	size_t wrong_length = 0, wrong_bounds = 0;
	for (const Ray& ray : student_rays(queries)) {
		if (!(std::abs(glm::length(DVec3(ray.dir)) - 1.0) <= DIRECTION_TOLERANCE)) wrong_length++;
		if (!(ray.dist_bounds.x == 0.0f && ray.dist_bounds.y == INF_F && ray.depth == 0)) wrong_bounds++;
	}
	INFO(wrong_length << " of 1000 camera rays do not have a unit-length direction: normalize it after the "
	     "transformation to world space (handout §1.2)");
	CHECK(wrong_length == 0);
	INFO(wrong_bounds << " of 1000 camera rays do not have dist_bounds = [0, inf) and depth 0: construct the Ray "
	     "from just a point and a direction (camera.h)");
	CHECK(wrong_bounds == 0);
}

TEST_CASE("generate_ray: camera_to_world moves the origin to the camera and rotates the directions", "[id:t1.ray.camera-to-world][fn:generate_ray]") {
	std::optional<RNG> rng = judge::secret_inputs();
	SECTION("a camera made by look_at looks at its target") {
		Vec3 position = place(rng, {3.0f, -2.0f, 5.0f}, 6.0f), target = place(rng, {0.0f, 1.0f, -1.0f}, 6.0f);
		Camera camera = Camera::look_at(position, target, Vec3{0.0f, 1.0f, 0.0f}, fov(rng, 40.0f), 1.25f);
		std::vector<Generate_Rays::Query> queries{{camera, Vec2{0.5f, 0.5f}}};
		for (DVec2 uv : {DVec2{0.0, 0.0}, DVec2{1.0, 0.25}, DVec2{0.3, 1.0}, DVec2{0.75, 0.6}}) {
			queries.push_back({camera, Vec2(uv)});
		}
		std::vector<Ray> rays = student_rays(queries);
		{
			const Ray& centre = rays[0];
			DVec3 to_target = glm::normalize(DVec3(target - position));
			INFO("the centre of the film must look from the camera position " << show(DVec3(position))
			     << " straight at the target, direction " << show(to_target) << "; got point "
			     << show(DVec3(centre.point)) << ", direction " << show(DVec3(centre.dir))
			     << ". Apply camera_to_world to the origin and the direction (handout §1.2)");
			CHECK(near(DVec3(centre.point), DVec3(position), 1e-5));
			CHECK(near(DVec3(centre.dir), to_target, DIRECTION_TOLERANCE));
		}
		for (size_t i = 1; i < queries.size(); i++) {
			if (!check_ray(queries[i], rays[i])) return;
		}
	}
	SECTION("a camera_to_world matrix set directly (rotation and translation)") {
		Camera camera = camera_at_origin(fov(rng, 65.0f), 0.8f);
		Vec3 axis = rng ? place(rng, {}, 1.0f) + Vec3{0.0f, 0.0f, 1.5f} : Vec3{1.0f, -2.0f, 0.5f};
		float angle = rng ? 6.0f * rng->unit() : 2.0f;
		Mat4 rotation = glm::rotate(Mat4{1.0f}, angle, glm::normalize(axis));
		camera.camera_to_world = glm::translate(Mat4{1.0f}, place(rng, {-4.0f, 7.5f, 2.0f}, 8.0f)) * rotation;
		std::vector<Generate_Rays::Query> queries;
		for (DVec2 uv : {DVec2{0.5, 0.5}, DVec2{0.0, 0.0}, DVec2{1.0, 1.0}, DVec2{0.1, 0.8}, DVec2{0.6, 0.05}}) {
			queries.push_back({camera, Vec2(uv)});
		}
		check_rays(queries);
	}
}
