// The framework's fast accelerator runs only where tasks 2 and 3 are both the reference
// (framework/api/accelerator.h, lab_link_tasks in cmake/lab.cmake): a program that links another
// task 2, as the task-2 grader links a student's, has its Triangle::hit decide every candidate
// triangle of the BVH, not only the closest one. This program links the counting task 2
// (counting_task2_shapes.cpp) through lab_link_tasks and renders the task-2 graded scene.
#include "graded_images.h"
#include "triangle_hit_counter.h"

#include "lab_catch2.h"

TEST_CASE("a task 2 other than the reference decides every candidate triangle, not only the closest",
          "[framework][isolation]") {
	const Graded_Scene& graded = graded_scene("eye_bunny");
	Scene scene = load_graded(graded);
	Triangle_Hit_Counter& counter = triangle_hit_counter();
	counter.calls = counter.misses = 0;
	render_graded(graded, scene, scene.settings.samples, scene.settings.seed);

	uint64_t camera_rays = uint64_t(scene.settings.width) * scene.settings.height * scene.settings.samples;
	INFO("rendering scenes/graded/eye_bunny.json (" << camera_rays << " camera rays) called Triangle::hit "
	     << counter.calls << " times, " << counter.misses << " of them on a triangle the ray misses. "
	     << "Only the fast accelerator, which decides the candidates itself and calls Triangle::hit on the "
	        "closest triangle alone, makes no call that misses: it must not be linked here (lab_link_tasks)");
	CHECK(counter.misses > 0);
}
