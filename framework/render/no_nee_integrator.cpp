// The NEE integrator's place in a program whose task 4 is a student's: next-event estimation
// (nee_integrator.h) is an estimator of task 4's own image, so it is never linked where task 4
// is graded, and a render that asks for it there is an error (cmake/lab.cmake, lab_link_tasks).
#include "error.h"
#include "nee_integrator.h"

namespace {
class Refusing_Integrator : public Path_Integrator {
public:
	Spectrum radiance(const Pathtracer&, RNG&, const Ray&) const override {
		throw Input_Error("--integrator nee needs the reference of task 4: next-event estimation is not part of a "
		                  "program built with your task 4 (use --integrator mixture)");
	}
};
} // namespace

const Path_Integrator& nee_integrator() {
	static const Refusing_Integrator refusing;
	return refusing;
}

float light_pdf(const Pathtracer&, const Ray&, const Trace&) {
	throw Input_Error("next-event estimation is not part of a program built with your task 4");
}
