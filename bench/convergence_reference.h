#pragma once
// The high-spp reference of a convergence experiment: rendered once, then read back from a cache
// directory, under a name made from everything the image depends on.
#include "convergence_metrics.h"
#include "pathtracer.h"

#include <string>

struct Cached_Reference {
	Reference reference;
	std::string path;       // the cached mean (EXR); the variance is next to it
	bool from_cache = false;
	double seconds = 0.0;   // wall time of the render, if it was rendered now
};

// `identity` names what the image depends on besides pathtracer.settings (film, spp, depth, seed,
// strategy switches): the scene file's text and the strategy's command-line flags. Renders
// pathtracer.settings.samples spp on `threads` threads (0 = all) if the cache has no such image.
Cached_Reference cached_reference(const Pathtracer& pathtracer, const std::string& identity,
                                  const std::string& cache_dir, uint32_t threads);
