#include "paired_noise.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace {
// P(Binomial(n, 1/2) = j).
double binomial_half(size_t n, size_t j) {
	return std::exp(std::lgamma(n + 1.0) - std::lgamma(j + 1.0) - std::lgamma(n - j + 1.0) - double(n) * std::log(2.0));
}

// P(Binomial(n, 1/2) >= k), summed from the smallest term up.
double upper_tail(size_t n, size_t k) {
	double sum = 0.0;
	for (size_t j = n + 1; j-- > k;) sum += binomial_half(n, j);
	return std::min(1.0, sum);
}

// The smallest count that fails: P(Binomial(n, 1/2) >= count) <= alpha (n + 1 if none does).
size_t critical_count(size_t n, double alpha) {
	double tail = 0.0;
	size_t k = n + 1;
	while (k > 0 && tail + binomial_half(n, k - 1) <= alpha) tail += binomial_half(n, --k);
	return k;
}
} // namespace

Paired_Noise compare_paired_variances(const std::vector<double>& submission, const std::vector<double>& reference,
                                      const std::vector<double>& rounding, double alpha) {
	if (submission.size() != reference.size() || rounding.size() != reference.size()) {
		throw std::invalid_argument("compare_paired_variances: the pairs differ in number");
	}
	Paired_Noise result;
	result.alpha = alpha;
	double sum_submission = 0.0, sum_reference = 0.0;
	for (size_t i = 0; i < submission.size(); i++) {
		double s = submission[i], r = reference[i];
		sum_submission += s, sum_reference += r;
		if (std::isnan(s)) { // a NaN variance is no evidence of anything correct
			result.pairs++, result.noisier++;
			continue;
		}
		if ((s <= rounding[i] && r <= rounding[i]) || s == r) {
			result.ties++;
			continue;
		}
		result.pairs++;
		if (s > r) result.noisier++;
	}
	result.p_value = upper_tail(result.pairs, result.noisier);
	result.pass = result.p_value > alpha;
	result.ratio = sum_reference > 0.0 ? sum_submission / sum_reference : (sum_submission > 0.0 ? INFINITY : 1.0);
	return result;
}

std::vector<double> batch_variances(const std::vector<double>& samples, size_t batches) {
	size_t size = batches ? samples.size() / batches : 0;
	if (size < 2) throw std::invalid_argument("batch_variances: a batch needs two samples");
	std::vector<double> variances;
	for (size_t b = 0; b < batches; b++) {
		double mean = 0.0, m2 = 0.0;
		for (size_t i = 0; i < size; i++) {
			double x = samples[b * size + i], delta = x - mean;
			mean += delta / double(i + 1);
			m2 += delta * (x - mean);
		}
		variances.push_back(m2 / double(size - 1));
	}
	return variances;
}

std::string describe(const Paired_Noise& noise, const std::string& unit) {
	std::ostringstream out;
	out.precision(3);
	out << "in " << noise.noisier << " of " << noise.pairs << " " << unit
	    << "s the samples vary more than the reference's (a correct solution reaches "
	    << critical_count(noise.pairs, noise.alpha) << " with probability below " << noise.alpha
	    << ": each is the noisier of the two by chance, 1 in 2); overall their variance is " << noise.ratio
	    << " times the reference's";
	return out.str();
}
