#include "light_closed_forms.h"

#include <cmath>

namespace closed_form {

double polygon_irradiance(const std::vector<DVec3>& polygon, DVec3 point, DVec3 normal, double radiance) {
	double sum = 0.0;
	for (size_t i = 0; i < polygon.size(); i++) {
		DVec3 a = glm::normalize(polygon[i] - point);
		DVec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - point);
		double theta = std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0));
		DVec3 gamma = glm::normalize(glm::cross(a, b));
		sum += theta * glm::dot(normal, gamma);
	}
	return 0.5 * radiance * std::abs(sum);
}

double centred_square_irradiance(double half_side, double height, double radiance) {
	double x = half_side / height, s = x / std::sqrt(1.0 + x * x);
	return 4.0 * radiance * s * std::atan(s);
}

double sphere_irradiance(double radius, double distance, double cos_beta, double radiance) {
	double ratio = radius / distance;
	return M_PI * radiance * ratio * ratio * cos_beta;
}

double triangle_solid_angle(DVec3 a, DVec3 b, DVec3 c, DVec3 point) {
	a -= point, b -= point, c -= point;
	double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
	double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
	double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
	return 2.0 * std::atan2(numerator, denominator);
}

double sphere_solid_angle(double radius, double distance) {
	double ratio = radius / distance;
	return 2.0 * M_PI * (1.0 - std::sqrt(1.0 - ratio * ratio));
}

} // namespace closed_form
