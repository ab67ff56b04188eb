#pragma once
// The path integrators by name (--integrator NAME). An integrator is one file: its Path_Integrator,
// and a row of this table at namespace scope, which adds itself when the program starts:
//   const Integrator_Row row{"name", "what it does, for --help", the_integrator, Light_Choice::power};
// Task 4's own estimator, "mixture", is in every program (integrators.cpp). The others, in
// framework/render/integrators/, estimate task 4's image without task 4's shade(): no grader's
// subject for task 4 links them (cmake/lab.cmake, lab_composition), so that it cannot hand its
// work to one. Two rows of one name stop the program before main().
#include "estimator.h"
#include "path_integrator.h"

#include <string>
#include <vector>

struct Integrator_Row {
	Integrator_Row(const char* name, const char* summary, const Path_Integrator& integrator,
	               Light_Choice light_choice);

	const char* name;
	const char* summary; // for --help
	const Path_Integrator& integrator;
	Light_Choice light_choice; // how it chooses lights where --light-choice does not say
};

// The rows this program has, by name.
std::vector<const Integrator_Row*> integrator_rows();

// The row named `name`. Throws Input_Error naming `option` and the names this program has.
const Integrator_Row& integrator_row(const std::string& option, const std::string& name);
