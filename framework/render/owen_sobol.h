#pragma once
// Owen-scrambled Sobol' points with hash-based scrambling (Burley 2020, "Practical Hash-based Owen
// Scrambling", JCGT 9(4)): the low-discrepancy numbers of Sampler::sobol (rng.h).
//
// The first two dimensions of Sobol's sequence form a (0,2)-sequence: every aligned block of 2^k
// consecutive points puts exactly one point into each of the 2^k elementary intervals of any shape
// (1 x 2^k, 2 x 2^(k-1), ..., 2^k x 1 cells). In 32-bit fixed point, point i is
//     x_0(i) = reverse_bits(i)                 (van der Corput)
//     x_1(i) = reverse_bits(pascal(i))         (direction numbers m_k = 1: the Pascal matrix mod 2)
// Owen scrambling permutes the digits hierarchically at random (each digit flipped by a random
// function of the digits above it): every point becomes uniform on [0, 1)^2 and the net property
// stays. On bit-reversed integers it is a "Laine-Karras" hash whose output bit b depends only on
// input bits <= b. Each dimension (one 1D or 2D draw) has its own seeds: it shuffles the point
// indices (an Owen scramble of the index, which maps the first 2^k indices onto an aligned block
// of 2^k) and scrambles the coordinates, so that different dimensions are not correlated
// ("padding", Kollig and Keller 2002).
#include <cstdint>

namespace owen_sobol {

// How RNG lays a pixel sample's draws over the dimensions (Sampler::sobol). Dimension 0 is the
// camera's; the vertex a ray of depth d hits starts at dimension 1 + d * DIMENSIONS_PER_VERTEX
// (RNG::begin_vertex), so that e.g. the first bounce's BSDF sample uses the same sequence in every
// sample of a pixel, however many numbers the camera drew. A vertex that draws more than its share
// continues into the next vertex's dimensions, which then start after it: a dimension is never used
// twice in one sample. The first LOW_DISCREPANCY_DIMENSIONS draws (the camera's and the first
// vertices') are low-discrepancy, the later ones independent (PCG32): the first bounces carry most
// of an image's noise, and a scrambled point costs several times a PCG32 draw.
constexpr uint32_t DIMENSIONS_PER_VERTEX = 8;
constexpr uint32_t LOW_DISCREPANCY_DIMENSIONS = 1 + 4 * DIMENSIONS_PER_VERTEX;

inline uint32_t reverse_bits(uint32_t x) {
	x = __builtin_bswap32(x);
	x = ((x & 0x0f0f0f0fu) << 4) | ((x >> 4) & 0x0f0f0f0fu);
	x = ((x & 0x33333333u) << 2) | ((x >> 2) & 0x33333333u);
	return ((x & 0x55555555u) << 1) | ((x >> 1) & 0x55555555u);
}

// Burley 2020, listing 3 (Laine and Karras 2011): an Owen scramble of a bit-reversed integer.
// Adding the seed and xor-ing with even multiples changes bit b only as a function of bits < b.
inline uint32_t laine_karras_permutation(uint32_t x, uint32_t seed) {
	x += seed;
	x ^= x * 0x6c50b47cu;
	x ^= x * 0xb82f1e52u;
	x ^= x * 0xc7afe638u;
	x ^= x * 0x8d22f6e6u;
	return x;
}

// Sobol's second dimension before the bit reversal: bit j of the result is the sum mod 2 over
// index bits k >= j of C(k, j) i_k, i.e. the coefficients of the polynomial i(t + 1) if bit k of i
// is the coefficient of t^k. (t + 1)^k is the product of (t^(2^m) + 1) over the bits m of k, so
// five shift-and-xor steps, one per bit m, expand it.
inline uint32_t pascal(uint32_t i) {
	i ^= (i & 0xaaaaaaaau) >> 1;
	i ^= (i & 0xccccccccu) >> 2;
	i ^= (i & 0xf0f0f0f0u) >> 4;
	i ^= (i & 0xff00ff00u) >> 8;
	i ^= (i & 0xffff0000u) >> 16;
	return i;
}

// The seeds of one dimension: the index shuffle's and one per coordinate.
struct Seeds {
	uint32_t shuffle, x, y;
};

// Point `index` of the scrambled sequence, as 32-bit fractions (value / 2^32), given the index
// already bit-reversed (computed once per pixel sample). The shuffled index is an Owen scramble
// of the index; scrambling reverse_bits(v) means reverse_bits(laine_karras_permutation(v)).
inline uint32_t shuffled_index(uint32_t reversed_index, uint32_t seed) {
	return reverse_bits(laine_karras_permutation(reversed_index, seed));
}
inline uint32_t dimension_0(uint32_t shuffled, uint32_t seed) {
	return reverse_bits(laine_karras_permutation(shuffled, seed));
}
inline uint32_t dimension_1(uint32_t shuffled, uint32_t seed) {
	return reverse_bits(laine_karras_permutation(pascal(shuffled), seed));
}

} // namespace owen_sobol
