#pragma once
// Furnace renders (furnace_scenes.h) with the code under test: the subject (tests/judge/) renders
// the scene with the student's task and the reference of the others, and the judge gets the film.
#include "film.h"
#include "scene.h"

// `scene` rendered on a square film of size x size pixels, spp samples per pixel, at most
// max_depth bounces, seeded with `seed` (one protocol::Render request).
Film render_square(const Scene& scene, uint32_t size, uint32_t spp, uint32_t max_depth, uint64_t seed);
