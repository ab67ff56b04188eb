#pragma once
// Furnace renders (furnace_scenes.h) with the code under test: the subject (grading/judge/) renders
// the scene with the student's task and the reference of the others, and the judge gets the film.
// Beside it the judge renders the same scene itself, with the reference implementation, for the
// noise a correct render has (film_statistics.h): standard errors never come from the submission.
#include "film_statistics.h"
#include "scene.h"

// `scene` rendered on a square film of size x size pixels, spp samples per pixel, at most
// max_depth bounces, seeded with `seed` (one protocol::Render request), and the reference's render
// of it with as many samples and a seed of its own.
//
// Why as many samples are enough: the reference render's per-sample variances, summed over a group
// of pixels, are off by sqrt(Σ Var(s²)) / Σ s² relative (noise_bound.h's Var(s²), from the render's
// fourth moments), and a standard error made from them by half that: measured on the public
// furnaces, 0.1 % to 0.5 % (the white furnace's silhouette 0.3 %, the geometric series at max_depth
// 40 0.5 %, task 7's sphere 0.3 %; 0 where the variance is 0), which moves a z-test's threshold by as
// much (its false-fail rate by about z² / 2 times that on average, second order). The noise check compares
// the two renders pixel by pixel (paired_noise.h), which is exact for renders of equal samples.
Furnace_Render render_square(const Scene& scene, uint32_t size, uint32_t spp, uint32_t max_depth, uint64_t seed);
