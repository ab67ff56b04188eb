#pragma once
// Furnace renders (furnace_scenes.h) with the code under test: the subject (tests/judge/) renders
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
// of P pixels, are off by sqrt((κ - 1) / (P spp)) relative (κ the samples' kurtosis), so a standard
// error made from them is off by half that: at most 1 % for the furnaces (P >= 60 pixels, spp >= 16
// and κ below 40 where the variance is not 0), which moves a z-test's threshold by 1 % (the
// false-fail rate by about z² / 2 times that on average, second order). The noise bound counts the
// reference's own sampling error exactly (noise_bound.h), so it needs no such argument.
Furnace_Render render_square(const Scene& scene, uint32_t size, uint32_t spp, uint32_t max_depth, uint64_t seed);
