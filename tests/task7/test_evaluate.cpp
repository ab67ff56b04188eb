// Task 7 grader, handout §7.3: Env_Map::evaluate, bilinear interpolation between texel centres,
// wrapping around the seam and clamping at the poles.
#include "env_test_support.h"

#include <catch2/catch.hpp>

using namespace env_test;

namespace {
constexpr uint32_t W = 8, H = 4;

// Every texel different, every channel a different pattern; the top and bottom rows differ from
// their neighbours, so wrapping in v or blending past the last row shows.
Spectrum texel(uint32_t i, uint32_t j) {
	i %= W;
	return Spectrum{1.0f + i + 8.0f * j, 60.0f - 3.0f * i - 7.0f * j, 0.5f + 0.25f * float((3 * i + 5 * j) % 7)};
}

HDR_Image pattern() {
	HDR_Image image(W, H);
	for (uint32_t j = 0; j < H; j++)
		for (uint32_t i = 0; i < W; i++) image.at(i, j) = texel(i, j);
	return image;
}

// Float rounding of the direction moves a lookup by ~1e-6 texel, changing the result by ~1e-5 here;
// the errors this grader looks for (a texel or half a texel off) change it by 0.5 or more.
constexpr float LOOKUP_TOLERANCE = 1e-3f;

bool close(Spectrum a, Spectrum b) {
	return glm::all(glm::lessThanEqual(glm::abs(a - b), Spectrum{LOOKUP_TOLERANCE}));
}

// Evaluates the map at image point (x, y) in texel units (texel (i, j) spans [i, i + 1) x [j, j + 1),
// its centre is (i + 0.5, j + 0.5)) and compares with `expected`.
struct Lookup_Checker {
	Env_Map env{pattern(), false};
	int failures = 0;
	std::string first;

	void check(double x, double y, Spectrum expected, const char* what) {
		Vec3 d = direction_at_texel_point(env.image, x, y);
		Spectrum got = env.evaluate(d);
		if (close(got, expected)) return;
		if (failures++ == 0) {
			std::ostringstream s;
			s << what << ": at image point (" << x << ", " << y << ") texels, direction " << str(d) << ", evaluate returned "
			  << str(got) << ", expected " << str(expected);
			first = s.str();
		}
	}
};
} // namespace

TEST_CASE("evaluate returns a texel's value at its centre", "[task7][evaluate]") {
	Lookup_Checker c;
	for (uint32_t j = 0; j < H; j++)
		for (uint32_t i = 0; i < W; i++) c.check(i + 0.5, j + 0.5, texel(i, j), "texel centre");
	INFO("texel (i, j) holds the radiance at its centre, uv = ((i + 0.5) / w, (j + 0.5) / h): x = u w - 0.5, "
	     "y = v h - 0.5 (handout §7.3). "
	     << c.failures << " of " << W * H << " centres wrong; first: " << c.first);
	CHECK(c.failures == 0);
}

TEST_CASE("evaluate interpolates bilinearly between texel centres", "[task7][evaluate]") {
	Lookup_Checker c;
	for (uint32_t j = 0; j < H; j++) {
		for (uint32_t i = 0; i + 1 < W; i++) {
			c.check(i + 1.0, j + 0.5, 0.5f * (texel(i, j) + texel(i + 1, j)), "halfway between two centres in u");
			c.check(i + 0.75, j + 0.5, 0.75f * texel(i, j) + 0.25f * texel(i + 1, j), "a quarter of the way in u");
		}
	}
	for (uint32_t j = 0; j + 1 < H; j++) {
		for (uint32_t i = 0; i < W; i++) {
			c.check(i + 0.5, j + 1.0, 0.5f * (texel(i, j) + texel(i, j + 1)), "halfway between two centres in v");
			c.check(i + 0.5, j + 0.75, 0.75f * texel(i, j) + 0.25f * texel(i, j + 1), "a quarter of the way in v");
		}
	}
	for (uint32_t j = 0; j + 1 < H; j++) {
		for (uint32_t i = 0; i + 1 < W; i++) {
			Spectrum four = 0.25f * (texel(i, j) + texel(i + 1, j) + texel(i, j + 1) + texel(i + 1, j + 1));
			c.check(i + 1.0, j + 1.0, four, "the middle of four centres");
		}
	}
	INFO("between texel centres, evaluate must blend the four nearest centres with weights (1 - fx, fx) x (1 - fy, fy) "
	     "(handout §7.3). "
	     << c.failures << " lookups wrong; first: " << c.first);
	CHECK(c.failures == 0);
}

TEST_CASE("evaluate wraps around the seam at phi = 0", "[task7][evaluate]") {
	{
		Lookup_Checker c;
		for (uint32_t j = 0; j < H; j++) {
			// u = 0 lies halfway between the centres of the last column and the first.
			c.check(0.0, j + 0.5, 0.5f * (texel(W - 1, j) + texel(0, j)), "on the seam u = 0");
			c.check(0.25, j + 0.5, 0.25f * texel(W - 1, j) + 0.75f * texel(0, j), "just after the seam");
			c.check(W - 0.25, j + 0.5, 0.75f * texel(W - 1, j) + 0.25f * texel(0, j), "just before the seam");
		}
		INFO("left of the first centre the lookup blends column 0 with column w - 1, and right of the last centre "
		     "column w - 1 with column 0: indices wrap around in u (handout §7.3). "
		     << c.failures << " lookups wrong; first: " << c.first);
		CHECK(c.failures == 0);
	}

	// And the result is continuous there: a step of 2 delta in phi moves the lookup by
	// 2 delta w / (2 pi) texels, changing it by at most that times the jump between the columns.
	Env_Map env(pattern(), false);
	const double delta = 1e-3;
	for (uint32_t j = 0; j < H; j++) {
		double theta = M_PI * (j + 0.5) / H;
		Spectrum after = env.evaluate(direction_at(theta, delta)), before = env.evaluate(direction_at(theta, -delta));
		Spectrum bound = float(2.0 * delta * W / (2.0 * M_PI)) * glm::abs(texel(0, j) - texel(W - 1, j)) + LOOKUP_TOLERANCE;
		INFO("row " << j << ": evaluate just after phi = 0 is " << str(after) << ", just before " << str(before)
		            << "; the radiance must be continuous across the seam (handout §7.3)");
		CHECK(glm::all(glm::lessThanEqual(glm::abs(after - before), bound)));
	}
}

TEST_CASE("evaluate clamps at the poles: the first and last rows are interpolated in u only", "[task7][evaluate]") {
	{
		Lookup_Checker c;
		for (uint32_t i = 0; i + 1 < W; i++) {
			// Above the first row's centres (y < 0.5) and below the last row's there is nothing to blend with.
			c.check(i + 0.75, 0.25, 0.75f * texel(i, 0) + 0.25f * texel(i + 1, 0), "above the centres of the first row");
			c.check(i + 0.75, 0.01, 0.75f * texel(i, 0) + 0.25f * texel(i + 1, 0), "next to the north pole");
			c.check(i + 0.75, H - 0.25, 0.75f * texel(i, H - 1) + 0.25f * texel(i + 1, H - 1),
			        "below the centres of the last row");
			c.check(i + 0.75, H - 0.01, 0.75f * texel(i, H - 1) + 0.25f * texel(i + 1, H - 1), "next to the south pole");
		}
		INFO("beyond the first and last rows of centres, the row index is clamped, not wrapped: v = 0 is the north "
		     "pole, not a neighbour of the south pole (handout §7.3). "
		     << c.failures << " lookups wrong; first: " << c.first);
		CHECK(c.failures == 0);
	}

	// Exactly at a pole phi is arbitrary, but the value must still come from that pole's row alone.
	Env_Map env(pattern(), false);
	for (int pole = 0; pole < 2; pole++) {
		uint32_t row = pole == 0 ? 0 : H - 1;
		Spectrum lo{INF_F}, hi{-INF_F};
		for (uint32_t i = 0; i < W; i++) lo = glm::min(lo, texel(i, row)), hi = glm::max(hi, texel(i, row));
		for (Vec3 d : {Vec3{0.0f, 1.0f, 0.0f}, Vec3{-0.0f, 1.0f, 0.0f}, Vec3{0.0f, 1.0f, -0.0f}}) {
			if (pole == 1) d.y = -1.0f;
			Spectrum L = env.evaluate(d);
			INFO("evaluate" << str(d) << " = " << str(L) << ": at the pole it must lie between " << str(lo) << " and "
			                << str(hi) << ", the values of row " << row << " (handout §7.3)");
			CHECK(is_finite(L));
			CHECK(glm::all(glm::greaterThanEqual(L, lo - LOOKUP_TOLERANCE)));
			CHECK(glm::all(glm::lessThanEqual(L, hi + LOOKUP_TOLERANCE)));
		}
	}
}
