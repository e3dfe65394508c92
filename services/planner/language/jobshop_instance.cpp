#include "jobshop_instance.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>

#include "domain_model.hpp"

namespace autonomy::planner {

std::string jobshop_label(int job, int operation) {
  return "j" + std::to_string(job) + "_o" + std::to_string(operation);
}

namespace {

// One whitespace-separated field of a line and the column it starts at.
struct Field {
  std::string_view text;
  unsigned column;
};

std::vector<Field> fields_of(std::string_view line) {
  std::vector<Field> out;
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    out.push_back({line.substr(i, j - i), unsigned(i + 1)});
    i = j;
  }
  return out;
}

// A decimal integer filling the whole field, or nothing (also when it overflows).
std::optional<long> integer_of(std::string_view text) {
  long value = 0;
  const char* first = text.data();
  if (!text.empty() && text[0] == '+') ++first;
  auto [end, error] = std::from_chars(first, text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || first == text.data() + text.size())
    return std::nullopt;
  return value;
}

}  // namespace

std::optional<JobShopInstance> parse_jobshop(std::string_view text, const std::string& file,
                                             Diagnostics* errors) {
  JobShopInstance inst;
  inst.file = file;
  // A UTF-8 byte-order mark is not part of the instance.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  unsigned number = 0;
  bool header = false;
  // The sum of all durations is the problem's horizon: it must stay below the temporal
  // network's "no bound" (2^52), and adding them must not overflow.
  long total = 0;
  auto fail = [&](unsigned column, const std::string& message) {
    errors->push_back({file, number, column, message});
    return std::nullopt;
  };
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t eol = text.find('\n', at);
    if (eol == std::string_view::npos) eol = text.size();
    const std::string_view line = text.substr(at, eol - at);
    at = eol + 1;
    ++number;
    std::vector<Field> fields = fields_of(line);
    if (fields.empty() || fields[0].text[0] == '#') continue;
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (fields[k].text[0] == '#') {  // a comment to the end of the line
        fields.resize(k);
        break;
      }
    }
    if (!header) {
      std::optional<long> jobs, machines;
      if (fields.size() >= 1) jobs = integer_of(fields[0].text);
      if (fields.size() >= 2) machines = integer_of(fields[1].text);
      if (!jobs || *jobs <= 0 || *jobs > 100000)
        return fail(fields.empty() ? 1 : fields[0].column,
                    "expected 'jobs machines' (two integers, 1 to 100000)");
      if (!machines || *machines <= 0 || *machines > 100000)
        return fail(fields.size() < 2 ? unsigned(line.size() + 1) : fields[1].column,
                    "expected 'jobs machines' (two integers, 1 to 100000)");
      if (fields.size() > 2) return fail(fields[2].column, "expected the end of the header line");
      inst.jobs = int(*jobs);
      inst.machines = int(*machines);
      inst.header_line = number;
      header = true;
      continue;
    }
    if (int(inst.operations.size()) == inst.jobs)
      return fail(fields[0].column,
                  "more job lines than the " + std::to_string(inst.jobs) + " declared");
    std::vector<std::pair<int, long>> ops;
    for (std::size_t k = 0; k < fields.size(); k += 2) {
      const std::optional<long> machine = integer_of(fields[k].text);
      if (!machine)
        return fail(fields[k].column, "expected a machine number (machine duration pairs)");
      if (k + 1 == fields.size())
        return fail(unsigned(line.size() + 1), "a machine without a duration");
      const std::optional<long> duration = integer_of(fields[k + 1].text);
      if (!duration) return fail(fields[k + 1].column, "expected a duration (an integer)");
      if (*machine < 0 || *machine >= inst.machines)
        return fail(fields[k].column, "machine " + std::string(fields[k].text) +
                                          " out of range 0.." + std::to_string(inst.machines - 1));
      if (*duration < 0) return fail(fields[k + 1].column, "negative duration");
      if (*duration >= kNoBound - total)
        return fail(fields[k + 1].column,
                    "the durations add up to 2^52 ticks or more (the horizon's limit)");
      total += *duration;
      ops.emplace_back(int(*machine), *duration);
    }
    if (int(ops.size()) != inst.machines)
      return fail(1, "job " + std::to_string(inst.operations.size()) + " has " +
                         std::to_string(ops.size()) + " operations, expected " +
                         std::to_string(inst.machines));
    inst.operations.push_back(std::move(ops));
    inst.job_lines.push_back(number);
  }
  number = std::max(number, 1u);
  if (!header) return fail(1, "empty instance: expected 'jobs machines'");
  if (int(inst.operations.size()) != inst.jobs)
    return fail(1, "expected " + std::to_string(inst.jobs) + " job lines, found " +
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
  p.set_horizon(total);  // all operations in a row always fit (below 2^52: parse_jobshop)
  // The horizon comes from the whole file; its errors point at the header line.
  p.mutable_location()->set_file(inst.file);
  p.mutable_location()->set_line(inst.header_line);
  p.mutable_location()->set_column(1);
  p.set_objective(pb::Problem::MAKESPAN);
  return p;
}

}  // namespace autonomy::planner
