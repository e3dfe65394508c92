#include "plan_json.hpp"

#include <google/protobuf/util/json_util.h>

namespace autonomy::planner {

std::string plan_json(const FlexiblePlan& plan) {
  std::string json;
  google::protobuf::util::JsonPrintOptions print;
  print.add_whitespace = true;
  print.always_print_primitive_fields = true;
  (void)google::protobuf::util::MessageToJsonString(to_message(plan), &json, print);
  return json;
}

}  // namespace autonomy::planner
