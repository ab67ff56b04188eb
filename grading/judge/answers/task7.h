#pragma once
// The subject's answers to task 7's requests (grading/judge/protocol.h): each runs the task
// functions on the request's inputs and returns their raw outputs. Included only by the subject's
// main (grading/judge/subject_main.cpp).
#include "protocol.h"

namespace {
using namespace protocol;

Direction_To_UV::Answer answer(const Direction_To_UV& request) {
	Direction_To_UV::Answer uvs;
	for (Vec3 dir : request.dirs) uvs.push_back(direction_to_uv(dir));
	return uvs;
}

UV_To_Direction::Answer answer(const UV_To_Direction& request) {
	UV_To_Direction::Answer dirs;
	for (Vec2 uv : request.uvs) dirs.push_back(uv_to_direction(uv));
	return dirs;
}

template<class Sampler> Sampler_Answer ask_sampler(const Sampler& sampler, const std::vector<Vec2>& us,
                                                   const std::vector<Vec3>& dirs) {
	Sampler_Answer result;
	for (Vec2 u : us) result.samples.push_back(sampler.sample(u));
	for (Vec3 dir : dirs) result.pdfs.push_back(sampler.pdf(dir));
	return result;
}

Uniform_Sphere::Answer answer(const Uniform_Sphere& request) {
	return ask_sampler(Samplers::Sphere::Uniform{}, request.us, request.dirs);
}

Image_Sampler::Answer answer(const Image_Sampler& request) {
	Samplers::Sphere::Image sampler(request.image);
	Image_Sampler::Answer result;
	result.w = sampler.w;
	result.h = sampler.h;
	result.pdf_texel = sampler.pdf_texel;
	result.cdf = sampler.cdf;
	result.queries = ask_sampler(sampler, request.us, request.dirs);
	return result;
}

// An environment's sample(u) for each u, pdf(dir) and evaluate(dir) for each dir.
template<class Environment> Env_Map_Queries::Answer ask_environment(const Environment& environment,
                                                                    const std::vector<Vec2>& us,
                                                                    const std::vector<Vec3>& dirs) {
	Env_Map_Queries::Answer result;
	result.queries = ask_sampler(environment, us, dirs);
	for (Vec3 dir : dirs) result.radiance.push_back(environment.evaluate(dir));
	return result;
}

Env_Map_Queries::Answer answer(const Env_Map_Queries& request) {
	return ask_environment(Env_Map(request.image, request.importance_sampling), request.us, request.dirs);
}

Env_Constant_Queries::Answer answer(const Env_Constant_Queries& request) {
	return ask_environment(Env_Constant{request.radiance}, request.us, request.dirs);
}

} // namespace
