#include "scene.h"

void Scene::commit() {
	area_lights.build(objects, materials);
	bvh.build(std::move(objects), 1);
	objects.clear();
}

Spectrum Scene::environment_radiance(Vec3 dir) const {
	if (!environment) return Spectrum{0.0f};
	return std::visit([&](const auto& env) { return env.evaluate(dir); }, *environment);
}
