#pragma once
// The token network manager (paper, sections 3 and 4): timelines with their tokens, each
// token's start/end timepoints in the temporal network and parameter variables in the
// constraint network, and the decision operations a search engine uses:
//   insert a token into a slot of its timeline (between two tokens), merge it with a token
//   already there (codesignation), omit an optional goal, restrict a parameter domain, choose
//   which value of a disjunctive requirement a configuration constraint uses.
// Configuration constraints are instantiated automatically: once a token is placed and the
// constants of a schema's master pattern are decided, the schema's requirements with a single
// allowed value create their slave tokens at once (the paper's "third requirement needs no
// selection"); requirements with several values become flaws. Timelines may have gaps
// between tokens (the attribute's value is then unconstrained); a model that needs
// transitions says so with schemata (pointAt is reached by a turn, see examples/camera.model).
//
// Every operation is undone exactly by undo_to(mark()): the token network, the temporal
// network and the constraint network all return to the marked state (chronological undo).
#include <cstddef>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "constraint_network.hpp"
#include "domain_model.hpp"
#include "temporal_network.hpp"

namespace autonomy::planner {

using TokenId = std::size_t;
inline constexpr TokenId kNoToken = static_cast<TokenId>(-1);

struct Timeline {
  std::string name;  // object.attribute
  int object = -1, attribute = -1;
  std::vector<TokenId> sequence;  // placed tokens in time order
};

struct Token {
  enum class State { kFree, kPlaced, kMerged, kOmitted };
  int predicate = -1;
  std::size_t timeline = 0;
  TimepointId start = 0, end = 0;
  std::vector<VariableId> parameters;
  State state = State::kFree;
  TokenId merged_into = kNoToken;
  int fact = -1;              // the problem fact it stands for, or -1
  TokenId master = kNoToken;  // for slaves: the token whose configuration constraint made it
  pb::TemporalRelation::Kind relation = pb::TemporalRelation::BEFORE;  // slave's relation
  bool optional = false;
  double penalty = 0;
  Time min_duration = 0;
  VariableId duration = static_cast<VariableId>(-1);  // only when a constraint names it
  Time pushed_min = 0, pushed_max = kInfinity;        // duration bounds given to the TN
};

// One configuration constraint schema applied to one placed token.
struct SchemaInstance {
  TokenId token;
  int schema;
  std::vector<VariableId> bindings;  // one per schema variable
  std::vector<int> chosen;           // per requirement: the alternative used, -1 while open
};

struct Flaw {
  enum class Kind { kFreeToken, kOpenRequirement, kUnboundParameter, kResourceConflict } kind;
  TokenId token = kNoToken;
  std::size_t instance = 0, requirement = 0;
  VariableId variable = 0;
  bool blocks_schema = false;  // an unbound parameter a schema's applicability waits for
  // kResourceConflict: the tokens involved; for a reservoir, `token` is where the level leaves
  // its bounds and `reservoir_low` says which way.
  std::vector<TokenId> involved;
  bool reservoir = false, reservoir_low = false;
};

struct Decision {
  // kOrder: token's end no later than the start (or, with requirement == 1, the end) of
  // token `index`: how resource conflicts are resolved.
  enum class Kind { kInsert, kMerge, kOmit, kRestrict, kChoose, kOrder } kind;
  TokenId token = kNoToken;
  std::size_t index = 0;  // insert: position; merge: target token; choose: alternative
  std::size_t instance = 0, requirement = 0;
  VariableId variable = 0;
  Domain domain = Domain::real(0, 0);
  std::string describe() const;
};

class TokenNetwork {
 public:
  TokenNetwork(const DomainModel& model, const PlanningProblem& problem);

  // Creates the timelines and a token for every initial value and goal, with their bounds and
  // relations. False when the problem is inconsistent from the start (see conflict()).
  [[nodiscard]] bool initialize();
  // Explanation of the last failure: the statements (facts, schemata) involved.
  const std::string& conflict() const { return conflict_; }

  [[nodiscard]] bool apply(const Decision& d);
  std::vector<Flaw> flaws() const;
  // Resource conflicts: pairs of tokens that may overlap and together exceed a reusable
  // resource's capacity, peaks at the earliest times, reservoir levels out of bounds at the
  // earliest times (resolved by ordering tokens; see the report of issue 11 for what the
  // flexible plan then guarantees).
  std::vector<Flaw> resource_flaws() const;
  std::vector<Decision> options(const Flaw& f) const;

  // Upper bound on every token's end (the objective's bound), part of the temporal network.
  [[nodiscard]] bool bound_makespan(Time ub);
  TimepointId makespan_timepoint() const { return makespan_; }
  double omitted_penalty() const;

  struct Mark {
    TemporalNetwork::Mark tn;
    ConstraintNetwork::Mark cn;
    std::size_t trail, tokens, instances;
  };
  Mark mark() const;
  void undo_to(const Mark& m);

  const DomainModel& model() const { return model_; }
  const PlanningProblem& problem() const { return problem_; }
  const std::vector<Timeline>& timelines() const { return timelines_; }
  const std::vector<Token>& tokens() const { return tokens_; }
  const std::vector<SchemaInstance>& instances() const { return instances_; }
  const TemporalNetwork& temporal() const { return tn_; }
  const ConstraintNetwork& constraints() const { return cn_; }
  std::string token_text(TokenId t) const;  // "dsone.camera == picture(asteroid)"
  std::string parameter_text(TokenId t, std::size_t i) const;
  // Token could take the pattern's values (predicate and constants), as far as domains tell.
  bool may_merge(TokenId a, TokenId b) const;
  // Initial values are the given state: configuration constraints are not applied to them
  // (what led to them lies before the horizon).
  bool is_initial(TokenId t) const;

  std::size_t decisions_applied() const { return decisions_; }

  // Conflict-directed backjumping (search/backjumping.cpp) needs to know why an apply() failed.
  // With explanations on, a failure in the temporal network names the constraints of one
  // negative cycle exactly (a Bellman-Ford pass, only on failure); failed_cycle() is then that
  // cycle (TemporalNetwork::kHorizonConstraint for the implicit horizon), and null when the
  // last apply() failed elsewhere (parameters, overload, ...) or explanations are off.
  void set_explain_conflicts(bool on) {
    explain_ = on;
    tn_.set_explain_conflicts(on);
  }
  const std::vector<TemporalConstraintId>* failed_cycle() const {
    return cycle_valid_ ? &cycle_ : nullptr;
  }

  // Asked during parameter propagation (a deadline, a cancellation): true ends it as a failure
  // that interrupted() marks, so that no search takes it for a proof.
  void set_stop(std::function<bool()> stop) { cn_.set_stop(std::move(stop)); }
  bool interrupted() const { return interrupted_; }

  // Not-first/not-last on every timeline beside edge finding (not_first_last.hpp); off by
  // default: at O(n^3) a propagation it costs more search time than its pruning saves on the
  // job-shop instances measured (docs/planner-search.md). Set before initialize().
  void set_not_first_not_last(bool on) { not_first_not_last_ = on; }

 private:
  TokenId new_token(std::size_t timeline, int predicate);
  bool setup_token(TokenId t, const std::string& why);
  bool add_temporal(TimepointId from, TimepointId to, Time lb, Time ub, const std::string& why);
  bool relate(TokenId master, TokenId slave, pb::TemporalRelation::Kind kind, Time lb, Time ub,
              const std::string& why);
  bool propagate_constraints(const std::string& why);
  bool insert(TokenId t, std::size_t position);
  bool merge(TokenId t, TokenId target);
  bool choose(std::size_t instance, std::size_t requirement, std::size_t alternative);
  // Instantiates applicable schemata of placed tokens and resolves single-value requirements.
  bool settle();
  enum class Applies { kYes, kNo, kUndecided };
  Applies applies(TokenId t, const ValuePatternDef& master, VariableId* undecided) const;
  bool exclusion_propagation();  // overload and detectable precedences on each timeline
  void on_undo(std::function<void()> f) { trail_.push_back(std::move(f)); }

  const DomainModel& model_;
  const PlanningProblem& problem_;
  TemporalNetwork tn_;
  ConstraintNetwork cn_;
  std::vector<Timeline> timelines_;
  std::vector<Token> tokens_;
  std::vector<SchemaInstance> instances_;
  std::vector<std::vector<int>> instantiated_;  // per token: schemata already applied (or not)
  std::vector<std::function<void()>> trail_;
  std::set<std::pair<TokenId, TokenId>> precedences_;  // inferred by exclusion_propagation
  std::vector<std::string> temporal_reasons_;          // per temporal constraint id: the statement
  TimepointId makespan_ = 0;
  std::string conflict_;
  std::size_t decisions_ = 0;
  bool interrupted_ = false;
  bool not_first_not_last_ = false;
  bool explain_ = false;
  bool cycle_valid_ = false;  // the last apply() failed at cycle_ (see failed_cycle())
  std::vector<TemporalConstraintId> cycle_;
};

}  // namespace autonomy::planner
