#pragma once
// Objects answered elsewhere. To count the objects a BVH traversal tests, a grader gives the code
// under test only the objects' boxes (Instances without their shapes) and answers each
// Instance::hit itself, counting the questions: while an Object_Answers is set on a thread,
// Instance::hit there asks it instead of intersecting the shape.
#include "ray.h"
#include "trace.h"

#include <cstdint>
#include <utility>

struct Object_Answers {
	// The hit of the object whose Instance::index is `object` with `ray`, in world space.
	virtual Trace hit(uint32_t object, const Ray& ray) const = 0;

	// The answers for this thread's Instance::hit calls while `answers` is alive.
	class Scope {
	public:
		explicit Scope(const Object_Answers& answers) : previous(std::exchange(current, &answers)) {
		}
		~Scope() {
			current = previous;
		}
		Scope(const Scope&) = delete;
		Scope& operator=(const Scope&) = delete;

	private:
		const Object_Answers* previous;
	};

	static const Object_Answers* on_this_thread() {
		return current;
	}

protected:
	~Object_Answers() = default;

private:
	static inline thread_local const Object_Answers* current = nullptr;
};
