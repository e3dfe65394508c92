#include "simulator/core/number_format.hpp"

#include <cmath>
#include <locale>
#include <sstream>

namespace autonomy::sim {

std::string format_number(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(6);
  out << value;
  std::string text = out.str();
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

}  // namespace autonomy::sim
