#pragma once
// Materials for scenes that tests build in code.
#include "material.h"

Material diffuse_material(Spectrum albedo, Spectrum emission = Spectrum{0.0f});
// A light: a black diffuse surface that emits `radiance` from its front side.
Material emitter(Spectrum radiance);
Material mirror_material(Spectrum reflectance);
Material glass_material(Spectrum reflectance, Spectrum transmittance, float index_of_refraction);
