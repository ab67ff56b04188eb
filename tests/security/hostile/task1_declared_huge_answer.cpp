// Hostile: answers the first request with a header that declares the largest payload the protocol
// allows (1 GiB) and then sends nothing, hoping the judge reserves the memory before it arrives.
#include "camera.h"
#include "pathtracer.h"

#include <cstdint>
#include <cstring>
#include <unistd.h>

namespace {
// The answer header (grading/judge/protocol.h) of the first request of a test case, of kind `kind`
// (1: generate_rays, 2: trace_pixels): magic "PTLJ", kind, sequence 1, status OK, length.
void declare_and_wait(uint32_t kind) {
	uint32_t words[4] = {0x4a4c5450, kind, 1, 0};
	uint64_t length = uint64_t(1) << 30;
	char header[24];
	std::memcpy(header, words, 16);
	std::memcpy(header + 16, &length, 8);
	(void)!write(4, header, sizeof header);
	pause();
}
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	declare_and_wait(1);
	return Ray(Vec3{0.0f}, Vec3{0.0f});
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	declare_and_wait(2);
	return Spectrum{0.0f};
}
