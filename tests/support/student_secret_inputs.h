#pragma once
// Inputs a submission cannot memorise (grading/judge/judge.h): with an instructor's grading seed a test
// case draws its inputs from a generator of its own; public runs keep the fixed public cases.
#include "rng.h"

#include <optional>
#include <string>

// The generator of `test_case`'s inputs under the grading seed, or none in a public run.
std::optional<RNG> secret_inputs(const std::string& test_case);

// `public_seed` in a public run, else a seed drawn from `secret` (for renders and generators).
uint64_t seed_or_public(std::optional<RNG>& secret, uint64_t public_seed);
