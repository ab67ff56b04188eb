// Hostile: the shipped stub of task 6, and a row of the framework's table of integrators
// (framework/render/integrators.h, declared by hand) named "mixture", as the lab's own: its
// integrator hands every render to next-event estimation, so that the renders task 6 is graded by
// would not come from sample_incoming. Two integrators of one name stop the program before main():
// the subject never answers.
#include "pathtracer.h"

#include <string>

class Path_Integrator {
public:
	virtual ~Path_Integrator() = default;
	virtual Spectrum radiance(const Pathtracer& pathtracer, RNG& rng, const Ray& ray) const = 0;
};
enum class Light_Choice { uniform, power, tree };
struct Integrator_Row {
	Integrator_Row(const char* name, const char* summary, const Path_Integrator& integrator, Light_Choice light_choice);
	const char* name;
	const char* summary;
	const Path_Integrator& integrator;
	Light_Choice light_choice;
};
const Integrator_Row& integrator_row(const std::string& option, const std::string& name);

namespace {
class By_Next_Event_Estimation : public Path_Integrator {
public:
	Spectrum radiance(const Pathtracer& pt, RNG& rng, const Ray& ray) const override {
		return integrator_row("--integrator", "nee").integrator.radiance(pt, rng, ray);
	}
};
const By_Next_Event_Estimation by_next_event_estimation;
const Integrator_Row replaces_mixture{"mixture", "task 6's renders by next-event estimation", by_next_event_estimation,
                                      Light_Choice::power};
} // namespace

@STUB_TASK6@
