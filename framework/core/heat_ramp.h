#pragma once
// A perceptually ordered heat ramp (black, blue, magenta, orange, yellow, white) for t in [0, 1]:
// the bvh view's node counts and the samples view's sample counts.
#include "vec_math.h"

#include <algorithm>
#include <array>

inline Spectrum heat_ramp(float t) {
	constexpr std::array<Spectrum, 6> stops{Spectrum{0.0f, 0.0f, 0.0f}, Spectrum{0.1f, 0.1f, 0.6f},
	                                        Spectrum{0.7f, 0.1f, 0.6f}, Spectrum{1.0f, 0.4f, 0.1f},
	                                        Spectrum{1.0f, 0.9f, 0.2f}, Spectrum{1.0f, 1.0f, 1.0f}};
	t = glm::clamp(t, 0.0f, 1.0f) * float(stops.size() - 1);
	size_t i = std::min(size_t(t), stops.size() - 2);
	return glm::mix(stops[i], stops[i + 1], t - float(i));
}
