#include "student_calls.h"

#include "judge.h"


namespace {
double channel_average(Spectrum s) {
	return (double(s.r) + double(s.g) + double(s.b)) / 3.0;
}
} // namespace

std::vector<float> student_power_heuristic(const std::vector<Vec2>& pairs) {
	return judge::ask(protocol::Power_Heuristic{pairs});
}

std::vector<double> student_direct_light(const Scene& scene, const Render_Settings& settings, const Trace& point,
                                         const BSDF& bsdf, Vec3 out_dir, size_t n, uint64_t seed) {
	protocol::Estimate_Direct request{scene, settings, {}, RNG_State::of(RNG(seed))};
	request.queries.assign(n, {point, bsdf, out_dir});
	std::vector<double> values;
	for (Spectrum s : judge::ask(request)) values.push_back(channel_average(s));
	return values;
}

std::vector<double> student_pixel_samples(const Scene& scene, const Render_Settings& settings, size_t n) {
	protocol::Trace_Pixels request{scene, settings, Estimator_Choice{"nee"}, View::path, {}};
	for (size_t i = 0; i < n; i++) request.samples.push_back({0, 0, RNG_State::of(RNG::for_sample(settings.seed, 0, i))});
	std::vector<double> values;
	for (Spectrum s : judge::ask(request)) values.push_back(channel_average(s));
	return values;
}
