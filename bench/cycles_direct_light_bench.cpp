// Direct light (max depth 1) against a closed form: Lambert's formula for area lights, a quadrature of
// the environment for a plane under an open sky. Ours, and Cycles as render_in_cycles.py exports and
// with the export's alternatives (--light-as-mesh, --subdivide-lights 4, --world-map-resolution N).
// `./lab bench cycles-direct-light --help`; bench/README.md, "Every shipped scene against Cycles".
#include "bench_usage.h"
#include "cycles/renderer_runs.h"
#include "light_closed_forms.h"
#include "scene_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

constexpr uint32_t GRID = 8;       // regions per side
constexpr uint32_t SUBPIXELS = 8;  // closed form at SUBPIXELS x SUBPIXELS points per pixel
constexpr uint32_t LIGHT_GRID = 6; // shadow rays to this many points per triangle edge, vertices included

struct Options {
	std::string scene = "scenes/cornell_small_light.json";
	uint32_t spp = 256, threads = 2;
	std::string out = "bench/results";
};

const Bench_Usage USAGE{"cycles_direct_light_bench",
	"usage: cycles_direct_light_bench [SCENE] [--spp N] [--threads T] [--out DIR]\n"
	"\n"
	"Direct light alone (max depth 1) of SCENE (default scenes/cornell_small_light.json) against a closed form,\n"
	"in each pixel whose 8 x 8 points, and those of its 8 neighbours, all lie on Lambertian surfaces where it\n"
	"applies: the pixel's value is albedo / pi x E. Area lights (flat emissive meshes): E by Lambert's formula\n"
	"for a polygon, at points that see each light triangle whole or lie behind it. An environment: E of the\n"
	"upper hemisphere by quadrature, at points of a surface facing +y that see the open sky (a scene like\n"
	"bench/cycles/ground_sun.json). Renders, N spp each (default 256) as two halves with seeds 1 and 2, on T\n"
	"threads (default 2): ours; Cycles as render_in_cycles.py exports; with area lights also Cycles with\n"
	"--light-as-mesh and with --subdivide-lights 4, and the solid angle of each light triangle as Cycles 3.4\n"
	"computes it in float against the exact one; with an image environment also Cycles with\n"
	"--world-map-resolution 1024 and 4096. Per renderer: renderer / closed form - 1 over all such pixels and\n"
	"over each region of an 8 x 8 grid, with standard errors. Writes DIR/cycles_direct_light_<scene>.md\n"
	"(default DIR: bench/results).\n"};

Options parse(int argc, char** argv) {
	Options o;
	for (int i = 1; i < argc; i++) {
		std::string arg = argv[i];
		USAGE.help_if_asked(arg);
		if (arg == "--spp" || arg == "--threads" || arg == "--out") {
			std::string value = USAGE.value_of(i, argc, argv);
			if (arg == "--out") {
				o.out = value;
				continue;
			}
			(arg == "--spp" ? o.spp : o.threads) = USAGE.whole_number(arg, value, arg == "--spp" ? 2 : 1);
		} else if (arg.rfind("--", 0) == 0) {
			USAGE.error("unknown option '" + arg + "'");
		} else {
			if (!std::filesystem::is_regular_file(arg)) USAGE.error("no such scene file: " + arg);
			o.scene = arg;
		}
	}
	return o;
}

using closed_form::DVec3;

// Cycles 3.4's fast_acosf (util/math_fast.h): sqrt(1 - |x|) times a cubic in |x|, mirrored for x < 0;
// its largest error is 4.5e-5 rad.
float polynomial_acos(float x) {
	float m = std::min(std::fabs(x), 1.0f);
	float a = std::sqrt(1.0f - m) * (1.5707963267f + m * (-0.213300989f + m * (0.077980478f + m * -0.02164095f)));
	return x < 0 ? float(M_PI) - a : a;
}

// The solid angle of triangle (a, b, c) seen from p as Cycles 3.4 computes it for its triangle light
// sampling and density (kernel/light/light.h, triangle_light_sample and triangle_light_pdf): in float,
// Girard's theorem, the sum of the spherical triangle's three angles minus pi, each angle the arccos
// (polynomial_acos by default) of the dot product of two unit normals of the planes through p and an
// edge.
float girard_solid_angle(Vec3 a, Vec3 b, Vec3 c, Vec3 p, float (*arccos)(float) = polynomial_acos) {
	Vec3 pa = a - p, pb = b - p, pc = c - p;
	Vec3 n_ab = glm::normalize(glm::cross(pa, pb)), n_ac = glm::normalize(glm::cross(pa, pc));
	Vec3 n_bc = glm::normalize(glm::cross(pb, pc));
	return arccos(glm::dot(n_ac, n_ab)) + arccos(-glm::dot(n_ab, n_bc)) + arccos(glm::dot(n_ac, n_bc)) - float(M_PI);
}

float float_acos(float x) {
	return std::acos(std::clamp(x, -1.0f, 1.0f));
}

// The closed form per pixel (albedo / pi x E, per channel; valid = false where it does not apply),
// and, for each pixel, the mean over its points of Cycles 3.4's solid angle / the exact one of each
// light triangle, weighted by the irradiance that triangle gives.
struct Closed_Form_Image {
	uint32_t w = 0, h = 0;
	std::vector<DVec3> value;
	std::vector<bool> valid;
	std::vector<double> weighted_ratio, weighted_ratio_exact_acos, weight; // sums of E x ratio, of E
};

// Irradiance on a surface facing +y from the environment's upper hemisphere, by the midpoint rule
// over (theta, phi) on a grid of 2048 x 4096 directions (fine enough for a sun of a few texels).
DVec3 sky_irradiance(const Scene& scene) {
	const int rings = 2048, segments = 4096;
	DVec3 e(0.0);
	for (int i = 0; i < rings; i++) {
		double theta = (i + 0.5) * (M_PI / 2) / rings;
		double weight = std::cos(theta) * std::sin(theta) * (M_PI / 2 / rings) * (2 * M_PI / segments);
		for (int j = 0; j < segments; j++) {
			double phi = (j + 0.5) * 2 * M_PI / segments;
			Spectrum l = scene.environment_radiance(Vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
			                                             float(std::sin(theta) * std::sin(phi))));
			e += weight * DVec3(l);
		}
	}
	return e;
}

// Whether p sees the sky in 16 azimuths at elevations 0.5, 5, 20 and 60 degrees and straight up: for
// a surface facing +y in an otherwise open scene (bench/cycles/ground_sun.json), the whole hemisphere.
bool sees_open_sky(const Scene& scene, Vec3 p) {
	const float elevations[] = {0.5f, 5.0f, 20.0f, 60.0f, 90.0f};
	Vec3 from = p + 1e-4f * std::max(1.0f, glm::length(p)) * Vec3(0, 1, 0);
	for (float elevation : elevations)
		for (int k = 0; k < 16; k++) {
			float a = float(k * M_PI / 8), e = glm::radians(elevation);
			if (scene.occluded(Ray(from, Vec3(std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a))))) return false;
		}
	return true;
}

Closed_Form_Image closed_form_image(const Scene& scene) {
	DVec3 sky = scene.environment ? sky_irradiance(scene) : DVec3(0.0);
	Closed_Form_Image image;
	image.w = scene.settings.width;
	image.h = scene.settings.height;
	size_t n = size_t(image.w) * image.h;
	image.value.assign(n, DVec3(0.0));
	image.valid.assign(n, true);
	image.weighted_ratio.assign(n, 0.0);
	image.weighted_ratio_exact_acos.assign(n, 0.0);
	image.weight.assign(n, 0.0);
	for (uint32_t y = 0; y < image.h; y++)
		for (uint32_t x = 0; x < image.w; x++) {
			size_t i = size_t(y) * image.w + x;
			for (uint32_t k = 0; k < SUBPIXELS * SUBPIXELS && image.valid[i]; k++) {
				Vec2 uv{(x + (k % SUBPIXELS + 0.5f) / SUBPIXELS) / image.w, (y + (k / SUBPIXELS + 0.5f) / SUBPIXELS) / image.h};
				Ray ray = scene.camera.generate_ray(uv);
				Trace hit = scene.hit(ray);
				const Material& material = scene.materials[hit.hit ? hit.material : 0];
				const auto* lambertian = std::get_if<BSDF_Lambertian>(&material.bsdf.bsdf);
				if (!hit.hit || material.is_emissive() || !lambertian) {
					image.valid[i] = false;
					break;
				}
				Vec3 p = hit.position, normal = glm::dot(hit.normal, ray.dir) < 0 ? hit.normal : -hit.normal;
				double irradiance = 0.0;
				DVec3 radiance_sum(0.0);
				if (scene.environment) {
					if (normal != Vec3(0, 1, 0) || !sees_open_sky(scene, p)) {
						image.valid[i] = false;
						break;
					}
					radiance_sum += sky;
				}
				for (size_t l = 0; l < scene.area_lights.count() && image.valid[i]; l++) {
					const Area_Light& light = scene.area_lights.light(l);
					Spectrum emission = scene.materials[light.material].emission;
					if (light.triangles.empty()) image.valid[i] = false; // a sphere light: not handled here
					for (const Light_Triangle& t : light.triangles) {
						if (glm::dot(p - t.p0, t.normal) <= 0) continue; // behind the one-sided emitter: no light
						int above = (glm::dot(t.p0 - p, normal) > 0) + (glm::dot(t.p1 - p, normal) > 0) + (glm::dot(t.p2 - p, normal) > 0);
						if (above == 0) continue;
						bool seen_whole = above == 3;
						for (uint32_t a = 0; a < LIGHT_GRID && seen_whole; a++)
							for (uint32_t b = 0; a + b < LIGHT_GRID && seen_whole; b++) {
								float u = float(a) / (LIGHT_GRID - 1), v = float(b) / (LIGHT_GRID - 1);
								Vec3 q = t.p0 + u * (t.p1 - t.p0) + v * (t.p2 - t.p0);
								Vec3 from = p + 1e-4f * std::max(1.0f, glm::length(p)) * normal;
								float distance = glm::length(q - from);
								seen_whole = !scene.occluded(Ray(from, (q - from) / distance, Vec2{0.0f, distance * (1.0f - 1e-4f)}));
							}
						if (!seen_whole) {
							image.valid[i] = false;
							break;
						}
						double e = closed_form::polygon_irradiance({DVec3(t.p0), DVec3(t.p1), DVec3(t.p2)}, DVec3(p), DVec3(normal), 1.0);
						double exact = closed_form::triangle_solid_angle(DVec3(t.p0), DVec3(t.p1), DVec3(t.p2), DVec3(p));
						radiance_sum += e * DVec3(emission);
						irradiance += e;
						image.weighted_ratio[i] += e * girard_solid_angle(t.p0, t.p1, t.p2, p) / exact;
						image.weighted_ratio_exact_acos[i] += e * girard_solid_angle(t.p0, t.p1, t.p2, p, float_acos) / exact;
					}
				}
				Spectrum albedo = lambertian->albedo;
				image.value[i] += DVec3(albedo) / M_PI * radiance_sum / double(SUBPIXELS * SUBPIXELS);
				image.weight[i] += irradiance;
			}
		}
	// A pixel counts only if its 8 neighbours do too: its own points cannot miss the edge of a shadow,
	// of an object or of an emitter that crosses it (edges between two valid surfaces remain).
	std::vector<bool> own = image.valid;
	for (uint32_t y = 0; y < image.h; y++)
		for (uint32_t x = 0; x < image.w; x++)
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++) {
					int nx = int(x) + dx, ny = int(y) + dy;
					if (nx >= 0 && ny >= 0 && nx < int(image.w) && ny < int(image.h) && !own[size_t(ny) * image.w + nx])
						image.valid[size_t(y) * image.w + x] = false;
				}
	return image;
}

// Sums over the valid pixels of [x0, x1) x [y0, y1), the three channels together.
struct Sums {
	double closed = 0.0, rendered = 0.0, variance = 0.0, ratio = 0.0, ratio_exact_acos = 0.0, weight = 0.0;
	size_t pixels = 0, total = 0;
};
Sums sums(const Closed_Form_Image& truth, const Noisy_Image* image, uint32_t x0, uint32_t x1, uint32_t y0, uint32_t y1) {
	Sums s;
	for (uint32_t y = y0; y < y1; y++)
		for (uint32_t x = x0; x < x1; x++) {
			s.total++;
			size_t i = size_t(y) * truth.w + x;
			if (!truth.valid[i]) continue;
			s.pixels++;
			s.closed += truth.value[i].x + truth.value[i].y + truth.value[i].z;
			s.ratio += truth.weighted_ratio[i];
			s.ratio_exact_acos += truth.weighted_ratio_exact_acos[i];
			s.weight += truth.weight[i];
			if (!image) continue;
			for (int c = 0; c < 3; c++) {
				s.rendered += image->mean.at(x, y)[c];
				s.variance += image->variance.at(x, y)[c];
			}
		}
	return s;
}

// "+0.12 ± 0.05" (%): rendered / closed form - 1; "0" where the closed form is 0 and so is the render.
std::string relative(const Sums& s) {
	if (s.closed > 0) return fmt("%+.2f ± %.2f", 100.0 * (s.rendered / s.closed - 1.0), 100.0 * std::sqrt(s.variance) / s.closed);
	return s.rendered == 0 ? "0 = 0" : fmt("0, rendered %.3g", s.rendered);
}

std::string grid_header() {
	std::string header = "| |", rule = "|---|";
	for (uint32_t gx = 0; gx < GRID; gx++) {
		header += " column " + std::to_string(gx) + " |";
		rule += "---|";
	}
	return header + "\n" + rule + "\n";
}

int run(const Options& o) {
	std::string name = std::filesystem::path(o.scene).stem().string();
	std::string work_dir = std::filesystem::temp_directory_path() / ("lab_cycles_direct_light_" + std::to_string(getpid()));
	std::filesystem::create_directories(work_dir);
	std::filesystem::create_directories(o.out);
	std::string load_before = load_average();
	std::printf("%s, max depth 1, %u spp per render (two halves), %u threads; load average: %s\n", o.scene.c_str(), o.spp,
	            o.threads, load_before.c_str());
	Scene scene = load_scene(o.scene);
	Closed_Form_Image truth = closed_form_image(scene);

	struct Variant {
		std::string label;
		Renderer renderer;
		std::vector<std::string> cycles_options;
	};
	std::vector<Variant> variants{{"ours", Renderer::lab, {}}, {"Cycles, as exported", Renderer::cycles, {}}};
	if (scene.area_lights.count() > 0) {
		variants.push_back({"Cycles, mesh light (--light-as-mesh)", Renderer::cycles, {"--light-as-mesh"}});
		variants.push_back({"Cycles, mesh light of 16 x the triangles (--subdivide-lights 4)", Renderer::cycles, {"--subdivide-lights", "4"}});
	}
	if (scene.environment && std::holds_alternative<Env_Map>(*scene.environment))
		for (const char* width : {"1024", "4096"})
			variants.push_back({std::string("Cycles, importance map ") + width + " wide (--world-map-resolution " + width + ")",
			                    Renderer::cycles, {"--world-map-resolution", width}});
	Sums all = sums(truth, nullptr, 0, truth.w, 0, truth.h);
	std::string summary = "| renderer | valid pixels: renderer / closed form − 1 (%) | regions within 3 se of 0 |\n|---|---|---|\n";
	std::string grids;
	for (const Variant& v : variants) {
		std::printf("%s ...\n", v.label.c_str());
		std::fflush(stdout);
		HDR_Image halves[2];
		for (uint64_t seed = 1; seed <= 2; seed++) {
			Render_Request request{o.scene, o.spp / 2, seed, o.threads, 1, {}, v.cycles_options, {}};
			halves[seed - 1] = run_renderer(v.renderer, request, work_dir).image;
		}
		Noisy_Image image = from_two_halves(halves[0], halves[1]);
		std::string grid = "**" + v.label + "**, renderer / closed form − 1 (%) per region, ± standard error:\n\n" + grid_header();
		uint32_t regions = 0, within = 0;
		for (uint32_t gy = 0; gy < GRID; gy++) {
			grid += "| row " + std::to_string(gy) + " |";
			for (uint32_t gx = 0; gx < GRID; gx++) {
				uint32_t x0 = truth.w * gx / GRID, x1 = truth.w * (gx + 1) / GRID, y0 = truth.h * gy / GRID, y1 = truth.h * (gy + 1) / GRID;
				Sums s = sums(truth, &image, x0, x1, y0, y1);
				if (s.pixels * 4 < s.total) { // fewer than a quarter of the region's pixels
					grid += " – |";
					continue;
				}
				grid += " " + relative(s) + " |";
				if (s.closed > 0) {
					regions++;
					within += std::abs(s.rendered - s.closed) <= 3 * std::sqrt(s.variance);
				}
			}
			grid += "\n";
		}
		Sums whole = sums(truth, &image, 0, truth.w, 0, truth.h);
		std::string row = "| " + v.label + " | " + relative(whole) + " | " + std::to_string(within) + " of " + std::to_string(regions) + " |\n";
		std::printf("%s", row.c_str());
		summary += row;
		grids += grid + "\n";
	}
	std::string ratios = "Cycles 3.4's float solid angle of the light's triangles (Girard's formula with its polynomial acos, as in "
	                     "its triangle light sampling; then the same with float std::acos) / the exact one − 1 (%), weighted by the "
	                     "irradiance each triangle gives:\n\n" +
	                     grid_header();
	for (uint32_t gy = 0; gy < GRID; gy++) {
		ratios += "| row " + std::to_string(gy) + " |";
		for (uint32_t gx = 0; gx < GRID; gx++) {
			Sums s = sums(truth, nullptr, truth.w * gx / GRID, truth.w * (gx + 1) / GRID, truth.h * gy / GRID, truth.h * (gy + 1) / GRID);
			ratios += s.pixels * 4 < s.total || s.weight == 0
			              ? " – |"
			              : fmt(" %+.1f / %+.2f |", 100.0 * (s.ratio / s.weight - 1.0), 100.0 * (s.ratio_exact_acos / s.weight - 1.0));
		}
		ratios += "\n";
	}
	if (scene.area_lights.count() == 0) ratios.clear();
	std::filesystem::remove_all(work_dir);
	std::string path = o.out + "/cycles_direct_light_" + name + ".md";
	std::ofstream(path) << "`" << o.scene << "`, direct light alone (max depth 1), " << o.spp
	                    << " spp per render (two halves, seeds 1 and 2), " << o.threads << " threads; load average "
	                    << load_before << " at the start, " << load_average() << " at the end. Closed form "
	                    << (scene.area_lights.count() ? "(Lambert's polygon formula) " : "(a quadrature of the sky) ") << "in " << all.pixels << " of " << all.total
	                    << " pixels (every point of the pixel and of its neighbours on a Lambertian surface where it applies: "
	                    << "it sees each light triangle whole or lies behind it; it faces +y under the open sky); rows from the top of the image, regions with fewer than a quarter of their "
	                    << "pixels valid shown as –.\n\n"
	                    << summary << "\n" << grids << ratios;
	std::printf("wrote %s\n", path.c_str());
	return 0;
}

} // namespace

int main(int argc, char** argv) {
	try {
		return run(parse(argc, argv));
	} catch (const std::exception& e) {
		std::fprintf(stderr, "error: %s\n", e.what());
		return 1;
	}
}
