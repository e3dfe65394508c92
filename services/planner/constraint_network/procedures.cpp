#include "procedures.hpp"

#include <algorithm>
#include <cmath>

namespace autonomy::planner {

namespace {

class Procedure : public ConstraintProcedure {
 public:
  explicit Procedure(std::vector<VariableId> scope) : scope_(std::move(scope)) {}
  const std::vector<VariableId>& scope() const override { return scope_; }

 protected:
  std::vector<VariableId> scope_;
};

class Equal final : public Procedure {
 public:
  Equal(VariableId a, VariableId b) : Procedure({a, b}) {}
  bool propagate(ConstraintNetwork& n) override {
    Domain a = n.domain(scope_[0]);
    return n.narrow(scope_[0], n.domain(scope_[1])) && n.narrow(scope_[1], a);
  }
  std::string name() const override { return "equal"; }
  void differences(std::vector<DifferenceEdge>* out) const override {
    out->push_back({scope_[0], scope_[1], 0});
    out->push_back({scope_[1], scope_[0], 0});
  }
};

class NotEqual final : public Procedure {
 public:
  NotEqual(VariableId a, VariableId b) : Procedure({a, b}) {}
  bool propagate(ConstraintNetwork& n) override {
    for (int i = 0; i < 2; ++i) {
      const Domain& x = n.domain(scope_[i]);
      if (x.is_singleton() && x.is_integer()) {
        if (!n.remove_value(scope_[1 - i], std::int64_t(x.lo()))) return false;
      }
    }
    const Domain &a = n.domain(scope_[0]), &b = n.domain(scope_[1]);
    // Two equal real points are the only real case that can be refused.
    return !(a.is_singleton() && b.is_singleton() && std::abs(a.lo() - b.lo()) < 1e-9);
  }
  std::string name() const override { return "not_equal"; }
};

class LessEqual final : public Procedure {
 public:
  LessEqual(VariableId a, VariableId b, double offset) : Procedure({a, b}), offset_(offset) {}
  bool propagate(ConstraintNetwork& n) override {
    return n.narrow_bounds(scope_[1], n.domain(scope_[0]).lo() + offset_, HUGE_VAL) &&
           n.narrow_bounds(scope_[0], -HUGE_VAL, n.domain(scope_[1]).hi() - offset_);
  }
  std::string name() const override { return "less_equal"; }
  void differences(std::vector<DifferenceEdge>* out) const override {
    out->push_back({scope_[0], scope_[1], offset_});
  }

 private:
  double offset_;
};

class LinearEqual final : public Procedure {
 public:
  LinearEqual(std::vector<VariableId> vars, std::vector<double> coefficients, double constant)
      : Procedure(std::move(vars)), c_(std::move(coefficients)), k_(constant) {}
  bool propagate(ConstraintNetwork& n) override {
    // Bounds consistency: each term lies within k minus the others' extreme sums.
    for (int pass = 0; pass < 3; ++pass) {
      double lo_sum = 0, hi_sum = 0;
      for (std::size_t i = 0; i < scope_.size(); ++i) {
        const Domain& d = n.domain(scope_[i]);
        lo_sum += c_[i] > 0 ? c_[i] * d.lo() : c_[i] * d.hi();
        hi_sum += c_[i] > 0 ? c_[i] * d.hi() : c_[i] * d.lo();
      }
      bool changed = false;
      for (std::size_t i = 0; i < scope_.size(); ++i) {
        if (c_[i] == 0) continue;
        const Domain& d = n.domain(scope_[i]);
        double term_lo = c_[i] > 0 ? c_[i] * d.lo() : c_[i] * d.hi();
        double term_hi = c_[i] > 0 ? c_[i] * d.hi() : c_[i] * d.lo();
        double others_lo = lo_sum - term_lo, others_hi = hi_sum - term_hi;
        double t_lo = k_ - others_hi, t_hi = k_ - others_lo;  // bounds on c_i * x_i
        double lo = c_[i] > 0 ? t_lo / c_[i] : t_hi / c_[i];
        double hi = c_[i] > 0 ? t_hi / c_[i] : t_lo / c_[i];
        Domain before = d;
        if (!n.narrow_bounds(scope_[i], lo, hi)) return false;
        changed |= !(before == n.domain(scope_[i]));
      }
      if (!changed) break;
    }
    return true;
  }
  std::string name() const override { return "linear_equal"; }

 private:
  std::vector<double> c_;
  double k_;
};

struct Interval {
  double lo, hi;
};
Interval times(Interval a, Interval b) {
  double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  for (double& x : p)
    if (std::isnan(x)) x = 0;  // 0 * inf: the product of a zero bound is zero
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
// a / b when b does not contain zero; otherwise no information.
Interval divide(Interval a, Interval b) {
  if (b.lo <= 0 && b.hi >= 0) return {-HUGE_VAL, HUGE_VAL};
  return times(a, {1 / b.hi, 1 / b.lo});
}

class SumProduct final : public Procedure {
 public:
  SumProduct(VariableId s, VariableId r, VariableId d, VariableId e) : Procedure({s, r, d, e}) {}
  bool propagate(ConstraintNetwork& n) override {
    auto iv = [&](int i) { return Interval{n.domain(scope_[i]).lo(), n.domain(scope_[i]).hi()}; };
    for (int pass = 0; pass < 4; ++pass) {
      std::vector<Domain> before;
      for (VariableId v : scope_) before.push_back(n.domain(v));
      Interval rd = times(iv(1), iv(2));
      // e = s + r*d
      if (!n.narrow_bounds(scope_[3], iv(0).lo + rd.lo, iv(0).hi + rd.hi)) return false;
      // s = e - r*d
      if (!n.narrow_bounds(scope_[0], iv(3).lo - rd.hi, iv(3).hi - rd.lo)) return false;
      // r*d = e - s
      Interval diff{iv(3).lo - iv(0).hi, iv(3).hi - iv(0).lo};
      Interval r = divide(diff, iv(2));
      if (!n.narrow_bounds(scope_[1], r.lo, r.hi)) return false;
      Interval d = divide(diff, iv(1));
      if (!n.narrow_bounds(scope_[2], d.lo, d.hi)) return false;
      bool changed = false;
      for (std::size_t i = 0; i < scope_.size(); ++i)
        changed |= !(before[i] == n.domain(scope_[i]));
      if (!changed) break;
    }
    return true;
  }
  std::string name() const override { return "sum_product"; }
};

class Member final : public Procedure {
 public:
  Member(VariableId x, std::vector<std::int64_t> values)
      : Procedure({x}), values_(Domain::values(std::move(values))) {}
  bool propagate(ConstraintNetwork& n) override { return n.narrow(scope_[0], values_); }
  std::string name() const override { return "member"; }

 private:
  Domain values_;
};

// The allowed tuples listed (an extensional constraint: the turn angle between two targets,
// say). Generalised arc consistency: a tuple is supported while each of its values is in its
// variable's domain; each variable keeps the values (sets) or the hull (intervals) of the
// supported tuples.
class Table final : public Procedure {
 public:
  Table(std::vector<VariableId> scope, std::vector<std::vector<double>> tuples)
      : Procedure(std::move(scope)), tuples_(std::move(tuples)) {}
  bool propagate(ConstraintNetwork& n) override {
    const std::size_t k = scope_.size();
    std::vector<std::vector<std::int64_t>> values(k);
    std::vector<double> lo(k, HUGE_VAL), hi(k, -HUGE_VAL);
    bool any = false;
    for (const std::vector<double>& t : tuples_) {
      bool supported = true;
      for (std::size_t i = 0; i < k && supported; ++i)
        supported = n.domain(scope_[i]).contains(t[i]);
      if (!supported) continue;
      any = true;
      for (std::size_t i = 0; i < k; ++i) {
        lo[i] = std::min(lo[i], t[i]);
        hi[i] = std::max(hi[i], t[i]);
        if (n.domain(scope_[i]).is_set()) values[i].push_back(std::int64_t(t[i]));
      }
    }
    if (!any) return n.narrow_bounds(scope_[0], 1, 0);  // empties it: nothing is allowed
    for (std::size_t i = 0; i < k; ++i) {
      const bool ok = n.domain(scope_[i]).is_set()
                          ? n.narrow(scope_[i], Domain::values(std::move(values[i])))
                          : n.narrow_bounds(scope_[i], lo[i], hi[i]);
      if (!ok) return false;
    }
    return true;
  }
  std::string name() const override { return "table"; }

 private:
  std::vector<std::vector<double>> tuples_;
};

}  // namespace

std::unique_ptr<ConstraintProcedure> make_equal(VariableId a, VariableId b) {
  return std::make_unique<Equal>(a, b);
}
std::unique_ptr<ConstraintProcedure> make_not_equal(VariableId a, VariableId b) {
  return std::make_unique<NotEqual>(a, b);
}
std::unique_ptr<ConstraintProcedure> make_less_equal(VariableId a, VariableId b, double offset) {
  return std::make_unique<LessEqual>(a, b, offset);
}
std::unique_ptr<ConstraintProcedure> make_linear_equal(std::vector<VariableId> vars,
                                                       std::vector<double> coefficients,
                                                       double constant) {
  return std::make_unique<LinearEqual>(std::move(vars), std::move(coefficients), constant);
}
std::unique_ptr<ConstraintProcedure> make_sum_product(VariableId s, VariableId r, VariableId d,
                                                      VariableId e) {
  return std::make_unique<SumProduct>(s, r, d, e);
}
std::unique_ptr<ConstraintProcedure> make_member(VariableId x, std::vector<std::int64_t> values) {
  return std::make_unique<Member>(x, std::move(values));
}

std::unique_ptr<ConstraintProcedure> make_table(std::vector<VariableId> vars,
                                                std::vector<std::vector<double>> tuples) {
  return std::make_unique<Table>(std::move(vars), std::move(tuples));
}

}  // namespace autonomy::planner
