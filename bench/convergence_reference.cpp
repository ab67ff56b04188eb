#include "convergence_reference.h"
#include "estimator.h"
#include "image_io.h"
#include "render.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace {

// FNV-1a, 64 bits: a stable name for a text (std::hash may differ between library versions).
uint64_t fnv1a(const std::string& text) {
	uint64_t hash = 14695981039346656037ull;
	for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
	return hash;
}

std::string cache_name(const Render_Settings& s, const Estimator_Choice& e, const std::string& identity) {
	std::string key = identity + "|" + std::to_string(s.width) + "x" + std::to_string(s.height) + "|spp " +
	                  std::to_string(s.samples) + "|depth " + std::to_string(s.max_depth) + "|seed " +
	                  std::to_string(s.seed) + "|lights " + std::to_string(s.light_sampling) + "|roulette " +
	                  std::to_string(s.russian_roulette) + "|sampler " + sampler_name(e.sampler) + "|integrator " +
	                  e.integrator + "|light choice " + light_choice_name(e.light_choice);
	char name[64];
	std::snprintf(name, sizeof name, "reference-%016llx", static_cast<unsigned long long>(fnv1a(key)));
	return name;
}

} // namespace

Cached_Reference cached_reference(const Pathtracer& pathtracer, const std::string& identity,
                                  const std::string& cache_dir, uint32_t threads) {
	const Render_Settings& settings = pathtracer.settings;
	std::string stem = cache_dir + "/" + cache_name(settings, pathtracer.estimator().choice, identity);
	Cached_Reference cached;
	cached.path = stem + "-mean.exr";
	std::string variance_path = stem + "-variance.exr";
	Reference& reference = cached.reference;
	reference.samples = settings.samples;
	if (std::filesystem::exists(cached.path) && std::filesystem::exists(variance_path)) {
		reference.mean = read_image(cached.path);
		reference.variance = read_image(variance_path);
		cached.from_cache = reference.mean.w == settings.width && reference.mean.h == settings.height &&
		                    reference.variance.w == settings.width && reference.variance.h == settings.height;
		if (cached.from_cache) return cached;
	}
	Render_Options options;
	options.threads = threads;
	auto start = std::chrono::steady_clock::now();
	Film film = render(pathtracer, options);
	cached.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	reference.mean = film.mean();
	reference.variance = film.variance();
	write_exr(cached.path, reference.mean);
	write_exr(variance_path, reference.variance);
	return cached;
}
