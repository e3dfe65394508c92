#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <random>

#include "constraint_network.hpp"
#include "procedures.hpp"

namespace autonomy::planner {
namespace {

TEST(Domain, IntervalsSetsAndTheirIntersections) {
  Domain d = Domain::integer(0.5, 7.2);
  EXPECT_EQ(d.lo(), 1);
  EXPECT_EQ(d.hi(), 7);
  EXPECT_EQ(d.size(), 7);
  EXPECT_TRUE(d.intersect(Domain::values({0, 3, 5, 9})));
  ASSERT_TRUE(d.is_set());
  EXPECT_EQ(d.set_values(), (std::vector<std::int64_t>{3, 5}));
  EXPECT_TRUE(d.remove(3));
  EXPECT_TRUE(d.is_singleton());
  Domain r = Domain::real(0, 10);
  EXPECT_FALSE(r.restrict_bounds(-1, 11));
  EXPECT_TRUE(r.restrict_bounds(2.5, 3));
  EXPECT_EQ(r.lo(), 2.5);
  EXPECT_TRUE(r.restrict_bounds(4, 5));
  EXPECT_TRUE(r.empty());
}

TEST(ConstraintNetwork, RecordPropagatesEveryWay) {
  // record(s, r, d, e): s + r*d = e with s in [0, 100], r = 2, d in [0, 30], e <= 50.
  ConstraintNetwork n;
  VariableId s = n.add_variable(Domain::real(0, 100), "s");
  VariableId r = n.add_variable(Domain::real(2, 2), "r");
  VariableId d = n.add_variable(Domain::real(0, 30), "d");
  VariableId e = n.add_variable(Domain::real(0, 50), "e");
  n.add_constraint(make_sum_product(s, r, d, e));
  ASSERT_TRUE(n.propagate());
  EXPECT_DOUBLE_EQ(n.domain(s).hi(), 50);
  EXPECT_DOUBLE_EQ(n.domain(d).hi(), 25);
  auto m = n.mark();
  ASSERT_TRUE(n.narrow_bounds(s, 40, 40));
  ASSERT_TRUE(n.propagate());
  EXPECT_DOUBLE_EQ(n.domain(d).hi(), 5);
  EXPECT_DOUBLE_EQ(n.domain(e).lo(), 40);
  ASSERT_TRUE(n.narrow_bounds(d, 5, 5));
  ASSERT_TRUE(n.propagate());
  EXPECT_TRUE(n.domain(e).is_singleton());
  EXPECT_DOUBLE_EQ(n.domain(e).lo(), 50);
  n.undo_to(m);
  EXPECT_DOUBLE_EQ(n.domain(s).hi(), 50);
  EXPECT_DOUBLE_EQ(n.domain(s).lo(), 0);
  EXPECT_DOUBLE_EQ(n.domain(d).hi(), 25);
}

TEST(ConstraintNetwork, InconsistencyNamesTheFailingProcedureAndUndoRecovers) {
  ConstraintNetwork n;
  VariableId a = n.add_variable(Domain::values({1, 2}));
  VariableId b = n.add_variable(Domain::values({1, 2}));
  VariableId c = n.add_variable(Domain::values({1, 2}));
  n.add_constraint(make_not_equal(a, b));
  n.add_constraint(make_not_equal(b, c));
  ConstraintId ac = n.add_constraint(make_equal(a, c));
  ASSERT_TRUE(n.propagate());
  auto m = n.mark();
  ConstraintId last = n.add_constraint(make_not_equal(a, c));
  ASSERT_TRUE(n.propagate());  // arc consistency alone does not see the odd cycle...
  ASSERT_TRUE(n.narrow(a, Domain::singleton(1)));
  PropagationResult r = n.propagate();  // ...but once a is assigned it does
  EXPECT_FALSE(r);
  EXPECT_TRUE(r.failed == last || r.failed == ac) << r.failed;
  n.undo_to(m);
  EXPECT_EQ(n.constraint_count(), 3u);
  ASSERT_TRUE(n.narrow(a, Domain::singleton(1)));
  ASSERT_TRUE(n.propagate());
  EXPECT_EQ(n.domain(c).set_values(), std::vector<std::int64_t>{1});
  EXPECT_EQ(n.domain(b).set_values(), std::vector<std::int64_t>{2});
  EXPECT_GT(n.statistics().procedure_calls, 0u);
}

// Brute force: on random small integer domains no procedure removes a value that belongs to an
// allowed assignment, and on singletons it refuses exactly the disallowed ones.
struct Case {
  const char* name;
  int arity;
  std::function<std::unique_ptr<ConstraintProcedure>(const std::vector<VariableId>&)> make;
  std::function<bool(const std::vector<std::int64_t>&)> allowed;
};

TEST(ConstraintProcedures, NeverRemoveAnAllowedValue) {
  std::vector<Case> cases = {
      {"equal", 2, [](auto& v) { return make_equal(v[0], v[1]); },
       [](auto& x) { return x[0] == x[1]; }},
      {"not_equal", 2, [](auto& v) { return make_not_equal(v[0], v[1]); },
       [](auto& x) { return x[0] != x[1]; }},
      {"less_equal", 2, [](auto& v) { return make_less_equal(v[0], v[1], 2); },
       [](auto& x) { return x[0] + 2 <= x[1]; }},
      {"linear", 3,
       [](auto& v) {
         return make_linear_equal({v[0], v[1], v[2]}, {1, -2, 3}, 4);
       },
       [](auto& x) { return x[0] - 2 * x[1] + 3 * x[2] == 4; }},
      {"sum_product", 4, [](auto& v) { return make_sum_product(v[0], v[1], v[2], v[3]); },
       [](auto& x) { return x[0] + x[1] * x[2] == x[3]; }},
      {"member", 1,
       [](auto& v) {
         return make_member(v[0], {-1, 2, 3});
       },
       [](auto& x) { return x[0] == -1 || x[0] == 2 || x[0] == 3; }},
      {"table", 3,
       [](auto& v) {
         return make_table({v[0], v[1], v[2]}, {{0, 1, 4}, {1, 0, 4}, {2, -1, 3}, {-3, 2, 0}});
       },
       [](auto& x) {
         return (x[0] == 0 && x[1] == 1 && x[2] == 4) || (x[0] == 1 && x[1] == 0 && x[2] == 4) ||
                (x[0] == 2 && x[1] == -1 && x[2] == 3) || (x[0] == -3 && x[1] == 2 && x[2] == 0);
       }},
  };
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> value(-3, 4), count(1, 4), coin(0, 1);
  int pruned = 0;
  for (const Case& c : cases) {
    for (int round = 0; round < 300; ++round) {
      ConstraintNetwork n;
      std::vector<VariableId> vars;
      for (int i = 0; i < c.arity; ++i) {
        std::vector<std::int64_t> vals;
        int k = count(rng);
        for (int j = 0; j < k; ++j) vals.push_back(value(rng));
        Domain d =
            coin(rng) ? Domain::values(vals) : Domain::integer(vals.front(), vals.front() + k - 1);
        vars.push_back(n.add_variable(d));
      }
      std::vector<Domain> before;
      for (VariableId v : vars) before.push_back(n.domain(v));
      n.add_constraint(c.make(vars));
      bool ok = bool(n.propagate());
      // Enumerate every assignment of the original domains.
      std::vector<std::vector<std::int64_t>> values;
      for (const Domain& d : before) {
        std::vector<std::int64_t> vs;
        for (int v = -3; v <= 7; ++v)
          if (d.contains(v)) vs.push_back(v);
        values.push_back(vs);
      }
      std::vector<std::size_t> index(c.arity, 0);
      bool any_allowed = false;
      while (true) {
        std::vector<std::int64_t> x;
        for (int i = 0; i < c.arity; ++i) x.push_back(values[i][index[i]]);
        if (c.allowed(x)) {
          any_allowed = true;
          ASSERT_TRUE(ok) << c.name << " refused a network with an allowed assignment";
          for (int i = 0; i < c.arity; ++i)
            ASSERT_TRUE(n.domain(vars[i]).contains(double(x[i])))
                << c.name << " removed " << x[i] << " of an allowed assignment";
        }
        int i = 0;
        while (i < c.arity && ++index[i] == values[i].size()) index[i++] = 0;
        if (i == c.arity) break;
      }
      if (!any_allowed) ++pruned;
    }
    // Singleton checks.
    for (int round = 0; round < 200; ++round) {
      ConstraintNetwork n;
      std::vector<VariableId> vars;
      std::vector<std::int64_t> x;
      for (int i = 0; i < c.arity; ++i) {
        x.push_back(value(rng));
        vars.push_back(n.add_variable(Domain::singleton(x.back())));
      }
      n.add_constraint(c.make(vars));
      EXPECT_EQ(bool(n.propagate()), c.allowed(x)) << c.name;
    }
  }
  EXPECT_GT(pruned, 0);
}

// a < b, b < a on a range of 2^52 (issue 29): bounds propagation alone would move each bound
// by one per call; the cycle of differences is found after a few thousand calls instead, for
// integers and reals, and through equalities.
TEST(ConstraintNetwork, ACycleOfStrictInequalitiesIsFoundInsteadOfStepped) {
  for (bool integer : {true, false}) {
    for (bool through_equal : {false, true}) {
      ConstraintNetwork n;
      const double big = 4503599627370496.0;
      auto domain = [&] { return integer ? Domain::integer(0, big) : Domain::real(0, big); };
      VariableId a = n.add_variable(domain(), "a"), b = n.add_variable(domain(), "b");
      VariableId c = n.add_variable(domain(), "c");
      const double step = integer ? 1 : 1e-6;
      ConstraintId ab = n.add_constraint(make_less_equal(a, b, step));
      ConstraintId bc = n.add_constraint(through_equal ? make_equal(b, c)
                                                       : make_less_equal(b, c, 0));
      ConstraintId ca = n.add_constraint(make_less_equal(c, a, through_equal ? 0 : step));
      auto m = n.mark();
      PropagationResult r = n.propagate();
      EXPECT_FALSE(r);
      EXPECT_FALSE(r.interrupted);
      std::vector<ConstraintId> cycle = r.cycle;
      std::sort(cycle.begin(), cycle.end());
      EXPECT_EQ(cycle, (std::vector<ConstraintId>{ab, bc, ca}));
      EXPECT_LT(n.statistics().procedure_calls, 10000u);
      n.undo_to(m);
      EXPECT_EQ(n.domain(a).hi(), big);
      EXPECT_EQ(n.domain(c).lo(), 0);
    }
  }
  // A cycle whose offsets add up to 0 is satisfiable: propagation ends consistent.
  ConstraintNetwork n;
  VariableId a = n.add_variable(Domain::integer(0, 1e9)), b = n.add_variable(Domain::integer(5, 7));
  n.add_constraint(make_less_equal(a, b, 0));
  n.add_constraint(make_less_equal(b, a, 0));
  ASSERT_TRUE(n.propagate());
  EXPECT_EQ(n.domain(a).lo(), 5);
  EXPECT_EQ(n.domain(a).hi(), 7);
}

// A propagation that steps without a cycle of differences (two linear equalities that cannot
// both hold) ends when the stop condition says so, and its trail does not grow with its steps.
TEST(ConstraintNetwork, StopEndsALongPropagationWhoseTrailStaysSmall) {
  ConstraintNetwork n;
  const double big = 1e12;
  VariableId a = n.add_variable(Domain::integer(0, big)), b = n.add_variable(Domain::integer(0, big));
  n.add_constraint(make_linear_equal({a, b}, {1, -1}, 1));   // a = b + 1
  n.add_constraint(make_linear_equal({a, b}, {1, -1}, -1));  // a = b - 1
  int asked = 0;
  n.set_stop([&] { return ++asked > 100; });
  auto m = n.mark();
  PropagationResult r = n.propagate();
  EXPECT_FALSE(r);
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(asked, 101);
  EXPECT_GT(n.statistics().narrowings, 20000u);
  EXPECT_LE(n.mark().trail - m.trail, 2u);  // each variable trailed once since the mark
  n.undo_to(m);
  EXPECT_EQ(n.domain(a).lo(), 0);
  EXPECT_EQ(n.domain(b).hi(), big);
}

}  // namespace
}  // namespace autonomy::planner
