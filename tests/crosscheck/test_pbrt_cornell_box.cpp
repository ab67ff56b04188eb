// Cross-check with an independent renderer: our reference path tracer against pbrt-v3 on the
// measured Cornell box (scenes/cornell_box.json = /work/shared/assets/scenes/cornell_box, and
// scenes/references/cornell_box_pbrt-v3_256px_1024spp.pfm: pbrt-v3, 1024 spp, box filter, depth 100).
//
// Compared: the whole-image mean per channel (within 0.5%) and the mean over each surface region
// (within 1%). pbrt's own noise in region means is under 0.3%, ours is printed alongside.
#include "pfm.h"
#include "render.h"
#include "scene_loader.h"

#include "lab_catch2.h"

#include <array>
#include <cstdio>
#include <map>
#include <optional>

namespace {
enum class Region { back_wall, floor, ceiling, red_wall, green_wall };
constexpr std::array<std::pair<Region, const char*>, 5> REGIONS{{{Region::back_wall, "back wall"},
                                                                 {Region::floor, "floor"},
                                                                 {Region::ceiling, "ceiling"},
                                                                 {Region::red_wall, "red wall"},
                                                                 {Region::green_wall, "green wall"}}};

// The region a camera ray's first hit belongs to, from the box's measured planes (mm) and the
// material; blocks, the light and misses belong to none.
std::optional<Region> region_of(const Scene& scene, const Ray& ray) {
	Trace hit = scene.hit(ray);
	if (!hit.hit) return std::nullopt;
	const std::string& material = scene.material_names[hit.material];
	Vec3 p = hit.position;
	if (material == "red") return Region::red_wall;
	if (material == "green") return Region::green_wall;
	if (material != "white") return std::nullopt;
	if (std::abs(p.z - 559.2f) < 1.0f) return Region::back_wall;
	if (std::abs(p.y) < 1.0f) return Region::floor;
	if (std::abs(p.y - 548.8f) < 1.0f) return Region::ceiling;
	return std::nullopt;
}

// A pixel belongs to a region when its centre and four points near its corners all see it, so
// edges (where box filtering mixes surfaces) are left out.
std::optional<Region> pixel_region(const Scene& scene, uint32_t x, uint32_t y, uint32_t w, uint32_t h) {
	std::optional<Region> region;
	for (Vec2 offset : {Vec2{0.5f, 0.5f}, Vec2{0.05f, 0.05f}, Vec2{0.95f, 0.05f}, Vec2{0.05f, 0.95f}, Vec2{0.95f, 0.95f}}) {
		Vec2 uv = (Vec2{float(x), float(y)} + offset) / Vec2{float(w), float(h)};
		std::optional<Region> r = region_of(scene, scene.camera.generate_ray(uv));
		if (!r || (region && *r != *region)) return std::nullopt;
		region = r;
	}
	return region;
}

struct Mean {
	glm::dvec3 sum{0.0};
	glm::dvec3 variance_sum{0.0}; // sum of the variances of the pixel means (ours only)
	size_t count = 0;
	Vec3 value() const {
		return Vec3(sum / double(count));
	}
	// Standard error of the mean over the pixels, relative to it.
	Vec3 relative_error() const {
		return Vec3(glm::sqrt(variance_sum) / sum);
	}
};
} // namespace

TEST_CASE("The reference renders the measured Cornell box like pbrt-v3 (image and region means)", "[crosscheck]") {
	Scene scene = load_scene("scenes/cornell_box.json");
	HDR_Image pbrt = read_pfm("scenes/references/cornell_box_pbrt-v3_256px_1024spp.pfm");
	REQUIRE(pbrt.w == scene.settings.width);
	REQUIRE(pbrt.h == scene.settings.height);

	Render_Settings settings = scene.settings;
	settings.samples = 512;
	settings.max_depth = 100; // as pbrt's render; Russian roulette ends paths long before
	settings.seed = 1;
	Film film = render(Pathtracer(scene, settings));
	HDR_Image ours = film.mean();
	HDR_Image ours_variance = film.variance(); // per sample; the pixel mean's is this / spp
	REQUIRE(film.non_finite() == 0);

	Mean ours_all, pbrt_all;
	std::map<Region, Mean> ours_region, pbrt_region;
	for (uint32_t y = 0; y < pbrt.h; y++) {
		for (uint32_t x = 0; x < pbrt.w; x++) {
			glm::dvec3 variance_of_mean = glm::dvec3(ours_variance.at(x, y)) / double(settings.samples);
			ours_all.sum += glm::dvec3(ours.at(x, y));
			ours_all.variance_sum += variance_of_mean;
			pbrt_all.sum += glm::dvec3(pbrt.at(x, y));
			ours_all.count++, pbrt_all.count++;
			if (auto region = pixel_region(scene, x, y, pbrt.w, pbrt.h)) {
				ours_region[*region].sum += glm::dvec3(ours.at(x, y));
				ours_region[*region].variance_sum += variance_of_mean;
				pbrt_region[*region].sum += glm::dvec3(pbrt.at(x, y));
				ours_region[*region].count++, pbrt_region[*region].count++;
			}
		}
	}

	std::printf("%-12s %7s  %-28s %-28s %-28s %s\n", "region", "pixels", "ours (R, G, B)", "pbrt-v3 (R, G, B)",
	            "difference", "our standard error");
	auto report = [](const char* name, const Mean& a, const Mean& b, float tolerance) {
		Vec3 ours_mean = a.value(), pbrt_mean = b.value();
		Vec3 rel = (ours_mean - pbrt_mean) / pbrt_mean;
		Vec3 se = a.relative_error();
		std::printf("%-12s %7zu  (%.4f, %.4f, %.4f)   (%.4f, %.4f, %.4f)   (%+.2f%%, %+.2f%%, %+.2f%%)   "
		            "(%.2f%%, %.2f%%, %.2f%%)\n",
		            name, a.count, ours_mean.r, ours_mean.g, ours_mean.b, pbrt_mean.r, pbrt_mean.g, pbrt_mean.b,
		            100 * rel.r, 100 * rel.g, 100 * rel.b, 100 * se.r, 100 * se.g, 100 * se.b);
		for (int c = 0; c < 3; c++) {
			INFO(name << ", channel " << "RGB"[c] << ": ours " << ours_mean[c] << ", pbrt-v3 " << pbrt_mean[c]
			          << ", relative difference " << rel[c] << " (allowed " << tolerance << ")");
			CHECK(std::abs(rel[c]) <= tolerance);
		}
	};
	report("whole image", ours_all, pbrt_all, 0.005f);
	for (auto [region, name] : REGIONS) {
		INFO("region " << name << " must be visible in the image");
		REQUIRE(ours_region[region].count > 200);
		report(name, ours_region[region], pbrt_region[region], 0.01f);
	}
	// The classification itself: the red wall is red and on the left (pbrt's orientation agrees).
	CHECK(pbrt_region[Region::red_wall].value().r > 4.0f * pbrt_region[Region::red_wall].value().g);
}
