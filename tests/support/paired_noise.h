#pragma once
// A one-sided, distribution-free test that a submission is not noisier than the reference, when the
// judge has drawn the reference's samples itself with the same design: the same pixels with the same
// number of samples each (a furnace render), or batches of the same size (a closed-form estimate).
//
// If the submission samples as the reference does, the two per-sample variances of a pair (pixel p
// of both renders, or batch b of both sample sets) are independent and identically distributed, so
// each is the larger with probability 1/2, whatever the law of the samples: the number of pairs in
// which the submission's is the larger is Binomial(pairs, 1/2) (the sign test; Dixon and Mood 1946,
// "The statistical sign test", JASA 41). It fails at significance α when that count is improbably
// large. No moment of the samples enters, so heavy tails, and rare events that one sample caught and
// the other did not, cannot make it fail a correct submission; an estimator noisier than the
// reference is the larger in most pairs and fails. (A variance ratio k never needs estimating: the
// count is the statistic.)
//
// Pairs in which both variances are within float rounding (`rounding`, the variance a pair may have
// from rounding alone) are ties and left out, as the sign test does: two correct implementations may
// round differently where the estimator has (almost) no noise.
#include <cstddef>
#include <string>
#include <vector>

struct Paired_Noise {
	bool pass = true;
	size_t pairs = 0;   // compared (ties left out)
	size_t noisier = 0; // in which the submission's variance is the larger
	size_t ties = 0;
	double p_value = 1.0; // P(Binomial(pairs, 1/2) >= noisier)
	double alpha = 0.0;
	double ratio = 1.0;   // sum of the submission's variances / sum of the reference's (for the message)
};

// submission[i], reference[i]: the per-sample variances of pair i; rounding[i]: its tie level.
Paired_Noise compare_paired_variances(const std::vector<double>& submission, const std::vector<double>& reference,
                                      const std::vector<double>& rounding, double alpha);

// The unbiased per-sample variances of `batches` consecutive batches of equal size (the rest of the
// samples left out).
std::vector<double> batch_variances(const std::vector<double>& samples, size_t batches);

// "in 58 of 60 <unit>s the submission's samples vary more than the reference's (a correct solution
// does so in more than 41 with probability below 0.001); overall 3.2 times the reference's variance".
std::string describe(const Paired_Noise& noise, const std::string& unit);
