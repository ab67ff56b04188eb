#pragma once
// The rubric (rubric.json, kept by the instructors): how many points each task is worth and how they are split over
// its test cases. Format:
//
//   {"tasks": [{"task": 1, "points": 5,
//               "test_cases": [{"name": "<the judge's TEST_CASE name>", "weight": 2},
//                              {"name": "...", "weight": 1, "visibility": "after_published"}, ...]},
//              ...]}
//
// A test case is worth points * weight / (sum of its task's weights); it earns them when it passes.
// Weight 0 marks a requirement: a test case that earns nothing by itself because a program doing
// nothing passes it (the stubs' single-leaf BVH answers every ray right, "a scene without light
// renders black"), but that costs "penalty" points when it fails (default: what a weighted test case
// of its task is worth on average). A task scores max(0, earned - penalties): the shipped stubs score
// exactly 0, the reference full marks. "visibility" (Gradescope's words: visible, after_published,
// after_due_date, hidden; default visible) says when students see the test case. Every test case of
// every judge must be in the rubric, and nothing else.
#include "task_result.h"

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

struct Rubric_Error : std::runtime_error {
	using std::runtime_error::runtime_error;
};

struct Rubric {
	struct Test_Case {
		std::string name;
		double weight = 1.0;
		double penalty = -1.0; // a requirement's cost when it fails; < 0: the default
		std::string visibility = "visible";
	};
	struct Task {
		double points = 0.0;
		std::vector<Test_Case> test_cases;
		double total_weight() const;
		double penalty(const Test_Case& c) const; // 0 for a weighted test case
	};
	std::map<int, Task> tasks;

	static Rubric read(const std::filesystem::path& file); // throws Rubric_Error naming the problem
};

// One test case's score: max_score when it passed, 0 when it failed, or for a requirement 0 when it
// passed and -penalty when it failed.
struct Scored_Test_Case {
	std::string name, visibility, output;
	double score = 0.0, max_score = 0.0;
	bool passed = false;
};

struct Task_Score {
	int task = 0;
	double score = 0.0, max_score = 0.0;
	std::vector<Scored_Test_Case> test_cases;
};

// A rubric for the judges as they are: the default points per task (the course's split), and every
// test case of every task weighted 1, or 0 where the shipped stubs pass it (`stubs`: the seven tasks'
// results of grading the stubs). Instructors then edit weights and visibilities by hand.
void write_default_rubric(std::ostream& out, const std::vector<Task_Result>& stubs);

// A task's points from its result. Throws Rubric_Error if the judge has a test case the rubric does
// not know or the rubric names one the judge does not have (a task that did not build has none).
Task_Score score(const Rubric& rubric, const Task_Result& result);
