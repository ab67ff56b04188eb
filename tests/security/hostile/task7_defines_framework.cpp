// Hostile: the shipped stub of task 7, and its own versions of framework functions, which the
// subject would link in place of the framework's: render() (every graded image), a member of the
// generator every sample draws from (RNG) and one of the film every render returns (Film). None is
// a task-7 function; the compile refuses the file, naming them.
#include "rng.h"

struct Pathtracer;
struct Render_Options;

struct Film {
	uint64_t non_finite() const;
};
uint64_t Film::non_finite() const {
	return 0; // no NaN is ever reported
}

Film render(const Pathtracer& pathtracer, const Render_Options& options) {
	throw 0; // whatever this version would do
}

float RNG::unit() {
	return 0.5f;
}

uint64_t film_non_finite_count_is_mine = 0;

@STUB_TASK7@
