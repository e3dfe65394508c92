#include "common/dds/error.hpp"

namespace autonomy::dds {

DdsError::DdsError(const std::string& what, dds_return_t code)
    : std::runtime_error(what + ": " + dds_strretcode(code)), code_(code) {}

dds_return_t check(dds_return_t rc, const char* what) {
  if (rc < 0) throw DdsError(what, rc);
  return rc;
}

}  // namespace autonomy::dds
