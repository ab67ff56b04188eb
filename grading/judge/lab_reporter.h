#pragma once
// The judge's default reporter (lab_reporter.cpp): what a student reads of `./lab grade N`.
// `-r console` chooses Catch2's own instead.
extern const char* const LAB_REPORTER; // its name, for -r
