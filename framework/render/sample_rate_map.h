#pragma once
// The picture of an adaptive render (./lab render --adaptive T --view samples, api/adaptive_sampling.h):
// the samples each pixel took.
#include "film.h"

#include <cstdint>

// Each pixel as the heat ramp (heat_ramp.h) of its samples / max_samples: black none, white all.
HDR_Image sample_rate_map(const Film& film, uint32_t max_samples);
