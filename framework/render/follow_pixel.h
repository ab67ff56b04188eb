#pragma once
// Prints the life of every ray of the first `samples` samples of pixel (x, y): exactly the paths
// the renderer takes for that pixel (same seeds), with what each ray hit and the samples drawn.
#include "pathtracer.h"

#include <ostream>

void follow_pixel(const Pathtracer& pathtracer, uint32_t x, uint32_t y, uint32_t samples, std::ostream& out);

// The same paths as one JSON document (--follow-format json; ./lab view draws and tabulates it):
//   {"pixel": [x, y], "seed", "view", "max_depth", "width", "height",
//    "samples": [{"index", "value": RGB, "ray": RAY}, ...]}
//   RAY = {"depth", "origin", "dir", "dist_bounds": [t_min, t_max or null for infinity],
//          "hit": null (the ray missed) or {"object", "material" (its name), "distance", "position",
//                 "normal", "film_pixel": [x, y] (where the camera sees the hit) or null},
//          "events": [{"kind": "bsdf_sample" | "bsdf_evaluate" | "bsdf_pdf" | "light_sample" |
//                      "light_pdf" | "shadow_ray", "text"}],
//          "weight": RGB (the weight applied to this ray's light; 1 for the camera ray),
//          "throughput": RGB (the product of the weights up to here),
//          "emitted": RGB, "contribution": RGB (throughput * emitted: what this vertex adds to
//          the pixel), "radiance": RGB (what the ray brought back), "children": [RAY, ...]}
// A weight that nothing tells (no light came back on that channel, lifecycle.h) is null.
// brightest > 0: of the `samples` samples, only the `brightest` of largest luminance, brightest
// first (where a firefly comes from), each with its index.
void follow_pixel_json(const Pathtracer& pathtracer, uint32_t x, uint32_t y, uint32_t samples, std::ostream& out,
                       uint32_t brightest = 0);
