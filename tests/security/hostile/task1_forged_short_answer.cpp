// Hostile: answers the judge itself, on the answer channel (descriptor 4), with an empty list of
// results in the protocol's own format (a judge that checked only the results it got would pass
// it), then leaves before the real answer.
#include "camera.h"
#include "pathtracer.h"

#include <unistd.h>

#include <cstdint>
#include <cstring>

namespace {
[[noreturn]] void answer_nothing(uint32_t kind) {
	const uint32_t magic = 0x4a4c5450, sequence = 1, status = 0;
	const uint64_t length = 8, count = 0;
	char message[4 * 4 + 8 + 8];
	std::memcpy(message, &magic, 4);
	std::memcpy(message + 4, &kind, 4);
	std::memcpy(message + 8, &sequence, 4);
	std::memcpy(message + 12, &status, 4);
	std::memcpy(message + 16, &length, 8);
	std::memcpy(message + 24, &count, 8);
	(void)!write(4, message, sizeof message);
	_exit(0);
}
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	answer_nothing(1); // generate_rays
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	answer_nothing(2); // trace_pixels
}
