// Task 3, handout §3.1: BBox::hit, the slab test, on cases worked out by hand. The student's
// BBox::hit answers in the subject, all the cases of a test case in one request. With a grading seed
// every case is moved by an integer offset and its direction scaled by a power of two, which keeps
// the arithmetic exact: the expected times scale by the inverse power of two.
#include "bbox.h"
#include "judge.h"

#include "lab_catch2.h"

#include <cmath>
#include <vector>

namespace {

const BBox UNIT{Vec3{0.0f}, Vec3{1.0f}};

struct Box_Case {
	const char* what; // the behaviour, in the handout's words
	BBox box;
	Ray ray;
	Vec2 times_in;
	bool hit;
	Vec2 times_out; // the overlap, when hit
};

Vec2 from_zero() {
	return Vec2{0.0f, INF_F};
}

std::string text(Vec3 v) {
	return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

// The case as the grading seed moves it: offset by integers, direction times 2^k, times / 2^k.
Box_Case moved(Box_Case c, RNG& rng) {
	Vec3 offset{float(int(rng.integer(129)) - 64), float(int(rng.integer(129)) - 64), float(int(rng.integer(129)) - 64)};
	float scale = std::ldexp(1.0f, int(rng.integer(7)) - 3);
	c.box.min += offset, c.box.max += offset, c.ray.point += offset;
	c.ray.dir *= scale;
	c.times_in /= scale, c.times_out /= scale;
	return c;
}

// Asks the student's BBox::hit for every case in one request and checks each answer.
void check(std::vector<Box_Case> cases) {
	if (std::optional<RNG> secret = judge::secret_inputs()) {
		for (Box_Case& c : cases) c = moved(c, *secret);
	}
	protocol::BBox_Hits request;
	for (const Box_Case& c : cases) request.queries.push_back({c.box, c.ray, c.times_in});
	std::vector<protocol::BBox_Hits::Result> answers = judge::ask(request);
	for (size_t i = 0; i < cases.size(); i++) {
		const Box_Case& c = cases[i];
		bool hit = answers[i].hit;
		Vec2 times = answers[i].times;
		INFO("BBox::hit (handout §3.1): " << c.what);
		INFO("box min " << text(c.box.min) << ", max " << text(c.box.max) << "; ray point " << text(c.ray.point)
		                << ", dir " << text(c.ray.dir) << "; times on entry [" << c.times_in.x << ", " << c.times_in.y
		                << "]");
		if (c.hit) {
			INFO("expected a hit with times = [" << c.times_out.x << ", " << c.times_out.y << "]");
			CHECK(hit);
			if (!hit) continue;
			INFO("got times = [" << times.x << ", " << times.y << "]: times must be narrowed to the overlap of the "
			                     "three slabs and the interval passed in");
			CHECK(times.x == Approx(c.times_out.x).margin(1e-6));
			CHECK(times.y == Approx(c.times_out.y).margin(1e-6));
		} else {
			INFO("expected a miss");
			CHECK_FALSE(hit);
		}
	}
}

} // namespace

TEST_CASE("BBox::hit: rays that cross a box hit it and times becomes [enter, exit]", "[id:t3.bbox.crossing][task3][bbox][fn:BBox::hit]") {
	check({
	         Box_Case{"a ray along +x through the middle enters at x = 0 and leaves at x = 1", UNIT,
	                  Ray{{-1.0f, 0.5f, 0.5f}, {1.0f, 0.0f, 0.0f}}, from_zero(), true, {1.0f, 2.0f}},
	         Box_Case{"a ray along -x (negative direction: swap the slab ends)", UNIT,
	                  Ray{{2.0f, 0.5f, 0.5f}, {-1.0f, 0.0f, 0.0f}}, from_zero(), true, {1.0f, 2.0f}},
	         Box_Case{"a diagonal ray enters through the corner (0,0,0) and leaves through (1,1,1)", UNIT,
	                  Ray{{-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}}, from_zero(), true, {1.0f, 2.0f}},
	         Box_Case{"t is in units of the ray's parameter: a direction of length 2 halves the times", UNIT,
	                  Ray{{-1.0f, 0.5f, 0.5f}, {2.0f, 0.0f, 0.0f}}, from_zero(), true, {0.5f, 1.0f}},
	         Box_Case{"an oblique ray: it enters when the last slab is entered (y, t = 2) and leaves when the "
	                  "first slab is left (y, t = 4)",
	                  BBox{{0.0f, 0.0f, 0.0f}, {4.0f, 1.0f, 1.0f}}, Ray{{-1.0f, -1.0f, 0.25f}, {1.0f, 0.5f, 0.0f}},
	                  from_zero(), true, {2.0f, 4.0f}},
	});
}

TEST_CASE("BBox::hit: rays that pass by or point away miss", "[id:t3.bbox.miss][task3][bbox][fn:BBox::hit]") {
	check({
	         Box_Case{"a ray parallel to x but above the box never enters the y slab", UNIT,
	                  Ray{{-1.0f, 2.0f, 0.5f}, {1.0f, 0.0f, 0.0f}}, from_zero(), false, {}},
	         Box_Case{"a ray pointing away from the box (the box is at negative t)", UNIT,
	                  Ray{{-1.0f, 0.5f, 0.5f}, {-1.0f, 0.0f, 0.0f}}, from_zero(), false, {}},
	         Box_Case{"a skew ray: inside the x slab for t in [1, 2] but the y slab for t in [-0.25, 0.25]", UNIT,
	                  Ray{{-1.0f, 0.5f, 0.5f}, {1.0f, 2.0f, 0.0f}}, from_zero(), false, {}},
	});
}

TEST_CASE("BBox::hit: a ray starting inside the box hits it from times.x on", "[id:t3.bbox.inside][task3][bbox][fn:BBox::hit]") {
	check({
	         Box_Case{"the origin is inside: the overlap starts at times.x = 0 and ends at the exit", UNIT,
	                  Ray{{0.5f, 0.5f, 0.5f}, {1.0f, 0.0f, 0.0f}}, from_zero(), true, {0.0f, 0.5f}},
	         Box_Case{"the origin is inside, oblique direction", UNIT, Ray{{0.5f, 0.25f, 0.5f}, {-1.0f, -1.0f, 2.0f}},
	                  from_zero(), true, {0.0f, 0.25f}},
	});
}

TEST_CASE("BBox::hit: flat boxes (min == max on an axis) are hit", "[id:t3.bbox.flat][task3][bbox][fn:BBox::hit]") {
	const BBox flat_z{{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}};
	const BBox point{{1.0f, 2.0f, 3.0f}, {1.0f, 2.0f, 3.0f}};
	check({
	         Box_Case{"a ray straight down through a box that is flat in z: enter = exit (compare with <=, not <)",
	                  flat_z, Ray{{0.5f, 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}}, from_zero(), true, {1.0f, 1.0f}},
	         Box_Case{"an oblique ray through a box that is flat in z", flat_z,
	                  Ray{{0.25f, 0.25f, 1.0f}, {0.25f, 0.25f, -1.0f}}, from_zero(), true, {1.0f, 1.0f}},
	         Box_Case{"a ray through a box that is a single point", point, Ray{{1.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 1.0f}},
	                  from_zero(), true, {3.0f, 3.0f}},
	         Box_Case{"a ray that crosses the plane of a flat box outside it misses", flat_z,
	                  Ray{{2.0f, 0.5f, 1.0f}, {0.0f, 0.0f, -1.0f}}, from_zero(), false, {}},
	});
}

TEST_CASE("BBox::hit: axis-aligned rays and rays in the plane of a face (1/0 = inf, 0 * inf = NaN)",
          "[id:t3.bbox.axis-aligned][task3][bbox][fn:BBox::hit]") {
	check({
	         Box_Case{"d = (0, 0, 1) from inside the x and y slabs: those slabs hold for every t", UNIT,
	                  Ray{{0.5f, 0.5f, -1.0f}, {0.0f, 0.0f, 1.0f}}, from_zero(), true, {1.0f, 2.0f}},
	         Box_Case{"d = (0, 0, 1) with the origin ON the plane x = min.x: (min.x - o.x) / 0 is NaN, which must not "
	                  "turn the hit into a miss",
	                  UNIT, Ray{{0.0f, 0.5f, -1.0f}, {0.0f, 0.0f, 1.0f}}, from_zero(), true, {1.0f, 2.0f}},
	         Box_Case{"the same with d = (-0, 0, 1): 1 / -0 = -inf", UNIT, Ray{{0.0f, 0.5f, -1.0f}, {-0.0f, 0.0f, 1.0f}},
	                  from_zero(), true, {1.0f, 2.0f}},
	         Box_Case{"origin on the plane x = max.x, d = (0, 0, 1)", UNIT, Ray{{1.0f, 0.5f, -1.0f}, {0.0f, 0.0f, 1.0f}},
	                  from_zero(), true, {1.0f, 2.0f}},
	         Box_Case{"origin on an edge line (x = 0 and y = 1), d = (0, 0, -1)", UNIT,
	                  Ray{{0.0f, 1.0f, 3.0f}, {0.0f, -0.0f, -1.0f}}, from_zero(), true, {2.0f, 3.0f}},
	         Box_Case{"a ray that slides along the top face (in the plane z = max.z)", UNIT,
	                  Ray{{-1.0f, 0.5f, 1.0f}, {1.0f, 0.0f, 0.0f}}, from_zero(), true, {1.0f, 2.0f}},
	         Box_Case{"d = (0, 0, 1) just outside the x slab misses", UNIT, Ray{{-0.5f, 0.5f, -1.0f}, {0.0f, 0.0f, 1.0f}},
	                  from_zero(), false, {}},
	         Box_Case{"d = (0, 0, 1) from the plane x = 0 of a box that is flat in x",
	                  BBox{Vec3{0.0f}, {0.0f, 1.0f, 1.0f}}, Ray{{0.0f, 0.5f, -1.0f}, {0.0f, 0.0f, 1.0f}}, from_zero(),
	                  true, {1.0f, 2.0f}},
	});
}

TEST_CASE("BBox::hit: times narrows to the overlap with the interval passed in", "[id:t3.bbox.interval-overlap][task3][bbox][fn:BBox::hit]") {
	const Ray ray{{-1.0f, 0.5f, 0.5f}, {1.0f, 0.0f, 0.0f}}; // inside the box for t in [1, 2]
	check({
	         Box_Case{"an interval that starts inside the box: the overlap starts there", UNIT, ray, {1.5f, 10.0f}, true,
	                  {1.5f, 2.0f}},
	         Box_Case{"an interval that ends inside the box: the overlap ends there", UNIT, ray, {0.0f, 1.25f}, true,
	                  {1.0f, 1.25f}},
	         Box_Case{"an interval inside the box's span is kept as it is", UNIT, ray, {1.2f, 1.8f}, true, {1.2f, 1.8f}},
	         Box_Case{"an interval that ends exactly where the box starts still touches it", UNIT, ray, {0.0f, 1.0f},
	                  true, {1.0f, 1.0f}},
	         Box_Case{"an interval that ends before the box starts: miss (e.g. a closer hit is already known)", UNIT,
	                  ray, {0.0f, 0.5f}, false, {}},
	         Box_Case{"an interval that starts after the box ends: miss", UNIT, ray, {3.0f, 10.0f}, false, {}},
	});
}
