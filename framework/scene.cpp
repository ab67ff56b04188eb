#include "scene.h"

void Scene::commit() {
	area_lights.build(objects, materials);
	// A handful of objects gets no hierarchy: one leaf holding them all, so a ray tests them in turn
	// after a single box test. More objects get a leaf each.
	size_t leaf_size = objects.size() <= HANDFUL_OF_OBJECTS ? objects.size() : 1;
	bvh.build(std::move(objects), leaf_size);
	accelerator = Accelerator<Instance>(bvh);
	objects.clear();
}

Spectrum Scene::environment_radiance(Vec3 dir) const {
	if (!environment) return Spectrum{0.0f};
	return std::visit([&](const auto& env) { return env.evaluate(dir); }, *environment);
}
