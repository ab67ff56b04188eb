#include "task6_inputs.h"

#include "frame.h"
#include "judge.h"
#include "light_scenes.h"

namespace task6 {

Vec3 direction_in_cone(RNG& rng, Vec3 axis, float cos_min, float cos_max) {
	// Uniform over the zone: cos(alpha) uniform in [cos_min, cos_max] (Archimedes), the azimuth uniform.
	float cos_alpha = cos_max - rng.unit() * (cos_max - cos_min);
	float sin_alpha = std::sqrt(std::max(0.0f, 1.0f - cos_alpha * cos_alpha));
	float phi = 2.0f * PI_F * rng.unit();
	Vec3 local{sin_alpha * std::cos(phi), cos_alpha, sin_alpha * std::sin(phi)};
	return glm::normalize(Frame::from_normal(glm::normalize(axis)).to_world(local));
}

Lit_Point lit_point() {
	std::optional<RNG> secret = judge::secret_inputs();
	if (!secret) {
		return Lit_Point{Vec3{0.2f, 0.0f, -0.1f}, glm::normalize(Vec3{0.25f, 1.0f, -0.15f}),
		                 glm::normalize(Vec3{-0.3f, 1.0f, 0.4f}), 0.5f, 1.0f};
	}
	RNG& rng = *secret;
	for (;;) {
		Lit_Point p;
		p.half_side = 0.3f + 0.4f * rng.unit();
		p.height = 0.8f + 0.6f * rng.unit();
		p.position = Vec3{0.6f * rng.unit() - 0.3f, 0.0f, 0.6f * rng.unit() - 0.3f};
		p.normal = direction_in_cone(rng, Vec3{0.0f, 1.0f, 0.0f}, std::cos(glm::radians(25.0f)),
		                             std::cos(glm::radians(10.0f)));
		p.out_dir = direction_in_cone(rng, p.normal, 0.3f);
		bool light_above_horizon = true;
		for (glm::dvec3 corner : ceiling_square_corners(p.half_side, p.height)) {
			glm::dvec3 to_corner = glm::normalize(corner - glm::dvec3(p.position));
			light_above_horizon = light_above_horizon && glm::dot(to_corner, glm::dvec3(p.normal)) > 0.1;
		}
		if (light_above_horizon) return p;
	}
}

std::vector<Incoming_Sample> student_samples(const Scene& scene, const Trace& hit, const BSDF& bsdf, Vec3 out_dir,
                                             size_t n, uint64_t seed) {
	protocol::Sample_Incoming request{scene, Render_Settings{}, {}, RNG_State::of(RNG(seed))};
	request.queries.assign(n, protocol::Sample_Incoming::Query{hit, bsdf, out_dir});
	return judge::ask(request);
}

} // namespace task6
