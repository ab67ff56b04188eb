#include "integrators.h"
#include "error.h"
#include "pathtracer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {
// The table, filled before main() by each row's constructor (in whatever order the program's files
// are initialized: hence a function's static, made on first use).
std::vector<const Integrator_Row*>& table() {
	static std::vector<const Integrator_Row*> rows;
	return rows;
}

// Task 4's estimator: the closest hit, shaded by Pathtracer::shade; the environment on a miss.
class Shading_Integrator : public Path_Integrator {
public:
	Spectrum radiance(const Pathtracer& pt, RNG& rng, const Ray& ray) const override {
		return trace_path_ray(
			pt.scene, rng, ray, [&](const Trace& hit) { return pt.shade(rng, ray, hit); },
			[&](const Trace&) { return pt.scene.environment_radiance(ray.dir); });
	}
};

const Shading_Integrator shading;
const Integrator_Row mixture{"mixture",
                             "task 4's shade() with task 6's one-sample mixture (the graders'; pathtracer_student's "
                             "default)",
                             shading, Light_Choice::power};
} // namespace

Integrator_Row::Integrator_Row(const char* name_, const char* summary_, const Path_Integrator& integrator_,
                               Light_Choice light_choice_)
	: name(name_), summary(summary_), integrator(integrator_), light_choice(light_choice_) {
	for (const Integrator_Row* row : table()) {
		if (std::strcmp(row->name, name) == 0) {
			std::fprintf(stderr, "error: two integrators are named '%s' (framework/render/integrators.h)\n", name);
			std::abort();
		}
	}
	table().push_back(this);
}

std::vector<const Integrator_Row*> integrator_rows() {
	std::vector<const Integrator_Row*> rows = table();
	std::sort(rows.begin(), rows.end(), [](auto* a, auto* b) { return std::strcmp(a->name, b->name) < 0; });
	return rows;
}

const Integrator_Row& integrator_row(const std::string& option, const std::string& name) {
	std::vector<const Integrator_Row*> rows = integrator_rows();
	std::string names;
	for (size_t i = 0; i < rows.size(); i++) {
		if (rows[i]->name == name) return *rows[i];
		names += (i == 0 ? "" : i + 1 == rows.size() ? " or " : ", ") + std::string(rows[i]->name);
	}
	throw Input_Error(option + ": expected " + names + ", got '" + name + "'");
}
