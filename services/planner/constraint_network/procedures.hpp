#pragma once
// The constraint procedures the model language can name. Each narrows bounds or values and
// never removes a value of an allowed assignment (checked by brute force in the tests).
#include <memory>
#include <vector>

#include "constraint_network.hpp"

namespace autonomy::planner {

// a == b
std::unique_ptr<ConstraintProcedure> make_equal(VariableId a, VariableId b);
// a != b
std::unique_ptr<ConstraintProcedure> make_not_equal(VariableId a, VariableId b);
// a + offset <= b
std::unique_ptr<ConstraintProcedure> make_less_equal(VariableId a, VariableId b, double offset = 0);
// sum coefficients[i] * vars[i] == constant
std::unique_ptr<ConstraintProcedure> make_linear_equal(std::vector<VariableId> vars,
                                                       std::vector<double> coefficients,
                                                       double constant);
// s + r * d == e (the paper's record(s, r, d, e)); interval arithmetic, every direction.
std::unique_ptr<ConstraintProcedure> make_sum_product(VariableId s, VariableId r, VariableId d,
                                                      VariableId e);
// x is one of values
std::unique_ptr<ConstraintProcedure> make_member(VariableId x, std::vector<std::int64_t> values);
// (vars...) is one of the tuples (each tuple has one value per variable)
std::unique_ptr<ConstraintProcedure> make_table(std::vector<VariableId> vars,
                                                std::vector<std::vector<double>> tuples);

}  // namespace autonomy::planner
