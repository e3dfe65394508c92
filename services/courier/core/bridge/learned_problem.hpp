#pragma once
// What experience taught, applied to a scheduling problem built from the office file
// (engine_schedule_source): expected instead of nominal handover times; a person's presence
// windows without the half hours their door is usually closed or they are usually away (so a
// job into a room usually closed at that hour is planned for later in the day by expected
// lateness, or comes back unschedulable and goes to the opportunistic list); learned travel
// times between places where a route exists. A door seen open lately overrules its habit.
#include <map>
#include <set>
#include <string>

#include "services/courier/core/execution/floor.hpp"
#include "services/courier/core/knowledge/experience.hpp"
#include "services/courier/core/scheduler/scheduling_problem.hpp"

namespace autonomy::courier {

// Changes `problem` in place; its first `places` locations are the floor's places by name.
// Returns, per person whose presence was cut, what was learned ("A-120 usually closed
// 10:00-11:00"), for the reasons of jobs that became unschedulable. With doors believed closed
// (`detours`) the problem's travel times go around them, longer than the drives learned through
// them: a learned time then only lengthens an estimate, never shortens a detour.
std::map<std::string, std::string> apply_experience(const Experience& experience, const Floor& floor,
                                                    const std::set<std::string>& doors_seen_open, bool detours,
                                                    std::size_t places, scheduling::SchedulingProblem& problem);

}  // namespace autonomy::courier
