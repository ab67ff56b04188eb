// Task 7 grader, handout §7.4: a map with a single bright texel, the hardest case for importance
// sampling with a bilinear lookup. The bilinear radiance of texel (i, j) reaches one texel width
// around its centre, into all eight neighbours; the pdf must cover that, and nothing far beyond.
#include "env_test_support.h"

#include "lab_catch2.h"

#include <future>
#include <vector>

using namespace env_test;

namespace {

constexpr uint32_t W = 32, H = 16;

struct Bright_Texel {
	std::string name;
	uint32_t i, j;

	HDR_Image map() const {
		return one_texel_map(W, H, i, j);
	}
};

// Texel (11, 6) (with a grading seed, another texel away from the seam and the poles), and texel
// (0, 0).
std::vector<Bright_Texel> cases() {
	Texel inner = inner_bright_texel();
	return {{texel_name(inner), inner.i, inner.j}, {"texel (0, 0), at the seam and the north pole", 0, 0}};
}

double tent(double t) {
	return std::max(0.0, 1.0 - std::abs(t));
}

// Integral over the sphere of the map's radiance (value 1 at texel (i, j)): bilinear interpolation
// is the product of two tents around the texel's centre, one in x (around the seam) and one in y
// clamped to the first and last rows of centres (handout §7.3). That is (2 pi / W) for the tent in
// phi, times the integral of the tent in theta against sin(theta) (Simpson's rule, far more
// accurate than needed).
double radiance_integral(const Bright_Texel& t) {
	const int n = 200000;
	const double d = M_PI / n;
	double sum = 0.0;
	for (int k = 0; k <= n; k++) {
		double theta = k * d;
		double f = tent(std::clamp(theta / d * (double(H) / n) - 0.5, 0.0, double(H - 1)) - t.j) * std::sin(theta);
		sum += f * (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0));
	}
	return (2.0 * M_PI / W) * sum * d / 3.0;
}

// The texel containing a direction (by the reference's direction_to_uv).
void texel_of(Vec3 d, int64_t& i, int64_t& j) {
	Vec2 uv = direction_to_uv(d);
	i = std::min<int64_t>(int64_t(uv.x * W), W - 1);
	j = std::min<int64_t>(int64_t(uv.y * H), H - 1);
}

// True if texel (i, j) is in the 3 x 3 block around the bright texel (wrapping in i): the only
// texels where its bilinear radiance can be non-zero.
bool in_reach(const Bright_Texel& t, int64_t i, int64_t j) {
	int64_t di = std::abs(i - int64_t(t.i));
	di = std::min(di, int64_t(W) - di);
	return di <= 1 && std::abs(j - int64_t(t.j)) <= 1;
}

} // namespace

TEST_CASE("one bright texel: importance samples stay in the texels its light reaches", "[id:t7.bright-texel.support][task7][bright-texel][uses:Env_Map::evaluate][uses:Image::sample][uses:Image::pdf]") {
	for (const Bright_Texel& t : cases()) {
		const size_t N = 100000;
		std::vector<Vec3> samples =
			student_image_sampler(t.map(), unit_points(judge::secret_seed_or(78), N), {}).queries.samples;
		size_t outside = 0;
		std::string first;
		for (Vec3 d : samples) {
			int64_t i, j;
			texel_of(d, i, j);
			if (!in_reach(t, i, j) && outside++ == 0) first = "direction " + str(d) + " in texel (" + std::to_string(i) + ", " + std::to_string(j) + ")";
		}
		// Rounding at the block's border may move a few samples across it (pbrt-v4 allows 1e-5).
		INFO("map of " << W << " x " << H << " texels, black except " << t.name << ": " << outside << " of " << N
		               << " samples fell outside the 3 x 3 texels around it (first: " << first
		               << "), where the radiance is 0. Texels whose 3 x 3 neighbourhood is black need probability 0 "
		                  "(handout §7.4)");
		CHECK(double(outside) <= 1e-5 * N);
	}
}

TEST_CASE("one bright texel: the pdf is positive wherever its radiance is, and L / pdf stays bounded",
          "[id:t7.bright-texel.bounded][task7][bright-texel][uses:Env_Map::evaluate][uses:Image::sample][uses:Image::pdf]") {
	// A table built from the texels' own luminance gives probability 0 to the neighbours, which the
	// bilinear lookup lights: light-only sampling would never find that light (a biased render). Any
	// table that follows the lookup keeps L / pdf within a small multiple of the integral of L:
	// the exact texel average of handout §7.4 reaches 16 times (diagonal neighbours: 1/4 of the
	// radiance, 1/64 of the probability), the 3 x 3 maximum 9 times. Allowed: 32 times. A pdf that
	// is merely floored at a tiny value goes far beyond. L is the reference's bilinear lookup.
	for (const Bright_Texel& t : cases()) {
		const double bound = 32.0 * radiance_integral(t);
		Env_Map reference(t.map(), false);
		RNG rng(judge::secret_seed_or(79));
		struct Point {
			double x, y, L;
			Vec3 d;
		};
		std::vector<Point> points;
		std::vector<Vec3> dirs;
		for (int n = 0; n < 20000; n++) {
			// A random image point within one texel of the bright centre (where the radiance is > 0).
			double x = t.i + 0.5 + (2.0 * rng.unit() - 1.0), y = t.j + 0.5 + (2.0 * rng.unit() - 1.0);
			y = std::clamp(y, 1e-3, H - 1e-3);
			Vec3 d = direction_at_texel_point(W, H, x, y);
			double L = reference.evaluate(d).g;
			if (L < 1e-3) continue; // stay clear of the support's edge, where rounding decides
			points.push_back({x, y, L, d});
			dirs.push_back(d);
		}
		std::vector<float> pdfs = student_image_sampler(t.map(), {}, dirs).queries.pdfs;
		size_t zero_pdf = 0, unbounded = 0;
		std::string first_zero, first_unbounded;
		for (size_t n = 0; n < points.size(); n++) {
			const Point& p = points[n];
			float pdf = pdfs[n];
			std::ostringstream where;
			where << "direction " << str(p.d) << " (image point " << p.x << ", " << p.y << "): radiance " << p.L
			      << ", pdf " << pdf;
			if (!(pdf > 0.0f)) {
				if (zero_pdf++ == 0) first_zero = where.str();
			} else if (!(p.L / pdf <= bound)) {
				if (unbounded++ == 0) first_unbounded = where.str() + ", L / pdf " + std::to_string(p.L / pdf);
			}
		}
		INFO("map of " << W << " x " << H << " texels, black except " << t.name << "; " << points.size()
		               << " directions where its bilinear radiance is positive");
		{
			INFO(zero_pdf << " of them have pdf 0 (first: " << first_zero
			              << "): build the table from what the bilinear lookup can return, i.e. from each texel's 3 x 3 "
			                 "neighbourhood (handout §7.4)");
			CHECK(zero_pdf == 0);
		}
		{
			INFO(unbounded << " of them have L / pdf above " << bound << " (32 times the integral of L; first: "
			               << first_unbounded << "): the pdf must follow the radiance of the lookup (handout §7.4)");
			CHECK(unbounded == 0);
		}
	}
}

TEST_CASE("one bright texel: the weights L / pdf average the integral of its radiance", "[id:t7.bright-texel.integral][statistical:4][estimate][task7][bright-texel][uses:Env_Map::evaluate][uses:Image::sample][uses:Image::pdf]") {
	// E[L / pdf] over importance samples = the integral of L over the directions where pdf > 0: all
	// of it only if the pdf covers the whole bilinear footprint (two of the grader's z-tests).
	for (const Bright_Texel& t : cases()) {
		const size_t N = 200000;
		const uint64_t seed = judge::secret_seed_or(80);
		// The reference's weights are drawn while the subject samples.
		auto reference_drawn = std::async(std::launch::async, [&] { return reference_weights(t.map(), seed, N)[1]; });
		Env_Samples samples = student_env_samples(t.map(), true, unit_points(seed, N));
		std::vector<double> weights;
		size_t not_finite = 0;
		for (size_t n = 0; n < N; n++) {
			float pdf = samples.pdfs[n];
			double weight = pdf > 0.0f ? double(samples.radiance[n].g) / pdf : 0.0; // a renderer skips pdf = 0
			if (!std::isfinite(weight)) {
				not_finite++;
				continue;
			}
			weights.push_back(weight);
		}
		std::vector<double> reference_samples = reference_drawn.get();
		Sample_Moments student = moments(weights), reference = moments(reference_samples);
		double expected = radiance_integral(t), error = standard_error(reference, N);
		double critical = judge::z_critical();
		double allowed = critical * error + 1e-5 * expected;
		INFO("map of " << W << " x " << H << " texels, black except " << t.name << " (value 1): mean of L / pdf over "
		               << N << " importance samples " << student.mean
		               << ", expected the integral of the bilinear radiance " << expected << " (allowed difference "
		               << allowed << ", " << critical << " standard errors of the reference's estimate); "
		               << not_finite
		               << " weights were not finite. Too small: the pdf misses part of the lit area (handout §7.4); "
		                  "check also evaluate (§7.3)");
		CHECK(not_finite == 0);
		CHECK(std::abs(student.mean - expected) <= allowed);
		Paired_Noise noise = compare_noise(weights, reference_samples, judge::significance(), 1e-5 * expected);
		INFO("too noisy: " << describe(noise, "batch") << ". Where the pdf is too small for the light the weights "
		     "grow without bound: the table must cover each texel's whole bilinear footprint (handout §7.4)");
		CHECK(noise.pass);
	}
}
