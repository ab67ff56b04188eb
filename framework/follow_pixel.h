#pragma once
// Prints the life of every ray of the first `samples` samples of pixel (x, y): exactly the paths
// the renderer takes for that pixel (same seeds), with what each ray hit and the samples drawn.
#include "pathtracer.h"

#include <ostream>

void follow_pixel(const Pathtracer& pathtracer, uint32_t x, uint32_t y, uint32_t samples, std::ostream& out);
