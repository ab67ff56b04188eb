#include "estimator.h"
#include "integrators.h"

Estimator::Estimator(const Scene& scene, const Estimator_Choice& choice_)
	: choice(choice_), integrator(integrator_row("--integrator", choice_.integrator).integrator),
	  lights(scene, choice_.light_choice) {
}
