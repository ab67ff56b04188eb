#pragma once
// The rubric (rubric.json, kept by the instructors): how many points each task is worth and how they are split over
// its test cases. Format:
//
//   {"tasks": [{"task": 1, "points": 5,
//               "test_cases": [{"id": "t1.ray.centre", "title": "generate_ray: the centre of ...", "weight": 2},
//                              {"id": "...", "weight": 1, "visibility": "after_published"}, ...]},
//              ...]}
//
// A test case is named by its id, the tag [id:ID] of the judge's TEST_CASE (cmake/test_case_ids.cmake),
// which stays when its title is reworded; "title" is only a reminder for the reader (grading
// ignores it; `rubric --update`, an instructors' command of ./lab, refreshes it).
// A test case is worth points * weight / (sum of its task's weights); it earns them when it passes.
// Weight 0 marks a requirement: a test case that earns nothing by itself because a program doing
// nothing passes it (the stubs' single-leaf BVH answers every ray right, "a scene without light
// renders black"), but that costs "penalty" points when it fails (default: what a weighted test case
// of its task is worth on average). A task scores max(0, earned - penalties): the shipped stubs score
// exactly 0, the reference full marks. "visibility" (Gradescope's words: visible, after_published,
// after_due_date, hidden; default visible) says when students see the test case. Every test case of
// every judge of tasks 1-8 must be in the rubric, and nothing else (checked when the build is
// configured, and again when grading).
#include "task_result.h"

#include <filesystem>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

struct Rubric_Error : std::runtime_error {
	using std::runtime_error::runtime_error;
};

struct Rubric {
	struct Test_Case {
		std::string id;
		std::string title; // informational: what the test case was called when the rubric was written
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
	std::string id;
	std::string name; // the judge's title of the test case (the rubric's title if the judge did not run)
	std::string visibility, output;
	double score = 0.0, max_score = 0.0;
	bool passed = false;
};

struct Task_Score {
	int task = 0;
	double score = 0.0, max_score = 0.0;
	std::vector<Scored_Test_Case> test_cases;
};

// A rubric for the judges as they are: the default points per task (the course's split), and every
// test case of every task weighted 1, or 0 where the shipped stubs pass it (`stubs`: the tasks'
// results of grading the stubs). Instructors then edit weights and visibilities by hand.
void write_default_rubric(std::ostream& out, const std::vector<Task_Result>& stubs);

// A rubric brought up to date with the judges as they are (`rubric --update` in ./lab): each task keeps its
// points and each test case whose id a judge still has keeps its weight and every other field (its
// title becomes the judge's); a test case new to the rubric gets weight 1; one that no judge has any
// longer is dropped. A rubric from before the ids (test cases named by "name", their title) is
// converted: an entry takes the id of the test case of that title. `changes`: one line per test case
// added or dropped. `stubs` as for write_default_rubric, whose results say which new test cases the
// stubs pass (a hint: weight 0 would make them requirements).
struct Rubric_Update {
	std::string text; // the updated rubric, JSON
	std::vector<std::string> changes;
};
Rubric_Update update_rubric(const std::filesystem::path& file, const std::vector<Task_Result>& stubs);

// A task's points from its result, matched by id. Throws Rubric_Error if the judge has a test case
// the rubric does not know, or one without an id, or the rubric names one the judge does not have (a
// task that did not build has none).
Task_Score score(const Rubric& rubric, const Task_Result& result);
