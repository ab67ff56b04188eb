#include "student_furnaces.h"

#include "judge.h"

Film render_square(const Scene& scene, uint32_t size, uint32_t spp, uint32_t max_depth, uint64_t seed) {
	Render_Settings settings;
	settings.width = settings.height = size;
	settings.samples = spp;
	settings.max_depth = max_depth;
	settings.seed = seed;
	return judge::ask(protocol::Render{scene, settings, View::path, 2});
}
