// What the courier believes of its objects, from its jobs: one object is in one open job at a
// time, and where an object lies follows the deliveries and returns of the jobs that moved it.
#include "services/courier/core/execution/courier_executive.hpp"

#include <cstdlib>

namespace autonomy::courier {

namespace {

// Jobs are numbered as they are accepted ("job-12"): the higher number is the later job. Ids of
// another form (restored from elsewhere) order after the numbered ones, by name.
bool accepted_before(const Job& a, const Job& b) {
  if (a.accepted_at_s != b.accepted_at_s) return a.accepted_at_s < b.accepted_at_s;
  const auto number = [](const std::string& id) {
    return id.rfind("job-", 0) == 0 ? std::strtol(id.c_str() + 4, nullptr, 10) : 0L;
  };
  if (number(a.id) != number(b.id)) return number(a.id) < number(b.id);
  return a.id < b.id;
}

}  // namespace

const Job* CourierExecutive::open_job_of_object(const std::string& object_id) const {
  for (const auto& [id, job] : jobs_)
    if (!job.finished() && job.object.id == object_id) return &job;
  return nullptr;
}

std::map<std::string, CourierExecutive::ObjectWhereabouts> CourierExecutive::object_whereabouts() const {
  std::map<std::string, const Job*> latest;
  for (const auto& [id, job] : jobs_) {
    const Job*& known = latest[job.object.id];
    // An open job's belief wins over any finished one; among finished jobs the latest.
    if (!known || (!job.finished() && known->finished()) ||
        (job.finished() == known->finished() && accepted_before(*known, job)))
      known = &job;
  }
  std::map<std::string, ObjectWhereabouts> out;
  for (const auto& [object, job] : latest) out[object] = {job->object_place, job->object_carrier, job->id};
  return out;
}

}  // namespace autonomy::courier
