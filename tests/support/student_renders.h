#pragma once
// Reference-image tests of a grader: the student's code renders a graded scene (in the subject,
// grading/judge/), and the judge compares the film with the stored reference (graded_images.h).
#include "scene.h"

#include <string>
#include <vector>

// What to look at when a function's own test cases failed (judge::unit_tests_failed): a render then
// fails because of that function, and the hint says where in the handout it is explained.
struct Image_Hint {
	std::string function; // as in the test cases' [fn:NAME] tags
	std::string hint;
};

// The grader's reference-image check as Catch2 checks: renders the graded scene `name` with the task
// under test, compares it with the stored reference (the means, and the render's noise against the
// reference's), and on failure shows where the image differs and what to look at: the hints of the
// functions whose own test cases failed, or else `hint` (in the handout's terms), and how to see
// the picture. For the grade report (report_record.h) it also
// writes the render, the reference and a heat map of the z-scores (z_heat_map.h) as PNGs and
// attaches them to the test case. With a grading seed the render uses a seed drawn from it.
// `integrator`: the integrator the render uses (task 6's extension renders with "nee").
// Its significance is two checks' share of the grader's (judge::significance(2): the z-tests of
// the means, and the bound on the render's noise, image_compare.h): tag the test case [statistical:2].
// `if_noisy`: what makes renders of this task noisier than the reference's, in the handout's terms.
struct Image_Test {
	std::string name, hint;
	std::vector<Image_Hint> if_failed;
	std::string if_noisy;
	std::string integrator = "mixture";
};
void check_renders_like_reference(const Image_Test& test);
