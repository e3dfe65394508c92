#include "jobshop_instance.hpp"

#include <sstream>

#include "domain_model.hpp"

namespace autonomy::planner {

std::string jobshop_label(int job, int operation) {
  return "j" + std::to_string(job) + "_o" + std::to_string(operation);
}

std::optional<JobShopInstance> parse_jobshop(std::string_view text, const std::string& file,
                                             Diagnostics* errors) {
  JobShopInstance inst;
  inst.file = file;
  std::istringstream in{std::string(text)};
  std::string line;
  unsigned number = 0;
  bool header = false;
  auto fail = [&](const std::string& message) {
    errors->push_back({file, number, 1, message});
    return std::nullopt;
  };
  while (std::getline(in, line)) {
    ++number;
    auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    if (!header) {
      if (!(fields >> inst.jobs >> inst.machines) || inst.jobs <= 0 || inst.machines <= 0)
        return fail("expected 'jobs machines' (two positive integers)");
      header = true;
      continue;
    }
    if (int(inst.operations.size()) == inst.jobs)
      return fail("more job lines than the " + std::to_string(inst.jobs) + " declared");
    std::vector<std::pair<int, long>> ops;
    int machine;
    long duration;
    while (fields >> machine) {
      if (!(fields >> duration)) return fail("a machine without a duration");
      if (machine < 0 || machine >= inst.machines)
        return fail("machine " + std::to_string(machine) + " out of range 0.." +
                    std::to_string(inst.machines - 1));
      if (duration < 0) return fail("negative duration");
      ops.emplace_back(machine, duration);
    }
    if (!fields.eof()) return fail("expected integers (machine duration pairs)");
    if (int(ops.size()) != inst.machines)
      return fail("job " + std::to_string(inst.operations.size()) + " has " +
                  std::to_string(ops.size()) + " operations, expected " +
                  std::to_string(inst.machines));
    inst.operations.push_back(std::move(ops));
    inst.job_lines.push_back(number);
  }
  if (!header) return fail("empty instance");
  if (int(inst.operations.size()) != inst.jobs)
    return fail("expected " + std::to_string(inst.jobs) + " job lines, found " +
                std::to_string(inst.operations.size()));
  return inst;
}

pb::Model jobshop_model(const JobShopInstance& inst) {
  pb::Model m;
  m.set_name("jobshop");
  pb::Predicate* op = m.add_predicates();
  op->set_name("op");
  for (auto [name, ub] : {std::pair{"job", inst.jobs - 1}, std::pair{"index", inst.machines - 1}}) {
    pb::Parameter* p = op->add_parameters();
    p->set_name(name);
    p->mutable_type()->set_kind(pb::ParameterType::INTEGER);
    p->mutable_type()->set_lb(0);
    p->mutable_type()->set_ub(ub);
  }
  op->mutable_duration()->set_lb(0);
  op->mutable_duration()->set_ub(kNoBound);
  pb::ModelClass* machine = m.add_classes();
  machine->set_name("Machine");
  pb::Attribute* busy = machine->add_attributes();
  busy->set_name("busy");
  busy->add_values("op");
  return m;
}

pb::Problem jobshop_problem(const JobShopInstance& inst) {
  pb::Problem p;
  p.set_name("jobshop");
  long total = 0;
  for (int k = 0; k < inst.machines; ++k) {
    pb::ObjectDeclaration* o = p.add_objects();
    o->set_name("m" + std::to_string(k));
    o->set_class_name("Machine");
  }
  for (int j = 0; j < inst.jobs; ++j) {
    for (int k = 0; k < inst.machines; ++k) {
      auto [machine, duration] = inst.operations[j][k];
      total += duration;
      pb::Fact* g = p.add_goals();
      g->set_label(jobshop_label(j, k));
      g->set_object("m" + std::to_string(machine));
      g->set_attribute("busy");
      g->set_predicate("op");
      g->add_arguments()->set_number(j);
      g->add_arguments()->set_number(k);
      g->mutable_duration()->set_lb(duration);
      g->mutable_duration()->set_ub(duration);
      if (std::size_t(j) < inst.job_lines.size()) {
        g->mutable_location()->set_file(inst.file);
        g->mutable_location()->set_line(inst.job_lines[j]);
        g->mutable_location()->set_column(1);
      }
      if (k > 0) {
        pb::FactRelation* r = p.add_relations();
        r->set_from(jobshop_label(j, k - 1));
        r->set_to(jobshop_label(j, k));
        r->mutable_relation()->set_kind(pb::TemporalRelation::BEFORE);
        r->mutable_relation()->mutable_bounds()->set_lb(0);
        r->mutable_relation()->mutable_bounds()->set_ub(kNoBound);
        if (std::size_t(j) < inst.job_lines.size()) *r->mutable_location() = g->location();
      }
    }
  }
  p.set_horizon(total);  // all operations in a row always fit
  p.set_objective(pb::Problem::MAKESPAN);
  return p;
}

}  // namespace autonomy::planner
