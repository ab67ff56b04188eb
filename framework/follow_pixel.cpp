#include "follow_pixel.h"
#include "lifecycle.h"

void follow_pixel(const Pathtracer& pathtracer, uint32_t x, uint32_t y, uint32_t samples, std::ostream& out) {
	const Render_Settings& settings = pathtracer.settings;
	size_t index = size_t(y) * settings.width + x;
	out << "pixel (" << x << ", " << y << "), seed " << settings.seed << ", view " << view_name(pathtracer.view)
	    << ", max_depth " << settings.max_depth << "\n";
	// What a '?' means (lifecycle.cpp, format_weight): a weight is recovered from the radiance that
	// came back along a ray, so a channel that brought no light back has no known weight.
	out << "(? in a weight or throughput: no light came back on that colour channel, so its weight is"
	       " unknown)\n";
	Lifecycle_Recorder recorder;
	for (uint32_t s = 0; s < samples; s++) {
		RNG rng = RNG::for_sample(settings.seed, index, s, settings.sampler); // as render() does
		pathtracer.trace_pixel(x, y, rng);
		out << "sample " << s << ": ";
		recorder.print(out, pathtracer.scene.material_names);
	}
}
