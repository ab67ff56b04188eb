// Hostile: task 4's answers derived, not traced. The Lambertian BSDF is done honestly; shade()
// returns, for every camera ray, what it can know without tracing a path:
//   - in the graded scene cornell_diffuse (64 x 64, four materials), the shipped reference image's
//     pixel the ray goes through (the test fills in scenes/graded/references/cornell_diffuse_mean.exr);
//   - in a furnace, one sphere, the closed form the request reveals: rho * L under a uniform sky
//     (black at max_depth 0), Le (1 + rho + ... + rho^D) inside an emitting sphere, 0 without light;
//   - anywhere else the stub's answer (its honest part: the test replaces the line marked HONEST).
#include "material.h"
#include "pathtracer.h"

#include <cmath>

Scatter BSDF_Lambertian::scatter(RNG& rng, Vec3 out_dir) const {
	Vec2 u = rng.unit2(); // a uniform point on the unit disk, lifted to the hemisphere (Malley)
	float r = std::sqrt(u.x), phi = 2.0f * PI_F * u.y;
	Vec3 in_dir{r * std::cos(phi), std::sqrt(std::max(0.0f, 1.0f - u.x)), r * std::sin(phi)};
	if (out_dir.y < 0.0f) in_dir.y = -in_dir.y;
	return Scatter{in_dir, evaluate(out_dir, in_dir)};
}

Spectrum BSDF_Lambertian::evaluate(Vec3 out_dir, Vec3 in_dir) const {
	return out_dir.y * in_dir.y > 0.0f ? albedo / PI_F : Spectrum{0.0f};
}

float BSDF_Lambertian::pdf(Vec3 out_dir, Vec3 in_dir) const {
	return out_dir.y * in_dir.y > 0.0f ? std::abs(in_dir.y) / PI_F : 0.0f;
}

namespace {

const float CORNELL_DIFFUSE_MEAN[] = @CORNELL_DIFFUSE_MEAN@;

// The pixel a camera ray passes through: generate_ray backwards.
bool pixel_of(const Camera& camera, const Ray& ray, uint32_t width, uint32_t height, uint32_t& x, uint32_t& y) {
	Vec3 d = Vec3(glm::inverse(camera.camera_to_world) * Vec4(ray.dir, 0.0f));
	if (d.z >= 0.0f) return false;
	float h = std::tan(0.5f * glm::radians(camera.v_fov)), w = camera.aspect_ratio * h;
	float u = 0.5f * (d.x / -d.z / w + 1.0f), v = 0.5f * (1.0f - d.y / -d.z / h);
	if (u < 0.0f || u >= 1.0f || v < 0.0f || v >= 1.0f) return false;
	x = uint32_t(u * float(width)), y = uint32_t(v * float(height));
	return true;
}

bool one_sphere(const Scene& scene) {
	return scene.bvh.primitives.size() == 1 && std::holds_alternative<Sphere>(scene.bvh.primitives[0].shape);
}

} // namespace

Spectrum Pathtracer::shade(RNG& rng, const Ray& ray, const Trace& hit) const {
	const Material& material = scene.materials[hit.material];
	uint32_t x = 0, y = 0;
	if (ray.depth == 0 && settings.width == 64 && settings.height == 64 && scene.materials.size() == 4 &&
	    pixel_of(scene.camera, ray, 64, 64, x, y)) {
		const float* pixel = &CORNELL_DIFFUSE_MEAN[3 * (size_t(y) * 64 + x)];
		return Spectrum{pixel[0], pixel[1], pixel[2]};
	}
	if (ray.depth == 0 && one_sphere(scene)) {
		Spectrum rho = material.bsdf.albedo(), le = material.emitted(Vec3{0.0f, 1.0f, 0.0f});
		if (scene.environment && std::holds_alternative<Env_Constant>(*scene.environment)) {
			Spectrum sky = std::get<Env_Constant>(*scene.environment).radiance;
			return settings.max_depth == 0 ? Spectrum{0.0f} : rho * sky;
		}
		Spectrum sum{0.0f}, power{1.0f};
		for (uint32_t k = 0; k <= settings.max_depth; k++, power *= rho) sum += power;
		return le * sum;
	}
	return eye_light(ray, hit); // HONEST
}
