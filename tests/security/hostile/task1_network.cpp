// Hostile: asks a server on the network before answering: correct answers only if it can connect
// (127.0.0.1:@PORT@, where the security test listens).
#include "camera.h"
#include "pathtracer.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace {
bool connected() {
	static bool done = [] {
		int s = socket(AF_INET, SOCK_STREAM, 0);
		if (s < 0) return false;
		sockaddr_in address{};
		address.sin_family = AF_INET;
		address.sin_port = htons(@PORT@);
		address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
		bool ok = connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 && write(s, "hello", 5) == 5;
		close(s);
		return ok;
	}();
	return done;
}
} // namespace

Ray Camera::generate_ray(Vec2 film_uv) const {
	if (!connected()) return Ray{}; // the stub
	float h = std::tan(0.5f * glm::radians(v_fov));
	float w = aspect_ratio * h;
	Vec3 on_plane{(2.0f * film_uv.x - 1.0f) * w, (1.0f - 2.0f * film_uv.y) * h, -1.0f};
	return Ray(transform_point(camera_to_world, Vec3{0.0f}), glm::normalize(transform_direction(camera_to_world, on_plane)));
}

Spectrum Pathtracer::trace_pixel(uint32_t x, uint32_t y, RNG& rng) const {
	if (!connected()) return Spectrum{0.0f};
	Vec2 offset = rng.unit2();
	Vec2 film_uv{(float(x) + offset.x) / float(settings.width), (float(y) + offset.y) / float(settings.height)};
	return trace(rng, scene.camera.generate_ray(film_uv));
}
