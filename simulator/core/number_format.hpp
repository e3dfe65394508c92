#pragma once
// Numbers in reasons and error messages: short, locale-independent and always recognisable as
// real numbers ("1.0", "3.2", "0.05"), so messages are stable enough to assert in tests.
#include <string>

namespace autonomy::sim {

std::string format_number(double value);

}  // namespace autonomy::sim
