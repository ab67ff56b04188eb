// Task 7 grader, handout §7.3: Env_Map::evaluate, bilinear interpolation between texel centres,
// wrapping around the seam and clamping at the poles.
#include "env_test_support.h"

#include "lab_catch2.h"

using namespace env_test;

namespace {
constexpr uint32_t W = 8, H = 4;

// Every texel different, every channel a different pattern; the top and bottom rows differ from
// their neighbours, so wrapping in v or blending past the last row shows. With a grading seed, the
// values are drawn (red and green in [1, 60], blue in [0.5, 2]).
struct Pattern {
	HDR_Image image{W, H};

	Pattern() {
		for (uint32_t j = 0; j < H; j++) {
			for (uint32_t i = 0; i < W; i++) {
				image.at(i, j) = Spectrum{1.0f + i + 8.0f * j, 60.0f - 3.0f * i - 7.0f * j,
				                          0.5f + 0.25f * float((3 * i + 5 * j) % 7)};
			}
		}
		std::optional<RNG> secret = judge::secret_inputs();
		if (!secret) return;
		for (Spectrum& value : image.pixels) {
			value = Spectrum{1.0f + 59.0f * secret->unit(), 1.0f + 59.0f * secret->unit(), 0.5f + 1.5f * secret->unit()};
		}
	}
	Spectrum texel(uint32_t i, uint32_t j) const {
		return image.at(i % W, j);
	}
};

// Float rounding of the direction moves a lookup by ~1e-6 texel, changing the result by ~1e-5 here;
// the errors this grader looks for (a texel or half a texel off) change it by 0.5 or more.
constexpr float LOOKUP_TOLERANCE = 1e-3f;

bool close(Spectrum a, Spectrum b) {
	return glm::all(glm::lessThanEqual(glm::abs(a - b), Spectrum{LOOKUP_TOLERANCE}));
}

// Lookups of the pattern at image points (x, y) in texel units (texel (i, j) spans [i, i + 1) x
// [j, j + 1), its centre is (i + 0.5, j + 0.5)), each with its expected value: collected with add(),
// sent to the student's evaluate in one request by run(), which counts the wrong ones.
struct Lookup_Checker {
	Pattern pattern;
	struct Lookup {
		double x, y;
		Spectrum expected;
		const char* what;
	};
	std::vector<Lookup> lookups;
	int failures = 0;
	std::string first;

	Spectrum texel(uint32_t i, uint32_t j) const {
		return pattern.texel(i, j);
	}
	void add(double x, double y, Spectrum expected, const char* what) {
		lookups.push_back({x, y, expected, what});
	}
	void run() {
		std::vector<Vec3> dirs;
		for (const Lookup& l : lookups) dirs.push_back(direction_at_texel_point(W, H, l.x, l.y));
		std::vector<Spectrum> got = student_env_map(pattern.image, false, {}, dirs).radiance;
		for (size_t n = 0; n < lookups.size(); n++) {
			const Lookup& l = lookups[n];
			if (close(got[n], l.expected)) continue;
			if (failures++ > 0) continue; // the first one is shown
			std::ostringstream s;
			s << l.what << ": at image point (" << l.x << ", " << l.y << ") texels, direction " << str(dirs[n])
			  << ", evaluate returned " << str(got[n]) << ", expected " << str(l.expected);
			first = s.str();
		}
	}
};
} // namespace

TEST_CASE("evaluate returns a texel's value at its centre", "[id:t7.evaluate.centre][task7][evaluate][fn:Env_Map::evaluate][uses:direction_to_uv]") {
	Lookup_Checker c;
	for (uint32_t j = 0; j < H; j++)
		for (uint32_t i = 0; i < W; i++) c.add(i + 0.5, j + 0.5, c.texel(i, j), "texel centre");
	c.run();
	INFO("texel (i, j) holds the radiance at its centre, uv = ((i + 0.5) / w, (j + 0.5) / h): x = u w - 0.5, "
	     "y = v h - 0.5 (handout §7.3). "
	     << c.failures << " of " << W * H << " centres wrong; first: " << c.first);
	CHECK(c.failures == 0);
}

TEST_CASE("evaluate interpolates bilinearly between texel centres", "[id:t7.evaluate.bilinear][task7][evaluate][fn:Env_Map::evaluate][uses:direction_to_uv]") {
	Lookup_Checker c;
	for (uint32_t j = 0; j < H; j++) {
		for (uint32_t i = 0; i + 1 < W; i++) {
			c.add(i + 1.0, j + 0.5, 0.5f * (c.texel(i, j) + c.texel(i + 1, j)), "halfway between two centres in u");
			c.add(i + 0.75, j + 0.5, 0.75f * c.texel(i, j) + 0.25f * c.texel(i + 1, j), "a quarter of the way in u");
		}
	}
	for (uint32_t j = 0; j + 1 < H; j++) {
		for (uint32_t i = 0; i < W; i++) {
			c.add(i + 0.5, j + 1.0, 0.5f * (c.texel(i, j) + c.texel(i, j + 1)), "halfway between two centres in v");
			c.add(i + 0.5, j + 0.75, 0.75f * c.texel(i, j) + 0.25f * c.texel(i, j + 1), "a quarter of the way in v");
		}
	}
	for (uint32_t j = 0; j + 1 < H; j++) {
		for (uint32_t i = 0; i + 1 < W; i++) {
			Spectrum four = 0.25f * (c.texel(i, j) + c.texel(i + 1, j) + c.texel(i, j + 1) + c.texel(i + 1, j + 1));
			c.add(i + 1.0, j + 1.0, four, "the middle of four centres");
		}
	}
	c.run();
	INFO("between texel centres, evaluate must blend the four nearest centres with weights (1 - fx, fx) x (1 - fy, fy) "
	     "(handout §7.3). "
	     << c.failures << " lookups wrong; first: " << c.first);
	CHECK(c.failures == 0);
}

TEST_CASE("evaluate wraps around the seam at phi = 0", "[id:t7.evaluate.seam][task7][evaluate][fn:Env_Map::evaluate][uses:direction_to_uv]") {
	{
		Lookup_Checker c;
		for (uint32_t j = 0; j < H; j++) {
			// u = 0 lies halfway between the centres of the last column and the first.
			c.add(0.0, j + 0.5, 0.5f * (c.texel(W - 1, j) + c.texel(0, j)), "on the seam u = 0");
			c.add(0.25, j + 0.5, 0.25f * c.texel(W - 1, j) + 0.75f * c.texel(0, j), "just after the seam");
			c.add(W - 0.25, j + 0.5, 0.75f * c.texel(W - 1, j) + 0.25f * c.texel(0, j), "just before the seam");
		}
		c.run();
		INFO("left of the first centre the lookup blends column 0 with column w - 1, and right of the last centre "
		     "column w - 1 with column 0: indices wrap around in u (handout §7.3). "
		     << c.failures << " lookups wrong; first: " << c.first);
		CHECK(c.failures == 0);
	}

	// And the result is continuous there: a step of 2 delta in phi moves the lookup by
	// 2 delta w / (2 pi) texels, changing it by at most that times the jump between the columns.
	Pattern pattern;
	const double delta = 1e-3;
	std::vector<Vec3> dirs; // just after and just before phi = 0, for each row
	for (uint32_t j = 0; j < H; j++) {
		float v = (j + 0.5f) / H, du = float(delta / (2.0 * M_PI));
		dirs.push_back(uv_to_direction(Vec2{du, v}));
		dirs.push_back(uv_to_direction(Vec2{-du, v}));
	}
	std::vector<Spectrum> got = student_env_map(pattern.image, false, {}, dirs).radiance;
	for (uint32_t j = 0; j < H; j++) {
		Spectrum after = got[2 * j], before = got[2 * j + 1];
		Spectrum jump = glm::abs(pattern.texel(0, j) - pattern.texel(W - 1, j));
		Spectrum bound = float(2.0 * delta * W / (2.0 * M_PI)) * jump + LOOKUP_TOLERANCE;
		INFO("row " << j << ": evaluate just after phi = 0 is " << str(after) << ", just before " << str(before)
		            << "; the radiance must be continuous across the seam (handout §7.3)");
		CHECK(glm::all(glm::lessThanEqual(glm::abs(after - before), bound)));
	}
}

TEST_CASE("evaluate clamps at the poles: the first and last rows are interpolated in u only", "[id:t7.evaluate.poles][task7][evaluate][fn:Env_Map::evaluate][uses:direction_to_uv]") {
	{
		Lookup_Checker c;
		for (uint32_t i = 0; i + 1 < W; i++) {
			// Above the first row's centres (y < 0.5) and below the last row's there is nothing to blend with.
			Spectrum first_row = 0.75f * c.texel(i, 0) + 0.25f * c.texel(i + 1, 0);
			Spectrum last_row = 0.75f * c.texel(i, H - 1) + 0.25f * c.texel(i + 1, H - 1);
			c.add(i + 0.75, 0.25, first_row, "above the centres of the first row");
			c.add(i + 0.75, 0.01, first_row, "next to the north pole");
			c.add(i + 0.75, H - 0.25, last_row, "below the centres of the last row");
			c.add(i + 0.75, H - 0.01, last_row, "next to the south pole");
		}
		c.run();
		INFO("beyond the first and last rows of centres, the row index is clamped, not wrapped: v = 0 is the north "
		     "pole, not a neighbour of the south pole (handout §7.3). "
		     << c.failures << " lookups wrong; first: " << c.first);
		CHECK(c.failures == 0);
	}

	// Exactly at a pole phi is arbitrary, but the value must still come from that pole's row alone.
	Pattern pattern;
	std::vector<Vec3> dirs;
	for (float y : {1.0f, -1.0f}) {
		for (Vec3 d : {Vec3{0.0f, y, 0.0f}, Vec3{-0.0f, y, 0.0f}, Vec3{0.0f, y, -0.0f}}) dirs.push_back(d);
	}
	std::vector<Spectrum> got = student_env_map(pattern.image, false, {}, dirs).radiance;
	for (size_t n = 0; n < dirs.size(); n++) {
		uint32_t row = dirs[n].y > 0.0f ? 0 : H - 1;
		Spectrum lo{INF_F}, hi{-INF_F};
		for (uint32_t i = 0; i < W; i++) lo = glm::min(lo, pattern.texel(i, row)), hi = glm::max(hi, pattern.texel(i, row));
		Spectrum L = got[n];
		INFO("evaluate" << str(dirs[n]) << " = " << str(L) << ": at the pole it must lie between " << str(lo) << " and "
		                << str(hi) << ", the values of row " << row << " (handout §7.3)");
		CHECK(is_finite(L));
		CHECK(glm::all(glm::greaterThanEqual(L, lo - LOOKUP_TOLERANCE)));
		CHECK(glm::all(glm::lessThanEqual(L, hi + LOOKUP_TOLERANCE)));
	}
}
