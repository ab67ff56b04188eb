#pragma once
// How a render estimates its image, beside what it renders (Render_Settings): the path integrator,
// the random numbers and the choice of lights (--integrator, --sampler, --light-choice). Every
// choice estimates the same image, with other noise. The defaults are what the graders'
// statistics assume: task 4's estimator, independent samples, lights chosen by power.
#include "light_distribution.h"
#include "sampler.h"

#include <string>

class Path_Integrator;

struct Estimator_Choice {
	std::string integrator = "mixture"; // a name of the integrator table (integrators.h)
	Sampler sampler = Sampler::independent;
	Light_Choice light_choice = Light_Choice::power;
};

// A choice made for one scene: the integrator it names, and the lights' distribution. Throws
// Input_Error for an integrator name the program does not have.
struct Estimator {
	Estimator(const Scene& scene, const Estimator_Choice& choice);

	Estimator_Choice choice;
	const Path_Integrator& integrator;
	Light_Distribution lights; // which light a light sample aims at
};
