#include "test_materials.h"

Material diffuse_material(Spectrum albedo, Spectrum emission) {
	Material m;
	m.bsdf = BSDF(BSDF_Lambertian{albedo});
	m.emission = emission;
	return m;
}

Material emitter(Spectrum radiance) {
	return diffuse_material(Spectrum{0.0f}, radiance);
}

Material mirror_material(Spectrum reflectance) {
	Material m;
	m.bsdf = BSDF(BSDF_Mirror{reflectance});
	return m;
}

Material glass_material(Spectrum reflectance, Spectrum transmittance, float index_of_refraction) {
	Material m;
	m.bsdf = BSDF(BSDF_Glass{reflectance, transmittance, index_of_refraction});
	return m;
}
